// The prismatic joint (after Box2D v3's). The anchors' separation d = pB - pA is split along the
// axis (fixed in A) and across it. Along it, on the translation x = dot(axis, d): a spring toward
// x = 0, a motor toward motorSpeed (at most maxMotorForce) and the two one-sided limits. Across
// it and in angle, a block part keeps B on the line and at the reference angle,
//   C1 = dot(normal, d) = 0, C2 = angleB - angleA - referenceAngle = 0,
// two coupled rows solved together, soft at the joint's stiffness with bias and rigid in the
// relax pass; last, because it matters most.
#include "rigid2d/prismatic_joint.hpp"

#include <impetus/math/scalar.hpp>

#include <cmath>

namespace impetus::rigid2d::detail {

SliderGeometry sliderGeometry(const Vec2f& axisAtStart, const JointFrame& f, const BodyState& a, const BodyState& b) {
  SliderGeometry g;
  g.rA = currentAnchor(a, f.frameA);
  g.rB = currentAnchor(b, f.frameB);
  g.d = anchorSeparation(f, a, b, g.rA, g.rB);
  g.axis = rotate(a.dq, axisAtStart);
  g.normal = perp(g.axis);
  return g;
}

namespace {

/// The line-and-angle block's rows and their position errors: B's anchor's distance from A's
/// line (m) and the relative angle's (rad).
RowPair blockRows(const SliderGeometry& g) { return {g.normalRow(), angleJointRow()}; }

std::array<float, 2> blockError(const PrismaticJoint& joint, const JointFrame& f, const SliderGeometry& g,
                                const BodyState& a, const BodyState& b) {
  const float angleError = unwindAngle(f.deltaAngle + relativeAngle(b.dq, a.dq) - joint.def.referenceAngle);
  return {dot(g.normal, g.d), angleError};
}

} // namespace

void prepareJoint(PrismaticJoint& joint, const JointFrame& /*frame*/, const JointPose& pose,
                  const StepContext& context) {
  joint.axisA = rotate(pose.qA, joint.def.localAxisA);
  joint.solvedAxis = joint.axisA;
  joint.spring.prepare(joint.def.enableSpring ? joint.def.hertz : 0.0f, joint.def.dampingRatio, context.h);
  clearSwitchedOffImpulses(joint);
}

void warmStartJoint(PrismaticJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex) {
  withBodies(frame, states, staticIndex, [&](BodyState& a, BodyState& b) {
    const SliderGeometry g = sliderGeometry(joint.axisA, frame, a, b);
    const JointRow axial = g.axialRow();
    joint.spring.warmStart(axial, frame, a, b);
    joint.motor.warmStart(axial, frame, a, b);
    joint.limit.warmStart(axial, frame, a, b);
    joint.block.warmStart(blockRows(g), frame, a, b);
  });
}

void solveJoint(PrismaticJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias) {
  withBodies(frame, states, staticIndex, [&](BodyState& a, BodyState& b) {
    const PrismaticJointSettings& def = joint.def;
    const SliderGeometry g = sliderGeometry(joint.axisA, frame, a, b);
    joint.solvedAxis = g.axis;
    const JointRow axial = g.axialRow();
    const float translation = g.translation();
    joint.spring.solve(axial, frame, a, b, translation, useBias);
    if (def.enableMotor) {
      joint.motor.solve(axial, frame, a, b, def.motorSpeed, context.h * def.maxMotorForce);
    }
    if (def.enableLimit) {
      joint.limit.solve(axial, frame, a, b, translation, def.lowerTranslation, def.upperTranslation, frame.softness,
                        context.inverseH, useBias);
    }
    joint.block.solve(blockRows(g), frame, a, b, blockError(joint, frame, g, a, b), rigidRowSoftness(frame, useBias));
  });
}

JointReaction jointReaction(const PrismaticJoint& joint, float inverseH) {
  // Force on B: the normal row along perp(axis) plus every axial row along the axis (the axis as
  // the last solve saw it). Torque: the angular row only (the torque that holds the relative
  // angle; the moments of the forces about B's centre are not included), as for the revolute joint.
  const float axial = joint.spring.impulse + joint.motor.impulse + joint.limit.lowerImpulse - joint.limit.upperImpulse;
  const Vec2f force = (perp(joint.solvedAxis) * joint.block.impulse[0] + joint.solvedAxis * axial) * inverseH;
  return {force, joint.block.impulse[1] * inverseH};
}

} // namespace impetus::rigid2d::detail
