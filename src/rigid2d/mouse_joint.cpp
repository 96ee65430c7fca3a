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

void prepareJoint(MouseJoint& joint, const JointFrame& frame, const StepContext& context) {
  joint.targetOffset = frame.centerB - joint.def.target;
  joint.linearSoftness = makeSoft(joint.def.hertz, joint.def.dampingRatio, context.h);
  // The damper's implicit impulse over a substep: the accumulated impulse P must equal
  // -I rate h w_after, which solved for the change gives a soft constraint without bias, with
  // massScale = rate h / (1 + rate h) and impulseScale = 1 / (1 + rate h).
  const float damping = mouseAngularDampingRate * context.h;
  joint.angularDamping = {0.0f, damping / (1.0f + damping), 1.0f / (1.0f + damping)};
  if (frame.iB == 0.0f) {
    joint.angularImpulse = 0.0f;
  }
}

void warmStartJoint(MouseJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex, JointRows rows) {
  if (!includes(rows, JointRows::working)) {
    return;
  }
  BodyState b = states[frame.indexB];
  const Vec2f rB = currentAnchor(b, frame.frameB);
  b.v += joint.linearImpulse * frame.mB;
  b.w += frame.iB * (cross(rB, joint.linearImpulse) + joint.angularImpulse);
  storeVelocity(states, frame.indexB, staticIndex, b);
}

void solveJoint(MouseJoint& joint, const JointFrame& frame, std::vector<BodyState>& states, std::uint32_t staticIndex,
                const StepContext& context, bool useBias) {
  BodyState b = states[frame.indexB];

  if (frame.iB > 0.0f) {
    const Softness& soft = joint.angularDamping;
    const float impulse = -soft.massScale * b.w / frame.iB - soft.impulseScale * joint.angularImpulse;
    joint.angularImpulse += impulse;
    b.w += frame.iB * impulse;
  }

  const Vec2f rB = currentAnchor(b, frame.frameB);
  const Vec2f cdot = b.v + cross(b.w, rB);
  Vec2f bias;
  float massScale = 1.0f;
  float impulseScale = 0.0f;
  const Vec2f c = b.dp + rB + joint.targetOffset; // m: anchor minus target
  if (joint.def.hertz > 0.0f) {
    bias = c * joint.linearSoftness.biasRate;
    massScale = joint.linearSoftness.massScale;
    impulseScale = joint.linearSoftness.impulseScale;
  } else if (useBias) {
    bias = c * frame.softness.biasRate;
    massScale = frame.softness.massScale;
    impulseScale = frame.softness.impulseScale;
  }
  const Vec2f solved = solve22(pointMass(frame, {}, rB), cdot + bias);
  const Vec2f old = joint.linearImpulse;
  joint.linearImpulse = old - solved * massScale - old * impulseScale;
  // The pull is bounded in magnitude, whatever its direction: clamp to a disc.
  const float maxImpulse = joint.def.maxForce * context.h;
  const float magnitude = length(joint.linearImpulse);
  if (magnitude > maxImpulse) {
    joint.linearImpulse = joint.linearImpulse * (maxImpulse / magnitude);
  }
  const Vec2f impulse = joint.linearImpulse - old;
  b.v += impulse * frame.mB;
  b.w += frame.iB * cross(rB, impulse);

  storeVelocity(states, frame.indexB, staticIndex, b);
}

JointReaction jointReaction(const MouseJoint& joint, const JointFrame&, float inverseH) {
  return {joint.linearImpulse * inverseH, joint.angularImpulse * inverseH};
}

} // namespace impetus::rigid2d::detail
