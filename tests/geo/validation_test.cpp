// The input validation audit of the geo layer (docs/reliability.md, "Input validation"): every
// function refuses NaN, infinity, latitudes beyond +-90 degrees, negative distances, zero radii,
// a bad ellipsoid and geometry that cannot be solved with an impetus::Error naming the field and
// showing the value. With IMPETUS_TEST_GEODESIC (impetus::geo built) the GeographicLib functions
// too.
#include "support/validation_table.hpp"

#include <impetus/geo/coordinates.hpp>
#include <impetus/geo/ellipsoid.hpp>
#include <impetus/geo/gps_clock.hpp>
#include <impetus/geo/great_circle.hpp>
#include <impetus/geo/rhumb.hpp>
#include <impetus/geo/trilateration.hpp>
#include <impetus/geo/vincenty.hpp>
#if IMPETUS_TEST_GEODESIC
#include <impetus/geo/geodesic.hpp>
#endif

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace impetus::geo {
namespace {

using impetus::testing::expectAccepted;
using impetus::testing::expectRejected;
using impetus::testing::infd;
using impetus::testing::nand;

constexpr LatLon origin{0.0, 0.0};
constexpr LatLon east{0.0, 1.0};

TEST(GeoValidation, points_and_ellipsoid) {
  expectRejected({
      {"from.latitude", "91",
       [] {
         (void)haversineDistance({91.0, 0.0}, east);
       }},
      {"from.latitude", "-90.5",
       [] {
         (void)haversineDistance({-90.5, 0.0}, east);
       }},
      {"from.latitude", "nan",
       [] {
         (void)haversineAngle({nand, 0.0}, east);
       }},
      {"to.longitude", "inf",
       [] {
         (void)initialBearing(origin, {0.0, infd});
       }},
      {"to.longitude", "-inf",
       [] {
         (void)finalBearing(origin, {0.0, -infd});
       }},
      {"point.latitude", "inf", [] { (void)mercatorLatitude(infd); }},
      {"position.latitude", "100",
       [] {
         (void)geodeticToEcef({{100.0, 0.0}, 0.0});
       }},
      {"position.height", "nan",
       [] {
         (void)geodeticToEcef({origin, nand});
       }},
      {"ellipsoid.equatorialRadius", "0",
       [] {
         (void)geodeticToEcef({origin, 0.0}, Ellipsoid{0.0, 0.0});
       }},
      {"ellipsoid.equatorialRadius", "inf",
       [] {
         (void)geodeticToEcef({origin, 0.0}, Ellipsoid{infd, 0.0});
       }},
      {"ellipsoid.flattening", "1",
       [] {
         (void)geodeticToEcef({origin, 0.0}, Ellipsoid{6e6, 1.0});
       }},
      {"ellipsoid.flattening", "-0.1",
       [] {
         (void)geodeticToEcef({origin, 0.0}, Ellipsoid{6e6, -0.1});
       }},
      {"ellipsoid.flattening", "nan",
       [] {
         (void)ecefToGeodetic({7e6, 0.0, 0.0}, Ellipsoid{6e6, nand});
       }},
      {"ecef.y", "nan",
       [] {
         (void)ecefToGeodetic({7e6, nand, 0.0});
       }},
      {"ecef.z", "-inf",
       [] {
         (void)ecefToGeodetic({7e6, 0.0, -infd});
       }},
      // Within 1 km of the centre: the geodetic latitude is not defined usefully there.
      {"ecef", "500",
       [] {
         (void)ecefToGeodetic({300.0, 400.0, 0.0});
       }},
  });
  expectAccepted({
      {"poles",
       [] {
         (void)haversineDistance({90.0, 0.0}, {-90.0, 0.0});
       }},
      {"any finite longitude",
       [] {
         (void)initialBearing({0.0, -540.0}, {0.0, 1e6});
       }},
      {"a sphere (f = 0)",
       [] {
         (void)geodeticToEcef({origin, 0.0}, Ellipsoid::sphere(6.371e6));
       }},
      {"below the surface",
       [] {
         (void)geodeticToEcef({origin, -6e6});
       }},
  });
}

TEST(GeoValidation, great_circle_and_rhumb) {
  expectRejected({
      {"radius", "0", [] { (void)haversineDistance(origin, east, 0.0); }},
      {"radius", "-6371000", [] { (void)sphericalLawOfCosinesDistance(origin, east, -6.371e6); }},
      {"radius", "inf", [] { (void)rhumbDistance(origin, east, infd); }},
      {"bearing", "nan", [] { (void)destination(origin, nand, 1.0); }},
      {"distance", "-1", [] { (void)destination(origin, 0.0, -1.0); }},
      {"distance", "inf", [] { (void)destination(origin, 0.0, infd); }},
      {"fraction", "nan", [] { (void)intermediatePoint(origin, east, nand); }},
      // Antipodes: every great circle through them is shortest, none is the path.
      {"to", "3.141592653589793",
       [] {
         (void)intermediatePoint(origin, {0.0, 180.0}, 0.5);
       }},
      {"start.latitude", "nan",
       [] {
         (void)crossTrackDistance({nand, 0.0}, east, origin);
       }},
      {"end.longitude", "inf",
       [] {
         (void)alongTrackDistance(origin, {0.0, infd}, origin);
       }},
      {"point.latitude", "-91",
       [] {
         (void)crossTrackDistance(origin, east, {-91.0, 0.0});
       }},
      {"radius", "0", [] { (void)alongTrackDistance(origin, east, origin, 0.0); }},
      {"range", "-5", [] { (void)withinRange(origin, east, -5.0); }},
      {"range", "nan", [] { (void)withinRange(origin, east, nand); }},
      {"point.latitude", "90.000001", [] { (void)mercatorLatitude(90.000001); }},
      {"from.latitude", "95",
       [] {
         (void)rhumbBearing({95.0, 0.0}, east);
       }},
      {"bearing", "inf", [] { (void)rhumbDestination(origin, infd, 1.0); }},
      {"distance", "-0.5", [] { (void)rhumbDestination(origin, 0.0, -0.5); }},
      {"radius", "nan", [] { (void)rhumbDestination(origin, 0.0, 1.0, nand); }},
  });
  expectAccepted({
      {"zero distance", [] { (void)destination(origin, 45.0, 0.0); }},
      {"zero range", [] { (void)withinRange(origin, origin, 0.0); }},
      {"fraction outside [0, 1] extends the circle", [] { (void)intermediatePoint(origin, east, 2.5); }},
      {"antipodes at an end",
       [] {
         (void)intermediatePoint(origin, {0.0, 180.0}, 1.0);
       }},
      {"rhumb line to a pole",
       [] {
         (void)rhumbDistance(origin, {90.0, 0.0});
       }},
  });
}

TEST(GeoValidation, trilateration_and_pseudoranges) {
  const std::array<Vec2d, 3> plane{Vec2d{0.0, 0.0}, Vec2d{10.0, 0.0}, Vec2d{0.0, 10.0}};
  const std::array<Vec3d, 3> space{Vec3d{0.0, 0.0, 0.0}, Vec3d{10.0, 0.0, 0.0}, Vec3d{4.0, 8.0, 0.0}};
  const std::vector<Vec3d> four{{2e7, 0.0, 0.0}, {0.0, 2e7, 0.0}, {0.0, 0.0, 2e7}, {-2e7, 0.0, 0.0}};
  const std::vector<double> rho{2e7, 2e7, 2e7, 2e7};
  const auto withOption = [&](auto change) {
    return [&four, &rho, change] {
      PseudorangeOptions o;
      change(o);
      (void)solvePseudoranges(four, rho, o);
    };
  };
  expectRejected({
      {"centres.x", "nan",
       [] {
         (void)trilaterate({Vec2d{nand, 0.0}, Vec2d{1.0, 0.0}, Vec2d{0.0, 1.0}}, {1.0, 1.0, 1.0});
       }},
      {"centres.z", "inf",
       [] {
         (void)trilaterate({Vec3d{0.0, 0.0, 0.0}, Vec3d{1.0, 0.0, infd}, Vec3d{0.0, 1.0, 0.0}}, {1.0, 1.0, 1.0});
       }},
      {"ranges", "-1",
       [&] {
         (void)trilaterate(plane, {1.0, -1.0, 2.0});
       }},
      {"ranges", "nan",
       [&] {
         (void)trilaterate(space, {nand, 1.0, 1.0});
       }},
      {"ranges", "inf",
       [&] {
         (void)trilaterate(plane, {1.0, 1.0, infd});
       }},
      // Unsolvable geometry: centres 1 and 2 coincide, all three collinear, spheres apart.
      {"centres", "0",
       [] {
         (void)trilaterate({Vec2d{1.0, 1.0}, Vec2d{1.0, 1.0}, Vec2d{0.0, 1.0}}, {1.0, 1.0, 1.0});
       }},
      {"centres", "0",
       [] {
         (void)trilaterate({Vec2d{0.0, 0.0}, Vec2d{1.0, 1.0}, Vec2d{2.0, 2.0}}, {1.0, 1.0, 2.0});
       }},
      {"centres", "0",
       [] {
         (void)trilaterate({Vec3d{0.0, 0.0, 0.0}, Vec3d{10.0, 0.0, 0.0}, Vec3d{20.0, 0.0, 0.0}}, {5.0, 5.0, 15.0});
       }},
      // Unit spheres 10 m apart: x = 5, y = 2.5, r1^2 - x^2 - y^2 = 1 - 25 - 6.25 m^2.
      {"ranges", "-30.25",
       [&] {
         (void)trilaterate(space, {1.0, 1.0, 1.0});
       }},
      {"receiver.y", "nan",
       [] {
         (void)pseudorange({0.0, nand, 0.0}, {2e7, 0.0, 0.0}, 0.0);
       }},
      {"satellite.x", "inf",
       [] {
         (void)pseudorange({}, {infd, 0.0, 0.0}, 0.0);
       }},
      {"satellite", "inf",
       [] {
         (void)pseudorange({-1e308, 0.0, 0.0}, {1e308, 0.0, 0.0}, 0.0);
       }},
      {"clockBias", "nan",
       [] {
         (void)pseudorange({}, {2e7, 0.0, 0.0}, nand);
       }},
      {"speedOfLight", "0",
       [] {
         (void)pseudorange({}, {2e7, 0.0, 0.0}, 0.0, 0.0);
       }},
      {"satellites", "3", [&] { (void)solvePseudoranges(std::span(four).first(3), std::span(rho).first(3)); }},
      {"satellites", "2",
       [] {
         (void)solvePseudoranges(std::vector<Vec2d>{{1e3, 0.0}, {0.0, 1e3}}, std::vector<double>{1e3, 1e3});
       }},
      {"pseudoranges", "3", [&] { (void)solvePseudoranges(four, std::span(rho).first(3)); }},
      {"pseudoranges", "nan",
       [&] {
         (void)solvePseudoranges(four, std::vector<double>{2e7, nand, 2e7, 2e7});
       }},
      {"satellites.x", "inf",
       [&] {
         std::vector<Vec3d> bad = four;
         bad[2].x = infd;
         (void)solvePseudoranges(bad, rho);
       }},
      {"maxIterations", "0", withOption([](PseudorangeOptions& o) { o.maxIterations = 0; })},
      {"tolerance", "-1e-09", withOption([](PseudorangeOptions& o) { o.tolerance = -1e-9; })},
      {"speedOfLight", "inf", withOption([](PseudorangeOptions& o) { o.speedOfLight = infd; })},
      {"initialPosition.z", "nan", withOption([](PseudorangeOptions& o) { o.initialPosition.z = nand; })},
      {"initialRangeBias", "inf", withOption([](PseudorangeOptions& o) { o.initialRangeBias = infd; })},
  });
  expectAccepted({
      {"zero ranges",
       [&] {
         (void)trilaterate(plane, {0.0, 10.0, 10.0});
       }},
      {"tangent spheres",
       [] {
         (void)trilaterate({Vec3d{0.0, 0.0, 0.0}, Vec3d{2.0, 0.0, 0.0}, Vec3d{1.0, 5.0, 0.0}}, {1.0, 1.0, 5.0});
       }},
  });
}

TEST(GeoValidation, gps_clock_and_vincenty) {
  const auto vincentyOption = [](auto change) {
    return [change] {
      VincentyOptions o;
      change(o);
      (void)vincentyInverse(origin, east, Ellipsoid::wgs84(), o);
    };
  };
  expectRejected({
      {"transmitTime", "nan", [] { (void)rangeFromTimeOfFlight(nand, 1.0); }},
      {"receiveTime", "inf", [] { (void)rangeFromTimeOfFlight(0.0, infd); }},
      {"receiveTime", "0.5", [] { (void)rangeFromTimeOfFlight(1.0, 0.5); }},
      {"speedOfLight", "-299792458", [] { (void)rangeFromTimeOfFlight(0.0, 1.0, -299792458.0); }},
      {"clockError", "inf", [] { (void)rangeErrorFromClockError(infd); }},
      {"speedOfLight", "0", [] { (void)rangeErrorFromClockError(1e-6, 0.0); }},
      {"rangeError", "nan", [] { (void)clockErrorFromRangeError(nand); }},
      {"rate", "nan", [] { (void)accumulatedRangeError(nand, 1.0); }},
      {"duration", "-1", [] { (void)accumulatedRangeError(4.46e-10, -1.0); }},
      {"from.latitude", "-91",
       [] {
         (void)vincentyInverse({-91.0, 0.0}, east);
       }},
      {"ellipsoid.flattening", "1",
       [] {
         (void)vincentyInverse(origin, east, Ellipsoid{6e6, 1.0});
       }},
      {"maxIterations", "0", vincentyOption([](VincentyOptions& o) { o.maxIterations = 0; })},
      {"tolerance", "0", vincentyOption([](VincentyOptions& o) { o.tolerance = 0.0; })},
      {"tolerance", "nan", vincentyOption([](VincentyOptions& o) { o.tolerance = nand; })},
  });
  expectAccepted({
      {"simultaneous transmit and receive", [] { (void)rangeFromTimeOfFlight(1.0, 1.0); }},
      {"negative clock error", [] { (void)rangeErrorFromClockError(-1e-6); }},
      {"zero duration", [] { (void)accumulatedRangeError(4.46e-10, 0.0); }},
      {"coincident points", [] { (void)vincentyInverse(east, east); }},
  });
}

#if IMPETUS_TEST_GEODESIC
TEST(GeoValidation, geodesic_reference) {
  expectRejected({
      {"to.latitude", "90.1",
       [] {
         (void)geodesicInverse(origin, {90.1, 0.0});
       }},
      {"from.longitude", "nan",
       [] {
         (void)geodesicInverse({0.0, nand}, east);
       }},
      {"ellipsoid.equatorialRadius", "-1",
       [] {
         (void)geodesicInverse(origin, east, Ellipsoid{-1.0, 0.0});
       }},
      {"azimuth", "inf", [] { (void)geodesicDestination(origin, infd, 1.0); }},
      {"distance", "-1", [] { (void)geodesicDestination(origin, 0.0, -1.0); }},
      {"from.latitude", "nan",
       [] {
         (void)rhumbInverse({nand, 0.0}, east);
       }},
      {"ellipsoid.flattening", "1.5",
       [] {
         (void)rhumbInverse(origin, east, Ellipsoid{6e6, 1.5});
       }},
      {"position.height", "inf",
       [] {
         (void)referenceGeodeticToEcef({origin, infd});
       }},
      {"ecef.x", "nan",
       [] {
         (void)referenceEcefToGeodetic({nand, 0.0, 0.0});
       }},
  });
  expectAccepted({
      {"antipodes",
       [] {
         (void)geodesicInverse(origin, {0.0, 180.0});
       }},
      {"zero distance", [] { (void)geodesicDestination(origin, 90.0, 0.0); }},
  });
}
#endif

} // namespace
} // namespace impetus::geo
