// The weld joint (after Box2D v3's): a row part on the angle, C = angleB - angleA -
// referenceAngle = 0, then a point part C = (cB + rB) - (cA + rA) = 0, last because it matters
// most. Each is rigid at hertz 0 (soft at the joint's stiffness with bias, rigid in the relax
// pass, like the revolute's pin); with hertz > 0 it is a soft constraint of that frequency and
// damping ratio in both passes (its softness is the physics asked for, not error correction).
// Solving the two parts one after the other instead of as a 3x3 block lets a long welded chain
// sag a little (each joint is as stiff as the joint hertz); Box2D v3 makes the same trade.
#include "rigid2d/weld_joint.hpp"

#include <impetus/math/scalar.hpp>

#include <cmath>

namespace impetus::rigid2d::detail {

void prepareJoint(WeldJoint& joint, const JointFrame& frame, const JointPose& /*pose*/, const StepContext& context) {
  joint.startAngle = unwindAngle(frame.deltaAngle - joint.def.referenceAngle);
  joint.point.prepare(frame.frameA, frame.frameB, frame);
  joint.linearSoftness = makeSoft(joint.def.linearHertz, joint.def.linearDampingRatio, context.h);
  joint.angularSoftness = makeSoft(joint.def.angularHertz, joint.def.angularDampingRatio, context.h);
}

void warmStartJoint(WeldJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex) {
  withBodies(frame, states, staticIndex, [&](BodyState& a, BodyState& b) {
    joint.angle.warmStart(angleRow(), frame, a, b);
    joint.point.warmStart(currentAnchor(a, frame.frameA), currentAnchor(b, frame.frameB), frame, a, b);
  });
}

void solveJoint(WeldJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& /*context*/, bool useBias) {
  withBodies(frame, states, staticIndex, [&](BodyState& a, BodyState& b) {
    const WeldJointSettings& def = joint.def;
    // A spring (hertz > 0) acts in both passes; a rigid row has its bias in the solve pass only.
    if (def.angularHertz > 0.0f || useBias) {
      const float angleError = unwindAngle(joint.startAngle + relativeAngle(b.dq, a.dq));
      joint.angle.solve(angleRow(), frame, a, b, angleError,
                        def.angularHertz > 0.0f ? joint.angularSoftness : frame.softness);
    } else {
      joint.angle.solveRigid(angleRow(), frame, a, b);
    }
    const Vec2f rA = currentAnchor(a, frame.frameA);
    const Vec2f rB = currentAnchor(b, frame.frameB);
    if (def.linearHertz > 0.0f || useBias) {
      joint.point.solve(rA, rB, frame, a, b, anchorSeparation(frame, a, b, rA, rB),
                        def.linearHertz > 0.0f ? joint.linearSoftness : frame.softness);
    } else {
      joint.point.solveRigid(rA, rB, frame, a, b);
    }
  });
}

JointReaction jointReaction(const WeldJoint& joint, float inverseH) {
  return {joint.point.impulse * inverseH, joint.angle.impulse * inverseH};
}

} // namespace impetus::rigid2d::detail
