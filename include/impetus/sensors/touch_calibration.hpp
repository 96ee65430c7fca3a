// Touch calibration: an affine map from raw panel coordinates (ADC counts, or the ideal positions
// of touch_resistive.hpp) to screen pixels, fitted to reference touches.
//
// A panel glued onto a display is offset, scaled and slightly rotated against it, and its film is
// not quite uniform. The affine map
//   x_s = a x_r + b y_r + c,   y_s = d x_r + e y_r + f
// takes out offset, scale, shear and rotation: three touches on targets not in a line fix its six
// coefficients exactly (the classic three-point calibration), more touches fit it by least
// squares and average the finger's scatter.
#pragma once

#include <impetus/math/vec2.hpp>

#include <array>
#include <span>

namespace impetus::sensors {

class TouchCalibration {
public:
  /// The identity map.
  TouchCalibration() = default;

  /// Fits the map to raw[i] -> screen[i] (least squares for more than three pairs). Throws
  /// impetus::Error: "points" when the spans differ in size or hold fewer than 3 pairs, "raw"
  /// when a value is non-finite or the raw points are (nearly) in a line, so the map is not
  /// determined.
  static TouchCalibration fit(std::span<const Vec2d> raw, std::span<const Vec2d> screen);

  [[nodiscard]] Vec2d apply(const Vec2d& raw) const noexcept {
    return {a_ * raw.x + b_ * raw.y + c_, d_ * raw.x + e_ * raw.y + f_};
  }

  /// Coefficients a, b, c (x row) and d, e, f (y row).
  [[nodiscard]] std::array<double, 6> coefficients() const noexcept { return {a_, b_, c_, d_, e_, f_}; }

private:
  double a_ = 1.0, b_ = 0.0, c_ = 0.0, d_ = 0.0, e_ = 1.0, f_ = 0.0;
};

} // namespace impetus::sensors
