#include <impetus/error.hpp>
#include <impetus/geo/rhumb.hpp>
#include <impetus/math/scalar.hpp>

#include <cmath>
#include <limits>

namespace impetus::geo {
namespace {

constexpr double halfPi = pi<double> / 2.0;

bool atPole(double latitude) { return std::abs(latitude) == 90.0; }

/// psi = asinh(tan phi): the same as ln(tan(pi/4 + phi/2)) and atanh(sin phi), but it keeps its
/// digits near the poles, where 1 - sin phi cancels.
double stretched(double phi) { return std::asinh(std::tan(phi)); }

/// dpsi = psi(phi2) - psi(phi1). For short north-south steps the difference of two psi loses
/// the step's digits; there it uses
///   atanh(a) - atanh(b) = atanh((a - b)/(1 - a b)),  a = sin phi2, b = sin phi1,
///   a - b = 2 cos((phi1 + phi2)/2) sin((phi2 - phi1)/2),
///   1 - a b = 2 sin^2((phi2 - phi1)/2) + cos phi1 cos phi2,
/// which is exact to rounding while its argument stays well below 1 (|dpsi| < 0.55). Larger
/// steps take the plain difference (the atanh of an argument near 1 would cancel instead).
/// Not for a pole (infinite).
double stretchedDifference(double phi1, double phi2) {
  const double half = 0.5 * (phi2 - phi1);
  const double sinHalf = std::sin(half);
  const double numerator = 2.0 * std::cos(0.5 * (phi1 + phi2)) * sinHalf;
  const double denominator = 2.0 * sinHalf * sinHalf + std::cos(phi1) * std::cos(phi2);
  const double x = numerator / denominator;
  if (std::abs(x) <= 0.5) {
    return std::atanh(x);
  }
  return stretched(phi2) - stretched(phi1);
}

/// q = dphi/dpsi: the cosine of latitude averaged along the line (cos phi on an east-west
/// line); 0 when an end is a pole.
double stretchRatio(double phi1, double phi2, bool pole) {
  if (pole) {
    return 0.0;
  }
  const double dPhi = phi2 - phi1;
  if (dPhi == 0.0) {
    return std::cos(phi1);
  }
  return dPhi / stretchedDifference(phi1, phi2);
}

/// dlambda the short way round, rad in (-pi, pi] (exactly half way round counts as east).
double shortLongitudeDifference(const LatLon& from, const LatLon& to) {
  const double d = wrapLongitude(to.longitude - from.longitude);
  return degToRad(d == -180.0 ? 180.0 : d);
}

} // namespace

double mercatorLatitude(double latitude) {
  requireValid(LatLon{latitude, 0.0}, "point");
  if (atPole(latitude)) {
    return std::copysign(std::numeric_limits<double>::infinity(), latitude);
  }
  return stretched(degToRad(latitude));
}

double rhumbDistance(const LatLon& from, const LatLon& to, double radius) {
  requireValid(from, "from");
  requireValid(to, "to");
  requirePositive(radius, "radius");
  const double phi1 = degToRad(from.latitude);
  const double phi2 = degToRad(to.latitude);
  const double q = stretchRatio(phi1, phi2, atPole(from.latitude) || atPole(to.latitude));
  const double dLambda = shortLongitudeDifference(from, to);
  return radius * std::hypot(phi2 - phi1, q * dLambda);
}

double rhumbBearing(const LatLon& from, const LatLon& to) {
  requireValid(from, "from");
  requireValid(to, "to");
  const double phi1 = degToRad(from.latitude);
  const double phi2 = degToRad(to.latitude);
  if (atPole(from.latitude) || atPole(to.latitude)) {
    // Every rhumb line into or out of a pole runs along a meridian.
    if (phi2 == phi1) {
      return 0.0;
    }
    return phi2 > phi1 ? 0.0 : 180.0;
  }
  const double dLambda = shortLongitudeDifference(from, to);
  const double dPsi = phi2 == phi1 ? 0.0 : stretchedDifference(phi1, phi2);
  return wrapBearing(radToDeg(std::atan2(dLambda, dPsi)));
}

LatLon rhumbDestination(const LatLon& from, double bearing, double distance, double radius) {
  requireValid(from, "from");
  requireFinite(bearing, "bearing");
  requireNonNegative(distance, "distance");
  requirePositive(radius, "radius");
  const double delta = distance / radius;
  const double theta = degToRad(bearing);
  const double phi1 = degToRad(from.latitude);
  double phi2 = phi1 + delta * std::cos(theta);
  if (std::abs(phi2) >= halfPi) {
    // The loxodrome reaches the pole after a finite distance and ends there.
    phi2 = std::copysign(halfPi, phi2);
    return {std::copysign(90.0, phi2), wrapLongitude(from.longitude)};
  }
  const double q = stretchRatio(phi1, phi2, atPole(from.latitude));
  const double dLambda = q == 0.0 ? 0.0 : delta * std::sin(theta) / q;
  return {radToDeg(phi2), wrapLongitude(from.longitude + radToDeg(dLambda))};
}

} // namespace impetus::geo
