// A vehicle wheel: a suspension spring along an axis of the chassis, free spin, a drive motor.
// The solver's side (wheel_joint.cpp); the definition is WheelJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"
#include "rigid2d/prismatic_joint.hpp" // SliderGeometry: the wheel slides on its axis as a prismatic joint does

namespace impetus::rigid2d::detail {

/// A row part for the point on the line; spring and limit parts along it; a motor part on the spin.
struct WheelJoint {
  WheelJointSettings def; ///< the type's settings (axes as given; motor and limit settings change at run time)
  RowPart line;           ///< across the axis, N s per substep
  SpringPart spring;      ///< the suspension, along the axis
  LimitPart limit;
  MotorPart motor; ///< on the relative spin, N m s per substep
  Vec2f axisA;     ///< the axis in world axes at the step's start
  /// The axis in world axes as the last solve saw it (the chassis turned through the step): the
  /// direction of the reaction's axial part.
  Vec2f solvedAxis;
};

void prepareJoint(WheelJoint& joint, const JointFrame& frame, const JointPose& pose, const StepContext& context);
void warmStartJoint(WheelJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex);
void solveJoint(WheelJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep (impulses times the substep rate).
[[nodiscard]] JointReaction jointReaction(const WheelJoint& joint, float inverseH);

} // namespace impetus::rigid2d::detail
