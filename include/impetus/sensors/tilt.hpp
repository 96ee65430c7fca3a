// Tilt from an accelerometer (ch. 21): the device's attitude from the direction of gravity.
//
// At rest an accelerometer reads the reaction to gravity, 1 g "up" in its own axes (x right,
// y towards the top edge, z out of the screen). The direction of that vector gives the tilt;
// rotation about it (yaw, heading) cannot be seen by accelerometers alone (a gyroscope or a
// compass is needed). The device must be still or moving steadily: any acceleration adds to the
// reading (the equivalence principle), so filter first (sensor_filters.hpp).
//
// Sign conventions differ between platforms. Android and most data sheets report the specific
// force (face up on a table: z = +1 g); iOS reports the direction of gravity (face up: z = -1 g,
// the book's Table 21-2). `AccelConvention` says which one a reading is in.
//
// One axis (a device held upright in the screen's plane, the book's find2dAngle):
//   theta = atan2(a_x, a_y) mapped to [0, 360): 0 deg upright (a = (0, 1)), 90 deg rotated 90 deg
// to the left (counter-clockwise seen from the front: a = (1, 0)), 180 deg upside down.
// The book takes atan2(a_y, a_x), which gives 90 deg upright, and maps negative angles with
// -alpha + 180, which mirrors them: -10 deg becomes 190 deg where 350 deg is right
// (bookFind2dAngle keeps that listing for comparison; docs/book-errata.md).
//
// Two axes from three (M. Pedley, "Tilt Sensing Using a Three-Axis Accelerometer", Freescale
// AN3461, 2013, eqs. 25-26, rotation sequence R_xyz): roll phi about the device's x axis (top
// edge up positive) and pitch theta about its y axis (right side down positive). A still device
// reads the specific force f = g (-sin theta, cos theta sin phi, cos theta cos phi), so
//   roll  phi   = atan2(f_y, f_z)                  in (-180, 180] deg (face down is +-180)
//   pitch theta = atan2(-f_x, sqrt(f_y^2 + f_z^2))  in [-90, 90] deg
// atan2 keeps every quadrant: no sign is lost for negative angles or past 90 degrees of roll.
#pragma once

#include <impetus/math/vec3.hpp>

namespace impetus::sensors {

enum class AccelConvention {
  specificForce,    ///< reads +1 g up: face up on a table z = +1 (Android, data sheets)
  gravityDirection, ///< reads the pull of gravity: face up z = -1 (iOS; the book's Table 21-2)
};

/// The reading as specific force (negated for gravityDirection).
[[nodiscard]] constexpr Vec3d toSpecificForce(const Vec3d& reading, AccelConvention convention) noexcept {
  return convention == AccelConvention::gravityDirection ? -reading : reading;
}

/// Single-axis tilt, deg in [0, 360): 0 upright (a_x, a_y) = (0, 1), increasing as the device
/// turns counter-clockwise (to the left) seen from the front. a_x, a_y in the specific-force
/// convention (any unit). Throws impetus::Error (field "ax"/"ay") when not finite, or both zero
/// (field "ay": lying flat, no in-plane gravity, no angle).
[[nodiscard]] double tiltAngle(double ax, double ay);

/// atan2(a_y, a_x) mapped to [0, 360) deg: the book's argument order with the mapping corrected
/// (deg < 0 ? deg + 360 : deg). 0 deg along +x.
[[nodiscard]] double angle360(double ax, double ay);

/// The book's find2dAngle as listed: atan2(a_y, a_x) in degrees, negative results mapped to
/// -deg + 180 (wrong for every negative angle but -90). For comparison and tests only.
[[nodiscard]] double bookFind2dAngle(double ax, double ay) noexcept;

struct Tilt {
  double pitch = 0.0; ///< rad in [-pi/2, pi/2], about the device's y axis: right side down positive
  double roll = 0.0;  ///< rad in (-pi, pi], about the device's x axis: top edge up positive
};

/// Pitch and roll from a 3-axis reading (any unit: only the direction matters). Throws
/// impetus::Error (field "reading") when it is not finite or zero (free fall: no gravity to see).
[[nodiscard]] Tilt tiltFromGravity(const Vec3d& reading, AccelConvention convention = AccelConvention::specificForce);

/// The specific force (in g) a still device reads at `tilt` (the inverse of tiltFromGravity).
[[nodiscard]] Vec3d gravityReading(const Tilt& tilt, AccelConvention convention = AccelConvention::specificForce);

/// The book's gross orientations (Table 21-2).
enum class GrossOrientation { faceUp, faceDown, rightSideDown, leftSideDown, bottomDown, topDown, unknown };

/// The axis with the largest |component| and its sign, if it exceeds the others by `deadBand`
/// (g, >= 0) and is at least half a g: otherwise unknown (in between, or moving). Throws
/// impetus::Error naming "reading" or "deadBand".
[[nodiscard]] GrossOrientation grossOrientation(const Vec3d& readingG, AccelConvention convention,
                                                double deadBand = 0.2);

[[nodiscard]] const char* toString(GrossOrientation orientation) noexcept;

} // namespace impetus::sensors
