#include <impetus/audio/binaural.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>

#include <algorithm>
#include <cmath>

namespace impetus::audio {

double interauralTimeDifference(double azimuth, double earSpacing, double speedOfSound) {
  requireFinite(azimuth, "azimuth");
  requirePositive(earSpacing, "earSpacing");
  requirePositive(speedOfSound, "speedOfSound");
  return earSpacing / speedOfSound * std::sin(azimuth);
}

double woodworthTimeDifference(double azimuth, double headRadius, double speedOfSound) {
  requireFinite(azimuth, "azimuth");
  requirePositive(headRadius, "headRadius");
  requirePositive(speedOfSound, "speedOfSound");
  // The lateral angle: asin(sin(azimuth)) folds a source behind onto its mirror in front.
  const double theta = std::asin(std::clamp(std::sin(azimuth), -1.0, 1.0));
  return headRadius / speedOfSound * (theta + std::sin(theta));
}

double headShadowGain(double angleFromEarAxis, double frequency, double headRadius, double speedOfSound) {
  requireFinite(angleFromEarAxis, "angleFromEarAxis");
  requirePositive(frequency, "frequency");
  requirePositive(headRadius, "headRadius");
  requirePositive(speedOfSound, "speedOfSound");
  constexpr double alphaMin = 0.1;
  constexpr double thetaMin = 150.0 * pi<double> / 180.0;
  // Fold the angle into 0..pi (the model is symmetric about the ear's axis).
  const double theta = std::acos(std::clamp(std::cos(angleFromEarAxis), -1.0, 1.0));
  const double alpha = (1.0 + 0.5 * alphaMin) + (1.0 - 0.5 * alphaMin) * std::cos(theta / thetaMin * pi<double>);
  const double w0 = speedOfSound / headRadius;
  const double x = 2.0 * pi<double> * frequency / (2.0 * w0);
  return std::sqrt((1.0 + alpha * alpha * x * x) / (1.0 + x * x));
}

double interauralLevelDifference(double azimuth, double frequency, double headRadius, double speedOfSound) {
  requireFinite(azimuth, "azimuth");
  // Ear axes point to azimuth +pi/2 (right) and -pi/2 (left): the angle to the source is
  // acos(sin azimuth) for the right ear, acos(-sin azimuth) for the left.
  const double s = std::clamp(std::sin(azimuth), -1.0, 1.0);
  const double right = headShadowGain(std::acos(s), frequency, headRadius, speedOfSound);
  const double left = headShadowGain(std::acos(-s), frequency, headRadius, speedOfSound);
  return 20.0 * std::log10(right / left);
}

} // namespace impetus::audio
