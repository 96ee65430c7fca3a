// Kinematics (ch. 2): constant acceleration, quadratic drag, plane rigid-body kinematics.
//
// Motion described without its causes. SI units: m, s, m/s, m/s^2, rad, rad/s, rad/s^2.
// Straight-line quantities are signed along the line of motion (a displacement of -3 m is 3 m
// backwards); times are elapsed times, never negative. Every function validates its input and
// throws impetus::Error naming the offending parameter (e.g. "time = -1: must be finite and
// non-negative"), including inputs no constant-acceleration motion can satisfy.
#pragma once

#include <impetus/math/vec2.hpp>
#include <impetus/math/vec3.hpp>

#include <optional>

namespace impetus {

// ---- Constant acceleration (the book's "to find / given / use" table) ------------------------
//
// v2 = v1 + a t,   s = v1 t + 1/2 a t^2,   v2^2 = v1^2 + 2 a s,   s = 1/2 (v1 + v2) t,
// with v1 the initial velocity, v2 the final velocity, a the acceleration, t the elapsed time and
// s the displacement (s2 - s1). The book's table survives with one row only (v1 = sqrt(v2^2 -
// 2 a s), with a spurious "/1"); these are all of them. Where a row takes a square root the sign
// of the velocity is not lost: it is the velocity at the *first* time t >= 0 the displacement is
// reached (its magnitude is the square root of the book's formula).

/// v2 = v1 + a t, m/s. time >= 0 s.
[[nodiscard]] double finalVelocityAfterTime(double initialVelocity, double acceleration, double time);

/// v2 with |v2| = sqrt(v1^2 + 2 a s), m/s, signed as the velocity when the displacement s is
/// first reached. Throws (naming displacement) when it is never reached: v1^2 + 2 a s < 0 (the
/// motion turns back first), or a = 0 and s has not the sign of v1.
[[nodiscard]] double finalVelocityAfterDisplacement(double initialVelocity, double acceleration, double displacement);

/// s = v1 t + 1/2 a t^2, m. time >= 0 s.
[[nodiscard]] double displacementAfterTime(double initialVelocity, double acceleration, double time);

/// s = (v2^2 - v1^2) / (2 a), m. Throws (naming acceleration) when a = 0, or when v2 would only
/// be reached at a negative time ((v2 - v1) / a < 0).
[[nodiscard]] double displacementBetweenVelocities(double initialVelocity, double finalVelocity, double acceleration);

/// s = 1/2 (v1 + v2) t, m (the mean velocity times the time). time >= 0 s.
[[nodiscard]] double displacementFromMeanVelocity(double initialVelocity, double finalVelocity, double time);

/// t = (v2 - v1) / a, s. Throws (naming acceleration) when a = 0 or t < 0.
[[nodiscard]] double timeBetweenVelocities(double initialVelocity, double finalVelocity, double acceleration);

/// The first t >= 0 with v1 t + 1/2 a t^2 = s, s: the book's (-v1 + sqrt(v1^2 + 2 a s)) / a,
/// computed without cancellation and valid for a = 0 (t = s / v1). Throws (naming displacement)
/// when s is never reached.
[[nodiscard]] double timeToDisplacement(double initialVelocity, double acceleration, double displacement);

/// a = (v2 - v1) / t, m/s^2. time > 0 s.
[[nodiscard]] double accelerationFromVelocityChange(double initialVelocity, double finalVelocity, double time);

/// a = (v2^2 - v1^2) / (2 s), m/s^2. Throws (naming displacement) when s = 0, or when s has not
/// the sign of v1 + v2 (s = 1/2 (v1 + v2) t with t > 0: no constant acceleration fits).
[[nodiscard]] double accelerationOverDisplacement(double initialVelocity, double finalVelocity, double displacement);

/// v1 = v2 - a t, m/s. time >= 0 s.
[[nodiscard]] double initialVelocityBeforeTime(double finalVelocity, double acceleration, double time);

/// v1 with |v1| = sqrt(v2^2 - 2 a s), m/s: the book's surviving row [T]. Signed for the most
/// recent start: the shortest time t >= 0 that ends at v2 after the displacement s. Throws
/// (naming displacement) when no start fits (v2^2 - 2 a s < 0, or a = 0 and s has not the sign
/// of v2).
[[nodiscard]] double initialVelocityBeforeDisplacement(double finalVelocity, double acceleration, double displacement);

/// The five quantities of one constant-acceleration motion.
struct ConstantAccelerationMotion {
  double initialVelocity; ///< v1, m/s
  double finalVelocity;   ///< v2, m/s
  double acceleration;    ///< a, m/s^2
  double time;            ///< t >= 0, s
  double displacement;    ///< s = s2 - s1, m
};

/// Exactly three of the five, the others left empty.
struct ConstantAccelerationKnowns {
  std::optional<double> initialVelocity;
  std::optional<double> finalVelocity;
  std::optional<double> acceleration;
  std::optional<double> time;
  std::optional<double> displacement;
};

/// Fills in the two unknowns from any three knowns (all ten combinations). Where two motions
/// fit (a square root), the one reaching its end first is chosen, as in the functions above.
/// Throws impetus::Error when not exactly three are given ("knowns"), when a value is not finite
/// or a time is negative, and when no motion fits or the knowns do not determine it (e.g. v1, v2
/// and s with v1 + v2 = 0, a = 0 with v1 != v2).
[[nodiscard]] ConstantAccelerationMotion solveConstantAcceleration(const ConstantAccelerationKnowns& knowns);

// ---- Quadratic drag: a = -k |v| v ------------------------------------------------------------
//
// A body moving along a line with no force but quadratic drag F = -C |v| v slows as
// a = -k |v| v with k = C / m (1/m; for a fluid k = 1/2 rho C_d A / m). Closed forms, valid for
// either sign of v1 (the book's v2 = v1 / (1 + k v1 t) and s2 = s1 + ln(1 + k v1 t) / k hold only
// for v1 >= 0 and blow up at t = 1 / (k |v1|) when v1 < 0):
//   v(t) = v1 / (1 + k |v1| t),   s(t) = s1 + sgn(v1) ln(1 + k |v1| t) / k,
//   |v(s)| = |v1| exp(-k |s - s1|).
// k = 0 gives uniform motion exactly (log1p / expm1, no 0/0).

/// Position (m) and velocity (m/s) on a line.
struct LinearState {
  double position;
  double velocity;
};

/// The state after `time` s (>= 0) from (initialPosition, initialVelocity), with
/// dragPerUnitMass k >= 0 (1/m).
[[nodiscard]] LinearState quadraticDragMotion(double initialPosition, double initialVelocity, double dragPerUnitMass,
                                              double time);

/// The velocity (m/s, signed) when the body passes `position`: v1 exp(-k |s - s1|). Throws
/// (naming position) when the position lies behind the start or the body is at rest elsewhere;
/// every position ahead is reached (the body never stops: s grows like ln t).
[[nodiscard]] double quadraticDragVelocityAt(double initialPosition, double initialVelocity, double dragPerUnitMass,
                                             double position);

/// The time (s) to reach `position`: t = (exp(k |s - s1|) - 1) / (k |v1|) (= |s - s1| / |v1|
/// for k = 0). Throws as quadraticDragVelocityAt.
[[nodiscard]] double quadraticDragTimeTo(double initialPosition, double initialVelocity, double dragPerUnitMass,
                                         double position);

// ---- Rotation with constant angular acceleration ---------------------------------------------
//
// The linear relations with the angle Omega for s, omega for v and alpha for a:
// omega2 = omega1 + alpha t,  Omega2 = Omega1 + omega1 t + 1/2 alpha t^2,
// omega2^2 = omega1^2 + 2 alpha (Omega2 - Omega1). Counter-clockwise positive (right-handed z).

/// Angle (rad) and angular velocity (rad/s).
struct AngularState {
  double angle;
  double angularVelocity;
};

/// The state after `time` s (>= 0) of constant angularAcceleration (rad/s^2).
[[nodiscard]] AngularState angularMotionAfterTime(double angle, double angularVelocity, double angularAcceleration,
                                                  double time);

/// omega2 with |omega2| = sqrt(omega1^2 + 2 alpha rotation), signed at the first time the
/// rotation (rad, signed) is reached; throws (naming rotation) when it never is.
[[nodiscard]] double angularVelocityAfterRotation(double angularVelocity, double angularAcceleration, double rotation);

/// A point at a fixed radius from a fixed axis (scalar relations of ch. 2).
struct CircularMotion {
  double tangentialSpeed;         ///< v = r omega, m/s (signed as omega)
  double tangentialAcceleration;  ///< a_t = r alpha, m/s^2 (signed as alpha)
  double centripetalAcceleration; ///< a_n = v^2 / r = r omega^2, m/s^2, toward the axis
  double acceleration;            ///< |a| = sqrt(a_t^2 + a_n^2), m/s^2
};

/// radius >= 0 m, angularVelocity in rad/s, angularAcceleration in rad/s^2. The arc length
/// swept by an angle Omega is r Omega.
[[nodiscard]] CircularMotion circularMotion(double radius, double angularVelocity, double angularAcceleration);

// ---- Plane and spatial rigid-body kinematics -------------------------------------------------
//
// For a point P fixed on a rigid body, with r the offset from the centre of gravity to P in
// world axes (r turns with the body):
//   v_P = v_cg + omega x r,   a_P = a_cg + alpha x r + omega x (omega x r).
// alpha x r is the tangential part (perpendicular to r) and omega x (omega x r) the centripetal
// part (toward the rotation axis, magnitude omega^2 times the distance from the axis). The
// order of the cross products matters: omega first.

/// The motion of a body in the plane: its centre of gravity and its rotation about z
/// (counter-clockwise positive).
struct PlanarBodyMotion {
  Vec2d velocity;             ///< of the centre of gravity, m/s
  Vec2d acceleration;         ///< of the centre of gravity, m/s^2
  double angularVelocity;     ///< omega, rad/s
  double angularAcceleration; ///< alpha, rad/s^2
};

/// The motion of a point of a body in the plane.
struct PlanarPointMotion {
  Vec2d velocity;                ///< v_cg + omega x r, m/s
  Vec2d acceleration;            ///< a_cg + tangential + centripetal, m/s^2
  Vec2d tangentialAcceleration;  ///< alpha x r = alpha perp(r), m/s^2
  Vec2d centripetalAcceleration; ///< omega x (omega x r) = -omega^2 r, m/s^2
};

/// `offset` = r, from the centre of gravity to the point in world axes, m.
[[nodiscard]] PlanarPointMotion pointOnRotatingBody(const PlanarBodyMotion& body, const Vec2d& offset);

/// The motion of a body in space: its centre of gravity and its rotation, in world axes.
struct BodyMotion {
  Vec3d velocity;            ///< of the centre of gravity, m/s
  Vec3d acceleration;        ///< of the centre of gravity, m/s^2
  Vec3d angularVelocity;     ///< omega, rad/s
  Vec3d angularAcceleration; ///< alpha = d omega / dt, rad/s^2
};

/// The motion of a point of a body in space.
struct PointMotion {
  Vec3d velocity;                ///< v_cg + omega x r, m/s
  Vec3d acceleration;            ///< a_cg + tangential + centripetal, m/s^2
  Vec3d tangentialAcceleration;  ///< alpha x r, m/s^2
  Vec3d centripetalAcceleration; ///< omega x (omega x r), m/s^2
};

/// `offset` = r, from the centre of gravity to the point in world axes, m.
[[nodiscard]] PointMotion pointOnRotatingBody(const BodyMotion& body, const Vec3d& offset);

} // namespace impetus
