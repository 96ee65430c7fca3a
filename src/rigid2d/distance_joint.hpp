// A rod, rope or spring between two anchors.
// The solver's side (distance_joint.cpp); the definition is DistanceJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

/// On the row along the anchors' axis (positive pushes them apart): a row part (a rod) or a
/// spring, motor and limit parts.
struct DistanceJoint {
  DistanceJointSettings def; ///< the type's settings (motor and limit settings change at run time)
  RowPart rod;               ///< the rigid length, N s per substep
  SpringPart spring;
  MotorPart motor;
  LimitPart limit; ///< minLength (pushes apart) and maxLength (pulls together)
  /// The unit axis from anchor A to anchor B at the last solve (zero when the anchors coincide):
  /// the direction of the reaction.
  Vec2f axis;
};

/// Rigid (a rod) unless a spring is asked for; a spring whose limits pin the length is a rod too.
[[nodiscard]] bool isRigid(const DistanceJointSettings& def);
void prepareJoint(DistanceJoint& joint, const JointFrame& frame, const JointPose& pose, const StepContext& context);
void warmStartJoint(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex);
void solveJoint(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias);
/// The force on body B over the last substep (the impulses along the axis times the substep
/// rate); a distance joint applies no torque.
[[nodiscard]] JointReaction jointReaction(const DistanceJoint& joint, float inverseH);

} // namespace impetus::rigid2d::detail
