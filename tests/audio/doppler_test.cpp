// Doppler: the spec's oracles (f = 440 Hz, c = 343.3 m/s), the vector and OpenAL 1.1 forms, the
// book's OpenAL demo (a tenth of the speed times a Doppler factor of 10), and a source passing
// a listener: the retarded time, the limits far before and after, and a physical rendering of
// the pass measured by zero crossings against the formula.
#include <impetus/audio/doppler.hpp>
#include <impetus/audio/pitch.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace impetus::audio {
namespace {

TEST(Doppler, moving_source_and_listener_match_the_spec) {
  EXPECT_NEAR(dopplerFrequency(440.0, 20.0, 0.0), 467.22, 0.005);  // source approaching
  EXPECT_NEAR(dopplerFrequency(440.0, -20.0, 0.0), 415.78, 0.005); // source receding
  EXPECT_NEAR(dopplerFrequency(440.0, 0.0, 20.0), 465.63, 0.005);  // listener approaching
  EXPECT_NEAR(dopplerFrequency(440.0, 20.0, 20.0), 494.44, 0.005); // both
  EXPECT_EQ(dopplerFrequency(440.0, 0.0, 0.0), 440.0);
}

TEST(Doppler, vector_form_projects_on_the_line_of_sight) {
  // Source at (100, 0, 0) moving at (-20, 5, 0) toward a listener at the origin moving at
  // (3, 7, 0): only the x components count.
  EXPECT_NEAR(dopplerFrequency(440.0, {100.0, 0.0, 0.0}, {-20.0, 5.0, 0.0}, {}, {3.0, 7.0, 0.0}),
              dopplerFrequency(440.0, 20.0, 3.0), 1e-12);
  // Crossing the line of sight at right angles: no shift.
  EXPECT_NEAR(dopplerFrequency(440.0, {0.0, 10.0, 0.0}, {30.0, 0.0, 0.0}, {}, {}), 440.0, 1e-12);
  // OpenAL's form with a factor of 1 is the same formula.
  EXPECT_NEAR(openALDopplerFrequency(440.0, {100.0, 0.0, 0.0}, {-20.0, 5.0, 0.0}, {}, {3.0, 7.0, 0.0}),
              dopplerFrequency(440.0, 20.0, 3.0), 1e-12);
}

TEST(Doppler, the_books_demo_hides_a_tenth_of_the_speed_behind_a_factor_of_ten) {
  // Start of the demo: source at (75, 0, -10), per-tick step (-1, 0.1, 0.25) set as the
  // velocity, 10 ticks a second, Doppler factor 10: pitch factor 1.0308 (spec).
  const Vec3d position{75.0, 0.0, -10.0};
  const Vec3d step{-1.0, 0.1, 0.25};
  const double book = openALDopplerFrequency(1.0, position, step, {}, {}, 10.0);
  EXPECT_NEAR(book, 1.0308, 5e-5);
  // The real velocity is 10 steps a second, with the physical factor 1: the same pitch.
  EXPECT_NEAR(openALDopplerFrequency(1.0, position, step * 10.0, {}, {}, 1.0), book, 1e-12);
  EXPECT_NEAR(length(step * 10.0), 10.36, 0.005);
  EXPECT_EQ(openALDopplerFrequency(440.0, position, step, {}, {}, 0.0), 440.0); // factor 0: off
}

TEST(Doppler, passing_source_retarded_time_and_limits) {
  const PassBy pass{440.0, 30.0, 10.0, 2.0, 343.3};
  for (const double t : {-10.0, -1.0, 0.0, 2.0, 2.0 + 10.0 / 343.3, 3.0, 9.0}) {
    const double tau = passByEmissionTime(pass, t);
    EXPECT_LE(tau, t);
    EXPECT_NEAR(length(passBySourcePosition(pass, tau)), 343.3 * (t - tau), 1e-9) << t;
    // The heard frequency is f d(tau)/dt.
    const double h = 1e-5;
    const double rate = (passByEmissionTime(pass, t + h) - passByEmissionTime(pass, t - h)) / (2.0 * h);
    EXPECT_NEAR(passByHeardFrequency(pass, t), 440.0 * rate, 1e-5) << t;
  }
  // Sound emitted at the closest point arrives d/c later, unshifted.
  EXPECT_NEAR(passByHeardFrequency(pass, 2.0 + 10.0 / 343.3), 440.0, 1e-9);
  // Far before and after: f c/(c - v) and f c/(c + v).
  EXPECT_NEAR(passByHeardFrequency(pass, -1e4), 440.0 * 343.3 / (343.3 - 30.0), 1e-4);
  EXPECT_NEAR(passByHeardFrequency(pass, 1e4), 440.0 * 343.3 / (343.3 + 30.0), 1e-4);
  // OpenAL's instantaneous form crosses f at the closest point itself, d/c earlier.
  EXPECT_NEAR(passByInstantaneousFrequency(pass, 2.0), 440.0, 1e-12);
}

TEST(Doppler, a_rendered_pass_measures_as_the_formula_says) {
  // The pressure at the listener sampled at 44.1 kHz (sound emitted at the retarded time,
  // amplitude 1/r), then measured by zero crossings over 0.2 s windows.
  const PassBy pass{440.0, 40.0, 10.0, 5.0, 343.3};
  const double rate = 44100.0;
  std::vector<float> samples(static_cast<std::size_t>(10.0 * rate));
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i] = static_cast<float>(passByPressure(pass, static_cast<double>(i) / rate, 10.0));
  }
  const std::size_t window = static_cast<std::size_t>(0.2 * rate);
  for (const double centre : {0.5, 2.0, 4.0, 6.5, 9.0}) {
    const std::size_t begin = static_cast<std::size_t>(centre * rate) - window / 2;
    const PitchEstimate p = zeroCrossingPitch(samples, rate, begin, window);
    EXPECT_NEAR(p.frequency / passByHeardFrequency(pass, centre), 1.0, 2e-4) << centre;
  }
}

TEST(Doppler, supersonic_and_degenerate_input_are_errors_not_infinities) {
  expectErrorField([] { (void)dopplerFrequency(440.0, 343.3, 0.0); }, "sourceSpeed");
  expectErrorField([] { (void)dopplerFrequency(440.0, 0.0, -400.0); }, "listenerSpeed");
  expectErrorField([] { (void)dopplerFrequency(0.0, 0.0, 0.0); }, "frequency");
  expectErrorField([] { (void)dopplerFrequency(440.0, {}, {}, {}, {}); }, "listenerPosition");
  expectErrorField(
      [] {
        (void)openALDopplerFrequency(440.0, {10.0, 0.0, 0.0}, {-400.0, 0.0, 0.0}, {}, {});
      },
      "sourceVelocity");
  expectErrorField([] { (void)passByHeardFrequency({440.0, 400.0, 10.0, 0.0, 343.3}, 0.0); }, "speed");
  expectErrorField([] { (void)passByHeardFrequency({440.0, 30.0, 0.0, 0.0, 343.3}, 0.0); }, "closestApproach");
}

} // namespace
} // namespace impetus::audio
