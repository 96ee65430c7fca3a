// Echoes and the image source: 2 d / c, a wall's mirror image, the lag and the weaker,
// absorbed reflection.
#include <impetus/audio/reflection.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace impetus::audio {
namespace {

TEST(Reflection, echo_delay_is_the_round_trip) {
  EXPECT_NEAR(echoDelay(171.65), 1.0, 1e-12); // 343.3 m there and back
  EXPECT_NEAR(reflectorDistance(echoDelay(42.0)), 42.0, 1e-12);
  EXPECT_NEAR(reflectionCoefficient(0.0), 1.0, 1e-15);
  EXPECT_NEAR(reflectionCoefficient(0.75), 0.5, 1e-15); // a quarter of the energy back: half the amplitude
}

TEST(Reflection, a_wall_reflects_from_the_image_source) {
  // Source and listener 2 m in front of the wall y = 0, 4 m apart: the image is 2 m behind
  // it, the reflected path sqrt(4^2 + 4^2), met at the wall half way.
  const PlaneReflection r = reflectOffPlane({0.0, 2.0, 0.0}, {4.0, 2.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 3.0, 0.0}, 0.5);
  EXPECT_NEAR(distance(r.imageSource, Vec3d{0.0, -2.0, 0.0}), 0.0, 1e-15);
  EXPECT_NEAR(distance(r.reflectionPoint, Vec3d{2.0, 0.0, 0.0}), 0.0, 1e-15);
  EXPECT_NEAR(r.directPath, 4.0, 1e-15);
  EXPECT_NEAR(r.reflectedPath, std::sqrt(32.0), 1e-15);
  EXPECT_NEAR(r.lag, (std::sqrt(32.0) - 4.0) / 343.3, 1e-15);
  EXPECT_NEAR(r.amplitudeRatio, 0.5 * 4.0 / std::sqrt(32.0), 1e-15);
  EXPECT_NEAR(r.levelDifference, 20.0 * std::log10(r.amplitudeRatio), 1e-12);
  // Standing at the source, the reflection is the echo: lag 2 d / c.
  const PlaneReflection echo = reflectOffPlane({0.0, 50.0, 0.0}, {0.0, 50.0, 1e-9}, {}, {0.0, 1.0, 0.0});
  EXPECT_NEAR(echo.reflectedDelay, echoDelay(50.0), 1e-12);
}

TEST(Reflection, bad_input_is_rejected) {
  expectErrorField([] { (void)reflectOffPlane({0.0, 1.0, 0.0}, {0.0, -1.0, 0.0}, {}, {0.0, 1.0, 0.0}); }, "listener");
  expectErrorField([] { (void)reflectOffPlane({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {}, {0.0, 1.0, 0.0}); }, "source");
  expectErrorField([] { (void)reflectOffPlane({0.0, 1.0, 0.0}, {1.0, 1.0, 0.0}, {}, {}); }, "planeNormal");
  expectErrorField(
      [] {
        (void)reflectOffPlane({0.0, 1.0, 0.0}, {1.0, 1.0, 0.0}, {}, {0.0, 1.0, 0.0}, 1.5);
      },
      "coefficient");
  expectErrorField([] { (void)reflectionCoefficient(-0.1); }, "absorption");
  expectErrorField([] { (void)echoDelay(-1.0); }, "distance");
}

} // namespace
} // namespace impetus::audio
