// Zero-crossing pitch: a sampled tone's frequency to ~1e-6, at any phase and amplitude, and
// silence reported as an error.
#include <impetus/audio/pitch.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace impetus::audio {
namespace {

std::vector<float> tone(double frequency, double rate, double seconds, double phase, double amplitude) {
  std::vector<float> s(static_cast<std::size_t>(seconds * rate));
  for (std::size_t i = 0; i < s.size(); ++i) {
    s[i] = static_cast<float>(amplitude *
                              std::sin(2.0 * std::numbers::pi * frequency * static_cast<double>(i) / rate + phase));
  }
  return s;
}

TEST(Pitch, zero_crossings_measure_a_tone) {
  for (const double f : {50.0, 440.0, 467.22, 2500.0}) {
    const std::vector<float> s = tone(f, 44100.0, 1.0, 0.4, 0.3);
    const PitchEstimate p = zeroCrossingPitch(s, 44100.0);
    EXPECT_NEAR(p.frequency / f, 1.0, 1e-5) << f;
    EXPECT_NEAR(p.crossings, f, 1.5);
  }
  const std::vector<float> s = tone(1000.0, 48000.0, 0.5, 0.0, 1e-3);
  EXPECT_NEAR(zeroCrossingPitch(s, 48000.0, 4800, 9600).frequency, 1000.0, 0.01);
}

TEST(Pitch, silence_and_bad_windows_are_errors) {
  const std::vector<float> silence(1000, 0.0f);
  expectErrorField([&] { (void)zeroCrossingPitch(silence, 44100.0); }, "samples");
  const std::vector<float> s = tone(440.0, 44100.0, 0.1, 0.0, 1.0);
  expectErrorField([&] { (void)zeroCrossingPitch(s, 44100.0, 4000, 1000); }, "samples");
  expectErrorField([&] { (void)zeroCrossingPitch(s, 0.0); }, "sampleRate");
}

} // namespace
} // namespace impetus::audio
