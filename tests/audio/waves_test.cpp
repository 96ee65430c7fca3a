// Harmonic waves and superposition: f = c / lambda (the book's f = 1/lambda drops c), a wave
// that travels at c, beats at |f1 - f2| (the product form of the sum), and cancellation.
#include <impetus/audio/waves.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace impetus::audio {
namespace {

TEST(Waves, wavelength_and_frequency_use_the_speed_of_sound) {
  // 440 Hz in air at 343.3 m/s: lambda = 0.780 m (spec).
  EXPECT_NEAR(wavelength(440.0), 0.780227, 1e-6);
  EXPECT_NEAR(frequencyFromWavelength(0.780227), 440.0, 1e-3);
  // The book's f = 1/lambda would give 1.28 "Hz" for the same wave.
  EXPECT_NEAR(1.0 / wavelength(440.0), 1.2817, 1e-4);
  const HarmonicWave w{2.0, 440.0, 0.3, 343.3};
  EXPECT_NEAR(w.wavelength() * w.frequency, 343.3, 1e-12);
  EXPECT_NEAR(w.wavenumber(), 2.0 * std::numbers::pi / w.wavelength(), 1e-12);
  EXPECT_NEAR(w.period(), 1.0 / 440.0, 1e-15);
}

TEST(Waves, a_harmonic_wave_travels_toward_plus_x_at_c) {
  const HarmonicWave w{1.5, 250.0, 0.7, 340.0};
  for (const double x : {0.0, 0.3, 2.0}) {
    for (const double t : {0.0, 0.001, 0.0137}) {
      const double dt = 0.0042;
      EXPECT_NEAR(w.pressure(x + w.speedOfSound * dt, t + dt), w.pressure(x, t), 1e-12);
      EXPECT_LE(std::abs(w.pressure(x, t)), 1.5);
    }
  }
}

TEST(Waves, two_close_tones_beat_at_their_difference) {
  // sin(a) + sin(b) = 2 sin((a + b)/2) cos((a - b)/2): a tone at 442 Hz whose envelope
  // 2 |cos(pi 4 t)| vanishes at t = 1/8 s: 4 beats a second.
  WaveSum sum;
  sum.add({1.0, 440.0, 0.0, 343.3});
  sum.add({1.0, 444.0, 0.0, 343.3});
  EXPECT_DOUBLE_EQ(beatFrequency(440.0, 444.0), 4.0);
  for (const double t : {0.0, 0.01, 0.05, 0.2, 0.777}) {
    // At x = 0: A sin(-w t) summed.
    const double product =
        -2.0 * std::sin(2.0 * std::numbers::pi * 442.0 * t) * std::cos(2.0 * std::numbers::pi * 2.0 * t);
    EXPECT_NEAR(sum.pressure(0.0, t), product, 1e-12);
  }
  // At the envelope's nodes the sum is silent, at its crests twice as loud.
  EXPECT_NEAR(sum.pressure(0.0, 0.125), 0.0, 1e-12);
  double loudest = 0.0;
  for (const double p : sum.sample(0.0, 44100.0, 441)) {
    loudest = std::max(loudest, std::abs(p));
  }
  EXPECT_GT(loudest, 1.99);
}

TEST(Waves, opposite_phases_cancel) {
  WaveSum sum;
  sum.add({0.8, 100.0, 0.0, 343.3});
  sum.add({0.8, 100.0, std::numbers::pi, 343.3});
  for (const double t : {0.0, 0.0031, 0.25}) {
    EXPECT_NEAR(sum.pressure(1.7, t), 0.0, 1e-12);
  }
}

TEST(Waves, bad_input_is_rejected) {
  expectErrorField([] { (void)wavelength(0.0); }, "frequency");
  expectErrorField([] { (void)wavelength(440.0, -1.0); }, "speedOfSound");
  expectErrorField([] { (void)frequencyFromWavelength(NAN); }, "wavelength");
  expectErrorField([] { WaveSum().add({-1.0, 440.0, 0.0, 343.3}); }, "amplitude");
  expectErrorField([] { WaveSum().add({1.0, 440.0, INFINITY, 343.3}); }, "phase");
  expectErrorField([] { (void)beatFrequency(440.0, 0.0); }, "frequency2");
}

} // namespace
} // namespace impetus::audio
