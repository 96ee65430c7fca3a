// Geodetic <-> ECEF on WGS 84: the axes (x = a on the equator at 0 E, z = b at the pole), round
// trips from the surface to GPS orbits, and bad input. GeographicLib's Geocentric is the
// reference in geodesic_reference_test.cpp.
#include <impetus/geo/ellipsoid.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

namespace impetus::geo {
namespace {

TEST(Ellipsoid, axes_are_where_the_definition_puts_them) {
  const Ellipsoid e = Ellipsoid::wgs84();
  EXPECT_NEAR(e.polarRadius(), 6356752.314245, 1e-6); // WGS 84's b
  const Vec3d equator = geodeticToEcef({{0.0, 0.0}, 0.0});
  EXPECT_NEAR(equator.x, 6378137.0, 1e-9);
  EXPECT_NEAR(equator.y, 0.0, 1e-9);
  const Vec3d east = geodeticToEcef({{0.0, 90.0}, 100.0});
  EXPECT_NEAR(east.y, 6378237.0, 1e-9);
  const Vec3d pole = geodeticToEcef({{90.0, 0.0}, 0.0});
  EXPECT_NEAR(pole.z, e.polarRadius(), 1e-9);
  EXPECT_NEAR(pole.x, 0.0, 1e-9);
}

TEST(Ellipsoid, round_trip_from_the_ground_to_the_gps_orbits) {
  for (const double lat : {-90.0, -60.0, -1e-7, 0.0, 33.3, 45.0, 89.999, 90.0}) {
    for (const double lon : {-179.0, 0.0, 77.7}) {
      for (const double h : {-400.0, 0.0, 8848.0, 2.0e7}) {
        const GeodeticPosition back = ecefToGeodetic(geodeticToEcef({{lat, lon}, h}));
        EXPECT_NEAR(back.point.latitude, lat, 1e-11) << lat << " " << lon << " " << h;
        if (std::abs(lat) < 90.0) {
          EXPECT_NEAR(back.point.longitude, lon, 1e-11) << lat << " " << lon << " " << h;
        }
        EXPECT_NEAR(back.height, h, 1e-6) << lat << " " << lon << " " << h;
      }
    }
  }
}

TEST(Ellipsoid, bad_input_is_rejected) {
  expectErrorField([] { (void)geodeticToEcef({{100.0, 0.0}, 0.0}); }, "position.latitude");
  expectErrorField([] { (void)geodeticToEcef({{0.0, 0.0}, NAN}); }, "position.height");
  expectErrorField([] { (void)ecefToGeodetic({1.0, 2.0, 3.0}); }, "ecef");
  expectErrorField([] { (void)ecefToGeodetic({NAN, 2.0, 3.0}); }, "ecef.x"); // the component at fault
  expectErrorField([] { (void)ecefToGeodetic({7e6, 0.0, 0.0}, Ellipsoid{6e6, -0.1}); }, "ellipsoid.flattening");
}

} // namespace
} // namespace impetus::geo
