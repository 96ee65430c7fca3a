// Surface-capacitive touch screens (ch. 20): position from the four corner currents.
//
// A uniform resistive coating on the glass is held at the same AC voltage at its four corners. A
// finger is a capacitor to ground (the book's ~22 pF; ESD models use ~100 pF), so current flows
// from the corners through the coating into the finger. The coating between the finger and a
// corner is a resistor that grows with distance, so the nearer corners supply more of it. In the
// separable (per-axis) model of a uniform sheet the share of the right-hand corners is the
// finger's fraction of the width, exactly as the two ends of a uniform wire split a current
// injected at x in the ratio x : (L - x):
//   x = W (I_UR + I_LR) / I,   y = H (I_UL + I_UR) / I,   I = I_UL + I_UR + I_LL + I_LR
// with x from the left edge and y up from the bottom edge. Real sheets bow the field lines near
// the edges; the controller takes that out with calibration (touch_calibration.hpp).
#pragma once

#include <impetus/math/vec2.hpp>

#include <optional>

namespace impetus::sensors {

/// Currents drawn from the four corners, A (any common unit: only their ratios matter).
struct CornerCurrents {
  double upperLeft = 0.0;
  double upperRight = 0.0;
  double lowerLeft = 0.0;
  double lowerRight = 0.0;
};

/// The touch position in [0, W] x [0, H] (x right, y up), or none when the total current is at
/// or below `minimumTotal` (no finger: the ratios would be noise over noise). Throws
/// impetus::Error naming the field for a negative or non-finite current, or width/height <= 0.
[[nodiscard]] std::optional<Vec2d> surfaceCapacitivePosition(const CornerCurrents& currents, double width,
                                                             double height, double minimumTotal = 0.0);

/// The corner currents a finger drawing `total` at `position` produces in the separable model
/// (the inverse of surfaceCapacitivePosition): for simulation and testing of controllers.
[[nodiscard]] CornerCurrents surfaceCapacitiveCurrents(const Vec2d& position, double width, double height,
                                                       double total);

} // namespace impetus::sensors
