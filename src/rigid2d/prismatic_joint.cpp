// The prismatic joint in the soft step (after Box2D v3's prismatic joint).
//
// The anchors' separation d = pB - pA is split along the axis (fixed in A) and across it. Across
// it and in angle, a 2-row block keeps B on the line and at the reference angle:
//   C1 = dot(normal, d) = 0, C2 = angleB - angleA - referenceAngle = 0,
// solved with the 2x2 effective mass [[mA + mB + iA s1^2 + iB s2^2, iA s1 + iB s2], [., iA + iB]]
// (s1, s2: the normal impulse's moment arms on A and B), soft at the world's joint stiffness with
// bias and rigid in velocity without. Along the axis, rows on the translation x = dot(axis, d)
// with the axial mass 1 / (mA + mB + iA a1^2 + iB a2^2): a spring (soft, toward x = 0), a motor
// (toward motorSpeed, at most maxMotorForce h per substep) and the two one-sided limits. Since A's
// line turns with A, the moment arms on A are taken about B's anchor (d + rA), not A's.
#include "rigid2d/prismatic_joint.hpp"

#include <algorithm>
#include <cmath>

namespace impetus::rigid2d::detail {

namespace {

float inverseOrZero(float k) { return k > 0.0f ? 1.0f / k : 0.0f; }

} // namespace

float sliderAxialMassNow(const SliderGeometry& g, const JointFrame& f) {
  return inverseOrZero(f.mA + f.mB + f.iA * g.a1 * g.a1 + f.iB * g.a2 * g.a2);
}

float sliderNormalMassNow(const SliderGeometry& g, const JointFrame& f) {
  return inverseOrZero(f.mA + f.mB + f.iA * g.s1 * g.s1 + f.iB * g.s2 * g.s2);
}

SliderGeometry sliderGeometry(const Vec2f& axisAtStart, const JointFrame& f, const BodyState& a, const BodyState& b) {
  SliderGeometry g;
  g.rA = currentAnchor(a, f.frameA);
  g.rB = currentAnchor(b, f.frameB);
  g.d = (b.dp - a.dp) + f.deltaCenter + (g.rB - g.rA);
  g.axis = rotate(a.dq, axisAtStart);
  g.normal = perp(g.axis);
  const Vec2f armA = g.d + g.rA; // from A's centre to B's anchor
  g.a1 = cross(armA, g.axis);
  g.a2 = cross(g.rB, g.axis);
  g.s1 = cross(armA, g.normal);
  g.s2 = cross(g.rB, g.normal);
  return g;
}

float axialSpeed(const SliderGeometry& g, const BodyState& a, const BodyState& b) {
  return dot(g.axis, b.v - a.v) + g.a2 * b.w - g.a1 * a.w;
}

void applyAxial(const SliderGeometry& g, const JointFrame& f, BodyState& a, BodyState& b, float impulse) {
  a.v -= g.axis * (f.mA * impulse);
  a.w -= f.iA * g.a1 * impulse;
  b.v += g.axis * (f.mB * impulse);
  b.w += f.iB * g.a2 * impulse;
}

float sliderAxialMass(const Vec2f& axis, const JointFrame& f) {
  const float a1 = cross(f.deltaCenter + f.frameB, axis); // d + rA = (cB + rB) - cA
  const float a2 = cross(f.frameB, axis);
  const float k = f.mA + f.mB + f.iA * a1 * a1 + f.iB * a2 * a2;
  return k > 0.0f ? 1.0f / k : 0.0f;
}

void solveTranslationLimit(float& accumulated, float c, float direction, const SliderGeometry& g, const JointFrame& f,
                           BodyState& a, BodyState& b, float axialMass, const StepContext& context, bool useBias) {
  const float applied = limitImpulse(accumulated, c, direction * axialSpeed(g, a, b), axialMass, context, useBias);
  applyAxial(g, f, a, b, direction * applied);
}

void prepareJoint(PrismaticJoint& joint, const JointFrame& frame, const StepContext& context) {
  joint.axisA = rotate(frame.qA, joint.def.localAxisA);
  joint.solvedAxis = joint.axisA;
  joint.axialMass = sliderAxialMass(joint.axisA, frame);
  joint.springSoftness = makeSoft(joint.def.hertz, joint.def.dampingRatio, context.h);
  clearSwitchedOffImpulses(joint);
}

void warmStartJoint(PrismaticJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex) {
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  const SliderGeometry g = sliderGeometry(joint.axisA, frame, a, b);
  const float axial = joint.springImpulse + joint.motorImpulse + joint.lowerImpulse - joint.upperImpulse;
  const float normal = joint.impulse.x;
  const float angular = joint.impulse.y;
  const Vec2f p = g.axis * axial + g.normal * normal;
  a.v -= p * frame.mA;
  a.w -= frame.iA * (axial * g.a1 + normal * g.s1 + angular);
  b.v += p * frame.mB;
  b.w += frame.iB * (axial * g.a2 + normal * g.s2 + angular);
  storeVelocity(states, frame.indexA, staticIndex, a);
  storeVelocity(states, frame.indexB, staticIndex, b);
}

void solveJoint(PrismaticJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias) {
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  const PrismaticJointDef& def = joint.def;
  const SliderGeometry g = sliderGeometry(joint.axisA, frame, a, b);
  joint.solvedAxis = g.axis;
  const float translation = dot(g.axis, g.d);
  const bool canSlide = joint.axialMass > 0.0f;
  const float axialMass = sliderAxialMassNow(g, frame);

  if (def.enableSpring && canSlide) {
    // A real spring (force -k x - c xdot with k = axialMass omega^2): applied in the relax pass too.
    const Softness& soft = joint.springSoftness;
    const float impulse = -soft.massScale * joint.axialMass * (axialSpeed(g, a, b) + soft.biasRate * translation) -
                          soft.impulseScale * joint.springImpulse;
    joint.springImpulse += impulse;
    applyAxial(g, frame, a, b, impulse);
  }
  if (def.enableMotor && canSlide) {
    const float maxImpulse = context.h * def.maxMotorForce;
    const float old = joint.motorImpulse;
    joint.motorImpulse = std::clamp(old - axialMass * (axialSpeed(g, a, b) - def.motorSpeed), -maxImpulse, maxImpulse);
    applyAxial(g, frame, a, b, joint.motorImpulse - old);
  }

  // The line and angle block.
  const Vec2f cdot{dot(g.normal, b.v - a.v) + g.s2 * b.w - g.s1 * a.w, b.w - a.w};
  Vec2f bias;
  float massScale = 1.0f;
  float impulseScale = 0.0f;
  if (useBias) {
    constexpr float twoPi = 6.28318530717959f;
    const float angleError = std::remainder(frame.deltaAngle + relativeAngle(b.dq, a.dq) - def.referenceAngle, twoPi);
    bias = Vec2f{dot(g.normal, g.d), angleError} * context.jointSoftness.biasRate;
    massScale = context.jointSoftness.massScale;
    impulseScale = context.jointSoftness.impulseScale;
  }
  const float k11 = frame.mA + frame.mB + frame.iA * g.s1 * g.s1 + frame.iB * g.s2 * g.s2;
  const float k12 = frame.iA * g.s1 + frame.iB * g.s2;
  float k22 = frame.iA + frame.iB;
  if (k22 == 0.0f) {
    k22 = 1.0f; // neither body turns: the angular row is idle, keep K invertible
  }
  const Vec2f solved = solve22(Mat22f{k11, k12, k12, k22}, cdot + bias);
  const Vec2f impulse = solved * -massScale - joint.impulse * impulseScale;
  joint.impulse += impulse;
  const Vec2f p = g.normal * impulse.x;
  a.v -= p * frame.mA;
  a.w -= frame.iA * (impulse.x * g.s1 + impulse.y);
  b.v += p * frame.mB;
  b.w += frame.iB * (impulse.x * g.s2 + impulse.y);

  // The limits last, after the block (Box2D v3 solves them before it): a limit is one-sided and
  // speculative, and a range shorter than a substep's travel has both rows acting in turn; solved
  // before the block they kicked a light body A's spin through the lever arm, the block turned
  // it back, and the warm start of the next substep replayed both (a 5 kg, 10 cm capsule on a
  // 0.76 m wheel, +-5 cm of travel, struck at 80 m/s: 45 times the energy in three steps). After
  // the block, the limit has the last word on the axial speed and the angle row is not undone.
  if (def.enableLimit && canSlide) {
    solveTranslationLimit(joint.lowerImpulse, translation - def.lowerTranslation, 1.0f, g, frame, a, b, axialMass,
                          context, useBias);
    solveTranslationLimit(joint.upperImpulse, def.upperTranslation - translation, -1.0f, g, frame, a, b, axialMass,
                          context, useBias);
  }

  storeVelocity(states, frame.indexA, staticIndex, a);
  storeVelocity(states, frame.indexB, staticIndex, b);
}

JointReaction jointReaction(const PrismaticJoint& joint, const JointFrame&, float inverseH) {
  // Force on B: the normal row along perp(axis) plus every axial row along the axis (the axis as
  // the last solve saw it). Torque: the angular row only (the torque that holds the relative
  // angle; the moments of the forces about B's centre are not included), as for the revolute joint.
  const float axial = joint.springImpulse + joint.motorImpulse + joint.lowerImpulse - joint.upperImpulse;
  const Vec2f force = (perp(joint.solvedAxis) * joint.impulse.x + joint.solvedAxis * axial) * inverseH;
  return {force, joint.impulse.y * inverseH};
}

} // namespace impetus::rigid2d::detail
