// Drags a point of a body toward a world target with a soft, force-limited spring.
// The solver's side (mouse_joint.cpp); the definition is MouseJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

/// The rate (1/s) of the mouse joint's angular damping: a torque -I * rate * w on the dragged
/// body, so a body swung about the grab point stops spinning (time constant 1/rate, about 1.7 s)
/// without a visible effect on a drag of a second or so. Box2D v3 damps likewise (a soft angular
/// velocity constraint of 0.5 Hz, damping ratio 0.1: about 0.65/s).
inline constexpr float mouseAngularDampingRate = 0.6f;

/// A soft point part of bounded magnitude and a damping row part on the angle.
struct MouseJoint {
  MouseJointSettings def;  ///< the type's settings (the target changes at run time)
  PointPart linear;        ///< N s per substep, on B at its anchor
  RowPart angular;         ///< N m s per substep: the angular damping on B
  Vec2f targetOffset;      ///< B's centre of mass minus the target at the step's start, m
  Softness linearSoftness; ///< the spring (hertz, dampingRatio)
  Softness angularDamping; ///< the implicit angular damper (no bias)
};

void prepareJoint(MouseJoint& joint, const JointFrame& frame, const JointPose& pose, const StepContext& context);
/// Applies the accumulated impulses of `rows` (the warm start: warmStartJoints).
void warmStartJoint(MouseJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex);
void solveJoint(MouseJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep (impulses times the substep rate).
[[nodiscard]] JointReaction jointReaction(const MouseJoint& joint, float inverseH);

} // namespace impetus::rigid2d::detail
