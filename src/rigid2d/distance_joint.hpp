// A rod, rope or spring between two anchors.
// The solver's side (distance_joint.cpp); the definition is DistanceJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

struct DistanceJoint {
  DistanceJointDef def; ///< the settings (anchors and axes as given; motor and limit settings change at run time)
  // Accumulated impulses: solver state, kept from step to step for warm starting.
  float impulse = 0.0f;      ///< rigid or spring part, N s per substep
  float lowerImpulse = 0.0f; ///< min-length limit
  float upperImpulse = 0.0f; ///< max-length limit
  float motorImpulse = 0.0f;
  // This step's constants.
  float axialMass = 0.0f; ///< kg
  Softness distanceSoftness;
};

void prepareJoint(DistanceJoint& joint, const JointFrame& frame, const StepContext& context);
void warmStartJoint(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex);
void solveJoint(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep (impulses times the substep rate).
[[nodiscard]] JointReaction jointReaction(const DistanceJoint& joint, const JointFrame& frame, float inverseH);

} // namespace impetus::rigid2d::detail
