// Barometric altitude (ch. 23): height from air pressure in the standard atmosphere.
//
// A phone's barometer is a MEMS piezoresistive absolute-pressure sensor (a sealed cavity under a
// silicon diaphragm with strain gauges in it; the BMP180 is good to about +-1 m). In the
// International Standard Atmosphere (ISO 2533, ICAO) the temperature falls linearly with height
// through the troposphere, T = T0 - L h, and hydrostatic balance dp/dh = -rho g with the ideal gas
// rho = p M / (R T) integrates to
//   p = p0 (1 - L h / T0)^(g M / (R L)),   h = (T0 / L) (1 - (p / p0)^(R L / (g M)))
// with T0 = 288.15 K, L = 0.0065 K/m, g = 9.80665 m/s^2, M = 0.0289644 kg/mol and the standard's
// R* = 8.31432 J/(mol K) (U.S. Standard Atmosphere 1976; CODATA's 8.3144626 would move the
// tables' pressures by up to 2e-5): the exponent R L / (g M) = 1 / 5.255876 and T0 / L = 44,330.8 m. Above 11 km (the
// tropopause, 22,632 Pa) the ISA is isothermal at 216.65 K up to 20 km:
//   h = 11,000 + (R T / (g M)) ln(p_11 / p).
// Android's SensorManager.getAltitude(p0, p) is the troposphere formula with rounded constants,
// 44330 (1 - (p / p0)^(1/5.255)) (`androidAltitude`). The height difference between two
// readings taken with the same p0 is getAltitude(p0, p2) - getAltitude(p0, p1): p0 cancels to
// first order, so a stale sea-level pressure hardly matters for floors and stairs.
// Near sea level 1 hPa is about 8.4 m, so the BMP180's 1 m is 0.12 hPa.
#pragma once

#include <impetus/core/constants.hpp>

namespace impetus::sensors {

namespace isa {
inline constexpr double seaLevelTemperature = 288.15;   ///< T0, K
inline constexpr double lapseRate = 0.0065;             ///< L, K/m (troposphere)
inline constexpr double molarMass = 0.0289644;          ///< M of dry air, kg/mol
inline constexpr double gasConstant = 8.31432;          ///< R*, J/(mol K) (the standard atmosphere's value)
inline constexpr double tropopause = 11'000.0;          ///< m
inline constexpr double tropopauseTemperature = 216.65; ///< K, constant from 11 to 20 km
inline constexpr double stratosphereTop = 20'000.0;     ///< m: the model's upper limit here
} // namespace isa

/// Geopotential altitude (m) at pressure p in the ISA over a sea-level pressure p0 (both Pa, > 0;
/// defaults to the standard 101,325 Pa). Valid from below sea level (p > p0) up to 20 km; throws
/// impetus::Error naming "pressure" for p <= 0 or above 20 km (p < 5474.9 Pa x p0/101325) and
/// "seaLevelPressure" for p0 <= 0.
[[nodiscard]] double barometricAltitude(double pressure, double seaLevelPressure = constants::standardAtmosphere);

/// The ISA pressure (Pa) at altitude h (m, up to 20 km) over p0 (the inverse of barometricAltitude).
[[nodiscard]] double pressureAtAltitude(double altitude, double seaLevelPressure = constants::standardAtmosphere);

/// Android's getAltitude(p0, p) = 44330 (1 - (p / p0)^(1 / 5.255)), m; pressures in any one unit
/// (Android uses hPa), > 0.
[[nodiscard]] double androidAltitude(double seaLevelPressure, double pressure);

/// h(p2) - h(p1): how far the second reading is above the first, m (ISA; > 0 when p2 < p1).
[[nodiscard]] double altitudeDifference(double pressure1, double pressure2,
                                        double seaLevelPressure = constants::standardAtmosphere);

} // namespace impetus::sensors
