// Relativistic time (ch. 1, ch. 22): the Lorentz factor, time dilation, and the clock rates of
// a GPS satellite (special relativity slows it, the weaker gravity of its orbit speeds it up).
//
// The book's light clock: a tick at rest takes t0 = 2L/c; moving at v it takes t = gamma t0 with
// gamma = 1/sqrt(1 - v^2/c^2). At v = c the formula divides by zero: here v >= c is an
// impetus::Error, never an infinity or NaN.
#pragma once

#include <impetus/core/constants.hpp>

#include <optional>

namespace impetus {

/// gamma = 1/sqrt(1 - v^2/c^2), dimensionless, >= 1. speed |v| in m/s, 0 <= v < c (c =
/// speedOfLight, m/s, > 0); evaluated as 1/sqrt((1 - b)(1 + b)), b = v/c, to keep its digits
/// near c. Throws impetus::Error naming "speed" for v >= c.
[[nodiscard]] double lorentzFactor(double speed, double speedOfLight = constants::speedOfLight);

/// t = gamma t0: the time one tick of proper duration t0 (s, >= 0; measured by the moving
/// clock) takes as seen by an observer the clock moves past at `speed` (m/s, < c).
[[nodiscard]] double dilatedTime(double properTime, double speed, double speedOfLight = constants::speedOfLight);

/// Fractional rate of a clock moving at `speed` relative to one at rest, first order:
/// -v^2/(2 c^2) (dimensionless; negative: it runs slow). Valid for v << c.
[[nodiscard]] double specialRelativisticRate(double speed, double speedOfLight = constants::speedOfLight);

/// The exact form of the same: 1/gamma - 1 = sqrt(1 - v^2/c^2) - 1, evaluated as
/// -b^2/(1 + sqrt(1 - b^2)) so that it does not cancel at small speeds. 0 <= v < c.
[[nodiscard]] double specialRelativisticRateExact(double speed, double speedOfLight = constants::speedOfLight);

/// Fractional rate of a clock at radius r (m) relative to one at radius R (m), both at rest in
/// the field of a mass with gravitational parameter GM (m^3/s^2), first order (weak field):
/// (GM/c^2)(1/R - 1/r); positive (runs fast) when r > R. R, r > 0.
[[nodiscard]] double gravitationalRate(double gravitationalParameter, double lowerRadius, double upperRadius,
                                       double speedOfLight = constants::speedOfLight);

/// A GPS satellite clock compared with a clock on the ground. The defaults are the spec's
/// (Ex 1.2): circular orbit r = 2.656e7 m, mean Earth radius 6.371e6 m, WGS 84 GM, orbital speed
/// sqrt(GM/r) = 3874 m/s, ground clock at rest.
struct GpsClockInputs {
  double orbitRadius = 2.656e7;                                           ///< m, > groundRadius
  double groundRadius = 6.371e6;                                          ///< m, > 0
  double gravitationalParameter = constants::earthGravitationalParameter; ///< GM, m^3/s^2, > 0
  double orbitalSpeed = 0.0;         ///< m/s, >= 0, < c; 0: circular, sqrt(GM/orbitRadius)
  double nominalFrequency = 10.23e6; ///< the frequency the clock must show on the ground, Hz, > 0
  /// Optional total potential of the ground clock's frame, m^2/s^2 (gravity + rotation, as
  /// seen by a clock on the rotating geoid: W0 = 62,636,856.0 m^2/s^2, IERS Conventions 2010).
  /// When set it replaces GM/groundRadius: this is what the GPS system actually corrects for,
  /// and it gives the factor 4.4647e-10 behind the book's 10.22999999543 MHz.
  std::optional<double> groundPotential;
};

struct GpsClockDrift {
  double orbitalSpeed = 0.0;                   ///< m/s
  double specialRate = 0.0;                    ///< -v^2/(2 c^2), fractional
  double gravitationalRate = 0.0;              ///< (GM/R - GM/r)/c^2 (or (W0 - GM/r)/c^2), fractional
  double netRate = 0.0;                        ///< sum: fractional rate satellite minus ground
  double specialNanosecondsPerDay = 0.0;       ///< specialRate * 86400 s, ns (negative: loses time)
  double gravitationalNanosecondsPerDay = 0.0; ///< ns (positive: gains time)
  double netNanosecondsPerDay = 0.0;           ///< ns
  /// The frequency to set on the satellite so that it reads nominalFrequency on the ground:
  /// f0 / (1 + netRate), Hz (10.22999999543 MHz for GPS).
  double correctedFrequency = 0.0;
  double rangeErrorPerDay = 0.0; ///< c * (net drift over one day): the position error it would cause, m
};

/// Clock rates of a satellite relative to the ground, first order in v^2/c^2 and GM/(r c^2).
/// Throws impetus::Error for radii that are not positive, an orbit below the ground, or a speed
/// of light or more.
[[nodiscard]] GpsClockDrift gpsClockDrift(const GpsClockInputs& inputs = {});

} // namespace impetus
