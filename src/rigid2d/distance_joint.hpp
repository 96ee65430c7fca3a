// A rod, rope or spring between two anchors.
// The solver's side (distance_joint.cpp); the definition is DistanceJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

struct DistanceJoint {
  DistanceJointDef def; ///< the settings (anchors and axes as given; motor and limit settings change at run time)
  // Accumulated impulses along the axis (positive pushes the anchors apart): solver state, kept
  // from step to step for warm starting.
  float impulse = 0.0f;      ///< rigid or spring part, N s per substep
  float lowerImpulse = 0.0f; ///< min-length limit (>= 0, pushes apart)
  float upperImpulse = 0.0f; ///< max-length limit (>= 0, pulls together)
  float motorImpulse = 0.0f;
  float positionShare = 0.0f; ///< of the rod's error corrected on positions this substep (positionShare)
  // This step's constants.
  float axialMass = 0.0f; ///< kg: 1 / (the inverse mass along the axis) at the step's start (the solve recomputes it
                          ///< from the current anchors)
  /// The spring over one substep (see springCoefficients in distance_joint.cpp): B = h omega^2
  /// (1/s) scales the stretch, A = 2 zeta omega h + theta (h omega)^2 (dimensionless) the damping
  /// and the implicit share of the stiffness, and relaxShare (0 to 1) how much of the spring is
  /// applied again in the relax pass; all zero without a spring.
  float springStiffness = 0.0f;
  float springDamping = 0.0f;
  float springRelaxShare = 0.0f;
  /// The unit axis from anchor A to anchor B at the last solve (zero when the anchors coincide):
  /// the direction of the reaction.
  Vec2f axis;
};

void prepareJoint(DistanceJoint& joint, const JointFrame& frame, const StepContext& context);
/// Rigid (a rod) unless a spring is asked for; a spring whose limits pin the length is a rod too.
[[nodiscard]] bool isRigid(const DistanceJointDef& def);
/// The rows of `impulse`: a rod's is passive, a spring's may do work.
[[nodiscard]] inline JointRows lengthRow(const DistanceJoint& joint) {
  return isRigid(joint.def) ? JointRows::passive : JointRows::working;
}
/// Scales the accumulated impulses of `rows` (what the warm start applied): warmStartJoints'
/// line search. The spring and motor may do work; a rod and the limits are passive.
inline void scaleImpulses(DistanceJoint& joint, float scale, JointRows rows) {
  if (includes(rows, lengthRow(joint))) {
    joint.impulse = joint.impulse * scale;
  }
  if (includes(rows, JointRows::passive)) {
    joint.lowerImpulse = joint.lowerImpulse * scale;
    joint.upperImpulse = joint.upperImpulse * scale;
  }
  if (includes(rows, JointRows::working)) {
    joint.motorImpulse = joint.motorImpulse * scale;
  }
}
/// Applies the accumulated impulses of `rows` (the warm start: warmStartJoints).
void warmStartJoint(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex, JointRows rows);
void solveJoint(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias);
/// The force on body B over the last substep (the impulses along the axis times the substep
/// rate); a distance joint applies no torque.
void correctJointPosition(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                          std::uint32_t staticIndex, const StepContext& context);
[[nodiscard]] JointReaction jointReaction(const DistanceJoint& joint, const JointFrame& frame, float inverseH);

} // namespace impetus::rigid2d::detail
