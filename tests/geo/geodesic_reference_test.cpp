// The geo layer's formulas against GeographicLib (impetus::geo), a reference they did not
// produce: the haversine within 0.5 % of the WGS 84 geodesic on long routes (and exact against
// the geodesic on a sphere), the great-circle bearings, destination and intermediate points on
// the sphere, Vincenty within 1 mm of the geodesic wherever it converges, the spherical rhumb
// line against GeographicLib's exact rhumb on a sphere at every latitude, and the ECEF
// conversions against GeographicLib's Geocentric.
#include <impetus/geo/ellipsoid.hpp>
#include <impetus/geo/geodesic.hpp>
#include <impetus/geo/great_circle.hpp>
#include <impetus/geo/rhumb.hpp>
#include <impetus/geo/vincenty.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <optional>
#include <vector>

namespace impetus::geo {
namespace {

/// Deterministic pairs of points, uniform on the sphere (a fixed LCG: the same pairs every run).
std::vector<std::pair<LatLon, LatLon>> randomPairs(int count, std::uint64_t seed) {
  std::uint64_t state = seed;
  auto uniform = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  auto point = [&] {
    const double z = 2.0 * uniform() - 1.0;
    return LatLon{std::asin(z) * 180.0 / std::numbers::pi, 360.0 * uniform() - 180.0};
  };
  std::vector<std::pair<LatLon, LatLon>> pairs;
  for (int i = 0; i < count; ++i) {
    const LatLon a = point();
    const LatLon b = point();
    pairs.emplace_back(a, b);
  }
  return pairs;
}

double angleDifference(double a, double b) { return std::abs(wrapLongitude(a - b)); }

TEST(GeodesicReference, haversine_is_within_half_a_percent_of_wgs84_on_long_routes) {
  // The mean radius R1 = (2a + b)/3 = 6371.0088 km against the WGS 84 geodesic, on random
  // routes and on the worst ones: along a meridian across the equator, where the meridian's
  // radius of curvature a (1 - e^2) = 6335.4 km is 0.56 % below R1. Over long (intercontinental,
  // >= 6000 km) routes the curvature averages out: within 0.5 %; over any route of 1000 km or
  // more, within 0.56 %.
  double worstLong = 0.0;
  double worstAny = 0.0;
  int longRoutes = 0;
  auto check = [&](const LatLon& a, const LatLon& b) {
    const GeodesicResult g = geodesicInverse(a, b);
    if (g.distance < 1.0e6) {
      return;
    }
    const double error = std::abs(haversineDistance(a, b) - g.distance) / g.distance;
    worstAny = std::max(worstAny, error);
    if (g.distance >= 6.0e6) {
      ++longRoutes;
      worstLong = std::max(worstLong, error);
    }
  };
  for (const auto& [a, b] : randomPairs(20000, 12345)) {
    check(a, b);
  }
  for (const double half : {4.5, 9.0, 27.0, 45.0, 60.0}) {
    check({-half, 0.0}, {half, 0.0}); // meridians across the equator
  }
  check({0.0, 0.0}, {0.0, 90.0}); // the equator: a = 6378.1 km, 0.11 % above R1
  std::printf("haversine vs WGS 84 geodesic: worst %.4f %% on %d routes >= 6000 km, %.4f %% on routes >= 1000 km\n",
              100.0 * worstLong, longRoutes, 100.0 * worstAny);
  EXPECT_GT(longRoutes, 10000);
  EXPECT_LT(worstLong, 0.005);
  EXPECT_LT(worstAny, 0.0056);
}

TEST(GeodesicReference, spherical_formulas_are_the_geodesic_of_a_sphere) {
  const Ellipsoid sphere = Ellipsoid::sphere(bookEarthRadius);
  for (const auto& [a, b] : randomPairs(500, 777)) {
    const GeodesicResult g = geodesicInverse(a, b, sphere);
    EXPECT_NEAR(haversineDistance(a, b, bookEarthRadius), g.distance, 1e-6);
    if (g.distance > 1e3 && g.distance < 0.999 * std::numbers::pi * bookEarthRadius) {
      EXPECT_LT(angleDifference(initialBearing(a, b), g.initialAzimuth), 1e-8);
      EXPECT_LT(angleDifference(finalBearing(a, b), g.finalAzimuth), 1e-8);
      const LatLon mid = intermediatePoint(a, b, 0.5);
      const LatLon geoMid = geodesicDestination(a, g.initialAzimuth, 0.5 * g.distance, sphere);
      EXPECT_NEAR(haversineDistance(mid, geoMid, bookEarthRadius), 0.0, 1e-6);
    }
    const LatLon d = destination(a, 37.0, 3.3e6, bookEarthRadius);
    const LatLon gd = geodesicDestination(a, 37.0, 3.3e6, sphere);
    EXPECT_NEAR(haversineDistance(d, gd, bookEarthRadius), 0.0, 1e-6);
  }
}

TEST(GeodesicReference, vincenty_is_within_a_millimetre_where_it_converges) {
  double worst = 0.0;
  double worstAzimuth = 0.0;
  int converged = 0;
  std::vector<std::pair<LatLon, LatLon>> pairs = randomPairs(4000, 4242);
  // Hard cases: short lines, poles, the equator, and near (not at) the antipode.
  pairs.push_back({{0.0, 0.0}, {0.0, 1e-6}});
  pairs.push_back({{89.999, 10.0}, {-89.999, -170.0}});
  pairs.push_back({{90.0, 0.0}, {-45.0, 33.0}});
  pairs.push_back({{0.0, 0.0}, {0.0, 179.0}});
  pairs.push_back({{10.0, 0.0}, {-9.5, 178.5}});
  for (const auto& [a, b] : pairs) {
    const std::optional<VincentyResult> v = vincentyInverse(a, b);
    if (!v) {
      continue;
    }
    ++converged;
    const GeodesicResult g = geodesicInverse(a, b);
    worst = std::max(worst, std::abs(v->distance - g.distance));
    if (g.distance > 1e3) {
      worstAzimuth = std::max(worstAzimuth, angleDifference(v->initialAzimuth, g.initialAzimuth));
    }
  }
  std::printf("Vincenty vs geodesic: %d of %zu converged, worst %.3g mm, azimuth %.3g deg\n", converged, pairs.size(),
              1000.0 * worst, worstAzimuth);
  EXPECT_GT(converged, 3990);
  EXPECT_LT(worst, 1e-3);
  EXPECT_LT(worstAzimuth, 1e-6);
  // Karney's nearly antipodal example (J. Geodesy 2013): s = 19936288.579 m, which Vincenty
  // still reaches to the millimetre (slowly).
  const GeodesicResult karney = geodesicInverse({0.0, 0.0}, {0.5, 179.5});
  EXPECT_NEAR(karney.distance, 19936288.579, 1e-3);
  const std::optional<VincentyResult> near = vincentyInverse({0.0, 0.0}, {0.5, 179.5});
  ASSERT_TRUE(near.has_value());
  EXPECT_NEAR(near->distance, karney.distance, 1e-3);
  // Closer to the antipode Vincenty gives up and says so; the geodesic still answers.
  EXPECT_FALSE(vincentyInverse({0.0, 0.0}, {0.5, 179.7}).has_value());
  const double across = geodesicInverse({0.0, 0.0}, {0.5, 179.7}).distance;
  EXPECT_GT(across, 1.99e7);
  EXPECT_LE(across, 20003931.46); // half a meridian: no geodesic on WGS 84 is longer
}

TEST(GeodesicReference, spherical_rhumb_line_is_exact_at_every_latitude) {
  const Ellipsoid sphere = Ellipsoid::sphere(bookEarthRadius);
  for (const double lat1 : {-89.9, -60.0, 0.0, 30.0, 44.9, 45.0, 50.0, 70.0, 85.0, 89.9}) {
    for (const double lat2 : {-70.0, 10.0, 46.0, 80.0, 89.99}) {
      for (const double dLon : {-175.0, -1.0, 0.0, 20.0, 150.0}) {
        const LatLon a{lat1, 3.0};
        const LatLon b{lat2, 3.0 + dLon};
        const RhumbResult ref = rhumbInverse(a, b, sphere);
        EXPECT_NEAR(rhumbDistance(a, b, bookEarthRadius), ref.distance, 1e-6 + 1e-11 * ref.distance)
            << lat1 << " " << lat2 << " " << dLon;
        if (ref.distance > 1.0) {
          EXPECT_LT(angleDifference(rhumbBearing(a, b), ref.bearing), 1e-9) << lat1 << " " << lat2 << " " << dLon;
        }
      }
    }
  }
}

TEST(GeodesicReference, ecef_conversions_match_geocentric) {
  for (const auto& [a, b] : randomPairs(300, 99)) {
    for (const double h : {-100.0, 0.0, 1.5e4, 2.02e7}) {
      const GeodeticPosition p{a, h};
      const Vec3d ours = geodeticToEcef(p);
      const Vec3d ref = referenceGeodeticToEcef(p);
      EXPECT_LT(distance(ours, ref), 1e-6);
      const GeodeticPosition back = ecefToGeodetic(ref);
      const GeodeticPosition refBack = referenceEcefToGeodetic(ref);
      EXPECT_NEAR(back.point.latitude, refBack.point.latitude, 1e-11);
      EXPECT_NEAR(back.height, refBack.height, 1e-6);
    }
  }
}

TEST(GeodesicReference, bad_input_is_rejected_like_the_rest_of_the_layer) {
  expectErrorField([] { (void)geodesicInverse({0.0, 0.0}, {90.1, 0.0}); }, "to.latitude");
  expectErrorField([] { (void)geodesicDestination({0.0, 0.0}, 0.0, -1.0); }, "distance");
  expectErrorField([] { (void)rhumbInverse({NAN, 0.0}, {0.0, 0.0}); }, "from.latitude");
}

} // namespace
} // namespace impetus::geo
