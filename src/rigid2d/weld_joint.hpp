// Two bodies glued at their anchors and relative angle, rigidly or softly.
// The solver's side (weld_joint.cpp); the definition is WeldJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

struct WeldJoint {
  WeldJointDef def; ///< the settings (anchors and axes as given; motor and limit settings change at run time)
  // Accumulated impulses: solver state, kept from step to step for warm starting.
  Vec2f linearImpulse;         ///< N s per substep
  float angularImpulse = 0.0f; ///< N m s per substep
  float positionShare = 0.0f;  ///< of the rigid parts' errors corrected on positions this substep (positionShare)
  // This step's constants.
  float axialMass = 0.0f;  ///< 1 / (iA + iB), kg m^2
  float startAngle = 0.0f; ///< the angle error at the step's start, angleB - angleA - referenceAngle, in (-pi, pi], rad
  Softness linearSoftness; ///< linearHertz's spring, or the world's joint softness when rigid
  Softness angularSoftness; ///< angularHertz's spring, or the world's joint softness when rigid
};

void prepareJoint(WeldJoint& joint, const JointFrame& frame, const StepContext& context);
/// Scales the accumulated impulses (what the warm start applied): warmStartJoints' line search.
inline void scaleImpulses(WeldJoint& joint, float scale) {
  joint.linearImpulse = joint.linearImpulse * scale;
  joint.angularImpulse = joint.angularImpulse * scale;
}
void warmStartJoint(WeldJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex);
void solveJoint(WeldJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep (impulses times the substep rate). The
/// torque is the joint's couple on B (its moment about the anchor), the force acts at the anchor.
/// The rigid parts' errors corrected on positions, after the relax pass (positionShare).
void correctJointPosition(WeldJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                          std::uint32_t staticIndex, const StepContext& context);
[[nodiscard]] JointReaction jointReaction(const WeldJoint& joint, const JointFrame& frame, float inverseH);

} // namespace impetus::rigid2d::detail
