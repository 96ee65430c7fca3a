// Interaural time and level differences: the spec's ITD figures (0.17 m: 0.495 ms; Woodworth's
// 8.75 cm head: 0.655 ms at 90 degrees), symmetry, and the head-shadow ILD's limits (0 dB at
// low frequency and straight ahead; 20 log10(2 / 0.2814) = 17 dB from the side at high ones).
#include <impetus/audio/binaural.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace impetus::audio {
namespace {

constexpr double quarter = std::numbers::pi / 2.0;

TEST(Binaural, time_differences) {
  EXPECT_NEAR(interauralTimeDifference(quarter) * 1e3, 0.4952, 1e-4);
  EXPECT_NEAR(woodworthTimeDifference(quarter) * 1e3, 0.6553, 1e-4);
  EXPECT_NEAR(interauralTimeDifference(-quarter), -interauralTimeDifference(quarter), 1e-18);
  EXPECT_NEAR(interauralTimeDifference(0.0), 0.0, 1e-18);
  // A source behind gives the ITD of its mirror in front (the cone of confusion).
  EXPECT_NEAR(woodworthTimeDifference(std::numbers::pi - 0.3), woodworthTimeDifference(0.3), 1e-15);
  EXPECT_NEAR(woodworthTimeDifference(std::numbers::pi), 0.0, 1e-15);
  // Woodworth exceeds the free-field path (the far ear is reached round the head).
  EXPECT_GT(woodworthTimeDifference(0.5), interauralTimeDifference(0.5, 2.0 * typicalHeadRadius));
}

TEST(Binaural, head_shadow_level_differences) {
  EXPECT_NEAR(interauralLevelDifference(0.0, 4000.0), 0.0, 1e-12);
  EXPECT_NEAR(interauralLevelDifference(quarter, 20.0), 0.0, 0.05); // low notes diffract round the head
  const double high = interauralLevelDifference(quarter, 1e6);
  EXPECT_NEAR(high, 20.0 * std::log10(2.0 / (1.05 + 0.95 * std::cos(1.2 * std::numbers::pi))), 1e-3);
  EXPECT_NEAR(high, 17.04, 0.01);
  EXPECT_GT(interauralLevelDifference(quarter, 4000.0), interauralLevelDifference(quarter, 1000.0));
  EXPECT_NEAR(interauralLevelDifference(-quarter, 3000.0), -interauralLevelDifference(quarter, 3000.0), 1e-12);
  // The facing ear at high frequency: +6 dB (pressure doubling); the darkest point 150 degrees
  // off the ear's axis: alpha_min = 0.1, -20 dB.
  EXPECT_NEAR(20.0 * std::log10(headShadowGain(0.0, 1e7)), 6.0206, 1e-3);
  EXPECT_NEAR(20.0 * std::log10(headShadowGain(150.0 * std::numbers::pi / 180.0, 1e7)), -20.0, 1e-3);
}

TEST(Binaural, bad_input_is_rejected) {
  expectErrorField([] { (void)interauralTimeDifference(NAN); }, "azimuth");
  expectErrorField([] { (void)interauralTimeDifference(0.1, 0.0); }, "earSpacing");
  expectErrorField([] { (void)woodworthTimeDifference(0.1, -1.0); }, "headRadius");
  expectErrorField([] { (void)interauralLevelDifference(0.1, 0.0); }, "frequency");
}

} // namespace
} // namespace impetus::audio
