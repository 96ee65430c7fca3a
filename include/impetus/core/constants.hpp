// Physical constants in SI units. The book changes its own constants between chapters
// (g = 9.8 or 9.81 m/s^2, air at 1.225 or 1.23 kg/m^3): models take these as parameters with
// these values as defaults, so a test can pin the book's value explicitly.
#pragma once

namespace impetus::constants {

/// Standard gravity g0, m/s^2 (exact by definition, CGPM 1901).
inline constexpr double standardGravity = 9.80665;

/// Speed of light in vacuum c, m/s (exact by definition of the metre).
inline constexpr double speedOfLight = 299'792'458.0;

/// Newtonian constant of gravitation G, m^3 kg^-1 s^-2 (CODATA 2018).
inline constexpr double gravitationalConstant = 6.674'30e-11;

/// Speed of sound in dry air at 20 degrees C, m/s: 331.3 sqrt(1 + T / 273.15) with T = 20.
inline constexpr double speedOfSoundAir20C = 343.21;

/// Density of dry air at sea level, 15 degrees C, 101 325 Pa (ISA), kg/m^3.
inline constexpr double airDensitySeaLevel = 1.225;

/// Standard atmospheric pressure at sea level, Pa (exact by definition).
inline constexpr double standardAtmosphere = 101'325.0;

/// Density of fresh water at 4 degrees C (its maximum), kg/m^3.
inline constexpr double freshWaterDensity = 999.97;

/// Typical density of sea water at the surface (salinity 35 g/kg, 15 degrees C), kg/m^3.
inline constexpr double seaWaterDensity = 1025.0;

/// Specific energy of TNT, J/kg: the conventional "ton of TNT" is 4.184e9 J per 1000 kg.
inline constexpr double tntSpecificEnergy = 4.184e6;

/// Mean radius of the Earth, m (IUGG mean radius R1 of WGS 84).
inline constexpr double earthMeanRadius = 6'371'008.8;

/// Earth's standard gravitational parameter GM, m^3/s^2 (WGS 84).
inline constexpr double earthGravitationalParameter = 3.986'004'418e14;

} // namespace impetus::constants
