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
/// The rows of the linear and the angular impulse: soft ones (a spring) may do work, rigid ones are
/// passive.
[[nodiscard]] inline JointRows linearRows(const WeldJoint& joint) {
  return joint.def.linearHertz > 0.0f ? JointRows::working : JointRows::passive;
}
[[nodiscard]] inline JointRows angularRows(const WeldJoint& joint) {
  return joint.def.angularHertz > 0.0f ? JointRows::working : JointRows::passive;
}
/// Scales the accumulated impulses of `rows` (what the warm start applied): warmStartJoints'
/// line search.
inline void scaleImpulses(WeldJoint& joint, float scale, JointRows rows) {
  if (includes(rows, linearRows(joint))) {
    joint.linearImpulse = joint.linearImpulse * scale;
  }
  if (includes(rows, angularRows(joint))) {
    joint.angularImpulse = joint.angularImpulse * scale;
  }
}
/// Applies the accumulated impulses of `rows` (the warm start: warmStartJoints).
void warmStartJoint(WeldJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex, JointRows rows);
void solveJoint(WeldJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep (impulses times the substep rate). The
/// torque is the joint's couple on B (its moment about the anchor), the force acts at the anchor.
/// The rigid parts' errors corrected on positions, after the relax pass (positionShare).
void correctJointPosition(WeldJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                          std::uint32_t staticIndex, const StepContext& context);
[[nodiscard]] JointReaction jointReaction(const WeldJoint& joint, const JointFrame& frame, float inverseH);

} // namespace impetus::rigid2d::detail
