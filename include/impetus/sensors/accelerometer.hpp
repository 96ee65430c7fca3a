// Accelerometer readings (ch. 21): units, the sensor's range and clipping, calibration.
//
// A MEMS accelerometer is a proof mass m on a spring k: under an acceleration a the spring
// deflects by dx = m a / k (F = -k dx), and the chip reports a = k dx / m in multiples of
// g (the book's 9.8 m/s^2; standard gravity 9.80665 here). The chip has a range (the iPhone's
// LIS331D is +-2 g, the Wii remote's ADXL330 +-3 g): beyond it the reading saturates and the
// trace shows flat tops. Phones report a little past the nominal range (about +-2.3 g) and then
// hold the limit. A clipped sample says only "at least this much"; offline the gap can be
// bridged by a curve through the good samples on both sides (`fillClippedGaps`), in real time
// only extrapolated or held.
//
// Calibration: a real axis reads r = b + s a: an offset b (g) and a scale s (1 when perfect).
// Reading the axis pointing straight up and straight down (+1 g and -1 g) gives
//   offset = (r_up + r_down) / 2,   scale = (r_up - r_down) / 2
// and the corrected reading is (r - offset) / scale (`AxisCalibration`).
#pragma once

#include <impetus/core/constants.hpp>
#include <impetus/math/vec3.hpp>

#include <span>
#include <vector>

namespace impetus::sensors {

/// g -> m/s^2.
[[nodiscard]] constexpr double gToMetresPerSecond2(double g, double gravity = constants::standardGravity) noexcept {
  return g * gravity;
}

/// The proof-mass model: the reading (g) of a mass `proofMass` kg on a spring of stiffness
/// `stiffness` N/m deflected by `deflection` m: a = k dx / (m g). Throws impetus::Error
/// naming the field (mass and stiffness > 0, gravity > 0).
[[nodiscard]] double proofMassReading(double deflection, double stiffness, double proofMass,
                                      double gravity = constants::standardGravity);

/// A saturated reading: the value the sensor reports for a true acceleration `trueG` and range
/// +-`range` (g, > 0: a zero range is rejected, field "range").
[[nodiscard]] double clipReading(double trueG, double range);

/// Whether a reported value sits at the limit (|value| >= range - tolerance). range > 0; a NaN
/// value is refused (field "value").
[[nodiscard]] bool isClipped(double value, double range, double tolerance = 1e-9);

/// Bridges each run of clipped samples (|x| >= range - tolerance) of an evenly sampled signal
/// with a cubic Hermite curve that leaves the last good sample before the run and joins the first
/// good sample after it with the slopes the signal had there (one-sided differences): the flat
/// top becomes a peak. Samples in a run that touches either end of the signal are left as they
/// are (only one side is known). Throws impetus::Error naming "samples" (non-finite) or "range".
[[nodiscard]] std::vector<double> fillClippedGaps(std::span<const double> samples, double range,
                                                  double tolerance = 1e-9);

/// One axis's offset and scale: corrected = (raw - offset) / scale.
struct AxisCalibration {
  double offset = 0.0; ///< g: what the axis reads at 0 g
  double scale = 1.0;  ///< reading per true g (> 0)

  /// From the readings with the axis pointing up (+1 g) and down (-1 g). Throws impetus::Error
  /// (field "readingUp") unless readingUp > readingDown and both are finite.
  static AxisCalibration fromFlip(double readingUp, double readingDown);

  [[nodiscard]] double apply(double raw) const noexcept { return (raw - offset) / scale; }
};

/// A 3-axis calibration from the six-position test (each axis up, then down).
struct AccelCalibration {
  AxisCalibration x{}, y{}, z{};

  [[nodiscard]] Vec3d apply(const Vec3d& raw) const noexcept {
    return {x.apply(raw.x), y.apply(raw.y), z.apply(raw.z)};
  }
};

} // namespace impetus::sensors
