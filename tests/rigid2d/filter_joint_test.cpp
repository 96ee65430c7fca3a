// The filter joint (Box2D v3's): two bodies joined by it pass through each other, with no force
// between them, and collide again once it is destroyed.
#include "support/error_field.hpp"

#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

namespace impetus::rigid2d {
namespace {

constexpr float dt = 1.0f / 60.0f;

TEST(FilterJoint, joined_bodies_pass_through_each_other_and_collide_again_once_it_is_gone) {
  WorldDef def;
  def.gravity = {};
  World world(def);
  BodyDef bd;
  bd.type = BodyType::dynamicBody;
  bd.enableSleep = false;
  bd.position = {-2.0f, 0.0f};
  bd.linearVelocity = {2.0f, 0.0f};
  const BodyId mover = world.createBody(bd);
  world.createShape(mover, {}, makeBox(0.5f, 0.5f));
  bd.position = {0.0f, 0.0f};
  bd.linearVelocity = {};
  const BodyId still = world.createBody(bd);
  world.createShape(still, {}, makeBox(0.5f, 0.5f));
  FilterJointDef filter;
  filter.bodyA = mover;
  filter.bodyB = still;
  const auto joint = world.createJoint(filter);
  EXPECT_EQ(world.jointType(joint), JointType::filter);
  for (int i = 0; i < 60; ++i) { // 1 s: the mover passes right through (its centre ends at x = 0)
    world.step(dt);
  }
  EXPECT_NEAR(world.linearVelocity(mover).x, 2.0f, 1e-6f); // no force between them
  EXPECT_NEAR(world.linearVelocity(still).x, 0.0f, 1e-6f);
  EXPECT_NEAR(world.position(mover).x, 0.0f, 1e-3f);
  EXPECT_FLOAT_EQ(length(world.jointReactionForce(joint)), 0.0f);
  // Gone, they collide again: the soft contact without restitution is inelastic, so the equal
  // boxes end moving together at half the speed, momentum kept.
  world.destroyJoint(joint);
  world.setTransform(mover, {-2.0f, 0.0f}, 0.0f);
  world.setLinearVelocity(mover, {2.0f, 0.0f});
  for (int i = 0; i < 60; ++i) {
    world.step(dt);
  }
  EXPECT_NEAR(world.linearVelocity(mover).x, 1.0f, 0.01f);
  EXPECT_NEAR(world.linearVelocity(still).x, 1.0f, 0.01f);
}

// A filter joint has no rows, so the solver keeps no copy of it; destroying it must still make
// the solver colour its joints again: a pin made in its slot (the same list of solved joints,
// the same moving bodies) holds a pendulum at its length, as a pin made anywhere else would.
TEST(FilterJoint, a_pin_made_in_its_slot_after_it_is_gone_is_solved) {
  World world;
  BodyDef bd;
  bd.type = BodyType::dynamicBody;
  bd.enableSleep = false;
  bd.position = {1.0f, 0.0f};
  const BodyId bob = world.createBody(bd);
  world.createShape(bob, {}, Circle{{}, 0.1f});
  bd.position = {0.0f, 0.0f};
  bd.gravityScale = 0.0f;
  const BodyId hub = world.createBody(bd); // free, but weightless: the bob swings about it
  world.createShape(hub, {}, Circle{{}, 0.1f});
  FilterJointDef filter;
  filter.bodyA = hub;
  filter.bodyB = bob;
  const auto old = world.createJoint(filter);
  world.step(dt);
  world.destroyJoint(old);
  RevoluteJointDef pin;
  pin.bodyA = hub;
  pin.bodyB = bob;
  pin.localAnchorB = {-1.0f, 0.0f};
  const auto id = world.createJoint(pin);
  ASSERT_EQ(id.id.index, old.id.index) << "the test needs the slot reused";
  for (int i = 0; i < 60; ++i) {
    world.step(dt);
  }
  EXPECT_NEAR(length(world.position(bob) - world.position(hub)), 1.0f, 0.01f) << "the pin holds the bob";
  EXPECT_GT(length(world.jointReactionForce(id)), 0.0f);
}

TEST(FilterJoint, one_that_would_let_its_bodies_collide_is_refused) {
  World world;
  BodyDef bd;
  bd.type = BodyType::dynamicBody;
  const BodyId a = world.createBody(bd);
  const BodyId b = world.createBody(bd);
  FilterJointDef filter;
  filter.bodyA = a;
  filter.bodyB = b;
  filter.collideConnected = true;
  expectErrorField([&] { (void)world.createJoint(filter); }, "collideConnected");
}

} // namespace
} // namespace impetus::rigid2d
