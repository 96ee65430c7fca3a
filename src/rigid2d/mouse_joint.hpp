// Drags a point of a body toward a world target with a soft, force-limited spring.
// The solver's side (mouse_joint.cpp); the definition is MouseJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

struct MouseJoint {
  MouseJointDef def; ///< the settings (anchors and axes as given; motor and limit settings change at run time)
  // Accumulated impulses: solver state, kept from step to step for warm starting.
  Vec2f linearImpulse; ///< N s per substep
  // This step's constants.
  Mat22f linearMass;
  Softness linearSoftness;
};

void prepareJoint(MouseJoint& joint, const JointFrame& frame, const StepContext& context);
void warmStartJoint(MouseJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex);
void solveJoint(MouseJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep (impulses times the substep rate).
[[nodiscard]] JointReaction jointReaction(const MouseJoint& joint, const JointFrame& frame, float inverseH);

} // namespace impetus::rigid2d::detail
