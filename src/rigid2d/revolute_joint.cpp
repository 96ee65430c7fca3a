// The revolute joint (after Box2D v3's): a point part keeps the anchors together,
// C = (cB + rB) - (cA + rA) = 0, two rows solved as a block, soft at the joint's stiffness with
// bias and rigid in the relax pass; on the angle row (the relative spin wB - wA), a torsional
// spring toward joint angle 0, a motor toward motorSpeed (at most maxMotorTorque), friction
// (toward zero relative spin, at most frictionTorque) and the two one-sided limits. The point
// part last: it matters most.
#include "rigid2d/revolute_joint.hpp"

#include <impetus/math/scalar.hpp>

#include <cmath>

namespace impetus::rigid2d::detail {
namespace {

/// The joint angle now (angleB - angleA - referenceAngle, in (-pi, pi]): at the step's start plus
/// what the bodies turned since.
float jointAngle(const RevoluteJoint& joint, const BodyState& a, const BodyState& b) {
  return unwindAngle(joint.angleAtStart + relativeAngle(b.dq, a.dq));
}

/// What the angle row's parts hold together (N m s per substep, on B).
float axialImpulse(const RevoluteJoint& joint) {
  return joint.spring.impulse + joint.motor.impulse + joint.friction.impulse + joint.limit.lowerImpulse -
         joint.limit.upperImpulse;
}

} // namespace

void prepareJoint(RevoluteJoint& joint, const JointFrame& frame, const JointPose& /*pose*/,
                  const StepContext& context) {
  // Read by the spring and the limits alone (the frame's deltaAngle is computed for them).
  joint.angleAtStart =
      joint.def.enableSpring || joint.def.enableLimit ? unwindAngle(frame.deltaAngle - joint.def.referenceAngle) : 0.0f;
  joint.point.prepare(frame.frameA, frame.frameB, frame);
  joint.spring.prepare(joint.def.enableSpring ? joint.def.hertz : 0.0f, joint.def.dampingRatio, context.h);
  clearSwitchedOffImpulses(joint);
  if (joint.def.frictionTorque == 0.0f) {
    joint.friction.impulse = 0.0f;
  }
}

void warmStartJoint(RevoluteJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex) {
  withBodies(frame, states, staticIndex, [&](BodyState& a, BodyState& b) {
    // The angle row's parts at once: one impulse, the sum of theirs.
    applyRow(angleRow(), frame, a, b, axialImpulse(joint));
    joint.point.warmStart(currentAnchor(a, frame.frameA), currentAnchor(b, frame.frameB), frame, a, b);
  });
}

namespace {

/// solveJoint for one pass, compiled once for each: the relax pass drops the point's bias
/// altogether (no separation to compute).
template <bool UseBias> void solvePass(RevoluteJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                                       std::uint32_t staticIndex, const StepContext& context) {
  withBodies(frame, states, staticIndex, [&](BodyState& a, BodyState& b) {
    const RevoluteJointSettings& def = joint.def;
    const AngleRow angle = angleRow();
    // The positions do not change within a pass: one joint angle for the spring and the limits.
    const float position = def.enableSpring || def.enableLimit ? jointAngle(joint, a, b) : 0.0f;
    if (def.enableSpring) {
      joint.spring.solve(angle, frame, a, b, position, UseBias);
    }
    if (def.enableMotor) {
      joint.motor.solve(angle, frame, a, b, def.motorSpeed, context.h * def.maxMotorTorque);
    }
    if (def.frictionTorque > 0.0f) {
      joint.friction.solve(angle, frame, a, b, 0.0f, context.h * def.frictionTorque);
    }
    if (def.enableLimit) {
      joint.limit.solve(angle, frame, a, b, position, def.lowerAngle, def.upperAngle, frame.softness, context.inverseH,
                        UseBias);
    }
    const Vec2f rA = currentAnchor(a, frame.frameA);
    const Vec2f rB = currentAnchor(b, frame.frameB);
    if constexpr (UseBias) {
      joint.point.solve(rA, rB, frame, a, b, anchorSeparation(frame, a, b, rA, rB), frame.softness);
    } else {
      joint.point.solveRigid(rA, rB, frame, a, b);
    }
  });
}

} // namespace

void solveJoint(RevoluteJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias) {
  if (useBias) {
    solvePass<true>(joint, frame, states, staticIndex, context);
  } else {
    solvePass<false>(joint, frame, states, staticIndex, context);
  }
}

JointReaction jointReaction(const RevoluteJoint& joint, float inverseH) {
  return {joint.point.impulse * inverseH, axialImpulse(joint) * inverseH};
}

} // namespace impetus::rigid2d::detail
