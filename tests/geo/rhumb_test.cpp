// Rhumb lines against the spec's oracles (ch. 22 section 3.6, R = 6371 km), the lines whose
// length is known exactly (meridians, parallels, to a pole), round trips at every latitude, and
// the book's listing as a regression: its tan(pi/4 + phi1) (no /2) is wrong and fails above 45 N.
#include <impetus/geo/great_circle.hpp>
#include <impetus/geo/rhumb.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impetus::geo {
namespace {

constexpr double r = bookEarthRadius;
constexpr double degree = std::numbers::pi / 180.0;

struct RhumbOracle {
  LatLon from;
  LatLon to;
  double km;
  double bearing;
};

const RhumbOracle oracles[] = {
    {{50.0663, -5.7147}, {58.6439, -3.0700}, 968.9212, 10.1405},
    {{0.0, 0.0}, {0.0, 90.0}, 10007.5434, 90.0},
    {{0.0, 0.0}, {0.0, 180.0}, 20015.0868, 90.0},
    {{35.0, 45.0}, {35.0, 135.0}, 8197.6996, 90.0},
    {{40.7128, -74.0060}, {51.5074, -0.1278}, 5794.1208, 78.0441},
    {{40.7128, -74.0060}, {39.9042, 116.4074}, 14379.95, 269.64},
    {{33.94, -118.40}, {35.55, 139.78}, 9304.2627, 271.1025},
};

TEST(Rhumb, distance_and_bearing_match_the_spec_oracles) {
  for (const RhumbOracle& o : oracles) {
    const double kmTol = o.km == 14379.95 ? 5e-3 : 5e-5;
    const double degTol = o.bearing == 269.64 ? 5e-3 : 5e-5;
    EXPECT_NEAR(rhumbDistance(o.from, o.to, r) / 1000.0, o.km, kmTol) << o.km;
    EXPECT_NEAR(rhumbBearing(o.from, o.to), o.bearing, degTol) << o.km;
  }
}

TEST(Rhumb, longer_than_the_great_circle_as_the_book_says) {
  // The book: about 5 % across the Atlantic, about 30 % from the US east coast to China.
  const LatLon nyc{40.7128, -74.0060};
  const double atlantic = rhumbDistance(nyc, {51.5074, -0.1278}, r) / haversineDistance(nyc, {51.5074, -0.1278}, r);
  const double china = rhumbDistance(nyc, {39.9042, 116.4074}, r) / haversineDistance(nyc, {39.9042, 116.4074}, r);
  EXPECT_NEAR(atlantic, 1.040, 0.001);
  EXPECT_NEAR(china, 1.309, 0.001);
}

TEST(Rhumb, meridians_parallels_and_the_pole_are_exact) {
  // Along a meridian: R dphi, north or south.
  EXPECT_NEAR(rhumbDistance({10.0, 5.0}, {80.0, 5.0}, r), r * 70.0 * degree, 1e-6);
  EXPECT_DOUBLE_EQ(rhumbBearing({10.0, 5.0}, {80.0, 5.0}), 0.0);
  EXPECT_DOUBLE_EQ(rhumbBearing({80.0, 5.0}, {10.0, 5.0}), 180.0);
  // Along a parallel: R cos(phi) dlambda, at every latitude (the book's fails from 45 up).
  for (const double lat : {0.0, 30.0, 45.0, 60.0, 75.0, 89.0, -89.9}) {
    EXPECT_NEAR(rhumbDistance({lat, -20.0}, {lat, 40.0}, r), r * std::cos(lat * degree) * 60.0 * degree, 1e-6) << lat;
    EXPECT_DOUBLE_EQ(rhumbBearing({lat, -20.0}, {lat, 40.0}), 90.0) << lat;
    EXPECT_DOUBLE_EQ(rhumbBearing({lat, 40.0}, {lat, -20.0}), 270.0) << lat;
  }
  // To a pole: the loxodrome circles it infinitely often, in a finite length R dphi.
  EXPECT_NEAR(rhumbDistance({45.0, 0.0}, {90.0, 123.0}, r), r * 45.0 * degree, 1e-6);
  EXPECT_DOUBLE_EQ(rhumbBearing({45.0, 0.0}, {90.0, 123.0}), 0.0);
  EXPECT_DOUBLE_EQ(rhumbBearing({-90.0, 0.0}, {10.0, 10.0}), 0.0);
  EXPECT_TRUE(std::isinf(mercatorLatitude(90.0)));
  EXPECT_NEAR(mercatorLatitude(45.0), std::log(std::tan(std::numbers::pi / 4.0 + 22.5 * degree)), 1e-15);
}

TEST(Rhumb, destination_retraces_the_line_at_all_latitudes) {
  for (const double lat1 : {-80.0, -45.0, 0.0, 44.0, 46.0, 60.0, 80.0, 89.5}) {
    for (const double dLon : {-170.0, -30.0, 0.5, 100.0}) {
      for (const double dLat : {-9.0, 0.0, 1e-9, 0.4}) {
        const LatLon from{lat1, 10.0};
        const LatLon to{std::clamp(lat1 + dLat, -90.0, 89.99), 10.0 + dLon};
        const double d = rhumbDistance(from, to, r);
        const LatLon end = rhumbDestination(from, rhumbBearing(from, to), d, r);
        EXPECT_NEAR(end.latitude, to.latitude, 1e-9) << lat1 << " " << dLon << " " << dLat;
        EXPECT_NEAR(wrapLongitude(end.longitude - to.longitude), 0.0, 1e-8) << lat1 << " " << dLon << " " << dLat;
      }
    }
  }
  // A line that would cross the pole ends there.
  EXPECT_DOUBLE_EQ(rhumbDestination({80.0, 0.0}, 10.0, 5e6, r).latitude, 90.0);
}

TEST(Rhumb, a_tiny_north_south_step_keeps_its_digits) {
  // dphi = 1e-9 degree over 10 degrees of longitude at 60 N: q must be cos(60) to ~1e-12
  // (a difference of logarithms would leave it good to ~1e-7).
  const double d = rhumbDistance({60.0, 0.0}, {60.0 + 1e-9, 10.0}, r);
  EXPECT_NEAR(d, r * 0.5 * 10.0 * degree, 1e-5);
}

/// The book's stretched-latitude difference, its missing /2 kept: tan(pi/4 + phi1).
double bookDeltaPsi(double lat1, double lat2) {
  return std::log(std::tan(std::numbers::pi / 4.0 + lat2 * degree / 2.0) /
                  std::tan(lat1 * degree + std::numbers::pi / 4.0));
}

/// The book's listing with its syntax fixed (ternary the right way round, the wrap's
/// parentheses balanced) and its formula kept, returning the distance it computes and discards.
double bookRhumbDistance(const LatLon& from, const LatLon& to) {
  const double phi1 = from.latitude * degree;
  const double phi2 = to.latitude * degree;
  const double dPhi = phi2 - phi1;
  double dLambda = (to.longitude - from.longitude) * degree;
  const double dPsi = bookDeltaPsi(from.latitude, to.latitude);
  const double q = std::abs(dPsi) > 1e-12 ? dPhi / dPsi : std::cos(phi1);
  if (std::abs(dLambda) > std::numbers::pi) {
    dLambda = dLambda > 0.0 ? -(2.0 * std::numbers::pi - dLambda) : 2.0 * std::numbers::pi + dLambda;
  }
  return r * std::sqrt(dPhi * dPhi + q * q * dLambda * dLambda);
}

TEST(Rhumb, the_books_formula_is_wrong_and_fails_above_45_degrees) {
  // New York - London: the book's formula gives about 1566 km (spec), the rhumb line is 5794 km.
  EXPECT_NEAR(bookRhumbDistance({40.7128, -74.0060}, {51.5074, -0.1278}) / 1000.0, 1566.0, 1.0);
  EXPECT_NEAR(rhumbDistance({40.7128, -74.0060}, {51.5074, -0.1278}, r) / 1000.0, 5794.1208, 1e-4);
  // From 50 N: tan(pi/4 + phi1) is negative, its logarithm NaN (a domain error); ours is finite
  // and the north-south part is exact.
  EXPECT_TRUE(std::isnan(bookDeltaPsi(50.0, 52.0)));
  EXPECT_NEAR(rhumbDistance({50.0, 0.0}, {52.0, 0.0}, r), r * 2.0 * degree, 1e-6);
  // Only at the equator is the book's term right.
  EXPECT_NEAR(bookDeltaPsi(0.0, 30.0), mercatorLatitude(30.0), 1e-15);
}

TEST(Rhumb, bad_input_is_rejected) {
  expectErrorField([] { (void)rhumbDistance({95.0, 0.0}, {0.0, 0.0}); }, "from.latitude");
  expectErrorField([] { (void)rhumbBearing({0.0, 0.0}, {0.0, NAN}); }, "to.longitude");
  expectErrorField([] { (void)rhumbDestination({0.0, 0.0}, 0.0, -5.0); }, "distance");
  expectErrorField([] { (void)mercatorLatitude(-91.0); }, "point.latitude");
}

} // namespace
} // namespace impetus::geo
