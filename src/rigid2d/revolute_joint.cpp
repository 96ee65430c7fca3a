// The revolute joint in the soft step (after Box2D v3's revolute joint).
//
// Point constraint: C = (cB + rB) - (cA + rA) = 0, two rows solved as a block with the 2x2
// effective mass K; with bias it is soft at the world's joint stiffness, so a joint pulled apart
// returns without overshoot. Angular rows act on the relative spin wB - wA with the axial mass
// 1 / (1/IA + 1/IB): a torsional spring (soft, toward joint angle 0), a motor (toward motorSpeed,
// clamped to maxMotorTorque h per substep), friction (toward zero relative spin, clamped to
// frictionTorque h) and the two one-sided limits (speculative when inside, soft when violated).
#include "rigid2d/revolute_joint.hpp"

#include <algorithm>
#include <cmath>
#include <impetus/math/scalar.hpp>

namespace impetus::rigid2d::detail {
namespace {

/// The joint angle now (angleB - angleA - referenceAngle, in (-pi, pi]): at the step's start plus
/// what the bodies turned since.
float jointAngle(const RevoluteJoint& joint, const BodyState& a, const BodyState& b) {
  return unwindAngle(joint.angleAtStart + relativeAngle(b.dq, a.dq));
}

/// An angular impulse on the relative spin: -impulse on A, +impulse on B.
void applyAngular(BodyState& a, BodyState& b, const JointFrame& f, float impulse) {
  a.w -= f.iA * impulse;
  b.w += f.iB * impulse;
}

/// A one-sided angular limit on C (+1: lower, C = angle - lower; -1: upper, C = upper - angle).
void solveLimit(float& accumulated, float c, float direction, BodyState& a, BodyState& b, const JointFrame& f,
                float axialMass, const StepContext& context, bool useBias) {
  const float applied = limitImpulse(accumulated, c, direction * (b.w - a.w), axialMass, f, context, useBias);
  applyAngular(a, b, f, direction * applied);
}

} // namespace

void prepareJoint(RevoluteJoint& joint, const JointFrame& frame, const StepContext& context) {
  const float k = frame.iA + frame.iB;
  joint.axialMass = k > 0.0f ? 1.0f / k : 0.0f;
  joint.angleAtStart = static_cast<float>(
      std::remainder(static_cast<double>(frame.deltaAngle) - joint.def.referenceAngle, 2.0 * pi<double>));
  joint.springSoftness = makeSoft(joint.def.hertz, joint.def.dampingRatio, context.h);
  clearSwitchedOffImpulses(joint);
  if (joint.def.frictionTorque == 0.0f) {
    joint.frictionImpulse = 0.0f;
  }
}

void warmStartJoint(RevoluteJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex, JointRows rows) {
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  const Vec2f rA = currentAnchor(a, frame.frameA);
  const Vec2f rB = currentAnchor(b, frame.frameB);
  constexpr JointRows working = JointRows::working;
  constexpr JointRows passive = JointRows::passive;
  const float axial = pick(rows, working, joint.springImpulse) + pick(rows, working, joint.motorImpulse) +
                      pick(rows, passive, joint.frictionImpulse) + pick(rows, passive, joint.lowerImpulse) -
                      pick(rows, passive, joint.upperImpulse);
  const Vec2f p = includes(rows, passive) ? joint.linearImpulse : Vec2f{};
  a.v -= p * frame.mA;
  a.w -= frame.iA * (cross(rA, p) + axial);
  b.v += p * frame.mB;
  b.w += frame.iB * (cross(rB, p) + axial);
  storeVelocity(states, frame.indexA, staticIndex, a);
  storeVelocity(states, frame.indexB, staticIndex, b);
}

void solveJoint(RevoluteJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias) {
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  const RevoluteJointDef& def = joint.def;
  const bool canTurn = joint.axialMass > 0.0f;

  if (def.enableSpring && canTurn) {
    const float c = jointAngle(joint, a, b);
    const Softness& soft = joint.springSoftness;
    const float impulse =
        -soft.massScale * joint.axialMass * (b.w - a.w + soft.biasRate * c) - soft.impulseScale * joint.springImpulse;
    joint.springImpulse += impulse;
    applyAngular(a, b, frame, impulse);
  }
  if (def.enableMotor && canTurn) {
    const float maxImpulse = context.h * def.maxMotorTorque;
    const float old = joint.motorImpulse;
    joint.motorImpulse = std::clamp(old - joint.axialMass * (b.w - a.w - def.motorSpeed), -maxImpulse, maxImpulse);
    applyAngular(a, b, frame, joint.motorImpulse - old);
  }
  if (def.frictionTorque > 0.0f && canTurn) {
    const float maxImpulse = context.h * def.frictionTorque;
    const float old = joint.frictionImpulse;
    joint.frictionImpulse = std::clamp(old - joint.axialMass * (b.w - a.w), -maxImpulse, maxImpulse);
    applyAngular(a, b, frame, joint.frictionImpulse - old);
  }
  if (def.enableLimit && canTurn) {
    const float angle = jointAngle(joint, a, b);
    solveLimit(joint.lowerImpulse, angle - def.lowerAngle, 1.0f, a, b, frame, joint.axialMass, context, useBias);
    solveLimit(joint.upperImpulse, def.upperAngle - angle, -1.0f, a, b, frame, joint.axialMass, context, useBias);
  }

  // The point constraint, last: it matters most.
  if (useBias) {
    joint.positionShare = positionShare(substepTurn(a, b, context));
  }
  solvePointConstraint(joint.linearImpulse, frame, a, b, frame.softness, useBias, 1.0f - joint.positionShare);

  storeVelocity(states, frame.indexA, staticIndex, a);
  storeVelocity(states, frame.indexB, staticIndex, b);
}

void correctJointPosition(RevoluteJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                          std::uint32_t staticIndex, const StepContext& /*context*/) {
  if (joint.positionShare == 0.0f) {
    return;
  }
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  correctPointPosition(frame, a, b, joint.positionShare * frame.positionCorrection);
  storePose(states, frame.indexA, staticIndex, a);
  storePose(states, frame.indexB, staticIndex, b);
}

JointReaction jointReaction(const RevoluteJoint& joint, const JointFrame&, float inverseH) {
  const float axial =
      joint.springImpulse + joint.motorImpulse + joint.frictionImpulse + joint.lowerImpulse - joint.upperImpulse;
  return {joint.linearImpulse * inverseH, axial * inverseH};
}

} // namespace impetus::rigid2d::detail
