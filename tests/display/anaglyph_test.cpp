// Anaglyph colour mixing (ch. 24) against pixels worked out by hand from each method's definition,
// and Dubois' matrices against their design property (white stays white: each output row of
// M_L + M_R sums to ~1) with the sRGB transfer function's published constants.
#include <impetus/display/anaglyph.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace impetus::display {
namespace {

void expectRgb(const Rgb& got, const Rgb& want, double tol) {
  EXPECT_NEAR(got.r, want.r, tol);
  EXPECT_NEAR(got.g, want.g, tol);
  EXPECT_NEAR(got.b, want.b, tol);
}

TEST(Anaglyph, every_mode_on_a_hand_computed_pixel) {
  // L = (0.2, 0.4, 0.6): Y = 0.0598 + 0.2348 + 0.0684 = 0.363.
  // R = (0.9, 0.5, 0.1): Y = 0.2691 + 0.2935 + 0.0114 = 0.574.
  const Rgb l{0.2, 0.4, 0.6}, r{0.9, 0.5, 0.1};
  expectRgb(anaglyph(l, r, AnaglyphMode::trueAnaglyph), {0.363, 0.0, 0.574}, 1e-15);
  expectRgb(anaglyph(l, r, AnaglyphMode::gray), {0.363, 0.574, 0.574}, 1e-15);
  expectRgb(anaglyph(l, r, AnaglyphMode::color), {0.2, 0.5, 0.1}, 0.0);
  expectRgb(anaglyph(l, r, AnaglyphMode::halfColor), {0.363, 0.5, 0.1}, 1e-15);
  expectRgb(anaglyph(l, r, AnaglyphMode::optimized), {0.7 * 0.4 + 0.3 * 0.6, 0.5, 0.1}, 1e-15);
}

TEST(Anaglyph, dubois_keeps_white_white_and_black_black_and_works_in_linear_light) {
  // Row sums of M_L + M_R: 1.132 - 0.133 = 0.999, -0.094 + 1.094 = 1.000, -0.041 + 1.041 = 1.000.
  const Rgb white{1.0, 1.0, 1.0}, black{};
  expectRgb(anaglyph(white, white, AnaglyphMode::dubois, AnaglyphEncoding::linear), {0.999, 1.0, 1.0}, 1e-12);
  expectRgb(anaglyph(black, black, AnaglyphMode::dubois), black, 0.0);
  // A pure red seen by the left eye only: linear (0.456, -0.040, -0.015) clips to (0.456, 0, 0),
  // and back to sRGB 1.055 x 0.456^(1/2.4) - 0.055.
  const Rgb red = anaglyph({1.0, 0.0, 0.0}, black, AnaglyphMode::dubois);
  EXPECT_NEAR(red.r, 1.055 * std::pow(0.456, 1.0 / 2.4) - 0.055, 1e-12);
  EXPECT_EQ(red.g, 0.0);
  EXPECT_EQ(red.b, 0.0);
  // A mid-grey (sRGB 0.5 = linear 0.21404) in both eyes stays grey to a few thousandths.
  const Rgb grey = anaglyph({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, AnaglyphMode::dubois);
  EXPECT_NEAR(grey.g, 0.5, 1e-12);
  EXPECT_NEAR(grey.r, 0.5, 2e-3);
  // sRGB constants: 0.04045 / 12.92 at the knee, and the round trip.
  EXPECT_NEAR(srgbToLinear(0.5), 0.21404114, 1e-8);
  EXPECT_NEAR(linearToSrgb(srgbToLinear(0.73)), 0.73, 1e-14);
}

TEST(Anaglyph, images_and_bad_pixels) {
  const std::vector<Rgb> left{{1, 0, 0}, {0, 1, 0}}, right{{0, 0, 1}, {0, 1, 1}};
  std::vector<Rgb> out(2);
  anaglyphImage(left, right, out, AnaglyphMode::color);
  EXPECT_EQ(out[0], (Rgb{1, 0, 1}));
  EXPECT_EQ(out[1], (Rgb{0, 1, 1}));
  std::vector<Rgb> small(1);
  expectErrorField([&] { anaglyphImage(left, right, small, AnaglyphMode::gray); }, "out");
  expectErrorField([] { (void)anaglyph({1.2, 0, 0}, {}, AnaglyphMode::gray); }, "left");
  expectErrorField([] { (void)anaglyph({}, {0, std::nan(""), 0}, AnaglyphMode::gray); }, "right");
  EXPECT_EQ(anaglyphModeFromString("half-color"), AnaglyphMode::halfColor);
  EXPECT_EQ(toString(AnaglyphMode::trueAnaglyph), "true");
  expectErrorField([] { (void)anaglyphModeFromString("purple"); }, "mode");
}

} // namespace
} // namespace impetus::display
