// The weld joint in the soft step (after Box2D v3's weld joint).
//
// Three rows: the angular one, C = angleB - angleA - referenceAngle = 0 on the relative spin
// wB - wA with the axial mass 1 / (1/IA + 1/IB), then the point constraint
// C = (cB + rB) - (cA + rA) = 0 as a 2x2 block with the effective mass K, last because it matters
// most. Each part is rigid at hertz 0: soft at the world's joint stiffness with bias and plain in
// the relax pass, like the revolute's pin. With hertz > 0 it is a spring of that frequency and
// damping ratio, in both passes (its softness is the physics asked for, not error correction).
// Solving the rows one after the other instead of as a 3x3 block lets a long welded chain sag a
// little (each joint is as stiff as the world's joint hertz); Box2D v3 makes the same trade.
#include "rigid2d/weld_joint.hpp"

#include <cmath>
#include <impetus/math/scalar.hpp>

namespace impetus::rigid2d::detail {

void prepareJoint(WeldJoint& joint, const JointFrame& frame, const StepContext& context) {
  const float k = frame.iA + frame.iB;
  joint.axialMass = k > 0.0f ? 1.0f / k : 0.0f;
  constexpr float twoPi = 2.0f * pi<float>;
  joint.startAngle = unwindAngle(std::remainder(frame.deltaAngle - joint.def.referenceAngle, twoPi));
  joint.linearSoftness = joint.def.linearHertz == 0.0f
                             ? frame.softness
                             : makeSoft(joint.def.linearHertz, joint.def.linearDampingRatio, context.h);
  joint.angularSoftness = joint.def.angularHertz == 0.0f
                              ? frame.softness
                              : makeSoft(joint.def.angularHertz, joint.def.angularDampingRatio, context.h);
}

void warmStartJoint(WeldJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex, JointRows rows) {
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  const Vec2f rA = currentAnchor(a, frame.frameA);
  const Vec2f rB = currentAnchor(b, frame.frameB);
  const Vec2f p = includes(rows, linearRows(joint)) ? joint.linearImpulse : Vec2f{};
  const float angular = pick(rows, angularRows(joint), joint.angularImpulse);
  a.v -= p * frame.mA;
  a.w -= frame.iA * (cross(rA, p) + angular);
  b.v += p * frame.mB;
  b.w += frame.iB * (cross(rB, p) + angular);
  storeVelocity(states, frame.indexA, staticIndex, a);
  storeVelocity(states, frame.indexB, staticIndex, b);
}

void solveJoint(WeldJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool useBias) {
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  if (useBias) {
    joint.positionShare = positionShare(substepTurn(a, b, context));
  }
  // The share of a rigid part's bias left to the position correction (a spring keeps its own).
  const float angularBiasScale = joint.def.angularHertz > 0.0f ? 1.0f : 1.0f - joint.positionShare;
  const float linearBiasScale = joint.def.linearHertz > 0.0f ? 1.0f : 1.0f - joint.positionShare;

  // The angular row (skipped when neither body can turn: two fixed-rotation bodies).
  if (joint.axialMass > 0.0f) {
    float bias = 0.0f;
    float massScale = 1.0f;
    float impulseScale = 0.0f;
    if (useBias || joint.def.angularHertz > 0.0f) {
      const float c = unwindAngle(joint.startAngle + relativeAngle(b.dq, a.dq));
      bias = joint.angularSoftness.biasRate * angularBiasScale * c;
      massScale = joint.angularSoftness.massScale;
      impulseScale = joint.angularSoftness.impulseScale;
    }
    const float impulse = -massScale * joint.axialMass * (b.w - a.w + bias) - impulseScale * joint.angularImpulse;
    joint.angularImpulse += impulse;
    a.w -= frame.iA * impulse;
    b.w += frame.iB * impulse;
  }

  // The point constraint, last.
  solvePointConstraint(joint.linearImpulse, frame, a, b, joint.linearSoftness, useBias || joint.def.linearHertz > 0.0f,
                       linearBiasScale);

  storeVelocity(states, frame.indexA, staticIndex, a);
  storeVelocity(states, frame.indexB, staticIndex, b);
}

void correctJointPosition(WeldJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                          std::uint32_t staticIndex, const StepContext& /*context*/) {
  if (joint.positionShare == 0.0f) {
    return;
  }
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  const float fraction = joint.positionShare * frame.positionCorrection;
  if (joint.def.angularHertz == 0.0f && joint.axialMass > 0.0f) {
    const float c = unwindAngle(joint.startAngle + relativeAngle(b.dq, a.dq));
    const float impulse = -joint.axialMass * fraction * c;
    applyPositionCorrection(frame, a, b, {}, impulse, impulse);
  }
  if (joint.def.linearHertz == 0.0f) {
    correctPointPosition(frame, a, b, fraction);
  }
  storePose(states, frame.indexA, staticIndex, a);
  storePose(states, frame.indexB, staticIndex, b);
}

JointReaction jointReaction(const WeldJoint& joint, const JointFrame&, float inverseH) {
  return {joint.linearImpulse * inverseH, joint.angularImpulse * inverseH};
}

} // namespace impetus::rigid2d::detail
