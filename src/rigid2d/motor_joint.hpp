// Drives B toward a target position and angle relative to A with bounded force and torque.
// The solver's side (motor_joint.cpp); the definition is MotorJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

/// A point part of bounded magnitude (the linear drive) and a motor part on the angle.
struct MotorJoint {
  MotorJointSettings def; ///< the type's settings (the offsets change at run time)
  PointPart linear;       ///< N s per substep, on B (at B's origin)
  MotorPart angular;      ///< N m s per substep, on B
  /// From A's centre of mass to the target point (A's origin + linearOffset, a point fixed in
  /// A), world axes at the step's start, m.
  Vec2f targetA;
  /// From B's centre of mass to B's origin, world axes at the step's start, m.
  Vec2f originB;
  /// The angular error angleB - angleA - angularOffset at the step's start, in (-pi, pi], rad.
  float angleError = 0.0f;
};

void prepareJoint(MotorJoint& joint, const JointFrame& frame, const JointPose& pose, const StepContext& context);
/// Applies the accumulated impulses of `rows` (the warm start: warmStartJoints).
void warmStartJoint(MotorJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex);
void solveJoint(MotorJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep (impulses times the substep rate).
[[nodiscard]] JointReaction jointReaction(const MotorJoint& joint, float inverseH);

} // namespace impetus::rigid2d::detail
