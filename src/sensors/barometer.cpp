#include <impetus/error.hpp>
#include <impetus/sensors/barometer.hpp>

#include <cmath>
#include <string_view>

namespace impetus::sensors {
namespace {

constexpr double g0 = constants::standardGravity;
// R L / (g M): the troposphere's exponent, 1 / 5.255876.
constexpr double troposphereExponent = isa::gasConstant * isa::lapseRate / (g0 * isa::molarMass);
// R T / (g M) at the tropopause: the isothermal layer's scale height, 6341.6 m.
constexpr double stratosphereScaleHeight = isa::gasConstant * isa::tropopauseTemperature / (g0 * isa::molarMass);

/// p / p0 at the tropopause: (T11 / T0)^(g M / (R L)) = 0.22336.
double tropopauseRatio() {
  return std::pow(isa::tropopauseTemperature / isa::seaLevelTemperature, 1.0 / troposphereExponent);
}

double altitude(double pressure, double seaLevelPressure, std::string_view field) {
  requirePositive(seaLevelPressure, "seaLevelPressure");
  requirePositive(pressure, field);
  const double ratio = pressure / seaLevelPressure;
  const double r11 = tropopauseRatio();
  if (ratio >= r11) {
    return isa::seaLevelTemperature / isa::lapseRate * (1.0 - std::pow(ratio, troposphereExponent));
  }
  const double h = isa::tropopause + stratosphereScaleHeight * std::log(r11 / ratio);
  if (h > isa::stratosphereTop * (1.0 + 1e-12)) {
    throwInvalid(field, pressure, "is below the model's range (above 20 km in the standard atmosphere)");
  }
  return h;
}

} // namespace

double barometricAltitude(double pressure, double seaLevelPressure) {
  return altitude(pressure, seaLevelPressure, "pressure");
}

double pressureAtAltitude(double altitude, double seaLevelPressure) {
  requirePositive(seaLevelPressure, "seaLevelPressure");
  requireFinite(altitude, "altitude");
  if (altitude > isa::stratosphereTop) {
    throwInvalid("altitude", altitude, "must be at most 20000 m (the model's range)");
  }
  // Below sea level the troposphere formula continues (warmer air); it breaks down where
  // 1 - L h / T0 would reach 0, 44 km down.
  if (altitude < -5000.0) {
    throwInvalid("altitude", altitude, "must be at least -5000 m");
  }
  if (altitude <= isa::tropopause) {
    return seaLevelPressure *
           std::pow(1.0 - isa::lapseRate * altitude / isa::seaLevelTemperature, 1.0 / troposphereExponent);
  }
  return seaLevelPressure * tropopauseRatio() * std::exp(-(altitude - isa::tropopause) / stratosphereScaleHeight);
}

double androidAltitude(double seaLevelPressure, double pressure) {
  requirePositive(seaLevelPressure, "seaLevelPressure");
  requirePositive(pressure, "pressure");
  return 44330.0 * (1.0 - std::pow(pressure / seaLevelPressure, 1.0 / 5.255));
}

double altitudeDifference(double pressure1, double pressure2, double seaLevelPressure) {
  const double h1 = altitude(pressure1, seaLevelPressure, "pressure1");
  return altitude(pressure2, seaLevelPressure, "pressure2") - h1;
}

} // namespace impetus::sensors
