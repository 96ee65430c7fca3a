#include <impetus/error.hpp>
#include <impetus/geo/great_circle.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace impetus::geo {
namespace {

constexpr double rad(double degrees) { return degToRad(degrees); }
constexpr double deg(double radians) { return radToDeg(radians); }

/// Unit vector of a point on the sphere (x toward 0N 0E, z toward the north pole).
Vec3d unitVector(const LatLon& p) {
  const double phi = rad(p.latitude);
  const double lambda = rad(p.longitude);
  return {std::cos(phi) * std::cos(lambda), std::cos(phi) * std::sin(lambda), std::sin(phi)};
}

LatLon fromUnitVector(const Vec3d& v) {
  return {deg(std::atan2(v.z, std::hypot(v.x, v.y))), wrapLongitude(deg(std::atan2(v.y, v.x)))};
}

/// Initial bearing in radians (-pi, pi], points already checked.
double bearingRadians(const LatLon& from, const LatLon& to) {
  const double phi1 = rad(from.latitude);
  const double phi2 = rad(to.latitude);
  const double dLambda = rad(to.longitude - from.longitude);
  const double y = std::sin(dLambda) * std::cos(phi2);
  const double x = std::cos(phi1) * std::sin(phi2) - std::sin(phi1) * std::cos(phi2) * std::cos(dLambda);
  return std::atan2(y, x);
}

/// The haversine central angle, points already checked.
double centralAngle(const LatLon& from, const LatLon& to) {
  const double phi1 = rad(from.latitude);
  const double phi2 = rad(to.latitude);
  const double sinHalfDPhi = std::sin(0.5 * (phi2 - phi1));
  const double sinHalfDLambda = std::sin(0.5 * rad(to.longitude - from.longitude));
  const double a = std::clamp(
      sinHalfDPhi * sinHalfDPhi + std::cos(phi1) * std::cos(phi2) * sinHalfDLambda * sinHalfDLambda, 0.0, 1.0);
  return 2.0 * std::atan2(std::sqrt(a), std::sqrt(1.0 - a));
}

void checkPair(const LatLon& from, const LatLon& to) {
  requireValid(from, "from");
  requireValid(to, "to");
}

} // namespace

double haversineAngle(const LatLon& from, const LatLon& to) {
  checkPair(from, to);
  return centralAngle(from, to);
}

double haversineDistance(const LatLon& from, const LatLon& to, double radius) {
  requirePositive(radius, "radius");
  return radius * haversineAngle(from, to);
}

double sphericalLawOfCosinesDistance(const LatLon& from, const LatLon& to, double radius) {
  checkPair(from, to);
  requirePositive(radius, "radius");
  const double phi1 = rad(from.latitude);
  const double phi2 = rad(to.latitude);
  const double c =
      std::sin(phi1) * std::sin(phi2) + std::cos(phi1) * std::cos(phi2) * std::cos(rad(to.longitude - from.longitude));
  return radius * std::acos(std::clamp(c, -1.0, 1.0));
}

double initialBearing(const LatLon& from, const LatLon& to) {
  checkPair(from, to);
  return wrapBearing(deg(bearingRadians(from, to)));
}

double finalBearing(const LatLon& from, const LatLon& to) {
  checkPair(from, to);
  return wrapBearing(deg(bearingRadians(to, from)) + 180.0);
}

LatLon destination(const LatLon& from, double bearing, double distance, double radius) {
  requireValid(from, "from");
  requireFinite(bearing, "bearing");
  requireNonNegative(distance, "distance");
  requirePositive(radius, "radius");
  const double phi1 = rad(from.latitude);
  const double theta = rad(bearing);
  const double delta = distance / radius;
  const double sinPhi2 =
      std::clamp(std::sin(phi1) * std::cos(delta) + std::cos(phi1) * std::sin(delta) * std::cos(theta), -1.0, 1.0);
  const double phi2 = std::asin(sinPhi2);
  const double lambda2 = rad(from.longitude) + std::atan2(std::sin(theta) * std::sin(delta) * std::cos(phi1),
                                                          std::cos(delta) - std::sin(phi1) * sinPhi2);
  return {deg(phi2), wrapLongitude(deg(lambda2))};
}

LatLon intermediatePoint(const LatLon& from, const LatLon& to, double fraction) {
  checkPair(from, to);
  requireFinite(fraction, "fraction");
  const Vec3d a = unitVector(from);
  const Vec3d b = unitVector(to);
  const double delta = centralAngle(from, to);
  const double sinDelta = std::sin(delta);
  if (sinDelta < 1e-12) {
    if (delta < 1.0) { // coincident: any fraction stays there
      return {from.latitude, wrapLongitude(from.longitude)};
    }
    if (fraction == 0.0 || fraction == 1.0) {
      return fraction == 0.0 ? LatLon{from.latitude, wrapLongitude(from.longitude)}
                             : LatLon{to.latitude, wrapLongitude(to.longitude)};
    }
    throwInvalid("to", delta, "is antipodal to from (central angle pi): no unique great circle between them");
  }
  // Slerp: sin((1 - t) delta)/sin delta a + sin(t delta)/sin delta b.
  const double wa = std::sin((1.0 - fraction) * delta) / sinDelta;
  const double wb = std::sin(fraction * delta) / sinDelta;
  return fromUnitVector(a * wa + b * wb);
}

double crossTrackDistance(const LatLon& start, const LatLon& end, const LatLon& point, double radius) {
  requireValid(start, "start");
  requireValid(end, "end");
  requireValid(point, "point");
  requirePositive(radius, "radius");
  const double delta13 = centralAngle(start, point);
  const double theta13 = bearingRadians(start, point);
  const double theta12 = bearingRadians(start, end);
  return radius * std::asin(std::clamp(std::sin(delta13) * std::sin(theta13 - theta12), -1.0, 1.0));
}

double alongTrackDistance(const LatLon& start, const LatLon& end, const LatLon& point, double radius) {
  requireValid(start, "start");
  requireValid(end, "end");
  requireValid(point, "point");
  requirePositive(radius, "radius");
  const double delta13 = centralAngle(start, point);
  const double theta13 = bearingRadians(start, point);
  const double theta12 = bearingRadians(start, end);
  // Napier's rule on the right spherical triangle: tan(along) = tan(delta13) cos(theta13 - theta12).
  return radius * std::atan2(std::sin(delta13) * std::cos(theta13 - theta12), std::cos(delta13));
}

bool withinRange(const LatLon& position, const LatLon& target, double range, double radius) {
  requireNonNegative(range, "range");
  return haversineDistance(position, target, radius) <= range;
}

} // namespace impetus::geo
