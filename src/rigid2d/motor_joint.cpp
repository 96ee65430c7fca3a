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
namespace {

/// Applies the linear impulse p on B at rB (and -p on A at rA) and the angular impulse `axial`.
void applyImpulses(BodyState& a, BodyState& b, const JointFrame& f, const Vec2f& rA, const Vec2f& rB, const Vec2f& p,
                   float axial) {
  a.v -= p * f.mA;
  a.w -= f.iA * (cross(rA, p) + axial);
  b.v += p * f.mB;
  b.w += f.iB * (cross(rB, p) + axial);
}

} // namespace

void prepareJoint(MotorJoint& joint, const JointFrame& frame, const StepContext&) {
  const MotorJointDef& def = joint.def;
  // The origins relative to the centres of mass, world axes: origin - c = -R(q) localCenter.
  const Vec2f originA = -rotate(frame.qA, frame.localCenterA);
  joint.originB = -rotate(frame.qB, frame.localCenterB);
  joint.targetA = originA + rotate(frame.qA, def.linearOffset);
  constexpr float twoPi = 2.0f * pi<float>;
  joint.angleError = std::remainder(frame.deltaAngle - def.angularOffset, twoPi);
  const float k = frame.iA + frame.iB;
  joint.angularMass = k > 0.0f ? 1.0f / k : 0.0f;
  if (joint.angularMass == 0.0f) {
    joint.angularImpulse = 0.0f;
  }
}

void warmStartJoint(MotorJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex, JointRows rows) {
  if (!includes(rows, JointRows::working)) {
    return;
  }
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  applyImpulses(a, b, frame, currentAnchor(a, joint.targetA), currentAnchor(b, joint.originB), joint.linearImpulse,
                joint.angularImpulse);
  storeVelocity(states, frame.indexA, staticIndex, a);
  storeVelocity(states, frame.indexB, staticIndex, b);
}

void solveJoint(MotorJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool) {
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  const MotorJointDef& def = joint.def;
  const float rate = def.correctionFactor * context.inverseH; // 1/s: fraction of the error closed per second

  // Angular drive first (the linear one, with the larger effect on the motion, last).
  if (joint.angularMass > 0.0f) {
    const float c = unwindAngle(joint.angleError + relativeAngle(b.dq, a.dq)); // rad
    const float maxImpulse = def.maxTorque * context.h;
    const float old = joint.angularImpulse;
    joint.angularImpulse = std::clamp(old - joint.angularMass * (b.w - a.w + rate * c), -maxImpulse, maxImpulse);
    const float impulse = joint.angularImpulse - old;
    a.w -= frame.iA * impulse;
    b.w += frame.iB * impulse;
  }

  // Linear drive: C = B's origin - T, both moved by this step's deltas so far.
  const Vec2f rA = currentAnchor(a, joint.targetA);
  const Vec2f rB = currentAnchor(b, joint.originB);
  const Vec2f c = (b.dp - a.dp) + (rB - rA) + frame.deltaCenter; // m
  const Vec2f cdot = (b.v + cross(b.w, rB)) - (a.v + cross(a.w, rA));
  const Vec2f old = joint.linearImpulse;
  joint.linearImpulse = old - solve22(pointMass(frame, rA, rB), cdot + c * rate);
  // The force is bounded in magnitude, whatever its direction: clamp to a disc.
  const float maxImpulse = def.maxForce * context.h;
  const float magnitude = length(joint.linearImpulse);
  if (magnitude > maxImpulse) {
    joint.linearImpulse = joint.linearImpulse * (maxImpulse / magnitude);
  }
  applyImpulses(a, b, frame, rA, rB, joint.linearImpulse - old, 0.0f);

  storeVelocity(states, frame.indexA, staticIndex, a);
  storeVelocity(states, frame.indexB, staticIndex, b);
}

JointReaction jointReaction(const MotorJoint& joint, const JointFrame&, float inverseH) {
  return {joint.linearImpulse * inverseH, joint.angularImpulse * inverseH};
}

} // namespace impetus::rigid2d::detail
