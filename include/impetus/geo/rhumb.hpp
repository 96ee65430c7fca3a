// Rhumb lines (loxodromes, ch. 22): paths of constant compass bearing, as ships steer them. On a
// Mercator chart a rhumb line is straight; on the globe it spirals toward the pole and is
// longer than the great circle (about 4 % New York-London, 31 % New York-Beijing).
//
// On a sphere of radius R (m), with the Mercator "stretched" latitude
//   psi(phi) = ln(tan(pi/4 + phi/2)),  dpsi = psi(phi2) - psi(phi1),
// the east-west stretch q = dphi/dpsi (cos phi on an east-west line, where dpsi = 0 and the
// ratio is 0/0), and dlambda taken the short way round ([-pi, pi]):
//   distance D = R sqrt(dphi^2 + q^2 dlambda^2),  bearing theta = atan2(dlambda, dpsi).
// The book's listing writes tan(pi/4 + phi1) for the first term (no /2): wrong except at the
// equator, and a domain error from 45 degrees up, where pi/4 + phi1 reaches pi/2; it also
// divides by dpsi exactly when dpsi = 0, and returns only the bearing. These are correct at
// every latitude to the poles (a rhumb line to a pole has length R |dphi|: it circles the pole
// infinitely often in a finite distance).
#pragma once

#include <impetus/core/constants.hpp>
#include <impetus/geo/coordinates.hpp>

namespace impetus::geo {

/// Mercator stretched latitude psi = ln(tan(pi/4 + phi/2)) = asinh(tan phi), rad, for a
/// latitude phi in degrees (-90..90); +-infinity at the poles.
[[nodiscard]] double mercatorLatitude(double latitude);

/// Length of the rhumb line from `from` to `to` on a sphere of `radius` (m), m.
[[nodiscard]] double rhumbDistance(const LatLon& from, const LatLon& to, double radius = constants::earthMeanRadius);

/// The constant compass bearing of the rhumb line from `from` to `to`, degrees [0, 360).
/// Coincident points give 0.
[[nodiscard]] double rhumbBearing(const LatLon& from, const LatLon& to);

/// The point reached after `distance` (m, >= 0) along the rhumb line of compass `bearing`
/// (degrees) from `from`:  phi2 = phi1 + delta cos theta, dlambda = delta sin theta / q.
/// A rhumb line that would pass a pole stops there (latitude clamped to +-90, the loxodrome's
/// end).
[[nodiscard]] LatLon rhumbDestination(const LatLon& from, double bearing, double distance,
                                      double radius = constants::earthMeanRadius);

} // namespace impetus::geo
