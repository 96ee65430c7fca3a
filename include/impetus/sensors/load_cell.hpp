// Strain gauges and load cells (ch. 23): from a bridge voltage to a force.
//
// A strain gauge is a thin serpentine wire bonded to a beam. Stretching the beam by the
// engineering strain eps = dL / L0 makes the wire longer and thinner, so its resistance
// R = rho_e L / A rises: dR / R = GF eps, with the gauge factor GF (about 2 for metal foil). The
// changes are tiny (eps ~ 1e-3 at full load), so the gauges sit in a Wheatstone bridge excited by
// V_ex, whose output is zero when balanced:
//   quarter bridge (one active gauge):                V_out / V_ex = GF eps / (4 + 2 GF eps)
//   half bridge (two gauges, +eps and -eps, adjacent): V_out / V_ex = GF eps / 2
//   full bridge (four gauges, +-eps in opposite pairs): V_out / V_ex = GF eps
// (the quarter bridge is slightly nonlinear; the others are exact). In the linear region the
// beam's stress is sigma = E eps and the force F = sigma A.
//
// A packaged load cell is specified by its capacity F_max and rated output S (V/V at capacity,
// typically 1-3 mV/V): F = F_max (V_out / V_ex - z) / S, with z its zero balance (tare).
#pragma once

namespace impetus::sensors {

enum class BridgeKind { quarter, half, full };

/// V_out / V_ex of a bridge at strain eps (|GF eps| < 1, GF > 0). Throws impetus::Error naming
/// "strain", "gaugeFactor" or "kind" (a value outside BridgeKind).
[[nodiscard]] double bridgeOutputRatio(double strain, double gaugeFactor, BridgeKind kind);

/// The strain that gives V_out / V_ex = ratio (the inverse of bridgeOutputRatio).
[[nodiscard]] double strainFromBridge(double outputRatio, double gaugeFactor, BridgeKind kind);

/// F = E eps A, N: Young's modulus E > 0 Pa, cross-section A > 0 m^2 (linear, elastic region).
[[nodiscard]] double forceFromStrain(double strain, double youngsModulus, double area);

struct LoadCell {
  double capacity = 500.0;     ///< N at rated output (> 0)
  double ratedOutput = 2.0e-3; ///< V/V at capacity (> 0): 2 mV/V
  double excitation = 5.0;     ///< V (> 0)
  double zeroBalance = 0.0;    ///< V/V read with no load (tare)

  /// F = capacity (V_out / V_ex - zeroBalance) / ratedOutput, N. Throws impetus::Error naming
  /// the field for bad settings or a non-finite voltage.
  [[nodiscard]] double force(double outputVolts) const;
  /// The output voltage at force F (the inverse).
  [[nodiscard]] double outputVolts(double force) const;
  /// |F| > capacity: beyond the rated (linear, calibrated) range.
  [[nodiscard]] bool overloaded(double force) const noexcept { return force > capacity || force < -capacity; }
};

} // namespace impetus::sensors
