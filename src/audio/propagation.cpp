#include <impetus/audio/propagation.hpp>
#include <impetus/core/constants.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>

#include <algorithm>
#include <cmath>

namespace impetus::audio {

double speedOfSoundInAir(double celsius) {
  requireFinite(celsius, "temperature");
  if (!(celsius > -273.15)) {
    throwInvalid("temperature", celsius, "must be above absolute zero (-273.15 degrees C)");
  }
  return 331.3 * std::sqrt(1.0 + celsius / 273.15);
}

double intensityAtDistance(double power, double distance) {
  requireNonNegative(power, "power");
  requirePositive(distance, "distance");
  return power / (4.0 * pi<double> * distance * distance);
}

double intensityLevel(double intensity) {
  requirePositive(intensity, "intensity");
  return 10.0 * std::log10(intensity / referenceIntensity);
}

double intensityFromLevel(double level) {
  requireFinite(level, "level");
  return referenceIntensity * std::pow(10.0, level / 10.0);
}

double pressureLevel(double pressure) {
  requirePositive(pressure, "pressure");
  return 20.0 * std::log10(pressure / referencePressure);
}

double pressureFromLevel(double level) {
  requireFinite(level, "level");
  return referencePressure * std::pow(10.0, level / 20.0);
}

double levelAtDistance(double level, double distance1, double distance2) {
  requireFinite(level, "level");
  requirePositive(distance1, "distance1");
  requirePositive(distance2, "distance2");
  return level - 20.0 * std::log10(distance2 / distance1);
}

double amplitudeRatio(double distance1, double distance2) {
  requirePositive(distance1, "distance1");
  requirePositive(distance2, "distance2");
  return distance1 / distance2;
}

double intensityRatio(double distance1, double distance2) {
  const double a = amplitudeRatio(distance1, distance2);
  return a * a;
}

double loudnessRatio(double levelDifference) {
  requireFinite(levelDifference, "levelDifference");
  return std::exp2(levelDifference / 10.0);
}

double flashToBangDelay(double distance, double speedOfSound) {
  requireNonNegative(distance, "distance");
  requirePositive(speedOfSound, "speedOfSound");
  return distance / speedOfSound - distance / constants::speedOfLight;
}

double distanceFromFlashToBang(double delay, double speedOfSound) {
  requireNonNegative(delay, "delay");
  requirePositive(speedOfSound, "speedOfSound");
  // t = d (1/c - 1/c_light)
  return delay / (1.0 / speedOfSound - 1.0 / constants::speedOfLight);
}

double distanceGain(const DistanceAttenuation& a, double distance) {
  requireNonNegative(distance, "distance");
  requirePositive(a.referenceDistance, "referenceDistance");
  requirePositive(a.maxDistance, "maxDistance");
  requireNonNegative(a.rolloff, "rolloff");
  const double ref = a.referenceDistance;
  const double max = a.maxDistance;
  if (static_cast<int>(a.model) < static_cast<int>(DistanceModel::none) ||
      static_cast<int>(a.model) > static_cast<int>(DistanceModel::exponentClamped)) {
    throwInvalid("model", static_cast<int>(a.model), "is not a DistanceModel");
  }
  const bool clamped = a.model == DistanceModel::inverseClamped || a.model == DistanceModel::linearClamped ||
                       a.model == DistanceModel::exponentClamped;
  if (clamped && max < ref) {
    throwInvalid("maxDistance", max, "must not be below referenceDistance for a clamped model");
  }
  double d = clamped ? std::clamp(distance, ref, max) : distance;
  switch (a.model) {
  case DistanceModel::none:
    return 1.0;
  case DistanceModel::inverse:
  case DistanceModel::inverseClamped: {
    // As OpenAL Soft: a denominator at or below zero (d < ref with a large rolloff) leaves 1.
    const double denominator = ref + a.rolloff * (d - ref);
    return denominator > 0.0 ? ref / denominator : 1.0;
  }
  case DistanceModel::linear:
  case DistanceModel::linearClamped:
    d = std::min(d, max);
    if (max == ref) {
      return 1.0;
    }
    return std::max(0.0, 1.0 - a.rolloff * (d - ref) / (max - ref));
  case DistanceModel::exponent:
  case DistanceModel::exponentClamped:
    return d > 0.0 ? std::pow(d / ref, -a.rolloff) : 1.0;
  }
  return 1.0;
}

} // namespace impetus::audio
