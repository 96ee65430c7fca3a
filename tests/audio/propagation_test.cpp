// Propagation: c(T) against the spec's values, decibels, the inverse-square law (intensity
// 1/r^2, amplitude 1/r: the book has the amplitude falling as 1/r^2), flash-to-bang, and
// OpenAL 1.1's distance models.
#include <impetus/audio/propagation.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace impetus::audio {
namespace {

TEST(Propagation, speed_of_sound_against_temperature) {
  EXPECT_NEAR(speedOfSoundInAir(0.0), 331.3, 1e-12);
  EXPECT_NEAR(speedOfSoundInAir(20.0), 343.21, 0.005);
  EXPECT_NEAR(speedOfSoundInAir(25.0), 346.13, 0.005);
  EXPECT_NEAR(speedOfSoundInAir(-10.0), 325.18, 0.005);
  // The ideal gas: c ~ sqrt(T in kelvin).
  EXPECT_NEAR(speedOfSoundInAir(100.0) / speedOfSoundInAir(0.0), std::sqrt(373.15 / 273.15), 1e-12);
  expectErrorField([] { (void)speedOfSoundInAir(-300.0); }, "temperature");
}

TEST(Propagation, decibels_of_intensity_and_pressure) {
  EXPECT_NEAR(intensityLevel(1e-12), 0.0, 1e-12);
  EXPECT_NEAR(intensityLevel(1e-6), 60.0, 1e-9);
  EXPECT_NEAR(intensityLevel(1.0), 120.0, 1e-9);
  EXPECT_NEAR(intensityFromLevel(60.0), 1e-6, 1e-18);
  EXPECT_NEAR(pressureLevel(20e-6), 0.0, 1e-12);
  EXPECT_NEAR(pressureLevel(1.0), 93.9794, 1e-4);
  EXPECT_NEAR(pressureFromLevel(93.9794), 1.0, 1e-5);
  // 130 dB against 60 dB: 2^7 = 128 times as loud.
  EXPECT_NEAR(loudnessRatio(70.0), 128.0, 1e-9);
}

TEST(Propagation, intensity_falls_as_the_square_and_amplitude_as_the_distance) {
  // A 1 W point source: I = 1/(4 pi r^2).
  EXPECT_NEAR(intensityAtDistance(1.0, 1.0), 1.0 / (4.0 * std::numbers::pi), 1e-15);
  EXPECT_NEAR(intensityAtDistance(1.0, 2.0) / intensityAtDistance(1.0, 1.0), 0.25, 1e-15);
  EXPECT_NEAR(intensityRatio(1.0, 2.0), 0.25, 1e-15);
  EXPECT_NEAR(amplitudeRatio(1.0, 2.0), 0.5, 1e-15); // not 0.25, as the book has it
  // Intensity is proportional to the square of the pressure amplitude: both laws are one.
  EXPECT_NEAR(amplitudeRatio(3.0, 7.0) * amplitudeRatio(3.0, 7.0), intensityRatio(3.0, 7.0), 1e-15);
  // -6.02 dB per doubling, -20 dB per factor ten.
  EXPECT_NEAR(levelAtDistance(100.0, 1.0, 2.0), 100.0 - 6.0206, 1e-4);
  EXPECT_NEAR(levelAtDistance(100.0, 1.0, 10.0), 80.0, 1e-12);
  EXPECT_NEAR(intensityLevel(intensityAtDistance(1.0, 10.0)) - intensityLevel(intensityAtDistance(1.0, 1.0)), -20.0,
              1e-9);
}

TEST(Propagation, flash_to_bang) {
  EXPECT_NEAR(flashToBangDelay(1000.0), 2.913, 5e-4); // spec: 1 km gives 2.913 s
  EXPECT_NEAR(distanceFromFlashToBang(flashToBangDelay(1234.0)), 1234.0, 1e-9);
}

TEST(Propagation, openal_distance_models) {
  DistanceAttenuation a; // inverse clamped, ref 1, rolloff 1: gain = 1/d, the physical 1/r
  EXPECT_NEAR(distanceGain(a, 10.0), 0.1, 1e-15);
  EXPECT_NEAR(distanceGain(a, 0.5), 1.0, 1e-15); // clamped to ref
  a.referenceDistance = 10.0;
  EXPECT_NEAR(distanceGain(a, 200.0), 0.05, 1e-15);
  a.rolloff = 2.0; // ref / (ref + 2 (d - ref))
  EXPECT_NEAR(distanceGain(a, 20.0), 10.0 / 30.0, 1e-15);
  a = {DistanceModel::inverse, 1.0, 1e30, 1.0};
  EXPECT_NEAR(distanceGain(a, 0.5), 2.0, 1e-15); // unclamped: louder than the reference inside it
  a = {DistanceModel::linearClamped, 2.0, 12.0, 1.0};
  EXPECT_NEAR(distanceGain(a, 7.0), 0.5, 1e-15);
  EXPECT_NEAR(distanceGain(a, 20.0), 0.0, 1e-15);
  a = {DistanceModel::exponent, 1.0, 1e30, 2.0}; // (d/ref)^-2: intensity-like
  EXPECT_NEAR(distanceGain(a, 4.0), 1.0 / 16.0, 1e-15);
  a = {DistanceModel::none, 1.0, 1e30, 1.0};
  EXPECT_EQ(distanceGain(a, 1e6), 1.0);
  expectErrorField([] { (void)distanceGain({DistanceModel::inverse, 0.0, 1.0, 1.0}, 1.0); }, "referenceDistance");
  expectErrorField([] { (void)distanceGain({}, -1.0); }, "distance");
  expectErrorField([] { (void)distanceGain({DistanceModel::inverse, 1.0, 1.0, -1.0}, 1.0); }, "rolloff");
}

TEST(Propagation, bad_input_is_rejected) {
  expectErrorField([] { (void)intensityLevel(0.0); }, "intensity");
  expectErrorField([] { (void)intensityAtDistance(1.0, 0.0); }, "distance");
  expectErrorField([] { (void)intensityAtDistance(-1.0, 1.0); }, "power");
  expectErrorField([] { (void)levelAtDistance(60.0, 1.0, 0.0); }, "distance2");
  expectErrorField([] { (void)flashToBangDelay(-1.0); }, "distance");
}

} // namespace
} // namespace impetus::audio
