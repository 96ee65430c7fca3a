// The reference geodesic (ch. 22), in the optional impetus::geo target: C. F. F. Karney's
// algorithms as GeographicLib implements them ("Algorithms for geodesics", J. Geodesy 87, 2013),
// accurate to about 15 nm on WGS 84 for any pair of points, antipodes included, where Vincenty
// (geo/vincenty.hpp) stops converging. The library's own formulas are tested against these.
//
// Link impetus::geo (built when Debian's libgeographiclib-dev is found). Points in degrees,
// azimuths as compass degrees [0, 360), distances in m; the same checks as the rest of the geo
// layer (impetus::Error naming "from.latitude" and so on).
#pragma once

#include <impetus/geo/coordinates.hpp>
#include <impetus/geo/ellipsoid.hpp>
#include <impetus/math/vec3.hpp>

namespace impetus::geo {

struct GeodesicResult {
  double distance = 0.0;       ///< s12, m along the ellipsoid
  double initialAzimuth = 0.0; ///< azi1, compass degrees [0, 360)
  double finalAzimuth = 0.0;   ///< azi2 (forward azimuth on arrival), compass degrees [0, 360)
};

/// The shortest geodesic between two points (GeographicLib::Geodesic::Inverse).
[[nodiscard]] GeodesicResult geodesicInverse(const LatLon& from, const LatLon& to,
                                             const Ellipsoid& ellipsoid = Ellipsoid::wgs84());

/// The point `distance` (m, >= 0) along the geodesic leaving `from` at compass `azimuth`
/// (degrees) (GeographicLib::Geodesic::Direct); longitude in [-180, 180).
[[nodiscard]] LatLon geodesicDestination(const LatLon& from, double azimuth, double distance,
                                         const Ellipsoid& ellipsoid = Ellipsoid::wgs84());

struct RhumbResult {
  double distance = 0.0; ///< m along the rhumb line
  double bearing = 0.0;  ///< constant compass bearing, degrees [0, 360)
};

/// The rhumb line on the ellipsoid (GeographicLib::Rhumb, exact): the reference for
/// geo/rhumb.hpp's spherical formulas (pass Ellipsoid::sphere(R) to compare on a sphere).
[[nodiscard]] RhumbResult rhumbInverse(const LatLon& from, const LatLon& to,
                                       const Ellipsoid& ellipsoid = Ellipsoid::wgs84());

/// ECEF position of a geodetic point by GeographicLib::Geocentric, m: the reference for
/// geodeticToEcef.
[[nodiscard]] Vec3d referenceGeodeticToEcef(const GeodeticPosition& position,
                                            const Ellipsoid& ellipsoid = Ellipsoid::wgs84());

/// Geodetic position of an ECEF point by GeographicLib::Geocentric (Vermeille's closed form):
/// the reference for ecefToGeodetic.
[[nodiscard]] GeodeticPosition referenceEcefToGeodetic(const Vec3d& ecef,
                                                       const Ellipsoid& ellipsoid = Ellipsoid::wgs84());

} // namespace impetus::geo
