// The Earth as an ellipsoid of revolution (ch. 22): WGS 84, the reference surface of GPS, and
// the conversions between geodetic coordinates (latitude, longitude, height above the
// ellipsoid) and Earth-centred, Earth-fixed (ECEF) Cartesian coordinates, the frame the GPS
// satellites' positions are given in and trilateration (geo/trilateration.hpp) solves in.
//
// ECEF: origin at the Earth's centre of mass, +z through the north pole, +x through latitude 0,
// longitude 0, +y through latitude 0, longitude 90 E; metres.
#pragma once

#include <impetus/geo/coordinates.hpp>
#include <impetus/math/vec3.hpp>

namespace impetus::geo {

/// An ellipsoid of revolution: equatorial radius a (m, > 0) and flattening f = (a - b)/a
/// (0 <= f < 1: a sphere has f = 0).
struct Ellipsoid {
  double equatorialRadius = 6'378'137.0;     ///< a, m (WGS 84)
  double flattening = 1.0 / 298.257'223'563; ///< f (WGS 84)

  /// WGS 84 (the GPS datum).
  [[nodiscard]] static constexpr Ellipsoid wgs84() noexcept { return {}; }
  /// A sphere of the given radius (m): f = 0.
  [[nodiscard]] static constexpr Ellipsoid sphere(double radius) noexcept { return {radius, 0.0}; }

  /// b = a (1 - f), m.
  [[nodiscard]] constexpr double polarRadius() const noexcept { return equatorialRadius * (1.0 - flattening); }
  /// First eccentricity squared e^2 = f (2 - f).
  [[nodiscard]] constexpr double eccentricitySquared() const noexcept { return flattening * (2.0 - flattening); }
};

/// Throws impetus::Error naming "ellipsoid.equatorialRadius" or "ellipsoid.flattening" unless
/// a > 0 and 0 <= f < 1 (finite).
void requireValid(const Ellipsoid& ellipsoid);

/// A point given by geodetic latitude/longitude (degrees) and height above the ellipsoid (m).
struct GeodeticPosition {
  LatLon point;
  double height = 0.0; ///< m above the ellipsoid
};

/// ECEF position of a geodetic point, m:
///   N = a / sqrt(1 - e^2 sin^2 phi) (prime-vertical radius of curvature),
///   x = (N + h) cos phi cos lambda,  y = (N + h) cos phi sin lambda,  z = (N (1 - e^2) + h) sin phi.
[[nodiscard]] Vec3d geodeticToEcef(const GeodeticPosition& position, const Ellipsoid& ellipsoid = Ellipsoid::wgs84());

/// The geodetic position of an ECEF point (m): longitude atan2(y, x); latitude by Bowring's
/// parametric-latitude iteration to convergence (sub-micrometre from the surface out past the
/// GPS orbits). Throws impetus::Error naming "ecef" for a non-finite point or one within 1 km
/// of the Earth's centre, where the geodetic latitude is not defined usefully.
[[nodiscard]] GeodeticPosition ecefToGeodetic(const Vec3d& ecef, const Ellipsoid& ellipsoid = Ellipsoid::wgs84());

} // namespace impetus::geo
