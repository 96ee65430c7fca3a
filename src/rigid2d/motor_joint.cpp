// The motor joint in the soft step (after Box2D v3's motor joint).
//
// Two velocity drives with bounded impulses, not rigid constraints: B's origin is driven toward
// the target point T = A's origin + linearOffset (a point fixed in A, so the target turns with
// A), and B's angle toward angleA + angularOffset. Each substep the target velocity closes
// `correctionFactor` of the current error: Cdot_target = -correctionFactor * C / h. The linear
// drive is a 2-row block (effective mass K at the anchors T on A and B's origin on B) whose
// accumulated impulse is clamped to a disc of radius maxForce h (so the force on B is at most
// maxForce in any direction); the angular drive acts on the relative spin with the axial mass
// 1 / (1/IA + 1/IB) and its accumulated impulse is clamped to maxTorque h.
//
// The drives use their bias in both the solve and the relax pass (as Box2D v3 does): the
// velocity toward the target is the motor's purpose, not a position correction to be relaxed
// away, and the clamps keep it from adding more than maxForce / maxTorque of push.
//
// Top-down friction: set the offsets to B's current pose relative to A every step; the target
// velocity is then zero and the drives act as dry friction of at most maxForce / maxTorque.
#include "rigid2d/motor_joint.hpp"

#include <algorithm>
#include <cmath>
#include <impetus/math/scalar.hpp>

namespace impetus::rigid2d::detail {

void prepareJoint(MotorJoint& joint, const JointFrame& frame, const JointPose& pose, const StepContext&) {
  const MotorJointSettings& def = joint.def;
  // The origins relative to the centres of mass, world axes: origin - c = -R(q) localCenter.
  const Vec2f originA = -rotate(pose.qA, pose.localCenterA);
  joint.originB = -rotate(pose.qB, pose.localCenterB);
  joint.targetA = originA + rotate(pose.qA, def.linearOffset);
  joint.angleError = unwindAngle(frame.deltaAngle - def.angularOffset);
  joint.linear.prepare(joint.targetA, joint.originB, frame);
}

void warmStartJoint(MotorJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex) {
  withBodies(frame, states, staticIndex, [&](BodyState& a, BodyState& b) {
    joint.angular.warmStart(angleRow(), frame, a, b);
    joint.linear.warmStart(currentAnchor(a, joint.targetA), currentAnchor(b, joint.originB), frame, a, b);
  });
}

void solveJoint(MotorJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool) {
  withBodies(frame, states, staticIndex, [&](BodyState& a, BodyState& b) {
    const MotorJointSettings& def = joint.def;
    const float rate = def.correctionFactor * context.inverseH; // 1/s: fraction of the error closed per second

    // Angular drive first (the linear one, with the larger effect on the motion, last).
    const float angleError = unwindAngle(joint.angleError + relativeAngle(b.dq, a.dq)); // rad
    joint.angular.solve(angleRow(), frame, a, b, -rate * angleError, def.maxTorque * context.h);

    // Linear drive: C = B's origin - T, both moved by this step's deltas so far; the force is
    // bounded in magnitude, whatever its direction.
    const Vec2f rA = currentAnchor(a, joint.targetA);
    const Vec2f rB = currentAnchor(b, joint.originB);
    const Vec2f c = anchorSeparation(frame, a, b, rA, rB); // m
    joint.linear.solve(rA, rB, frame, a, b, c, Softness{rate, 1.0f, 0.0f}, def.maxForce * context.h);
  });
}

JointReaction jointReaction(const MotorJoint& joint, float inverseH) {
  return {joint.linear.impulse * inverseH, joint.angular.impulse * inverseH};
}

} // namespace impetus::rigid2d::detail
