// Great-circle navigation against the spec's oracles (ch. 22 section 3.6: R = 6371 km, values
// derived independently of this code), identities of spherical trigonometry, and bad input.
#include <impetus/geo/great_circle.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace impetus::geo {
namespace {

constexpr double r = bookEarthRadius;

struct Route {
  LatLon from;
  LatLon to;
  double haversineKm;
  double initial; // degrees
  double final;   // degrees, NaN when the spec gives none
};

// Spec section 3.6 (derived in double with R = 6371 km).
const Route routes[] = {
    {{50.0663, -5.7147}, {58.6439, -3.0700}, 968.8643, 9.1196, 11.2750},     // Land's End - John o' Groats
    {{0.0, 0.0}, {0.0, 90.0}, 10007.5434, 90.0, 90.0},                       // a quarter of the equator
    {{35.0, 45.0}, {35.0, 135.0}, 7871.7691, 60.1624, 119.8376},             // along a parallel
    {{40.7128, -74.0060}, {51.5074, -0.1278}, 5570.2222, 51.2126, 108.3297}, // New York - London
    {{40.7128, -74.0060}, {39.9042, 116.4074}, 10989.09, 351.93, std::numeric_limits<double>::quiet_NaN()},
    {{33.94, -118.40}, {35.55, 139.78}, 8813.2995, 305.8498, 235.7418}, // LAX - Tokyo, over the date line
};

TEST(GreatCircle, haversine_and_bearings_match_the_spec_oracles) {
  for (const Route& route : routes) {
    // The table's last digit: 5e-5 km (5e-3 km for the 2-decimal row), 5e-5 deg (5e-3).
    const double kmTol = route.haversineKm == 10989.09 ? 5e-3 : 5e-5;
    const double degTol = route.initial == 351.93 ? 5e-3 : 5e-5;
    EXPECT_NEAR(haversineDistance(route.from, route.to, r) / 1000.0, route.haversineKm, kmTol);
    EXPECT_NEAR(initialBearing(route.from, route.to), route.initial, degTol);
    if (!std::isnan(route.final)) {
      EXPECT_NEAR(finalBearing(route.from, route.to), route.final, degTol);
    }
  }
}

TEST(GreatCircle, antipode_is_half_the_circumference) {
  EXPECT_NEAR(haversineDistance({0.0, 0.0}, {0.0, 180.0}, r), std::numbers::pi * r, 1e-6);
  EXPECT_NEAR(haversineDistance({90.0, 0.0}, {-90.0, 0.0}, r), std::numbers::pi * r, 1e-6);
  EXPECT_NEAR(sphericalLawOfCosinesDistance({0.0, 0.0}, {0.0, 180.0}, r), std::numbers::pi * r, 1e-6);
}

TEST(GreatCircle, law_of_cosines_agrees_with_haversine_far_and_loses_digits_near) {
  for (const Route& route : routes) {
    EXPECT_NEAR(sphericalLawOfCosinesDistance(route.from, route.to, r), haversineDistance(route.from, route.to, r),
                1e-6);
  }
  // One metre north at 45 N: the haversine keeps ~1e-10 m, acos near 1 about 1e-2 m (double).
  const LatLon a{45.0, 7.0};
  const LatLon b{45.0 + 1.0 / (r * std::numbers::pi / 180.0), 7.0};
  EXPECT_NEAR(haversineDistance(a, b, r), 1.0, 1e-9);
  EXPECT_NEAR(sphericalLawOfCosinesDistance(a, b, r), 1.0, 0.05);
}

TEST(GreatCircle, book_bearing_example_and_final_bearing_wrap) {
  // The book: an initial bearing computed as -10 degrees is the compass value 350; its final
  // bearing adds 180 and wraps: 530 -> 170.
  EXPECT_DOUBLE_EQ(wrapBearing(-10.0), 350.0);
  EXPECT_DOUBLE_EQ(wrapBearing(350.0 + 180.0), 170.0);
  // Due north along a meridian: 0, never 360 (the book's `bearing > 0` test sends 0 to 360).
  EXPECT_EQ(initialBearing({10.0, 20.0}, {30.0, 20.0}), 0.0);
  EXPECT_EQ(finalBearing({10.0, 20.0}, {30.0, 20.0}), 0.0);
  EXPECT_DOUBLE_EQ(initialBearing({30.0, 20.0}, {10.0, 20.0}), 180.0);
}

TEST(GreatCircle, destination_retraces_the_route) {
  for (const Route& route : routes) {
    const double d = haversineDistance(route.from, route.to, r);
    const LatLon end = destination(route.from, initialBearing(route.from, route.to), d, r);
    EXPECT_NEAR(haversineDistance(end, route.to, r), 0.0, 1e-4) << route.haversineKm;
  }
  // Over the pole: 90 degrees of arc north from 45 N 10 E lands at 45 N 170 W.
  const LatLon over = destination({45.0, 10.0}, 0.0, r * std::numbers::pi / 2.0, r);
  EXPECT_NEAR(over.latitude, 45.0, 1e-9);
  EXPECT_NEAR(over.longitude, -170.0, 1e-9);
}

TEST(GreatCircle, intermediate_points_lie_on_the_circle_at_their_fraction) {
  const LatLon nyc{40.7128, -74.0060};
  const LatLon london{51.5074, -0.1278};
  const double total = haversineDistance(nyc, london, r);
  for (const double t : {0.0, 0.25, 0.5, 0.9, 1.0}) {
    const LatLon p = intermediatePoint(nyc, london, t);
    EXPECT_NEAR(haversineDistance(nyc, p, r), t * total, 1e-6);
    EXPECT_NEAR(crossTrackDistance(nyc, london, p, r), 0.0, 1e-6);
  }
  // The route's vertex is further north than either end (a great circle bulges poleward).
  EXPECT_GT(intermediatePoint(nyc, london, 0.5).latitude, 51.5074);
  expectErrorField([] { (void)intermediatePoint({0.0, 0.0}, {0.0, 180.0}, 0.5); }, "to");
}

TEST(GreatCircle, cross_and_along_track_on_the_equator) {
  // Route along the equator eastward; a point 1 degree north at 10 E is 1 degree of arc to the
  // left (negative) and 10 degrees along.
  const double degree = r * std::numbers::pi / 180.0;
  EXPECT_NEAR(crossTrackDistance({0.0, 0.0}, {0.0, 40.0}, {1.0, 10.0}, r), -degree, 1e-6);
  EXPECT_NEAR(crossTrackDistance({0.0, 0.0}, {0.0, 40.0}, {-1.0, 10.0}, r), degree, 1e-6);
  EXPECT_NEAR(alongTrackDistance({0.0, 0.0}, {0.0, 40.0}, {1.0, 10.0}, r), 10.0 * degree, 1e-3);
  EXPECT_NEAR(alongTrackDistance({0.0, 0.0}, {0.0, 40.0}, {0.0, -5.0}, r), -5.0 * degree, 1e-6);
}

TEST(GreatCircle, within_range_for_reverse_geocaching) {
  const LatLon cache{51.5007, -0.1246}; // Big Ben
  const LatLon player{51.5010, -0.1240};
  EXPECT_TRUE(withinRange(player, cache, 60.0));
  EXPECT_FALSE(withinRange(player, cache, 40.0));
}

TEST(GreatCircle, latitudes_out_of_range_and_bad_values_are_rejected) {
  expectErrorField([] { (void)haversineDistance({91.0, 0.0}, {0.0, 0.0}); }, "from.latitude");
  expectErrorField([] { (void)haversineDistance({0.0, 0.0}, {-90.5, 0.0}); }, "to.latitude");
  expectErrorField([] { (void)initialBearing({NAN, 0.0}, {0.0, 0.0}); }, "from.latitude");
  expectErrorField([] { (void)finalBearing({0.0, INFINITY}, {0.0, 0.0}); }, "from.longitude");
  expectErrorField([] { (void)haversineDistance({0.0, 0.0}, {1.0, 0.0}, 0.0); }, "radius");
  expectErrorField([] { (void)destination({0.0, 0.0}, 10.0, -1.0); }, "distance");
  expectErrorField([] { (void)destination({0.0, 0.0}, NAN, 1.0); }, "bearing");
  expectErrorField([] { (void)withinRange({0.0, 0.0}, {0.0, 0.0}, -1.0); }, "range");
  expectErrorField([] { (void)crossTrackDistance({0.0, 0.0}, {0.0, 1.0}, {100.0, 0.0}); }, "point.latitude");
  // The message names the value.
  try {
    (void)haversineDistance({91.0, 0.0}, {0.0, 0.0});
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("from.latitude = 91"), std::string::npos) << e.what();
  }
  // Longitudes wrap rather than fail: 190 E is 170 W.
  EXPECT_NEAR(haversineDistance({0.0, 190.0}, {0.0, -170.0}, r), 0.0, 1e-6);
  EXPECT_DOUBLE_EQ(wrapLongitude(190.0), -170.0);
  EXPECT_DOUBLE_EQ(wrapLongitude(180.0), -180.0);
  EXPECT_DOUBLE_EQ(wrapLongitude(-540.0), -180.0);
}

} // namespace
} // namespace impetus::geo
