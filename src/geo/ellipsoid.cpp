#include <impetus/error.hpp>
#include <impetus/geo/ellipsoid.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>

#include <cmath>

namespace impetus::geo {

void requireValid(const Ellipsoid& ellipsoid) {
  requirePositive(ellipsoid.equatorialRadius, "ellipsoid.equatorialRadius");
  if (!(std::isfinite(ellipsoid.flattening) && ellipsoid.flattening >= 0.0 && ellipsoid.flattening < 1.0)) {
    throwInvalid("ellipsoid.flattening", ellipsoid.flattening, "must be within [0, 1) (0: a sphere)");
  }
}

Vec3d geodeticToEcef(const GeodeticPosition& position, const Ellipsoid& ellipsoid) {
  requireValid(position.point, "position");
  requireFinite(position.height, "position.height");
  requireValid(ellipsoid);
  const double phi = degToRad(position.point.latitude);
  const double lambda = degToRad(position.point.longitude);
  const double e2 = ellipsoid.eccentricitySquared();
  const double sinPhi = std::sin(phi);
  const double cosPhi = std::cos(phi);
  const double n = ellipsoid.equatorialRadius / std::sqrt(1.0 - e2 * sinPhi * sinPhi);
  const double h = position.height;
  return {(n + h) * cosPhi * std::cos(lambda), (n + h) * cosPhi * std::sin(lambda), (n * (1.0 - e2) + h) * sinPhi};
}

GeodeticPosition ecefToGeodetic(const Vec3d& ecef, const Ellipsoid& ellipsoid) {
  requireValid(ellipsoid);
  requireFinite(ecef, "ecef");
  const double r = length(ecef);
  if (r < 1000.0) {
    throwInvalid("ecef", r, "is within 1 km of the Earth's centre: geodetic latitude undefined there");
  }
  const double a = ellipsoid.equatorialRadius;
  const double f = ellipsoid.flattening;
  const double b = ellipsoid.polarRadius();
  const double e2 = ellipsoid.eccentricitySquared();
  const double ep2 = e2 / ((1.0 - f) * (1.0 - f)); // second eccentricity squared, (a^2 - b^2)/b^2
  const double p = std::hypot(ecef.x, ecef.y);
  const double z = ecef.z;
  // Bowring: iterate the parametric (reduced) latitude beta, tan beta = (1 - f) tan phi.
  double beta = std::atan2(z, (1.0 - f) * p);
  double phi = 0.0;
  for (int i = 0; i < 10; ++i) {
    const double sinBeta = std::sin(beta);
    const double cosBeta = std::cos(beta);
    const double next = std::atan2(z + ep2 * b * sinBeta * sinBeta * sinBeta, p - e2 * a * cosBeta * cosBeta * cosBeta);
    const bool done = i > 0 && std::abs(next - phi) < 1e-15;
    phi = next;
    if (done) {
      break;
    }
    beta = std::atan2((1.0 - f) * std::sin(phi), std::cos(phi));
  }
  const double sinPhi = std::sin(phi);
  // h = p cos phi + z sin phi - a^2/N: no division by cos phi, so it holds at the poles.
  const double height = p * std::cos(phi) + z * sinPhi - a * std::sqrt(1.0 - e2 * sinPhi * sinPhi);
  return {{radToDeg(phi), wrapLongitude(radToDeg(std::atan2(ecef.y, ecef.x)))}, height};
}

} // namespace impetus::geo
