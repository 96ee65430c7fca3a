// Measuring pitch (ch. 26): the frequency of a recorded tone from its zero crossings, the
// instrument the Doppler tests and demo read a rendered pass with.
//
// A tone crosses zero upward once a period. Between the first and the last upward crossing in
// a window there are n - 1 whole periods, so f = (n - 1) / (t_last - t_first); each crossing's
// time is interpolated linearly between the two samples around it, which makes the estimate
// good to ~1e-5 of f for a clean tone over a few hundred periods.
#pragma once

#include <cstddef>
#include <span>

namespace impetus::audio {

struct PitchEstimate {
  double frequency = 0.0; ///< Hz
  int crossings = 0;      ///< upward zero crossings used
};

/// The frequency of the tone in `samples` (sampled at sampleRate Hz, > 0). Throws
/// impetus::Error naming "samples" when there are fewer than two upward zero crossings or a
/// sample is not finite.
[[nodiscard]] PitchEstimate zeroCrossingPitch(std::span<const float> samples, double sampleRate);

/// The same over samples [begin, begin + count) of a signal.
[[nodiscard]] PitchEstimate zeroCrossingPitch(std::span<const float> samples, double sampleRate, std::size_t begin,
                                              std::size_t count);

} // namespace impetus::audio
