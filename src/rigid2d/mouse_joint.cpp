// The mouse joint in the soft step (after Box2D v3's mouse joint).
//
// A soft point constraint between the anchor of B (localAnchorB) and a fixed world point, the
// target: C = cB + rB - target, two rows solved as a block with the 2x2 effective mass K of
// B alone (body A is the world: the joint's frame gives it the static state). The spring is
// makeSoft(hertz, dampingRatio): a spring-damper whose frequency and damping ratio hold for the
// effective mass, whatever the body weighs; zero hertz makes it rigid (held at the world's
// joint stiffness, like the other joints' hard rows). The accumulated impulse is clamped to a
// disc of radius maxForce h, so the pull never exceeds maxForce: a light body follows the
// cursor at the spring's frequency, a heavy one is dragged with at most maxForce.
//
// A spring at one point lets the body spin freely about it; a little angular damping (an
// implicit torque -I * mouseAngularDampingRate * w) lets a swung body settle.
//
// The spring is solved in both passes (a soft constraint is the physics, not a correction).
#include "rigid2d/mouse_joint.hpp"

namespace impetus::rigid2d::detail {

void prepareJoint(MouseJoint& joint, const JointFrame& frame, const JointPose& pose, const StepContext& context) {
  joint.targetOffset = pose.centerB - joint.def.target;
  joint.linear.prepare({}, frame.frameB, frame);
  joint.linearSoftness = makeSoft(joint.def.hertz, joint.def.dampingRatio, context.h);
  // The damper's implicit impulse over a substep: the accumulated impulse P must equal
  // -I rate h w_after, which solved for the change gives a soft constraint without bias, with
  // massScale = rate h / (1 + rate h) and impulseScale = 1 / (1 + rate h).
  const float damping = mouseAngularDampingRate * context.h;
  joint.angularDamping = {0.0f, damping / (1.0f + damping), 1.0f / (1.0f + damping)};
  if (frame.iB == 0.0f) {
    joint.angular.impulse = 0.0f;
  }
}

void warmStartJoint(MouseJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex) {
  withBodies(frame, states, staticIndex, [&](BodyState& a, BodyState& b) {
    joint.angular.warmStart(angleRow(), frame, a, b);
    joint.linear.warmStart({}, currentAnchor(b, frame.frameB), frame, a, b);
  });
}

void solveJoint(MouseJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool useBias) {
  withBodies(frame, states, staticIndex, [&](BodyState& a, BodyState& b) {
    joint.angular.solve(angleRow(), frame, a, b, 0.0f, joint.angularDamping);
    const Vec2f rB = currentAnchor(b, frame.frameB);
    const Vec2f c = b.dp + rB + joint.targetOffset; // m: anchor minus target
    joint.linear.solve({}, rB, frame, a, b, c,
                       joint.def.hertz > 0.0f ? joint.linearSoftness : rigidRowSoftness(frame, useBias),
                       joint.def.maxForce * context.h);
  });
}

JointReaction jointReaction(const MouseJoint& joint, float inverseH) {
  return {joint.linear.impulse * inverseH, joint.angular.impulse * inverseH};
}

} // namespace impetus::rigid2d::detail
