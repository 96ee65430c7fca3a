// The motor joint against mechanics: it drives a body to its target pose (also on a turning
// base), its force and torque limits bound the accelerations (F/m, T/I), and used as top-down
// friction it decelerates a sliding, spinning box as dry friction does; bad input names the field.
#include "support/error_field.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace impetus::rigid2d {
namespace {

constexpr float dt = 1.0f / 60.0f;

WorldDef noGravity() {
  WorldDef def;
  def.gravity = {};
  return def;
}

/// A dynamic box (half extents hx, hy, density 1 kg/m^2) whose centre of mass sits at `center`
/// in the body frame, so the body origin and the centre of mass differ.
BodyId addBox(World& world, const Vec2f& position, float angle, float hx, float hy, const Vec2f& center = {}) {
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = position;
  def.angle = angle;
  def.enableSleep = false;
  const BodyId b = world.createBody(def);
  world.createShape(b, {}, makeOffsetBox(hx, hy, center, 0.0f));
  return b;
}

/// Where the motor joint wants B's origin: A's origin plus the offset turned with A.
Vec2f targetOf(const World& world, BodyId a, const Vec2f& offset) {
  return world.position(a) + rotate(world.transform(a).q, offset);
}

float angleError(const World& world, BodyId a, BodyId b, float angularOffset) {
  return std::remainder(world.angle(b) - world.angle(a) - angularOffset, 2.0f * pi<float>);
}

// With ample force and torque the drive closes the error at the rate correctionFactor per
// substep (time constant h / 0.3, 14 ms), so after 2 s only round-off remains; the tolerance
// is the brief's 1 cm (and 0.01 rad). A rotated base and a centre of mass away from B's origin
// check that the offset is taken in A's frame between the origins (the anchors, set to
// nonsense, are ignored). Gravity pulls throughout: the drive holds B against it, and the
// reaction readout is B's weight (m g = 5 N, well within maxForce; 1 %).
TEST(MotorJoint2D, drives_body_to_offset_and_angle) {
  World world; // gravity -10
  BodyDef baseDef;
  baseDef.position = {1.0f, 2.0f};
  baseDef.angle = 0.5f;
  const BodyId base = world.createBody(baseDef);
  const BodyId box = addBox(world, {-2.0f, -1.0f}, 2.0f, 0.5f, 0.25f, {0.4f, -0.2f});
  MotorJointDef def;
  def.bodyA = base;
  def.bodyB = box;
  def.linearOffset = {2.0f, 1.0f};
  def.angularOffset = 0.7f;
  def.maxForce = 1000.0f;
  def.maxTorque = 1000.0f;
  def.localAnchorA = {5.0f, 5.0f}; // not used by this joint
  def.localAnchorB = {-3.0f, 1.0f};
  const auto id = world.createJoint(def);
  for (int i = 0; i < 120; ++i) {
    world.step(dt);
  }
  const float error = length(world.position(box) - targetOf(world, base, def.linearOffset));
  EXPECT_LT(error, 0.01f);
  EXPECT_LT(std::abs(angleError(world, base, box, def.angularOffset)), 0.01f);
  EXPECT_NEAR(world.jointReactionForce(id).y, world.mass(box) * 10.0f, 0.01f * world.mass(box) * 10.0f);
  EXPECT_NEAR(world.jointReactionForce(id).x, 0.0f, 0.01f);

  // A new target at run time: reached as well.
  setMotorJointTarget(world, id, {-1.0f, 3.0f}, -2.5f);
  for (int i = 0; i < 120; ++i) {
    world.step(dt);
  }
  EXPECT_LT(length(world.position(box) - targetOf(world, base, {-1.0f, 3.0f})), 0.01f);
  EXPECT_LT(std::abs(angleError(world, base, box, -2.5f)), 0.01f);
}

// The target is a point fixed in A: on a kinematic base turning at 1 rad/s, B is carried round
// on its circle (1.5 m radius) and keeps its angle relative to the base. The drive's velocity
// target lags the turning target by the base's motion during a substep only (1.5 m/s * h,
// corrected at 0.3 per substep: a few mm), under the 1 cm tolerance.
TEST(MotorJoint2D, target_turns_with_body_a) {
  World world(noGravity());
  BodyDef baseDef;
  baseDef.type = BodyType::kinematicBody;
  baseDef.angularVelocity = 1.0f;
  const BodyId base = world.createBody(baseDef);
  const BodyId box = addBox(world, {1.5f, 0.0f}, 0.0f, 0.3f, 0.3f);
  MotorJointDef def;
  def.bodyA = base;
  def.bodyB = box;
  def.linearOffset = {1.5f, 0.0f};
  def.maxForce = 1000.0f;
  def.maxTorque = 1000.0f;
  world.createJoint(def);
  float worst = 0.0f;
  float worstAngle = 0.0f;
  for (int i = 0; i < 240; ++i) {
    world.step(dt);
    if (i >= 60) {
      worst = std::max(worst, length(world.position(box) - targetOf(world, base, def.linearOffset)));
      worstAngle = std::max(worstAngle, std::abs(angleError(world, base, box, 0.0f)));
    }
  }
  EXPECT_FLOAT_EQ(world.angularVelocity(base), 1.0f); // it has turned through 4 rad
  EXPECT_LT(worst, 0.01f);
  EXPECT_LT(worstAngle, 0.01f);
  EXPECT_NEAR(length(world.linearVelocity(box)), 1.5f, 0.01f);
}

// A weak motor far from its target: the accumulated impulse per substep is clamped to maxForce h
// (maxTorque h), so B's acceleration never exceeds maxForce / m (maxTorque / I): checked every
// step, with 0.1 % for float round-off. Far from the target the drive is saturated and the
// acceleration is exactly the limit (1 %). The reaction readout never exceeds maxForce.
TEST(MotorJoint2D, force_and_torque_limits_bound_the_acceleration) {
  World world(noGravity());
  const BodyId base = world.createBody({});
  const BodyId box = addBox(world, {}, 0.0f, 1.0f, 0.5f); // 2 kg
  MotorJointDef def;
  def.bodyA = base;
  def.bodyB = box;
  def.linearOffset = {10.0f, 5.0f};
  def.angularOffset = 3.0f;
  def.maxForce = 2.0f;
  def.maxTorque = 0.25f;
  const auto id = world.createJoint(def);
  const float m = world.mass(box);
  const float inertia = world.rotationalInertia(box);
  const float maxAcceleration = def.maxForce / m;               // 1 m/s^2
  const float maxAngularAcceleration = def.maxTorque / inertia; // 0.3 rad/s^2
  Vec2f v = world.linearVelocity(box);
  float w = world.angularVelocity(box);
  float worst = 0.0f;
  float worstAngular = 0.0f;
  float worstForce = 0.0f;
  for (int i = 0; i < 60; ++i) {
    world.step(dt);
    const float a = length(world.linearVelocity(box) - v) / dt;
    const float alpha = std::abs(world.angularVelocity(box) - w) / dt;
    v = world.linearVelocity(box);
    w = world.angularVelocity(box);
    worst = std::max(worst, a);
    worstAngular = std::max(worstAngular, alpha);
    worstForce = std::max(worstForce, length(world.jointReactionForce(id)));
    EXPECT_NEAR(a, maxAcceleration, 0.01f * maxAcceleration) << "step " << i;
    EXPECT_NEAR(alpha, maxAngularAcceleration, 0.01f * maxAngularAcceleration) << "step " << i;
  }
  EXPECT_LE(worst, maxAcceleration * 1.001f);
  EXPECT_LE(worstAngular, maxAngularAcceleration * 1.001f);
  EXPECT_LE(worstForce, def.maxForce * 1.001f);
  // Pushed straight toward the target (the offset's direction), from rest.
  const Vec2f direction = normalize(def.linearOffset);
  EXPECT_NEAR(dot(normalize(v), direction), 1.0f, 1e-4f);
  EXPECT_NEAR(w, maxAngularAcceleration * 1.0f, 0.01f * maxAngularAcceleration);
}

// Top-down friction: a box slides and spins on a static ground body seen from above (no
// gravity); each step the joint's target is set to the box's own pose, so the drives aim at
// zero velocity with at most maxForce and maxTorque, as dry friction would. The box must slow
// at exactly maxForce / m (never more: 0.1 % round-off) in a straight line, stop after
// v0 m / maxForce (6.32 s here, within a step), and then stay put; the spin likewise stops at
// w0 I / maxTorque.
TEST(MotorJoint2D, top_down_friction_decelerates_like_dry_friction) {
  World world(noGravity());
  const BodyId ground = world.createBody({});
  const BodyId box = addBox(world, {}, 0.0f, 1.0f, 1.0f); // 4 kg
  const Vec2f v0{3.0f, 1.0f};
  const float w0 = 2.0f;
  world.setLinearVelocity(box, v0);
  world.setAngularVelocity(box, w0);
  MotorJointDef def;
  def.bodyA = ground;
  def.bodyB = box;
  def.maxForce = 2.0f;
  def.maxTorque = 0.5f;
  const auto id = world.createJoint(def);
  const float m = world.mass(box);
  const float inertia = world.rotationalInertia(box);
  const float deceleration = def.maxForce / m;               // 0.5 m/s^2
  const float angularDeceleration = def.maxTorque / inertia; // 0.19 rad/s^2
  const float stopTime = length(v0) / deceleration;          // 6.32 s
  const float spinStopTime = w0 / angularDeceleration;       // 10.7 s
  float speed = length(v0);
  float spin = w0;
  float worst = 0.0f;
  float stoppedAt = -1.0f;
  float spinStoppedAt = -1.0f;
  const Vec2f direction = normalize(v0);
  for (int i = 1; i <= 13 * 60; ++i) {
    setMotorJointTarget(world, id, world.position(box), world.angle(box));
    world.step(dt);
    const float newSpeed = length(world.linearVelocity(box));
    const float newSpin = world.angularVelocity(box);
    worst = std::max(worst, (speed - newSpeed) / dt);
    if (newSpeed > 0.1f) {
      EXPECT_NEAR((speed - newSpeed) / dt, deceleration, 0.01f * deceleration) << "step " << i;
      EXPECT_NEAR(dot(world.linearVelocity(box), direction) / newSpeed, 1.0f, 1e-4f) << "step " << i;
    }
    if (newSpin > 0.1f) {
      EXPECT_NEAR((spin - newSpin) / dt, angularDeceleration, 0.01f * angularDeceleration) << "step " << i;
    }
    if (stoppedAt < 0.0f && newSpeed < 1e-3f) {
      stoppedAt = static_cast<float>(i) * dt;
    }
    if (spinStoppedAt < 0.0f && std::abs(newSpin) < 1e-3f) {
      spinStoppedAt = static_cast<float>(i) * dt;
    }
    speed = newSpeed;
    spin = newSpin;
  }
  EXPECT_LE(worst, deceleration * 1.001f);
  EXPECT_NEAR(stoppedAt, stopTime, dt);
  EXPECT_NEAR(spinStoppedAt, spinStopTime, dt);
  EXPECT_LT(length(world.linearVelocity(box)), 1e-4f);
  EXPECT_LT(std::abs(world.angularVelocity(box)), 1e-4f);
  // Where dry friction stops it: v0^2 / (2 a) along v0 (within 2 cm: the step's discretization
  // of the deceleration, v dt / 2 per step at most, accumulates to about a step's travel).
  const float distance = dot(v0, v0) / (2.0f * deceleration);
  EXPECT_NEAR(length(world.position(box)), distance, 0.02f);
}

TEST(MotorJoint2D, bad_definitions_name_the_field) {
  World world;
  const BodyId a = world.createBody({});
  const BodyId b = addBox(world, {}, 0.0f, 0.5f, 0.5f);
  MotorJointDef def;
  def.bodyA = a;
  def.bodyB = b;
  def.correctionFactor = -0.1f;
  expectErrorField([&] { (void)world.createJoint(def); }, "correctionFactor");
  def.correctionFactor = 1.5f;
  expectErrorField([&] { (void)world.createJoint(def); }, "correctionFactor");
  def.correctionFactor = std::nanf("");
  expectErrorField([&] { (void)world.createJoint(def); }, "correctionFactor");
  def.correctionFactor = 1.0f;
  def.maxForce = -1.0f;
  expectErrorField([&] { (void)world.createJoint(def); }, "maxForce");
  def.maxForce = 1.0f;
  def.maxTorque = -1.0f;
  expectErrorField([&] { (void)world.createJoint(def); }, "maxTorque");
  def.maxTorque = 1.0f;
  def.linearOffset = {0.0f, std::nanf("")};
  expectErrorField([&] { (void)world.createJoint(def); }, "linearOffset.y");
  def.linearOffset = {};
  EXPECT_EQ(world.jointCount(), 0U);
  const auto id = world.createJoint(def); // correctionFactor 1 is allowed
  expectErrorField([&] { setMotorJointTarget(world, id, {}, std::nanf("")); }, "angularOffset");
  expectErrorField([&] { setMouseTarget(world, MouseJointId{id}, {}); }, "joint id");
}

} // namespace
} // namespace impetus::rigid2d
