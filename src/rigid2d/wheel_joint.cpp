// The wheel joint in the soft step (after Box2D v3's wheel joint).
//
// B's anchor (the wheel's hub) slides on a line fixed in A (the chassis) as in the prismatic
// joint, but B turns freely. Rows, in order: the motor on the relative spin wB - wA (mass
// 1 / (iA + iB), at most maxMotorTorque h per substep); the suspension spring on the translation
// x = dot(axis, d) toward x = 0 (soft at hertz and dampingRatio with the axial mass
// 1 / (mA + mB + iA a1^2 + iB a2^2), so its stiffness is k = axialMass (2 pi hertz)^2); the two
// one-sided translation limits; and last the point-on-line row C = dot(normal, d) = 0 (soft at the
// world's joint stiffness with bias, rigid in velocity without). Without the spring the wheel
// slides freely along the axis (between the limits, if any).
#include "rigid2d/wheel_joint.hpp"

#include <algorithm>

namespace impetus::rigid2d::detail {

void prepareJoint(WheelJoint& joint, const JointFrame& frame, const StepContext& context) {
  joint.axisA = rotate(frame.qA, joint.def.localAxisA);
  joint.solvedAxis = joint.axisA;
  joint.axialMass = sliderAxialMass(joint.axisA, frame);
  const float km = frame.iA + frame.iB;
  joint.motorMass = km > 0.0f ? 1.0f / km : 0.0f;
  joint.springSoftness = makeSoft(joint.def.hertz, joint.def.dampingRatio, context.h);
  clearSwitchedOffImpulses(joint);
}

void warmStartJoint(WheelJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex, JointRows rows) {
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  const SliderGeometry g = sliderGeometry(joint.axisA, frame, a, b);
  constexpr JointRows working = JointRows::working;
  constexpr JointRows passive = JointRows::passive;
  const float axial = pick(rows, working, joint.springImpulse) + pick(rows, passive, joint.lowerImpulse) -
                      pick(rows, passive, joint.upperImpulse);
  const float perp = pick(rows, passive, joint.perpImpulse);
  const float motor = pick(rows, working, joint.motorImpulse);
  const Vec2f p = g.axis * axial + g.normal * perp;
  a.v -= p * frame.mA;
  a.w -= frame.iA * (axial * g.a1 + perp * g.s1 + motor);
  b.v += p * frame.mB;
  b.w += frame.iB * (axial * g.a2 + perp * g.s2 + motor);
  storeVelocity(states, frame.indexA, staticIndex, a);
  storeVelocity(states, frame.indexB, staticIndex, b);
}

void solveJoint(WheelJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool useBias) {
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  const WheelJointDef& def = joint.def;
  const SliderGeometry g = sliderGeometry(joint.axisA, frame, a, b);
  joint.solvedAxis = g.axis;
  const float translation = dot(g.axis, g.d);
  const bool canSlide = joint.axialMass > 0.0f;
  const float axialMass = sliderAxialMassNow(g, frame);

  if (def.enableMotor && joint.motorMass > 0.0f) {
    const float maxImpulse = context.h * def.maxMotorTorque;
    const float old = joint.motorImpulse;
    joint.motorImpulse = std::clamp(old - joint.motorMass * (b.w - a.w - def.motorSpeed), -maxImpulse, maxImpulse);
    const float impulse = joint.motorImpulse - old;
    a.w -= frame.iA * impulse;
    b.w += frame.iB * impulse;
  }
  if (def.enableSpring && canSlide) {
    // A real spring (the suspension): applied in the relax pass too.
    const Softness& soft = joint.springSoftness;
    const float impulse = -soft.massScale * joint.axialMass * (axialSpeed(g, a, b) + soft.biasRate * translation) -
                          soft.impulseScale * joint.springImpulse;
    joint.springImpulse += impulse;
    applyAxial(g, frame, a, b, impulse);
  }
  if (def.enableLimit && canSlide) {
    solveTranslationLimit(joint.lowerImpulse, translation - def.lowerTranslation, 1.0f, g, frame, a, b, axialMass,
                          context, useBias);
    solveTranslationLimit(joint.upperImpulse, def.upperTranslation - translation, -1.0f, g, frame, a, b, axialMass,
                          context, useBias);
  }

  // The hub on the line, last: it matters most.
  float bias = 0.0f;
  float massScale = 1.0f;
  float impulseScale = 0.0f;
  if (useBias) {
    joint.positionShare = positionShare(substepTurn(a, b, context));
    bias = frame.softness.biasRate * (1.0f - joint.positionShare) * dot(g.normal, g.d);
    massScale = frame.softness.massScale;
    impulseScale = frame.softness.impulseScale;
  }
  const float cdot = dot(g.normal, b.v - a.v) + g.s2 * b.w - g.s1 * a.w;
  const float impulse = -massScale * sliderNormalMassNow(g, frame) * (cdot + bias) - impulseScale * joint.perpImpulse;
  joint.perpImpulse += impulse;
  const Vec2f p = g.normal * impulse;
  a.v -= p * frame.mA;
  a.w -= frame.iA * g.s1 * impulse;
  b.v += p * frame.mB;
  b.w += frame.iB * g.s2 * impulse;

  storeVelocity(states, frame.indexA, staticIndex, a);
  storeVelocity(states, frame.indexB, staticIndex, b);
}

void correctJointPosition(WheelJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                          std::uint32_t staticIndex, const StepContext& /*context*/) {
  if (joint.positionShare == 0.0f) {
    return;
  }
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  const SliderGeometry g = sliderGeometry(joint.axisA, frame, a, b);
  const float impulse =
      -sliderNormalMassNow(g, frame) * joint.positionShare * frame.positionCorrection * dot(g.normal, g.d);
  applyPositionCorrection(frame, a, b, g.normal * impulse, g.s1 * impulse, g.s2 * impulse);
  storePose(states, frame.indexA, staticIndex, a);
  storePose(states, frame.indexB, staticIndex, b);
}

JointReaction jointReaction(const WheelJoint& joint, const JointFrame&, float inverseH) {
  // Force on B: the line row along perp(axis) plus the suspension and limits along the axis (the
  // axis as the last solve saw it). Torque: the motor's (the free spin transmits nothing else).
  const float axial = joint.springImpulse + joint.lowerImpulse - joint.upperImpulse;
  const Vec2f force = (perp(joint.solvedAxis) * joint.perpImpulse + joint.solvedAxis * axial) * inverseH;
  return {force, joint.motorImpulse * inverseH};
}

} // namespace impetus::rigid2d::detail
