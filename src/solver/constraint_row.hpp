// One row of a constraint between two bodies, as every joint part sees it (the solver layer: no
// dimension in it). A row is its Jacobian: a direction for the bodies' linear velocities and a
// moment arm for each body's angular velocity, so that the row's speed is
//   Cdot = dot(linear, vB - vA) + angularB . wB - angularA . wA.
// In 2D the angular parts are scalars (cross(r, n)); in 3D they are vectors (r x n), and an
// angle row has linear = 0 and both arms along the axis. The caller builds rows from its own
// geometry each time it solves; the parts below only need the row and the bodies' inverse masses.
#pragma once

#include <impetus/math/mat33.hpp>
#include <impetus/math/vec3.hpp>

namespace impetus::solver {

// The angular algebra of a plane: an angular velocity is a scalar, and so is an inverse inertia.
[[nodiscard]] inline float angularDot(float a, float b) { return a * b; }
[[nodiscard]] inline float inverseInertiaTimes(float inverseInertia, float angular) { return inverseInertia * angular; }
[[nodiscard]] inline float angularLength(float a) { return a < 0.0f ? -a : a; }
[[nodiscard]] inline double preciseAngularDot(float a, float b) { return static_cast<double>(a) * b; }
/// dot in double, for any vector with x and y (the 3D overload below adds z).
template <class Vec> [[nodiscard]] inline double preciseDot(const Vec& a, const Vec& b) {
  return static_cast<double>(a.x) * b.x + static_cast<double>(a.y) * b.y;
}

// The angular algebra of space: an angular velocity is a vector, an inverse inertia a matrix
// (world axes).
[[nodiscard]] inline float angularDot(const Vec3f& a, const Vec3f& b) { return dot(a, b); }
[[nodiscard]] inline Vec3f inverseInertiaTimes(const Mat33f& inverseInertia, const Vec3f& angular) {
  return inverseInertia * angular;
}
[[nodiscard]] inline float angularLength(const Vec3f& a) { return length(a); }
[[nodiscard]] inline double preciseDot(const Vec3f& a, const Vec3f& b) {
  return static_cast<double>(a.x) * b.x + static_cast<double>(a.y) * b.y + static_cast<double>(a.z) * b.z;
}
[[nodiscard]] inline double preciseAngularDot(const Vec3f& a, const Vec3f& b) { return preciseDot(a, b); }

/// The Jacobian of one row: B moves along +linear, A along -linear.
template <class Vec, class Angular> struct Row {
  Vec linear;       ///< unit direction (or zero for an angle row)
  Angular angularA; ///< A's moment arm (m in 2D: cross(arm, linear)), or the axis of an angle row
  Angular angularB;
};

/// The rate of change of a row's constraint, m/s (or rad/s for an angle row). `Body` is any type
/// with velocities `v` and `w`.
template <class Vec, class Angular, class Body>
[[nodiscard]] inline float rowSpeed(const Row<Vec, Angular>& row, const Body& a, const Body& b) {
  return dot(row.linear, b.v - a.v) + angularDot(row.angularB, b.w) - angularDot(row.angularA, a.w);
}

/// The inverse of a row's effective mass, J M^-1 J^T (1/kg or 1/(kg m^2)). `Mass` is any type with
/// inverse masses `mA`, `mB` and inverse inertias `iA`, `iB`.
template <class Vec, class Angular, class Mass>
[[nodiscard]] inline float rowInverseMass(const Row<Vec, Angular>& row, const Mass& m) {
  return (m.mA + m.mB) * dot(row.linear, row.linear) +
         angularDot(row.angularA, inverseInertiaTimes(m.iA, row.angularA)) +
         angularDot(row.angularB, inverseInertiaTimes(m.iB, row.angularB));
}

/// J_i M^-1 J_j^T: how an impulse along row j changes row i's speed (a coupled block's K_ij).
template <class Vec, class Angular, class Mass>
[[nodiscard]] inline float rowCoupling(const Row<Vec, Angular>& i, const Row<Vec, Angular>& j, const Mass& m) {
  return (m.mA + m.mB) * dot(i.linear, j.linear) + angularDot(i.angularA, inverseInertiaTimes(m.iA, j.angularA)) +
         angularDot(i.angularB, inverseInertiaTimes(m.iB, j.angularB));
}

/// rowCoupling in double: a block's elimination needs K's entries to more digits than float keeps
/// (solveSymmetric, joint_parts.hpp).
template <class Vec, class Angular, class Mass>
[[nodiscard]] inline double rowCouplingPrecise(const Row<Vec, Angular>& i, const Row<Vec, Angular>& j, const Mass& m) {
  return (static_cast<double>(m.mA) + m.mB) * preciseDot(i.linear, j.linear) +
         preciseAngularDot(i.angularA, inverseInertiaTimes(m.iA, j.angularA)) +
         preciseAngularDot(i.angularB, inverseInertiaTimes(m.iB, j.angularB));
}

/// The effective mass of a row (kg or kg m^2), zero when neither body can move along it. `R` is
/// a Row or an AngularRow (rowInverseMass of either).
template <class R, class Mass> [[nodiscard]] inline float rowMass(const R& row, const Mass& m) {
  const float k = rowInverseMass(row, m);
  return k > 0.0f ? 1.0f / k : 0.0f;
}

/// The largest impulse a row may hold (N s, or N m s for an angle row): what stops the fastest
/// relative motion the world's speed caps allow along it, 2 maxSpeed on the direction plus
/// maxSpin on each moment arm, at the row's effective mass. No constraint of a game needs more in
/// a substep (a 10:1 load hangs at 10 g h of it); a bigger one can only be an unstable
/// system's impulses running away, which this holds finite. `Pair` has the inverse masses and the
/// caps `maxSpeed` (m/s) and `maxSpin` (rad/s).
template <class Vec, class Angular, class Pair>
[[nodiscard]] inline float maxRowImpulse(const Row<Vec, Angular>& row, float mass, const Pair& p) {
  const float speed =
      2.0f * p.maxSpeed * length(row.linear) + p.maxSpin * (angularLength(row.angularA) + angularLength(row.angularB));
  return mass * speed;
}

/// A row on the bodies' rotations alone (an angle row: a revolute joint's spring, motor and
/// limits, a weld's angle): Row with no linear part. Its own type, because the general row's
/// zero direction still costs its products with the linear velocities (0 times a speed cannot be
/// folded away in IEEE arithmetic), on the chain of dependent updates a joint's parts form.
template <class Angular> struct AngularRow {
  Angular angularA; ///< the axis A turns about (2D: 1)
  Angular angularB;
};

template <class Angular, class Body>
[[nodiscard]] inline float rowSpeed(const AngularRow<Angular>& row, const Body& a, const Body& b) {
  return angularDot(row.angularB, b.w) - angularDot(row.angularA, a.w);
}

template <class Angular, class Mass>
[[nodiscard]] inline float rowInverseMass(const AngularRow<Angular>& row, const Mass& m) {
  return angularDot(row.angularA, inverseInertiaTimes(m.iA, row.angularA)) +
         angularDot(row.angularB, inverseInertiaTimes(m.iB, row.angularB));
}

/// maxRowImpulse of an angle row: maxSpin on each arm.
template <class Angular, class Pair>
[[nodiscard]] inline float maxRowImpulse(const AngularRow<Angular>& row, float mass, const Pair& p) {
  return mass * (p.maxSpin * (angularLength(row.angularA) + angularLength(row.angularB)));
}

template <class Angular, class Mass, class Body>
inline void applyRow(const AngularRow<Angular>& row, const Mass& m, Body& a, Body& b, float impulse) {
  a.w -= inverseInertiaTimes(m.iA, row.angularA * impulse);
  b.w += inverseInertiaTimes(m.iB, row.angularB * impulse);
}

/// Applies an impulse (N s, or N m s for an angle row) along a row: +impulse on B, -impulse on A.
template <class Vec, class Angular, class Mass, class Body>
inline void applyRow(const Row<Vec, Angular>& row, const Mass& m, Body& a, Body& b, float impulse) {
  a.v -= row.linear * (m.mA * impulse);
  a.w -= inverseInertiaTimes(m.iA, row.angularA * impulse);
  b.v += row.linear * (m.mB * impulse);
  b.w += inverseInertiaTimes(m.iB, row.angularB * impulse);
}

} // namespace impetus::solver
