#include <impetus/audio/pitch.hpp>
#include <impetus/error.hpp>

#include <cmath>

namespace impetus::audio {

PitchEstimate zeroCrossingPitch(std::span<const float> samples, double sampleRate) {
  return zeroCrossingPitch(samples, sampleRate, 0, samples.size());
}

PitchEstimate zeroCrossingPitch(std::span<const float> samples, double sampleRate, std::size_t begin,
                                std::size_t count) {
  requirePositive(sampleRate, "sampleRate");
  if (begin > samples.size() || count > samples.size() - begin) {
    throwInvalid("samples", static_cast<double>(samples.size()), "the window runs past the end of the samples");
  }
  double first = 0.0;
  double last = 0.0;
  int crossings = 0;
  // A NaN compares false and would be skipped, an infinity would put a crossing at NaN.
  for (std::size_t i = begin; i < begin + count; ++i) {
    if (!std::isfinite(samples[i])) {
      throwInvalid("samples", samples[i], "must be finite");
    }
  }
  for (std::size_t i = begin + 1; i < begin + count; ++i) {
    const double a = samples[i - 1];
    const double b = samples[i];
    if (a < 0.0 && b >= 0.0) {
      // Linear interpolation of the crossing between samples i - 1 and i.
      const double t = (static_cast<double>(i - 1) + a / (a - b)) / sampleRate;
      if (crossings == 0) {
        first = t;
      }
      last = t;
      ++crossings;
    }
  }
  if (crossings < 2 || !(last > first)) {
    throwInvalid("samples", crossings, "need at least two upward zero crossings to measure a frequency");
  }
  return {static_cast<double>(crossings - 1) / (last - first), crossings};
}

} // namespace impetus::audio
