// Joints inside the solver: the common part of every joint (bodies, anchors, the solver's
// per-step frame), the rows of the plane that the joint parts (solver/joint_parts.hpp) solve,
// and the per-type compositions, one file per type (revolute_joint.cpp, ...). Each type provides
// prepare, warm start, solve (with or without bias, like the contacts) and its reaction.
#pragma once

#include "rigid2d/world_impl.hpp"
#include "solver/joint_parts.hpp"
#include "solver/point_part.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/joint.hpp>

#include <array>
#include <cmath>
#include <vector>

namespace impetus::rigid2d::detail {

using solver::BlockPart;
using solver::LimitPart;
using solver::MotorPart;
using PointPart = solver::PointPart<Vec2f>;
using solver::rigidRow;
using solver::RowPart;
using solver::SpringPart;

/// One constraint row of the plane: a direction and each body's moment arm (solver::Row).
using JointRow = solver::Row<Vec2f, float>;
/// A row on the rotations alone (solver::AngularRow).
using AngleRow = solver::AngularRow<float>;
/// The two rows of a point constraint (x and y), or of a slider's line and angle.
using RowPair = std::array<JointRow, 2>;

/// A joint's force and torque on body B (N, N m).
struct JointReaction {
  Vec2f force;
  float torque = 0.0f;
};

/// The solver's view of a joint for one step, shared by every type.
struct JointFrame {
  std::uint32_t indexA = 0, indexB = 0; ///< solver indices (the static index for static bodies)
  float mA = 0.0f, mB = 0.0f;           ///< inverse masses, 1/kg
  float iA = 0.0f, iB = 0.0f;           ///< inverse rotational inertias, 1/(kg m^2)
  Vec2f frameA, frameB;                 ///< anchors relative to the centres of mass, world axes, at the step's start, m
  Vec2f deltaCenter;                    ///< cB - cA at the step's start, m
  float deltaAngle = 0.0f;              ///< angleB - angleA at the step's start, rad (0 unless readsStartAngle)
  Softness softness;                    ///< the rigid rows' stiffness (the joint's constraintHertz, or the world's)
  float maxSpeed = 0.0f;                ///< the world's speed cap, m/s (bounds the rows' impulses: maxRowImpulse)
  float maxSpin = 0.0f;                 ///< the spin cap, rad/s (a quarter turn a substep)
};

/// What a joint type's prepare may read of its bodies besides the frame: their poses at the
/// step's start. Not kept: the passes of the substeps read only the frame.
struct JointPose {
  Rot2f qA, qB;                     ///< the bodies' rotations at the step's start
  Vec2f localCenterA, localCenterB; ///< centres of mass in the body frames, m (origin = c - rotate(q, localCenter))
  Vec2f centerB;                    ///< B's centre of mass at the step's start, world, m (the mouse joint)
};

/// The softness of a joint's rigid rows in a pass: its stiffness with bias, rigid in the relax pass.
[[nodiscard]] inline Softness rigidRowSoftness(const JointFrame& f, bool useBias) {
  return useBias ? f.softness : rigidRow;
}

/// The angle of qB relative to qA, in [-pi, pi] (portableAtan2: the same bits everywhere).
[[nodiscard]] inline float relativeAngle(const Rot2f& qB, const Rot2f& qA) {
  const Rot2f q = invMul(qA, qB);
  return portableAtan2(q.s, q.c);
}

/// An angle wrapped into (-pi, pi].
[[nodiscard]] inline float unwindAngle(float a) {
  constexpr float pi = impetus::pi<float>;
  if (a < -pi) {
    return a + 2.0f * pi;
  }
  if (a > pi) {
    return a - 2.0f * pi;
  }
  return a;
}

/// An angle of any size wrapped into [-pi, pi]: the reference angles a joint is made with, once,
/// so that the step's angle errors (a sum of at most three angles in (-pi, pi]) need only
/// unwindAngle.
[[nodiscard]] inline float wrapAngle(float a) {
  return unwindAngle(static_cast<float>(std::remainder(static_cast<double>(a), 2.0 * impetus::pi<double>)));
}

/// The anchors now: the step's frames turned by each body's rotation so far this step.
[[nodiscard]] inline Vec2f currentAnchor(const BodyState& s, const Vec2f& frame) { return rotate(s.dq, frame); }

/// The separation of two anchors now (B's minus A's), m: the step's start plus what the bodies
/// moved since.
[[nodiscard]] inline Vec2f anchorSeparation(const JointFrame& f, const BodyState& a, const BodyState& b,
                                            const Vec2f& rA, const Vec2f& rB) {
  return (b.dp - a.dp) + (rB - rA) + f.deltaCenter;
}

/// The row along `direction` for anchors rA (on A) and rB (on B), relative to the centres of mass.
[[nodiscard]] inline JointRow linearRow(const Vec2f& direction, const Vec2f& rA, const Vec2f& rB) {
  return {direction, cross(rA, direction), cross(rB, direction)};
}

/// The angle row: the relative spin wB - wA.
[[nodiscard]] inline AngleRow angleRow() { return {1.0f, 1.0f}; }
/// The angle row as a general row, for a block that couples it with a linear one (a slider).
[[nodiscard]] inline JointRow angleJointRow() { return {{}, 1.0f, 1.0f}; }

/// Writes a body's new velocities back unless it is the static state.
inline void storeVelocity(std::vector<BodyState>& states, std::uint32_t index, std::uint32_t staticIndex,
                          const BodyState& s) {
  if (index != staticIndex) {
    states[index].v = s.v;
    states[index].w = s.w;
  }
}

/// Runs `solve(a, b)` on copies of the joint's two bodies' states and writes the velocities back.
template <class Solve>
inline void withBodies(const JointFrame& f, std::vector<BodyState>& states, std::uint32_t staticIndex, Solve&& solve) {
  BodyState a = states[f.indexA];
  BodyState b = states[f.indexB];
  solve(a, b);
  storeVelocity(states, f.indexA, staticIndex, a);
  storeVelocity(states, f.indexB, staticIndex, b);
}

/// A joint whose spring, motor or limits are switched off holds no impulse for them (it would be
/// warm started otherwise). For the joint types with those three parts.
template <class JointData> void clearSwitchedOffImpulses(JointData& joint) {
  if (!joint.def.enableSpring) {
    joint.spring.impulse = 0.0f;
  }
  if (!joint.def.enableMotor) {
    joint.motor.impulse = 0.0f;
  }
  if (!joint.def.enableLimit) {
    joint.limit.clear();
  }
}

} // namespace impetus::rigid2d::detail
