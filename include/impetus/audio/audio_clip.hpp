// A sampled sound: interleaved float samples (nominally -1..1), a channel count and a sample
// rate. What the OpenAL renderer produces and the WAV files hold (impetus::audio).
#pragma once

#include <cstddef>
#include <vector>

namespace impetus::audio {

struct AudioClip {
  std::vector<float> samples; ///< interleaved: frame i, channel c at samples[i * channels + c]
  int channels = 1;           ///< 1 mono, 2 stereo (left, right)
  int sampleRate = 44100;     ///< frames per second, Hz

  [[nodiscard]] std::size_t frames() const noexcept {
    return channels > 0 ? samples.size() / static_cast<std::size_t>(channels) : 0;
  }
  [[nodiscard]] double duration() const noexcept {
    return sampleRate > 0 ? static_cast<double>(frames()) / sampleRate : 0.0;
  }
  /// The channels averaged into one (a copy for a mono clip).
  [[nodiscard]] std::vector<float> mono() const {
    if (channels <= 1) {
      return samples;
    }
    std::vector<float> out(frames());
    for (std::size_t i = 0; i < out.size(); ++i) {
      float sum = 0.0f;
      for (int c = 0; c < channels; ++c) {
        sum += samples[i * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)];
      }
      out[i] = sum / static_cast<float>(channels);
    }
    return out;
  }
};

} // namespace impetus::audio
