// Vincenty's inverse formula (ch. 22, named in the book as the accurate, more complex method):
// the geodesic distance and azimuths between two points on an ellipsoid (T. Vincenty, "Direct
// and inverse solutions of geodesics on the ellipsoid with application of nested equations",
// Survey Review 23 (176), 1975).
//
// It iterates on the longitude difference lambda on the auxiliary sphere (reduced latitudes
// tan U = (1 - f) tan phi) until it changes by less than 1e-12 rad (~6e-6 m), then evaluates
// the series for the distance s = b A (sigma - dsigma). It agrees with Karney's geodesic
// (GeographicLib, geo/geodesic.hpp) to ~0.1 mm where it converges. For nearly antipodal points
// the iteration oscillates or lambda runs past pi and it does not converge: the result then
// says so (std::nullopt) and the caller falls back to the geodesic (or a spherical estimate).
#pragma once

#include <impetus/geo/coordinates.hpp>
#include <impetus/geo/ellipsoid.hpp>

#include <optional>

namespace impetus::geo {

struct VincentyResult {
  double distance = 0.0;       ///< s, m, along the ellipsoid
  double initialAzimuth = 0.0; ///< alpha1, compass degrees [0, 360) (0 for coincident points)
  double finalAzimuth = 0.0;   ///< alpha2 on arrival, compass degrees [0, 360)
  int iterations = 0;          ///< iterations the lambda loop took
};

struct VincentyOptions {
  int maxIterations = 200;  ///< > 0
  double tolerance = 1e-12; ///< on lambda, rad, > 0
};

/// Vincenty's inverse solution, or std::nullopt when the iteration does not converge (nearly
/// antipodal points). Throws impetus::Error for invalid points, ellipsoid or options.
[[nodiscard]] std::optional<VincentyResult> vincentyInverse(const LatLon& from, const LatLon& to,
                                                            const Ellipsoid& ellipsoid = Ellipsoid::wgs84(),
                                                            const VincentyOptions& options = {});

} // namespace impetus::geo
