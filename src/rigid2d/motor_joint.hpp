// Drives B toward a target position and angle relative to A with bounded force and torque.
// The solver's side (motor_joint.cpp); the definition is MotorJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

struct MotorJoint {
  MotorJointDef def; ///< the settings (anchors and axes as given; motor and limit settings change at run time)
  // Accumulated impulses: solver state, kept from step to step for warm starting.
  Vec2f linearImpulse;         ///< N s per substep
  float angularImpulse = 0.0f; ///< N m s per substep
  // This step's constants.
  Mat22f linearMass;
  float angularMass = 0.0f;
};

void prepareJoint(MotorJoint& joint, const JointFrame& frame, const StepContext& context);
void warmStartJoint(MotorJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex);
void solveJoint(MotorJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep (impulses times the substep rate).
[[nodiscard]] JointReaction jointReaction(const MotorJoint& joint, const JointFrame& frame, float inverseH);

} // namespace impetus::rigid2d::detail
