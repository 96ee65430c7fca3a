// A slider: translation along an axis of A only, with limits, a motor and a spring.
// The solver's side (prismatic_joint.cpp); the definition is PrismaticJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

struct PrismaticJoint {
  PrismaticJointDef def; ///< the settings (anchors and axes as given; motor and limit settings change at run time)
  // Accumulated impulses: solver state, kept from step to step for warm starting.
  Vec2f impulse;              ///< perpendicular (x) and angular (y) constraint, per substep
  float springImpulse = 0.0f; ///< N s per substep, along the axis
  float motorImpulse = 0.0f;
  float lowerImpulse = 0.0f;
  float upperImpulse = 0.0f;
  // This step's constants.
  Vec2f axisA;            ///< the axis in world axes at the step's start
  float axialMass = 0.0f; ///< kg
  Softness springSoftness;
};

void prepareJoint(PrismaticJoint& joint, const JointFrame& frame, const StepContext& context);
void warmStartJoint(PrismaticJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex);
void solveJoint(PrismaticJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep (impulses times the substep rate).
[[nodiscard]] JointReaction jointReaction(const PrismaticJoint& joint, const JointFrame& frame, float inverseH);

} // namespace impetus::rigid2d::detail
