// The distance joint (after Box2D v3's). One row along the axis u = (pB - pA) / |pB - pA|
// between the current world anchors, C = |pB - pA| - L. The joint is
//  - rigid (a rod) without a spring: a row part at `length` (within the limits when they are on),
//    soft at the joint's stiffness with bias and rigid in the relax pass, like the revolute's pin;
//  - otherwise a spring part toward `length` at `hertz` and `dampingRatio` (hertz 0: no spring
//    force at all, so only the limits and the motor act), a motor on the length rate (at most
//    maxMotorForce) and the two one-sided limits, last so that they win: minLength (pushes) and
//    maxLength (pulls). A rope is the spring mode with hertz 0 and the limits [0, L].
// The axis is recomputed from the current anchors at every solve. When the anchors coincide it
// has no direction: the joint then applies nothing (and forgets its impulses) until they part.
#include "rigid2d/distance_joint.hpp"

#include <algorithm>
#include <cmath>

namespace impetus::rigid2d::detail {
namespace {

/// Below this separation (m) the anchors count as coinciding: the axis is undefined.
constexpr float minAxisLength = 1e-5f;

/// The joint's row now and the distance between its anchors (m); no row when they coincide.
struct AxisGeometry {
  JointRow row;
  float length = 0.0f;
  bool defined = false;
};

AxisGeometry currentGeometry(const JointFrame& f, const BodyState& a, const BodyState& b) {
  AxisGeometry g;
  const Vec2f rA = currentAnchor(a, f.frameA);
  const Vec2f rB = currentAnchor(b, f.frameB);
  const Vec2f separation = anchorSeparation(f, a, b, rA, rB);
  g.length = length(separation);
  g.defined = g.length > minAxisLength;
  g.row = linearRow(g.defined ? separation / g.length : Vec2f{}, rA, rB);
  return g;
}

/// A minimum of (about) zero enforces nothing a length could break; acting on it would stop a body
/// passing through the other anchor (a rope's end swinging past its pin).
bool hasLowerLimit(const DistanceJointSettings& def) { return def.enableLimit && def.minLength > linearSlop; }
/// The default infinity: no upper limit.
bool hasUpperLimit(const DistanceJointSettings& def) { return def.enableLimit && std::isfinite(def.maxLength); }

} // namespace

bool isRigid(const DistanceJointSettings& def) {
  return !def.enableSpring || (def.enableLimit && def.minLength >= def.maxLength);
}

void prepareJoint(DistanceJoint& joint, const JointFrame& /*frame*/, const JointPose& /*pose*/,
                  const StepContext& context) {
  const DistanceJointSettings& def = joint.def;
  const bool rigid = isRigid(def);
  joint.spring.prepare(rigid ? 0.0f : def.hertz, def.dampingRatio, context.h);
  // What is switched off holds no impulse (it would be warm started otherwise).
  if (!rigid) {
    joint.rod.impulse = 0.0f;
  }
  if (rigid || !hasLowerLimit(def)) {
    joint.limit.lowerImpulse = 0.0f;
  }
  if (rigid || !hasUpperLimit(def)) {
    joint.limit.upperImpulse = 0.0f;
  }
  if (rigid || !def.enableMotor) {
    joint.motor.impulse = 0.0f;
  }
}

void warmStartJoint(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex) {
  withBodies(frame, states, staticIndex, [&](BodyState& a, BodyState& b) {
    const AxisGeometry g = currentGeometry(frame, a, b);
    joint.rod.warmStart(g.row, frame, a, b);
    joint.spring.warmStart(g.row, frame, a, b);
    joint.motor.warmStart(g.row, frame, a, b);
    joint.limit.warmStart(g.row, frame, a, b);
  });
}

void solveJoint(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias) {
  withBodies(frame, states, staticIndex, [&](BodyState& a, BodyState& b) {
    const DistanceJointSettings& def = joint.def;
    const AxisGeometry g = currentGeometry(frame, a, b);
    joint.axis = g.row.linear;
    if (!g.defined || solver::rowInverseMass(g.row, frame) == 0.0f) {
      // No direction (coinciding anchors) or nothing can move along it: no row to solve.
      joint.rod.impulse = joint.spring.impulse = joint.motor.impulse = 0.0f;
      joint.limit.clear();
      return;
    }
    if (isRigid(def)) {
      const float target = def.enableLimit ? std::clamp(def.length, def.minLength, def.maxLength) : def.length;
      joint.rod.solve(g.row, frame, a, b, g.length - target, rigidRowSoftness(frame, useBias));
      return;
    }
    joint.spring.solve(g.row, frame, a, b, g.length - def.length, useBias);
    if (def.enableMotor) {
      joint.motor.solve(g.row, frame, a, b, def.motorSpeed, context.h * def.maxMotorForce);
    }
    if (hasLowerLimit(def)) {
      joint.limit.solveLower(g.row, frame, a, b, g.length - def.minLength, frame.softness, context.inverseH, useBias);
    }
    if (hasUpperLimit(def)) {
      joint.limit.solveUpper(g.row, frame, a, b, def.maxLength - g.length, frame.softness, context.inverseH, useBias);
    }
  });
}

JointReaction jointReaction(const DistanceJoint& joint, float inverseH) {
  const float axial = joint.rod.impulse + joint.spring.impulse + joint.motor.impulse + joint.limit.lowerImpulse -
                      joint.limit.upperImpulse;
  return {joint.axis * (axial * inverseH), 0.0f};
}

} // namespace impetus::rigid2d::detail
