// The wheel joint (after Box2D v3's). B's anchor (the wheel's hub) slides on a line fixed in A
// (the chassis) as in the prismatic joint, but B turns freely. Parts, in order: the motor on the
// relative spin wB - wA (at most maxMotorTorque); the suspension spring on the translation
// x = dot(axis, d) toward x = 0 (its stiffness k = m (2 pi hertz)^2 for the axial effective
// mass m); the two one-sided translation limits; and last the point-on-line row
// C = dot(normal, d) = 0 (soft at the joint's stiffness with bias, rigid without). Without the
// spring the wheel slides freely along the axis (between the limits, if any).
#include "rigid2d/wheel_joint.hpp"

namespace impetus::rigid2d::detail {

void prepareJoint(WheelJoint& joint, const JointFrame& /*frame*/, const JointPose& pose, const StepContext& context) {
  joint.axisA = rotate(pose.qA, joint.def.localAxisA);
  joint.solvedAxis = joint.axisA;
  joint.spring.prepare(joint.def.enableSpring ? joint.def.hertz : 0.0f, joint.def.dampingRatio, context.h);
  clearSwitchedOffImpulses(joint);
}

void warmStartJoint(WheelJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex) {
  withBodies(frame, states, staticIndex, [&](BodyState& a, BodyState& b) {
    const SliderGeometry g = sliderGeometry(joint.axisA, frame, a, b);
    const JointRow axial = g.axialRow();
    joint.motor.warmStart(angleRow(), frame, a, b);
    joint.spring.warmStart(axial, frame, a, b);
    joint.limit.warmStart(axial, frame, a, b);
    joint.line.warmStart(g.normalRow(), frame, a, b);
  });
}

void solveJoint(WheelJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool useBias) {
  withBodies(frame, states, staticIndex, [&](BodyState& a, BodyState& b) {
    const WheelJointSettings& def = joint.def;
    if (def.enableMotor) {
      joint.motor.solve(angleRow(), frame, a, b, def.motorSpeed, context.h * def.maxMotorTorque);
    }
    const SliderGeometry g = sliderGeometry(joint.axisA, frame, a, b);
    joint.solvedAxis = g.axis;
    const JointRow axial = g.axialRow();
    joint.spring.solve(axial, frame, a, b, g.translation(), useBias);
    if (def.enableLimit) {
      joint.limit.solve(axial, frame, a, b, g.translation(), def.lowerTranslation, def.upperTranslation, frame.softness,
                        context.inverseH, useBias);
    }
    joint.line.solve(g.normalRow(), frame, a, b, dot(g.normal, g.d), rigidRowSoftness(frame, useBias));
  });
}

JointReaction jointReaction(const WheelJoint& joint, float inverseH) {
  // Force on B: the line row along perp(axis) plus the suspension and limits along the axis (the
  // axis as the last solve saw it). Torque: the motor's (the free spin transmits nothing else).
  const float axial = joint.spring.impulse + joint.limit.lowerImpulse - joint.limit.upperImpulse;
  const Vec2f force = (perp(joint.solvedAxis) * joint.line.impulse + joint.solvedAxis * axial) * inverseH;
  return {force, joint.motor.impulse * inverseH};
}

} // namespace impetus::rigid2d::detail
