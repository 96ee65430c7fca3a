// A vehicle wheel: a suspension spring along an axis of the chassis, free spin, a drive motor.
// The solver's side (wheel_joint.cpp); the definition is WheelJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"
#include "rigid2d/prismatic_joint.hpp" // SliderGeometry: the wheel slides on its axis as a prismatic joint does

namespace impetus::rigid2d::detail {

struct WheelJoint {
  WheelJointDef def; ///< the settings (anchors and axes as given; motor and limit settings change at run time)
  // Accumulated impulses: solver state, kept from step to step for warm starting.
  float perpImpulse = 0.0f;   ///< across the axis, N s per substep
  float springImpulse = 0.0f; ///< along the axis
  float motorImpulse = 0.0f;  ///< N m s per substep
  float lowerImpulse = 0.0f;
  float upperImpulse = 0.0f;
  float positionShare = 0.0f; ///< of the line's error corrected on positions this substep (positionShare)
  // This step's constants.
  Vec2f axisA;            ///< the axis in world axes at the step's start
  float axialMass = 0.0f; ///< along the axis, kg: the mass the suspension spring carries
  float motorMass = 0.0f; ///< 1 / (iA + iB), kg m^2
  Softness springSoftness;
  /// The axis in world axes as the last solve saw it (the chassis turned through the step): the
  /// direction of the reaction's axial part.
  Vec2f solvedAxis;
};

void prepareJoint(WheelJoint& joint, const JointFrame& frame, const StepContext& context);
/// Scales the accumulated impulses of `rows` (what the warm start applied): warmStartJoints'
/// line search. The suspension spring and the motor may do work; the line and limits are passive.
inline void scaleImpulses(WheelJoint& joint, float scale, JointRows rows) {
  if (includes(rows, JointRows::passive)) {
    joint.perpImpulse = joint.perpImpulse * scale;
    joint.lowerImpulse = joint.lowerImpulse * scale;
    joint.upperImpulse = joint.upperImpulse * scale;
  }
  if (includes(rows, JointRows::working)) {
    joint.springImpulse = joint.springImpulse * scale;
    joint.motorImpulse = joint.motorImpulse * scale;
  }
}
/// Lets go of part of the accumulated impulses before the warm start (sliderWarmStartFactor).
inline void beginWarmStart(WheelJoint& joint) { scaleImpulses(joint, sliderWarmStartFactor, JointRows::all); }
/// Applies the accumulated impulses of `rows` (the warm start: warmStartJoints).
void warmStartJoint(WheelJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex, JointRows rows);
void solveJoint(WheelJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep (impulses times the substep rate).
/// The line's error corrected on positions, after the relax pass (positionShare).
void correctJointPosition(WheelJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                          std::uint32_t staticIndex, const StepContext& context);
[[nodiscard]] JointReaction jointReaction(const WheelJoint& joint, const JointFrame& frame, float inverseH);

} // namespace impetus::rigid2d::detail
