// A pin between two bodies, with limits, a motor, a torsional spring and joint friction.
// The solver's side (revolute_joint.cpp); the definition is RevoluteJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

/// A point part for the pin; spring, motor, friction and limit parts on the angle.
struct RevoluteJoint {
  RevoluteJointSettings def; ///< the type's settings (motor and limit settings change at run time)
  PointPart point;           ///< the pin, N s per substep
  SpringPart spring;         ///< N m s per substep
  MotorPart motor;
  MotorPart friction;
  LimitPart limit;
  float angleAtStart = 0.0f; ///< the joint angle (angleB - angleA - referenceAngle) at the step's start, rad
};

void prepareJoint(RevoluteJoint& joint, const JointFrame& frame, const JointPose& pose, const StepContext& context);
void warmStartJoint(RevoluteJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex);
void solveJoint(RevoluteJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep (impulses times the substep rate).
[[nodiscard]] JointReaction jointReaction(const RevoluteJoint& joint, float inverseH);

} // namespace impetus::rigid2d::detail
