// The prismatic joint in the soft step (after Box2D v3's prismatic joint).
//
// The anchors' separation d = pB - pA is split along the axis (fixed in A) and across it. Across
// it and in angle, a 2-row block keeps B on the line and at the reference angle:
//   C1 = dot(normal, d) = 0, C2 = angleB - angleA - referenceAngle = 0,
// solved with the 2x2 effective mass [[mA + mB + iA s1^2 + iB s2^2, iA s1 + iB s2], [., iA + iB]]
// (s1, s2: the normal impulse's moment arms on A and B), rigid in velocity, with the position
// error fed back at the joint stiffness's bias rate in the solve pass. Along the axis, rows on
// the translation x = dot(axis, d) with the axial mass 1 / (mA + mB + iA a1^2 + iB a2^2): a
// spring (soft, toward x = 0), a motor (toward motorSpeed, at most maxMotorForce h per substep)
// and the two one-sided limits, each solved with the block held. Since A's line turns with A,
// the moment arms on A are taken about B's anchor (d + rA), not A's.
//
// Three departures from Box2D v3, for sliders on bodies of little inertia (1 cm discs of several
// kg: inverse inertias 10^3 to 10^4): the block is rigid, the limits hold it, and the end of
// each substep rebases the angular impulse on the moments the bodies got in it. Each is
// explained where it is done (docs/reliability.md tells how they were found). Chains of such
// sliders also need the warm start trimmed: warmStartJoints, joint.cpp.
#include "rigid2d/prismatic_joint.hpp"

#include <algorithm>
#include <cmath>
#include <impetus/math/scalar.hpp>

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
  const float applied = limitImpulse(accumulated, c, direction * axialSpeed(g, a, b), axialMass, f, context, useBias);
  applyAxial(g, f, a, b, direction * applied);
}

namespace {

/// Impulses along the axis, across it and in angle (N s, N s, N m s): -P on A and +P on B at B's
/// anchor, with their moments, plus the angular impulse; their moments about each centre are
/// added to the substep's tally (`torqueOnA`, `torqueOnB`).
void applySlider(PrismaticJoint& joint, const SliderGeometry& g, const JointFrame& f, BodyState& a, BodyState& b,
                 float axial, float normal, float angular) {
  const Vec2f p = g.axis * axial + g.normal * normal;
  const float torqueA = axial * g.a1 + normal * g.s1 + angular;
  const float torqueB = axial * g.a2 + normal * g.s2 + angular;
  a.v -= p * f.mA;
  a.w -= f.iA * torqueA;
  b.v += p * f.mB;
  b.w += f.iB * torqueB;
  joint.torqueOnA += torqueA;
  joint.torqueOnB += torqueB;
}

float accumulatedAxial(const PrismaticJoint& joint) {
  return joint.springImpulse + joint.motorImpulse + joint.lowerImpulse - joint.upperImpulse;
}

/// The line-and-angle block's position error: B's anchor's distance from A's line (m) and the
/// relative angle's (rad).
Vec2f blockError(const PrismaticJoint& joint, const JointFrame& f, const SliderGeometry& g, const BodyState& a,
                 const BodyState& b) {
  constexpr float twoPi = 2.0f * pi<float>;
  const float angleError = std::remainder(f.deltaAngle + relativeAngle(b.dq, a.dq) - joint.def.referenceAngle, twoPi);
  return {dot(g.normal, g.d), angleError};
}

/// The block's 2x2 effective mass matrix (inverse): [[mA + mB + iA s1^2 + iB s2^2, iA s1 + iB s2],
/// [., iA + iB]].
Mat22f blockMass(const SliderGeometry& g, const JointFrame& f) {
  const float k11 = f.mA + f.mB + f.iA * g.s1 * g.s1 + f.iB * g.s2 * g.s2;
  const float k12 = f.iA * g.s1 + f.iB * g.s2;
  float k22 = f.iA + f.iB;
  if (k22 == 0.0f) {
    k22 = 1.0f; // neither body turns: the angular row is idle, keep K invertible
  }
  return {k11, k12, k12, k22};
}

/// One translation limit (as solveTranslationLimit) solved with the line-and-angle block held:
/// the limit's axial impulse comes with the normal and angular impulses that leave the block's
/// velocities as they were. Alone, a limit on a body with little inertia kicks its spin through
/// the smallest lever arm (a 1 cm, 4 kg disc carrying a 1 m rail: an axial impulse 5 cm off the
/// line turns it at thousands of rad/s) and the block, solved next, turns it back, a
/// Gauss-Seidel pair that gains energy each substep. Held, the row's mass
/// is 1 / S with S = K_aa - K_ab K_bb^-1 K_ba, the Schur complement of the block in the joint's
/// 3x3 effective mass K (rows: axial, normal, angle), and the update minimises the kinetic
/// energy along a direction that changes only the limit's speed: it never adds energy in the
/// relax pass. In double: the block is as badly conditioned as iA (x^2 + 1) / (mA + mB), 10^4 to
/// 10^8 in such pairs, and S is the small difference of large terms (in float it came out
/// negative: NaN).
void solveLimitHoldingBlock(PrismaticJoint& joint, float& accumulated, float c, float direction,
                            const SliderGeometry& g, const JointFrame& f, BodyState& a, BodyState& b,
                            const StepContext& context, bool useBias) {
  const double mass = static_cast<double>(f.mA) + f.mB;
  const double iA = f.iA;
  const double iB = f.iB;
  const double a1 = g.a1, a2 = g.a2, s1 = g.s1, s2 = g.s2;
  const double kaa = mass + iA * a1 * a1 + iB * a2 * a2;
  const double kan = iA * a1 * s1 + iB * a2 * s2;
  const double kaw = iA * a1 + iB * a2;
  const double knn = mass + iA * s1 * s1 + iB * s2 * s2;
  const double knw = iA * s1 + iB * s2;
  const double kww = iA + iB > 0.0 ? iA + iB : 1.0; // neither turns: the angle row is idle
  const double det = knn * kww - knw * knw;
  // The block's answer to a unit axial impulse, K_bb^-1 K_ba, and the Schur complement.
  double holdNormal = 0.0;
  double holdAngle = 0.0;
  double schur = kaa;
  if (det > 1e-12 * knn * kww) {
    holdNormal = (kww * kan - knw * kaw) / det;
    holdAngle = (knn * kaw - knw * kan) / det;
    schur = kaa - (kan * holdNormal + kaw * holdAngle);
  }
  if (!(schur > 1e-9 * kaa)) { // rounding: solve the limit alone
    holdNormal = 0.0;
    holdAngle = 0.0;
    schur = kaa;
  }
  if (!(schur > 0.0)) {
    return; // neither body can move along the axis
  }
  const auto rowMass = static_cast<float>(1.0 / schur);
  const float applied = limitImpulse(accumulated, c, direction * axialSpeed(g, a, b), rowMass, f, context, useBias);
  const float axial = direction * applied;
  const auto normal = static_cast<float>(-holdNormal * axial);
  const auto angular = static_cast<float>(-holdAngle * axial);
  joint.impulse += Vec2f{normal, angular};
  applySlider(joint, g, f, a, b, axial, normal, angular);
}

} // namespace

void prepareJoint(PrismaticJoint& joint, const JointFrame& frame, const StepContext& context) {
  joint.axisA = rotate(frame.qA, joint.def.localAxisA);
  joint.solvedAxis = joint.axisA;
  joint.axialMass = sliderAxialMass(joint.axisA, frame);
  joint.springSoftness = makeSoft(joint.def.hertz, joint.def.dampingRatio, context.h);
  clearSwitchedOffImpulses(joint);
}

void warmStartJoint(PrismaticJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex, JointRows rows) {
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  const SliderGeometry g = sliderGeometry(joint.axisA, frame, a, b);
  constexpr JointRows working = JointRows::working;
  constexpr JointRows passive = JointRows::passive;
  const float axial = pick(rows, working, joint.springImpulse) + pick(rows, working, joint.motorImpulse) +
                      pick(rows, passive, joint.lowerImpulse) - pick(rows, passive, joint.upperImpulse);
  const float torqueA = joint.torqueOnA;
  const float torqueB = joint.torqueOnB;
  applySlider(joint, g, frame, a, b, axial, pick(rows, passive, joint.impulse.x), pick(rows, passive, joint.impulse.y));
  if (rows == passive) {
    joint.passiveTorqueOnA = joint.torqueOnA - torqueA;
    joint.passiveTorqueOnB = joint.torqueOnB - torqueB;
  }
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

  if (def.enableSpring && canSlide) {
    // A real spring (force -k x - c xdot with k = axialMass omega^2): applied in the relax pass too.
    const Softness& soft = joint.springSoftness;
    const float impulse = -soft.massScale * joint.axialMass * (axialSpeed(g, a, b) + soft.biasRate * translation) -
                          soft.impulseScale * joint.springImpulse;
    joint.springImpulse += impulse;
    applySlider(joint, g, frame, a, b, impulse, 0.0f, 0.0f);
  }
  if (def.enableMotor && canSlide) {
    const float maxImpulse = context.h * def.maxMotorForce;
    const float old = joint.motorImpulse;
    joint.motorImpulse = std::clamp(old - sliderAxialMassNow(g, frame) * (axialSpeed(g, a, b) - def.motorSpeed),
                                    -maxImpulse, maxImpulse);
    applySlider(joint, g, frame, a, b, joint.motorImpulse - old, 0.0f, 0.0f);
  }

  // The line and angle block: rigid in velocity in both passes, the position error fed back at
  // the joint stiffness's bias rate with bias. Not soft, as Box2D v3's: with a body of little
  // inertia, the soft block (mass scale 0.9 at 60 Hz and 240 substeps a second) left a tenth
  // of the warm start's error in that body's spin, thousands of rad/s, and the positions
  // integrated from it turned it half a turn a substep (NaN within seconds).
  const Vec2f cdot{dot(g.normal, b.v - a.v) + g.s2 * b.w - g.s1 * a.w, b.w - a.w};
  Vec2f bias;
  if (useBias) {
    joint.positionShare = positionShare(substepTurn(a, b, context));
    bias = blockError(joint, frame, g, a, b) * (frame.softness.biasRate * (1.0f - joint.positionShare));
  }
  const Vec2f impulse = -solve22(blockMass(g, frame), cdot + bias);
  joint.impulse += impulse;
  applySlider(joint, g, frame, a, b, 0.0f, impulse.x, impulse.y);

  // The limits last, after the block (Box2D v3 solves them before it), each with the block held
  // (solveLimitHoldingBlock): the limit has the last word on the axial speed and the line and
  // angle stay as the block left them.
  if (def.enableLimit && canSlide) {
    solveLimitHoldingBlock(joint, joint.lowerImpulse, translation - def.lowerTranslation, 1.0f, g, frame, a, b, context,
                           useBias);
    solveLimitHoldingBlock(joint, joint.upperImpulse, def.upperTranslation - translation, -1.0f, g, frame, a, b,
                           context, useBias);
  }

  storeVelocity(states, frame.indexA, staticIndex, a);
  storeVelocity(states, frame.indexB, staticIndex, b);
}

void correctJointPosition(PrismaticJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                          std::uint32_t staticIndex, const StepContext& /*context*/) {
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  if (joint.positionShare > 0.0f) {
    const SliderGeometry g = sliderGeometry(joint.axisA, frame, a, b);
    const Vec2f impulse = solve22(blockMass(g, frame), blockError(joint, frame, g, a, b)) *
                          -(joint.positionShare * frame.positionCorrection);
    applyPositionCorrection(frame, a, b, g.normal * impulse.x, impulse.x * g.s1 + impulse.y,
                            impulse.x * g.s2 + impulse.y);
    storePose(states, frame.indexA, staticIndex, a);
    storePose(states, frame.indexB, staticIndex, b);
  }

  // The substep is over: the accumulated impulses are what the next warm start applies, in this
  // geometry (nothing moves before it). The angular impulse is rebased on the moments the bodies
  // got over this substep. Kept as accumulated, it would not give them again: the normal
  // impulse's moment arm on A, cross(d + rA, normal), grows with the translation, so as B slides
  // the stored normal and angular impulses no longer cancel on A, and a 5 mm, 7 kg disc carrying
  // the line (inverse inertia 10^4) was warm started at 5 x 10^5 rad/s every substep, held by the
  // runaway clamp, its angular momentum lost and the pair's energy growing tenfold. Each body's
  // moment wants its own angular impulse; weighted by the inverse inertias, the warm start gives
  // the bodies the relative spin the substep gave them.
  const SliderGeometry g = sliderGeometry(joint.axisA, frame, a, b);
  const float axial = accumulatedAxial(joint);
  const float angularForA = joint.torqueOnA - (axial * g.a1 + joint.impulse.x * g.s1);
  const float angularForB = joint.torqueOnB - (axial * g.a2 + joint.impulse.x * g.s2);
  const float inverseInertia = frame.iA + frame.iB;
  if (inverseInertia > 0.0f) {
    joint.impulse.y = (frame.iA * angularForA + frame.iB * angularForB) / inverseInertia;
  }
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
