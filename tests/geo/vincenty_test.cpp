// Vincenty's inverse formula against published values it did not produce: Geoscience
// Australia's worked example (Flinders Peak to Buninyong on GRS80, from the GDA technical
// manual), exact cases on the ellipsoid (meridian quadrant, the equator), and its
// non-convergence for nearly antipodal points, reported as such. GeographicLib's geodesic, the
// 1 mm reference over many routes, is in geodesic_reference_test.cpp (impetus::geo).
#include <impetus/geo/great_circle.hpp>
#include <impetus/geo/vincenty.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace impetus::geo {
namespace {

double dms(double d, double m, double s) { return std::copysign(std::abs(d) + m / 60.0 + s / 3600.0, d); }

TEST(Vincenty, flinders_peak_to_buninyong_matches_the_published_solution) {
  const Ellipsoid grs80{6378137.0, 1.0 / 298.257222101};
  const LatLon flinders{dms(-37, 57, 3.72030), dms(144, 25, 29.52440)};
  const LatLon buninyong{dms(-37, 39, 10.15610), dms(143, 55, 35.38390)};
  const std::optional<VincentyResult> v = vincentyInverse(flinders, buninyong, grs80);
  ASSERT_TRUE(v.has_value());
  // Published: s = 54972.271 m, alpha12 = 306 52' 05.37", alpha21 = 127 10' 25.07" (the
  // reverse azimuth; the forward azimuth on arrival is alpha21 - 180).
  EXPECT_NEAR(v->distance, 54972.271, 0.0005);
  EXPECT_NEAR(v->initialAzimuth, dms(306, 52, 5.37), 0.005 / 3600.0);
  EXPECT_NEAR(v->finalAzimuth, dms(127, 10, 25.07) + 180.0, 0.005 / 3600.0);
}

TEST(Vincenty, meridian_quadrant_and_equator_are_exact) {
  const Ellipsoid e = Ellipsoid::wgs84();
  // The WGS 84 meridian quadrant (equator to pole) is 10,001,965.729 m.
  const std::optional<VincentyResult> q = vincentyInverse({0.0, 0.0}, {90.0, 0.0}, e);
  ASSERT_TRUE(q.has_value());
  EXPECT_NEAR(q->distance, 10001965.729, 0.001);
  // Along the equator (short of the antipodal region): a dlambda exactly.
  const std::optional<VincentyResult> eq = vincentyInverse({0.0, 0.0}, {0.0, 90.0}, e);
  ASSERT_TRUE(eq.has_value());
  EXPECT_NEAR(eq->distance, e.equatorialRadius * std::numbers::pi / 2.0, 1e-5); // lambda to 1e-12 rad
  EXPECT_DOUBLE_EQ(eq->initialAzimuth, 90.0);
  // On a sphere (f = 0) Vincenty is the great circle.
  const Ellipsoid sphere = Ellipsoid::sphere(bookEarthRadius);
  const std::optional<VincentyResult> s = vincentyInverse({40.7128, -74.0060}, {51.5074, -0.1278}, sphere);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->distance, haversineDistance({40.7128, -74.0060}, {51.5074, -0.1278}, bookEarthRadius), 1e-6);
  EXPECT_NEAR(s->initialAzimuth, initialBearing({40.7128, -74.0060}, {51.5074, -0.1278}), 1e-9);
  // Coincident points.
  const std::optional<VincentyResult> zero = vincentyInverse({12.0, 34.0}, {12.0, 34.0}, e);
  ASSERT_TRUE(zero.has_value());
  EXPECT_EQ(zero->distance, 0.0);
}

TEST(Vincenty, nearly_antipodal_points_do_not_converge_and_say_so) {
  // The classic failure: (0, 0) to (0.5, 179.7) on WGS 84.
  EXPECT_FALSE(vincentyInverse({0.0, 0.0}, {0.5, 179.7}).has_value());
  EXPECT_FALSE(vincentyInverse({0.0, 0.0}, {0.0, 179.9}).has_value());
  // A few degrees away from the antipode it converges again.
  EXPECT_TRUE(vincentyInverse({0.0, 0.0}, {5.0, 170.0}).has_value());
}

TEST(Vincenty, bad_input_is_rejected) {
  expectErrorField([] { (void)vincentyInverse({-91.0, 0.0}, {0.0, 0.0}); }, "from.latitude");
  expectErrorField([] { (void)vincentyInverse({0.0, 0.0}, {0.0, 0.0}, Ellipsoid{6e6, 1.0}); }, "ellipsoid.flattening");
  expectErrorField(
      [] {
        (void)vincentyInverse({0.0, 0.0}, {0.0, 0.0}, Ellipsoid{-1.0, 0.0});
      },
      "ellipsoid.equatorialRadius");
  expectErrorField(
      [] {
        (void)vincentyInverse({0.0, 0.0}, {1.0, 1.0}, Ellipsoid::wgs84(), {0, 1e-12});
      },
      "maxIterations");
}

} // namespace
} // namespace impetus::geo
