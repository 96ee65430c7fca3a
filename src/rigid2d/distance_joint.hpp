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
/// Scales the accumulated impulses (what the warm start applied): warmStartJoints' line search.
inline void scaleImpulses(DistanceJoint& joint, float scale) {
  joint.impulse = joint.impulse * scale;
  joint.lowerImpulse = joint.lowerImpulse * scale;
  joint.upperImpulse = joint.upperImpulse * scale;
  joint.motorImpulse = joint.motorImpulse * scale;
}
void warmStartJoint(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex);
void solveJoint(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias);
/// The force on body B over the last substep (the impulses along the axis times the substep
/// rate); a distance joint applies no torque.
void correctJointPosition(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                          std::uint32_t staticIndex, const StepContext& context);
[[nodiscard]] JointReaction jointReaction(const DistanceJoint& joint, const JointFrame& frame, float inverseH);

} // namespace impetus::rigid2d::detail
