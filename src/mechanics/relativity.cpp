#include <impetus/error.hpp>
#include <impetus/mechanics/relativity.hpp>

#include <cmath>

namespace impetus {
namespace {

constexpr double secondsPerDay = 86'400.0;

/// b = v/c after checking 0 <= v < c.
double beta(double speed, double speedOfLight) {
  requirePositive(speedOfLight, "speedOfLight");
  requireNonNegative(speed, "speed");
  if (!(speed < speedOfLight)) {
    throwInvalid("speed", speed, "must be less than the speed of light (gamma is infinite at v = c)");
  }
  return speed / speedOfLight;
}

} // namespace

double lorentzFactor(double speed, double speedOfLight) {
  const double b = beta(speed, speedOfLight);
  return 1.0 / std::sqrt((1.0 - b) * (1.0 + b));
}

double dilatedTime(double properTime, double speed, double speedOfLight) {
  requireNonNegative(properTime, "properTime");
  return lorentzFactor(speed, speedOfLight) * properTime;
}

double specialRelativisticRate(double speed, double speedOfLight) {
  const double b = beta(speed, speedOfLight);
  return -0.5 * b * b;
}

double specialRelativisticRateExact(double speed, double speedOfLight) {
  const double b = beta(speed, speedOfLight);
  return -b * b / (1.0 + std::sqrt((1.0 - b) * (1.0 + b)));
}

double gravitationalRate(double gravitationalParameter, double lowerRadius, double upperRadius, double speedOfLight) {
  requirePositive(gravitationalParameter, "gravitationalParameter");
  requirePositive(lowerRadius, "lowerRadius");
  requirePositive(upperRadius, "upperRadius");
  requirePositive(speedOfLight, "speedOfLight");
  return gravitationalParameter / (speedOfLight * speedOfLight) * (1.0 / lowerRadius - 1.0 / upperRadius);
}

GpsClockDrift gpsClockDrift(const GpsClockInputs& in) {
  requirePositive(in.groundRadius, "groundRadius");
  requirePositive(in.orbitRadius, "orbitRadius");
  if (!(in.orbitRadius > in.groundRadius)) {
    throwInvalid("orbitRadius", in.orbitRadius, "must be greater than the ground radius");
  }
  requirePositive(in.gravitationalParameter, "gravitationalParameter");
  requireNonNegative(in.orbitalSpeed, "orbitalSpeed");
  if (!(in.orbitalSpeed < constants::speedOfLight)) {
    throwInvalid("orbitalSpeed", in.orbitalSpeed, "must be less than the speed of light");
  }
  requirePositive(in.nominalFrequency, "nominalFrequency");
  if (in.groundPotential) {
    requirePositive(*in.groundPotential, "groundPotential");
  }
  const double c = constants::speedOfLight;
  GpsClockDrift d;
  d.orbitalSpeed = in.orbitalSpeed > 0.0 ? in.orbitalSpeed : std::sqrt(in.gravitationalParameter / in.orbitRadius);
  d.specialRate = specialRelativisticRate(d.orbitalSpeed);
  const double groundPotential = in.groundPotential.value_or(in.gravitationalParameter / in.groundRadius);
  d.gravitationalRate = (groundPotential - in.gravitationalParameter / in.orbitRadius) / (c * c);
  d.netRate = d.specialRate + d.gravitationalRate;
  d.specialNanosecondsPerDay = d.specialRate * secondsPerDay * 1e9;
  d.gravitationalNanosecondsPerDay = d.gravitationalRate * secondsPerDay * 1e9;
  d.netNanosecondsPerDay = d.netRate * secondsPerDay * 1e9;
  d.correctedFrequency = in.nominalFrequency / (1.0 + d.netRate);
  d.rangeErrorPerDay = c * d.netRate * secondsPerDay;
  return d;
}

} // namespace impetus
