// Sleeping: islands at rest fall asleep and cost nothing; touched or changed, they wake whole.
#include <impetus/rigid3d/world.hpp>

#include <gtest/gtest.h>

#include <vector>

namespace impetus::rigid3d {
namespace {

constexpr float dt = 1.0f / 60.0f;

struct Scene {
  World world;
  std::vector<BodyId> stack;
  BodyId loner;
};

/// A stack of three boxes and, apart from it, a ball, on the ground.
void build(Scene& s) {
  BodyDef groundDef;
  groundDef.position = {0.0f, -0.5f, 0.0f};
  s.world.createShape(s.world.createBody(groundDef), ShapeDef{}, makeBoxHull({20.0f, 0.5f, 20.0f}));
  for (int i = 0; i < 3; ++i) {
    BodyDef def;
    def.type = BodyType::dynamicBody;
    def.position = {0.0f, 0.5f + static_cast<float>(i), 0.0f};
    const BodyId box = s.world.createBody(def);
    s.world.createShape(box, ShapeDef{}, makeBoxHull({0.5f, 0.5f, 0.5f}));
    s.stack.push_back(box);
  }
  BodyDef ballDef;
  ballDef.type = BodyType::dynamicBody;
  ballDef.position = {5.0f, 0.3f, 0.0f};
  s.loner = s.world.createBody(ballDef);
  s.world.createShape(s.loner, ShapeDef{}, Sphere{{}, 0.3f});
}

void run(World& world, int steps) {
  for (int i = 0; i < steps; ++i) {
    world.step(dt);
  }
}

TEST(Rigid3dSleep, a_stack_at_rest_falls_asleep_and_stays_where_it_was) {
  Scene s;
  build(s);
  run(s.world, 120);
  for (const BodyId box : s.stack) {
    EXPECT_FALSE(s.world.isAwake(box));
  }
  EXPECT_FALSE(s.world.isAwake(s.loner));
  const std::uint64_t asleep = s.world.stateHash();
  run(s.world, 60);
  EXPECT_EQ(s.world.stateHash(), asleep); // nothing moves, not by a bit
  // Its contacts are kept with their impulses: the bottom box still carries the stack's weight
  // (three boxes of 1000 kg, m g h per substep).
  std::vector<ContactData> contacts;
  s.world.contacts(contacts);
  float groundLoad = 0.0f;
  for (const ContactData& c : contacts) {
    if (s.world.shapeBody(c.shapeB) == s.stack[0]) {
      for (int k = 0; k < c.manifold.pointCount; ++k) {
        groundLoad += c.normalImpulses[static_cast<std::size_t>(k)];
      }
    }
  }
  EXPECT_NEAR(groundLoad / (dt / 4.0f), 3.0f * 1000.0f * 10.0f, 0.01f * 30000.0f);
}

TEST(Rigid3dSleep, a_ball_landing_on_a_sleeping_stack_wakes_all_of_it_and_nothing_else) {
  Scene s;
  build(s);
  run(s.world, 120);
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = {0.2f, 4.0f, 0.0f};
  const BodyId ball = s.world.createBody(def);
  s.world.createShape(ball, ShapeDef{}, Sphere{{}, 0.25f});
  bool stackWoke = false;
  for (int i = 0; i < 60 && !stackWoke; ++i) {
    s.world.step(dt);
    stackWoke = s.world.isAwake(s.stack[0]) && s.world.isAwake(s.stack[2]);
  }
  EXPECT_TRUE(stackWoke); // the whole island: the bottom box too
  EXPECT_FALSE(s.world.isAwake(s.loner));
}

TEST(Rigid3dSleep, changing_a_sleeping_body_wakes_its_island_and_sleep_can_be_refused) {
  Scene s;
  build(s);
  run(s.world, 120);
  s.world.applyLinearImpulse(s.stack[1], {10.0f, 0.0f, 0.0f}, s.world.worldCenter(s.stack[1]));
  EXPECT_TRUE(s.world.isAwake(s.stack[0]));
  EXPECT_TRUE(s.world.isAwake(s.stack[2]));
  s.world.setAwake(s.loner, true);
  EXPECT_TRUE(s.world.isAwake(s.loner));
  s.world.setAwake(s.loner, false);
  EXPECT_FALSE(s.world.isAwake(s.loner));
  // A body that may not sleep stays awake at rest; a world without sleep sleeps nothing.
  BodyDef restless;
  restless.type = BodyType::dynamicBody;
  restless.position = {-5.0f, 0.3f, 0.0f};
  restless.enableSleep = false;
  const BodyId insomniac = s.world.createBody(restless);
  s.world.createShape(insomniac, ShapeDef{}, Sphere{{}, 0.3f});
  run(s.world, 120);
  EXPECT_TRUE(s.world.isAwake(insomniac));
  WorldDef def;
  def.enableSleep = false;
  World awake(def);
  BodyDef ballDef;
  ballDef.type = BodyType::dynamicBody;
  const BodyId floating = awake.createBody(ballDef);
  awake.setGravity({0.0f, 0.0f, 0.0f});
  run(awake, 120);
  EXPECT_TRUE(awake.isAwake(floating));
}

} // namespace
} // namespace impetus::rigid3d
