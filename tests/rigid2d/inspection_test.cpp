// The inspection API the samples app and tools draw from: contacts with their manifolds and
// impulses, joints with their anchors, per-body flags.
#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

namespace impetus::rigid2d {
namespace {

TEST(Inspection2D, a_resting_box_reports_one_contact_carrying_its_weight) {
  World world;
  const BodyId ground = world.createBody({});
  world.createShape(ground, {}, makeOffsetBox(5.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = {0.0f, 0.5f};
  def.enableSleep = false;
  const BodyId box = world.createBody(def);
  world.createShape(box, {}, makeBox(0.5f, 0.5f)); // 1 kg
  const float dt = 1.0f / 60.0f;
  for (int i = 0; i < 120; ++i) {
    world.step(dt);
  }
  std::vector<ContactData> contacts;
  world.contacts(contacts);
  ASSERT_EQ(contacts.size(), 1U);
  const Manifold& m = contacts[0].manifold;
  ASSERT_EQ(m.pointCount, 2);
  EXPECT_NEAR(std::abs(m.normal.y), 1.0f, 1e-5f);
  // The stored impulses are the last substep's: together they carry m g over a substep h.
  const float h = dt / static_cast<float>(world.settings().substeps);
  const float support = (m.points[0].normalImpulse + m.points[1].normalImpulse) / h;
  EXPECT_NEAR(support, 10.0f, 0.1f); // N: 1 kg at g = 10 m/s^2
  EXPECT_TRUE(world.isValid(contacts[0].shapeA));
  EXPECT_FALSE(world.isBullet(box));
  EXPECT_FALSE(world.isSleepEnabled(box));
}

TEST(Inspection2D, joints_list_in_slot_order_with_their_anchors_together) {
  World world;
  const BodyId ground = world.createBody({});
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = {1.0f, 0.0f};
  const BodyId bob = world.createBody(def);
  world.createShape(bob, {}, Circle{{}, 0.1f});
  RevoluteJointDef pin;
  pin.bodyA = ground;
  pin.bodyB = bob;
  pin.localAnchorB = {-1.0f, 0.0f};
  const auto first = world.createJoint(pin);
  DistanceJointDef rope;
  rope.bodyA = ground;
  rope.bodyB = bob;
  rope.localAnchorA = {0.0f, 1.0f};
  rope.length = std::sqrt(2.0f);
  const auto second = world.createJoint(rope);
  for (int i = 0; i < 30; ++i) {
    world.step(1.0f / 60.0f);
  }
  std::vector<JointId> joints;
  world.jointIds(joints);
  ASSERT_EQ(joints.size(), 2U);
  EXPECT_EQ(joints[0], first.id);
  EXPECT_EQ(joints[1], second.id);
  // The pin holds: its two anchors stay together (within the soft joint's give).
  EXPECT_LT(length(world.jointAnchorA(first) - world.jointAnchorB(first)), 0.01f);
  EXPECT_NEAR(length(world.jointAnchorA(second) - Vec2f{0.0f, 1.0f}), 0.0f, 1e-6f);
  EXPECT_NEAR(length(world.jointAnchorB(second) - world.worldCenterOfMass(bob)), 0.0f, 1e-5f);
}

} // namespace
} // namespace impetus::rigid2d
