// The scalar helpers: portableAtan2 against the double-precision arctangent.
#include <impetus/math/scalar.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace impetus {
namespace {

// Every direction around the circle (and at magnitudes from 1e-30 to 1e30): within 3e-7 rad of
// atan2 in double, as good as the C library's float atan2f (whose error on these float inputs is
// 2.5e-7). Near an axis the error is relative: the angle of (1e-6, 1) is right to 1e-7 of itself.
TEST(PortableAtan2, matches_the_double_precision_arctangent_everywhere) {
  double worst = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const double t = -pi<double> + 2.0 * pi<double> * i / 200000.0;
    for (const float scale : {1e-30f, 1e-3f, 1.0f, 7.0f, 1e30f}) {
      const float y = static_cast<float>(std::sin(t)) * scale;
      const float x = static_cast<float>(std::cos(t)) * scale;
      const double exact = std::atan2(static_cast<double>(y), static_cast<double>(x));
      worst = std::max(worst, std::abs(static_cast<double>(portableAtan2(y, x)) - exact));
    }
  }
  EXPECT_LT(worst, 3e-7);
  for (const float y : {1e-6f, 3e-4f, 0.01f}) {
    const double exact = std::atan2(static_cast<double>(y), 1.0);
    EXPECT_NEAR(portableAtan2(y, 1.0f), exact, 1e-7 * exact) << y;
  }
}

TEST(PortableAtan2, is_exact_on_the_axes_and_propagates_nan) {
  EXPECT_EQ(portableAtan2(0.0f, 1.0f), 0.0f);
  EXPECT_FLOAT_EQ(portableAtan2(1.0f, 0.0f), 0.5f * pi<float>);
  EXPECT_FLOAT_EQ(portableAtan2(-1.0f, 0.0f), -0.5f * pi<float>);
  EXPECT_FLOAT_EQ(portableAtan2(0.0f, -1.0f), pi<float>);
  EXPECT_FLOAT_EQ(portableAtan2(1.0f, 1.0f), 0.25f * pi<float>);
  EXPECT_FLOAT_EQ(portableAtan2(-1.0f, -1.0f), -0.75f * pi<float>);
  EXPECT_EQ(portableAtan2(0.0f, 0.0f), 0.0f);
  EXPECT_TRUE(std::isnan(portableAtan2(std::nanf(""), 1.0f)));
  EXPECT_TRUE(std::isnan(portableAtan2(1.0f, std::nanf(""))));
}

} // namespace
} // namespace impetus
