// A pin between two bodies, with limits, a motor, a torsional spring and joint friction.
// The solver's side (revolute_joint.cpp); the definition is RevoluteJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

struct RevoluteJoint {
  RevoluteJointDef def; ///< the settings (anchors and axes as given; motor and limit settings change at run time)
  // Accumulated impulses: solver state, kept from step to step for warm starting.
  Vec2f linearImpulse;        ///< point constraint, N s per substep
  float springImpulse = 0.0f; ///< N m s per substep
  float motorImpulse = 0.0f;
  float lowerImpulse = 0.0f;
  float upperImpulse = 0.0f;
  float frictionImpulse = 0.0f;
  float positionShare = 0.0f; ///< of the pin's error corrected on positions this substep (positionShare)
  // This step's constants.
  float axialMass = 0.0f;    ///< 1 / (iA + iB), kg m^2
  float angleAtStart = 0.0f; ///< the joint angle (angleB - angleA - referenceAngle) at the step's start, rad
  Softness springSoftness;
};

void prepareJoint(RevoluteJoint& joint, const JointFrame& frame, const StepContext& context);
/// Scales the accumulated impulses of `rows` (what the warm start applied): warmStartJoints'
/// line search. The spring and motor may do work; the pin, limits and friction are passive.
inline void scaleImpulses(RevoluteJoint& joint, float scale, JointRows rows) {
  if (includes(rows, JointRows::passive)) {
    joint.linearImpulse = joint.linearImpulse * scale;
    joint.lowerImpulse = joint.lowerImpulse * scale;
    joint.upperImpulse = joint.upperImpulse * scale;
    joint.frictionImpulse = joint.frictionImpulse * scale;
  }
  if (includes(rows, JointRows::working)) {
    joint.springImpulse = joint.springImpulse * scale;
    joint.motorImpulse = joint.motorImpulse * scale;
  }
}
/// Applies the accumulated impulses of `rows` (the warm start: warmStartJoints).
void warmStartJoint(RevoluteJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex, JointRows rows);
void solveJoint(RevoluteJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep (impulses times the substep rate).
void correctJointPosition(RevoluteJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                          std::uint32_t staticIndex, const StepContext& context);
[[nodiscard]] JointReaction jointReaction(const RevoluteJoint& joint, const JointFrame& frame, float inverseH);

} // namespace impetus::rigid2d::detail
