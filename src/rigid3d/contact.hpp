// The 3D world's contacts: a record for each pair of shapes whose boxes overlap (the broadphase's
// pairs), holding the pair's manifold and the impulses its points carry from step to step, and
// the solver's constraint made from it each step.
#pragma once

#include <impetus/math/mat33.hpp>
#include <impetus/math/quat.hpp>
#include <impetus/math/vec3.hpp>
#include <impetus/rigid3d/manifold.hpp>

#include <array>
#include <cstdint>

namespace impetus::rigid3d::detail {

/// What a contact point carries to the next step's warm start, N s.
struct PointImpulse {
  float normal = 0.0f;
  float tangent1 = 0.0f; ///< along the manifold's first tangent
  float tangent2 = 0.0f;
};

/// A pair of shapes whose fat boxes overlap. Shape A is the one whose geometry comes first in
/// the narrowphase's table (a hull before a capsule before a sphere), so that each pair has one
/// manifold function; the normal points from A to B.
struct Contact {
  /// The pair's key: A's and B's shape slots and generations (contactKey), so that a slot
  /// reused by a new shape never inherits an old contact.
  std::uint64_t keyA = 0, keyB = 0;
  std::uint32_t shapeA = 0, shapeB = 0; ///< shape slots
  std::uint32_t bodyA = 0, bodyB = 0;   ///< body slots
  /// One of the shapes is a sensor: the pair is reported, never solved.
  bool sensor = false;
  bool sensorIsA = false; ///< which of the two is the sensor
  /// Touching this step: a manifold with points (a sensor's pair: overlapping).
  bool touching = false;
  float friction = 0.0f; ///< the geometric mean of the shapes'
  /// How far A's and B's surfaces lie out from their cores, m: a sphere's or capsule's radius
  /// (0 for a hull).
  float roundingA = 0.0f, roundingB = 0.0f;
  float restitution = 0.0f; ///< the larger of the shapes'
  /// The torque against rolling per newton of normal force, m: the larger coefficient of the
  /// two shapes times the larger rolling radius (a sphere's or capsule's; a hull rolls on none).
  float rollingResistance = 0.0f;
  /// The rolling resistance's angular impulse of the last substep, world, N m s (warm start).
  Vec3f rollingImpulse;
  Manifold manifold;
  std::array<PointImpulse, 4> impulses{}; ///< by manifold point
  /// The manifold's tangents (world, unit; t2 = n x t1): kept while the normal turns little, so
  /// the friction impulses carried by them keep their meaning.
  Vec3f tangent1, tangent2;
};

/// One contact point in the solver.
struct ConstraintPoint {
  Vec3f rA, rB; ///< anchors relative to the centres of mass, world axes, m
  /// The anchors moved in to the shapes' cores (by a sphere's or capsule's radius along the
  /// normal), m: what turns with a body. A ball's contact stays under its centre however it
  /// rolls; its surface point, turned with it, would rise off the ground.
  Vec3f coreA, coreB;
  /// The separation at the step's start less what the cores' offsets contribute, m: the current
  /// separation is dot(dB + qB coreB - dA - qA coreA, n) plus this.
  float adjustedSeparation = 0.0f;
  PointImpulse impulse;
  float normalMass = 0.0f;   ///< kg
  float tangentMass1 = 0.0f; ///< kg
  float tangentMass2 = 0.0f;
  float normalBound = 0.0f;      ///< the most normal impulse the point may hold, N s
  float approachSpeed = 0.0f;    ///< the normal velocity at the step's start, m/s (negative approaching)
  float maxNormalImpulse = 0.0f; ///< the most pushed in one solve this step, N s (restitution's test)
};

/// A contact as the solver holds it for the step.
struct ContactConstraint {
  std::uint32_t indexA = 0, indexB = 0; ///< solver indices (staticIndex: a static body)
  std::uint32_t contact = 0;            ///< the contact's index in the world's list
  float mA = 0.0f, mB = 0.0f;           ///< inverse masses, 1/kg
  Mat33f iA, iB;                        ///< world inverse inertias at the step's start
  Vec3f normal, tangent1, tangent2;
  float friction = 0.0f;
  float restitution = 0.0f;
  float rollingResistance = 0.0f; ///< m (Contact::rollingResistance)
  /// The rolling rows (the relative spin about tangent1 and tangent2): their accumulated angular
  /// impulses, N m s, and the inverse of their 2x2 effective mass matrix [t_i . (IA + IB) t_j].
  float rollingImpulse1 = 0.0f, rollingImpulse2 = 0.0f;
  float rollingInverse11 = 0.0f, rollingInverse12 = 0.0f, rollingInverse22 = 0.0f;
  bool stiffer = false; ///< against a static or kinematic body: the stiffer softness
  int pointCount = 0;
  std::array<ConstraintPoint, 4> points{};
};

/// A contact's key part of one shape: its slot and generation.
[[nodiscard]] inline std::uint64_t shapeKey(std::uint32_t index, std::uint32_t generation) {
  return (static_cast<std::uint64_t>(index) << 32U) | generation;
}

} // namespace impetus::rigid3d::detail
