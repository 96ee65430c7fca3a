// Regressions found by reviewing the engine: each test fails on the code before its fix.
#include "support/error_field.hpp"

#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace impetus::rigid2d {
namespace {

constexpr float dt = 1.0f / 60.0f;

BodyId addGround(World& world) {
  const BodyId ground = world.createBody({});
  world.createShape(ground, {}, makeOffsetBox(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
  return ground;
}

BodyId addBox(World& world, const Vec2f& position, float angle = 0.0f, const ShapeDef& shape = {}) {
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = position;
  def.angle = angle;
  const BodyId b = world.createBody(def);
  world.createShape(b, shape, makeBox(0.5f, 0.5f));
  return b;
}

// The revolute joint's limits and spring act on angleB - angleA - referenceAngle.
TEST(Review2D, revolute_limits_are_measured_from_the_reference_angle) {
  WorldDef def;
  def.gravity = {};
  World world(def);
  const BodyId ground = world.createBody({});
  const BodyId arm = addBox(world, {0.0f, 0.0f}, 1.0f);
  RevoluteJointDef joint;
  joint.bodyA = ground;
  joint.bodyB = arm;
  joint.referenceAngle = 1.0f;
  joint.enableLimit = true;
  joint.lowerAngle = -0.1f;
  joint.upperAngle = 0.1f;
  const auto id = world.createJoint(joint);
  for (int i = 0; i < 120; ++i) {
    world.step(dt);
  }
  EXPECT_NEAR(world.angle(arm), 1.0f, 1e-3f);
  EXPECT_NEAR(revoluteAngle(world, id), 0.0f, 1e-3f);
  // Limits beyond half a turn are refused (the joint angle wraps at pi).
  joint.upperAngle = 4.0f;
  expectErrorField([&] { (void)world.createJoint(joint); }, "upperAngle");
}

// A joint that turns off its bodies' collision ends their touching contact with an event.
TEST(Review2D, a_joint_that_stops_a_collision_reports_its_end) {
  World world;
  const BodyId ground = addGround(world);
  const BodyId box = addBox(world, {0.0f, 0.5f});
  world.step(dt);
  ASSERT_EQ(world.contactEvents().begins.size(), 1U);
  RevoluteJointDef joint;
  joint.bodyA = ground;
  joint.bodyB = box;
  joint.localAnchorA = {0.0f, 0.5f};
  world.createJoint(joint);
  world.step(dt);
  EXPECT_EQ(world.contactEvents().ends.size(), 1U);
}

// Continuous collision stops a fast body only at what it may collide with: not at static shapes
// its filter excludes, not at a body jointed to it, and not at a one-sided chain from behind.
TEST(Review2D, continuous_collision_respects_filters_joints_and_one_sided_chains) {
  {
    World world;
    addGround(world);
    ShapeDef ghost;
    ghost.filter.mask = 0;
    const BodyId box = addBox(world, {0.0f, 5.0f}, 0.0f, ghost);
    world.setLinearVelocity(box, {0.0f, -60.0f});
    for (int i = 0; i < 30; ++i) {
      world.step(dt);
    }
    EXPECT_LT(world.position(box).y, -10.0f);
  }
  {
    World world;
    const BodyId ground = world.createBody({});
    ChainDef chain;
    chain.points = {{10.0f, 0.0f}, {-10.0f, 0.0f}}; // solid below, free above
    world.createChain(ground, {}, chain);
    const BodyId box = addBox(world, {0.0f, -5.0f});
    world.setLinearVelocity(box, {0.0f, 60.0f});
    for (int i = 0; i < 10; ++i) { // 1 m a step: past the chain after 5
      world.step(dt);
    }
    EXPECT_GT(world.position(box).y, 2.0f) << "passed up through the chain from its solid side";
  }
  for (const bool bullet : {false, true}) {
    WorldDef def;
    def.gravity = {};
    World world(def);
    const BodyId mount = world.createBody({});
    world.createShape(mount, {}, makeOffsetBox(0.05f, 2.0f, {0.0f, 0.0f}, 0.0f));
    BodyDef shot;
    shot.type = BodyType::dynamicBody;
    shot.position = {-3.0f, 0.0f};
    shot.linearVelocity = {100.0f, 0.0f};
    shot.bullet = bullet;
    const BodyId projectile = world.createBody(shot);
    world.createShape(projectile, {}, makeBox(0.1f, 0.1f));
    DistanceJointDef leash; // slack: it only says the two do not collide
    leash.bodyA = mount;
    leash.bodyB = projectile;
    leash.length = 50.0f;
    leash.enableSpring = true;
    leash.enableLimit = true;
    leash.maxLength = 50.0f;
    world.createJoint(leash);
    for (int i = 0; i < 3; ++i) { // 1.67 m a step: past the mount (x = 0) after 2
      world.step(dt);
    }
    EXPECT_GT(world.position(projectile).x, 1.0f) << (bullet ? "bullet" : "fast body");
  }
}

TEST(Review2D, world_settings_are_validated) {
  WorldDef def;
  def.jointHertz = -60.0f;
  expectErrorField([&] { World world(def); }, "jointHertz");
  def = {};
  def.timeToSleep = -1.0f;
  expectErrorField([&] { World world(def); }, "timeToSleep");
  def = {};
  def.hitEventThreshold = std::nanf("");
  expectErrorField([&] { World world(def); }, "hitEventThreshold");
}

// Teleporting a support away wakes what slept on it.
TEST(Review2D, moving_a_support_wakes_what_rests_on_it) {
  World world;
  BodyDef platformDef;
  platformDef.type = BodyType::kinematicBody;
  const BodyId platform = world.createBody(platformDef);
  world.createShape(platform, {}, makeOffsetBox(2.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
  const BodyId box = addBox(world, {0.0f, 0.5f});
  for (int i = 0; i < 120; ++i) {
    world.step(dt);
  }
  ASSERT_FALSE(world.isAwake(box));
  world.setTransform(platform, {100.0f, 0.0f}, 0.0f);
  for (int i = 0; i < 60; ++i) {
    world.step(dt);
  }
  EXPECT_LT(world.position(box).y, -3.0f);
}

// The mouse joint ignores bodyA: naming the ground must not turn off the ground's collision.
TEST(Review2D, mouse_joint_ignores_body_a) {
  World world;
  const BodyId ground = addGround(world);
  const BodyId box = addBox(world, {0.0f, 0.5f});
  MouseJointDef mouse;
  mouse.bodyA = ground;
  mouse.bodyB = box;
  mouse.target = {0.0f, -3.0f}; // under the ground
  mouse.maxForce = 5.0f;        // weaker than the ground
  world.createJoint(mouse);
  for (int i = 0; i < 120; ++i) {
    world.step(dt);
  }
  EXPECT_GT(world.position(box).y, 0.45f);
}

// With a zero hit threshold a resting contact raises no hit events: hits need an approach.
TEST(Review2D, resting_contacts_raise_no_hits_at_a_zero_threshold) {
  WorldDef def;
  def.hitEventThreshold = 0.0f;
  def.enableSleep = false;
  World world(def);
  addGround(world);
  addBox(world, {0.0f, 0.5f});
  for (int i = 0; i < 60; ++i) {
    world.step(dt);
  }
  int hits = 0;
  for (int i = 0; i < 60; ++i) {
    world.step(dt);
    hits += static_cast<int>(world.contactEvents().hits.size());
  }
  EXPECT_EQ(hits, 0);
}

} // namespace
} // namespace impetus::rigid2d
