// impetus::geo: thin wrappers over GeographicLib that check their input the way the geo layer
// does and convert azimuths to compass values.
#include <impetus/error.hpp>
#include <impetus/geo/geodesic.hpp>
#include <impetus/math/validate.hpp>

#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/Rhumb.hpp>

#include <cmath>

namespace impetus::geo {

GeodesicResult geodesicInverse(const LatLon& from, const LatLon& to, const Ellipsoid& ellipsoid) {
  requireValid(from, "from");
  requireValid(to, "to");
  requireValid(ellipsoid);
  const GeographicLib::Geodesic geodesic(ellipsoid.equatorialRadius, ellipsoid.flattening);
  GeodesicResult r;
  double azi1 = 0.0;
  double azi2 = 0.0;
  geodesic.Inverse(from.latitude, from.longitude, to.latitude, to.longitude, r.distance, azi1, azi2);
  r.initialAzimuth = wrapBearing(azi1);
  r.finalAzimuth = wrapBearing(azi2);
  return r;
}

LatLon geodesicDestination(const LatLon& from, double azimuth, double distance, const Ellipsoid& ellipsoid) {
  requireValid(from, "from");
  requireFinite(azimuth, "azimuth");
  requireNonNegative(distance, "distance");
  requireValid(ellipsoid);
  const GeographicLib::Geodesic geodesic(ellipsoid.equatorialRadius, ellipsoid.flattening);
  LatLon to;
  geodesic.Direct(from.latitude, from.longitude, azimuth, distance, to.latitude, to.longitude);
  to.longitude = wrapLongitude(to.longitude);
  return to;
}

RhumbResult rhumbInverse(const LatLon& from, const LatLon& to, const Ellipsoid& ellipsoid) {
  requireValid(from, "from");
  requireValid(to, "to");
  requireValid(ellipsoid);
  const GeographicLib::Rhumb rhumb(ellipsoid.equatorialRadius, ellipsoid.flattening, true);
  RhumbResult r;
  double azimuth = 0.0;
  rhumb.Inverse(from.latitude, from.longitude, to.latitude, to.longitude, r.distance, azimuth);
  r.bearing = wrapBearing(azimuth);
  return r;
}

Vec3d referenceGeodeticToEcef(const GeodeticPosition& position, const Ellipsoid& ellipsoid) {
  requireValid(position.point, "position");
  requireFinite(position.height, "position.height");
  requireValid(ellipsoid);
  const GeographicLib::Geocentric geocentric(ellipsoid.equatorialRadius, ellipsoid.flattening);
  Vec3d p;
  geocentric.Forward(position.point.latitude, position.point.longitude, position.height, p.x, p.y, p.z);
  return p;
}

GeodeticPosition referenceEcefToGeodetic(const Vec3d& ecef, const Ellipsoid& ellipsoid) {
  requireFinite(ecef, "ecef");
  requireValid(ellipsoid);
  const GeographicLib::Geocentric geocentric(ellipsoid.equatorialRadius, ellipsoid.flattening);
  GeodeticPosition g;
  geocentric.Reverse(ecef.x, ecef.y, ecef.z, g.point.latitude, g.point.longitude, g.height);
  return g;
}

} // namespace impetus::geo
