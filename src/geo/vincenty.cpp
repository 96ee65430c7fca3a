#include <impetus/error.hpp>
#include <impetus/geo/vincenty.hpp>
#include <impetus/math/scalar.hpp>

#include <cmath>

namespace impetus::geo {

std::optional<VincentyResult> vincentyInverse(const LatLon& from, const LatLon& to, const Ellipsoid& ellipsoid,
                                              const VincentyOptions& options) {
  requireValid(from, "from");
  requireValid(to, "to");
  requireValid(ellipsoid);
  if (options.maxIterations <= 0) {
    throwInvalid("maxIterations", options.maxIterations, "must be positive");
  }
  requirePositive(options.tolerance, "tolerance");

  const double a = ellipsoid.equatorialRadius;
  const double f = ellipsoid.flattening;
  const double b = ellipsoid.polarRadius();
  const double bigL = degToRad(wrapLongitude(to.longitude - from.longitude));
  // Reduced latitudes on the auxiliary sphere, from tan U = (1 - f) tan phi without tan (poles).
  const auto reduced = [f](double latitude, double& sinU, double& cosU) {
    const double phi = degToRad(latitude);
    const double u = std::atan2((1.0 - f) * std::sin(phi), std::cos(phi));
    sinU = std::sin(u);
    cosU = std::cos(u);
  };
  double sinU1 = 0.0;
  double cosU1 = 0.0;
  double sinU2 = 0.0;
  double cosU2 = 0.0;
  reduced(from.latitude, sinU1, cosU1);
  reduced(to.latitude, sinU2, cosU2);

  double lambda = bigL;
  double sinLambda = 0.0;
  double cosLambda = 0.0;
  double sinSigma = 0.0;
  double cosSigma = 0.0;
  double sigma = 0.0;
  double cosSqAlpha = 0.0;
  double cos2SigmaM = 0.0;
  int iterations = 0;
  bool converged = false;
  while (iterations < options.maxIterations) {
    ++iterations;
    sinLambda = std::sin(lambda);
    cosLambda = std::cos(lambda);
    const double t1 = cosU2 * sinLambda;
    const double t2 = cosU1 * sinU2 - sinU1 * cosU2 * cosLambda;
    sinSigma = std::sqrt(t1 * t1 + t2 * t2);
    if (sinSigma == 0.0) {
      // Coincident points (or a pole with itself): distance 0.
      return VincentyResult{0.0, 0.0, 0.0, iterations};
    }
    cosSigma = sinU1 * sinU2 + cosU1 * cosU2 * cosLambda;
    sigma = std::atan2(sinSigma, cosSigma);
    const double sinAlpha = cosU1 * cosU2 * sinLambda / sinSigma;
    cosSqAlpha = 1.0 - sinAlpha * sinAlpha;
    // On the equator (cos^2 alpha = 0) the geodesic is the equator and 2 sigma_m drops out.
    cos2SigmaM = cosSqAlpha != 0.0 ? cosSigma - 2.0 * sinU1 * sinU2 / cosSqAlpha : 0.0;
    const double c = f / 16.0 * cosSqAlpha * (4.0 + f * (4.0 - 3.0 * cosSqAlpha));
    const double previous = lambda;
    lambda = bigL + (1.0 - c) * f * sinAlpha *
                        (sigma + c * sinSigma * (cos2SigmaM + c * cosSigma * (-1.0 + 2.0 * cos2SigmaM * cos2SigmaM)));
    if (!std::isfinite(lambda) || std::abs(lambda) > pi<double>) {
      return std::nullopt; // lambda past pi: the nearly antipodal case the formula cannot reach
    }
    if (std::abs(lambda - previous) < options.tolerance) {
      converged = true;
      break;
    }
  }
  if (!converged) {
    return std::nullopt;
  }
  const double uSq = cosSqAlpha * (a * a - b * b) / (b * b);
  const double bigA = 1.0 + uSq / 16384.0 * (4096.0 + uSq * (-768.0 + uSq * (320.0 - 175.0 * uSq)));
  const double bigB = uSq / 1024.0 * (256.0 + uSq * (-128.0 + uSq * (74.0 - 47.0 * uSq)));
  const double c2 = cos2SigmaM * cos2SigmaM;
  const double deltaSigma =
      bigB * sinSigma *
      (cos2SigmaM + bigB / 4.0 *
                        (cosSigma * (-1.0 + 2.0 * c2) -
                         bigB / 6.0 * cos2SigmaM * (-3.0 + 4.0 * sinSigma * sinSigma) * (-3.0 + 4.0 * c2)));
  VincentyResult result;
  result.distance = b * bigA * (sigma - deltaSigma);
  result.initialAzimuth =
      wrapBearing(radToDeg(std::atan2(cosU2 * sinLambda, cosU1 * sinU2 - sinU1 * cosU2 * cosLambda)));
  result.finalAzimuth =
      wrapBearing(radToDeg(std::atan2(cosU1 * sinLambda, -sinU1 * cosU2 + cosU1 * sinU2 * cosLambda)));
  result.iterations = iterations;
  return result;
}

} // namespace impetus::geo
