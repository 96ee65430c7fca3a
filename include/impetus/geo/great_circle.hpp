// Navigation on a sphere (ch. 22): the great circle, the shortest path between two points on
// the surface, as aircraft fly it. Every function works in double on a sphere of radius R
// (m, default the mean Earth radius R1 = 6371.0088 km; the book uses 6371 km,
// geo::bookEarthRadius). The sphere is within 0.5 % of the WGS 84 ellipsoid's geodesic
// distance (geo/vincenty.hpp, geo/geodesic.hpp) on any route.
//
// Angles: points in degrees (geo/coordinates.hpp); bearings are compass values in degrees,
// clockwise from north, in [0, 360). Distances in m.
#pragma once

#include <impetus/core/constants.hpp>
#include <impetus/geo/coordinates.hpp>

namespace impetus::geo {

/// The central angle between two points by the haversine formula, rad:
///   a = sin^2(dphi/2) + cos phi1 cos phi2 sin^2(dlambda/2),  C = 2 atan2(sqrt a, sqrt(1 - a)).
/// Well conditioned for short distances (a ~ (d/2R)^2 keeps its digits), exact to rounding up
/// to the antipode (a = 1 gives pi).
[[nodiscard]] double haversineAngle(const LatLon& from, const LatLon& to);

/// Great-circle distance R C by the haversine formula, m. radius > 0 (m).
[[nodiscard]] double haversineDistance(const LatLon& from, const LatLon& to,
                                       double radius = constants::earthMeanRadius);

/// Great-circle distance by the spherical law of cosines, R acos(sin phi1 sin phi2 + cos phi1
/// cos phi2 cos dlambda), m (argument clamped to [-1, 1]). The same distance as the haversine
/// in exact arithmetic, but acos is ill conditioned near 0: in double it loses about half its
/// digits for short distances (a 1 m step is good to ~1e-2 m), in float it is useless below a
/// few km (the book's advice: use the haversine for short distances).
[[nodiscard]] double sphericalLawOfCosinesDistance(const LatLon& from, const LatLon& to,
                                                   double radius = constants::earthMeanRadius);

/// Initial great-circle bearing (forward azimuth) from `from` toward `to`, degrees [0, 360):
///   theta = atan2(sin dlambda cos phi2, cos phi1 sin phi2 - sin phi1 cos phi2 cos dlambda).
/// The heading changes along the route (except along the equator or a meridian). For
/// coincident or antipodal points every direction is a great circle; the formula gives 0 or
/// the atan2 of rounding residues, and callers should not rely on it there.
[[nodiscard]] double initialBearing(const LatLon& from, const LatLon& to);

/// Final bearing on arrival at `to`, degrees [0, 360): the initial bearing from `to` back to
/// `from`, reversed, (b + 180) mod 360. (The book's listing takes % of a float and maps 0 to
/// 360.)
[[nodiscard]] double finalBearing(const LatLon& from, const LatLon& to);

/// The point reached travelling `distance` (m, >= 0) from `from` along the great circle that
/// leaves it at compass `bearing` (degrees):
///   phi2 = asin(sin phi1 cos delta + cos phi1 sin delta cos theta),
///   lambda2 = lambda1 + atan2(sin theta sin delta cos phi1, cos delta - sin phi1 sin phi2),
/// delta = distance/R. Longitude wrapped to [-180, 180).
[[nodiscard]] LatLon destination(const LatLon& from, double bearing, double distance,
                                 double radius = constants::earthMeanRadius);

/// The point a `fraction` of the way along the great circle from `from` to `to` (0 = from,
/// 1 = to; any finite value extends the circle), by spherical linear interpolation of the unit
/// vectors. Throws impetus::Error naming "to" when the points are antipodal (no unique great
/// circle) and the fraction is strictly between them.
[[nodiscard]] LatLon intermediatePoint(const LatLon& from, const LatLon& to, double fraction);

/// Signed distance of `point` from the great circle through `start` and `end` (m), positive to
/// the right of the direction of travel: d_xt = asin(sin delta13 sin(theta13 - theta12)) R,
/// with delta13 the angular distance start-point and theta the initial bearings.
[[nodiscard]] double crossTrackDistance(const LatLon& start, const LatLon& end, const LatLon& point,
                                        double radius = constants::earthMeanRadius);

/// Distance from `start` along the great circle toward `end` to the foot of the perpendicular
/// from `point`, m (negative when the foot is behind the start):
///   d_at = atan2(sin delta13 cos(theta13 - theta12), cos delta13) R (stable form of
///   acos(cos delta13 / cos delta_xt)).
[[nodiscard]] double alongTrackDistance(const LatLon& start, const LatLon& end, const LatLon& point,
                                        double radius = constants::earthMeanRadius);

/// Reverse geocaching: whether `position` lies within `range` (m, >= 0) of `target`, by the
/// haversine distance on the sphere.
[[nodiscard]] bool withinRange(const LatLon& position, const LatLon& target, double range,
                               double radius = constants::earthMeanRadius);

} // namespace impetus::geo
