// Two bodies glued at their anchors and relative angle, rigidly or softly.
// The solver's side (weld_joint.cpp); the definition is WeldJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

/// A row part on the angle and a point part.
struct WeldJoint {
  WeldJointSettings def;   ///< the type's settings
  RowPart angle;           ///< N m s per substep
  PointPart point;         ///< N s per substep
  float startAngle = 0.0f; ///< the angle error at the step's start, angleB - angleA - referenceAngle, in (-pi, pi], rad
  Softness linearSoftness; ///< linearHertz's spring (unused when rigid)
  Softness angularSoftness; ///< angularHertz's spring (unused when rigid)
};

void prepareJoint(WeldJoint& joint, const JointFrame& frame, const JointPose& pose, const StepContext& context);
void warmStartJoint(WeldJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex);
void solveJoint(WeldJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep (impulses times the substep rate). The
/// torque is the joint's couple on B (its moment about the anchor), the force acts at the anchor.
[[nodiscard]] JointReaction jointReaction(const WeldJoint& joint, float inverseH);

} // namespace impetus::rigid2d::detail
