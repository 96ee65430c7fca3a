// Persistent islands and the awake set: what sleeps together wakes together, what came apart
// sleeps and wakes apart, and a sleeping island is not touched by the step.
#include "solver/islands.hpp"

#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace impetus::rigid2d {
namespace {

constexpr float dt = 1.0f / 60.0f;

void stepN(World& world, int n) {
  for (int i = 0; i < n; ++i) {
    world.step(dt);
  }
}

BodyId addGround(World& world, float friction = 0.6f) {
  const BodyId ground = world.createBody({});
  ShapeDef shape;
  shape.friction = friction;
  world.createShape(ground, shape, makeOffsetBox(50.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
  return ground;
}

BodyId addBox(World& world, const Vec2f& position, float friction = 0.6f, bool enableSleep = true) {
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = position;
  def.enableSleep = enableSleep;
  const BodyId box = world.createBody(def);
  ShapeDef shape;
  shape.friction = friction;
  world.createShape(box, shape, makeBox(0.5f, 0.5f));
  return box;
}

std::vector<BodyId> addStack(World& world, float x, int count) {
  std::vector<BodyId> stack;
  for (int i = 0; i < count; ++i) {
    stack.push_back(addBox(world, {x, 0.5f + static_cast<float>(i)}));
  }
  return stack;
}

std::vector<std::uint32_t> sorted(std::span<const std::uint32_t> bodies) {
  std::vector<std::uint32_t> out(bodies.begin(), bodies.end());
  std::sort(out.begin(), out.end());
  return out;
}

// The islands on their own: a chain 0-1-2-3 and a lone 4.
TEST(Islands, join_on_link_and_come_apart_only_when_split) {
  solver::Islands islands;
  for (std::uint32_t body = 0; body < 5; ++body) {
    islands.addBody(body);
  }
  EXPECT_EQ(islands.count(), 5U);
  islands.link(0, 1);
  islands.link(2, 3);
  islands.link(1, 2);
  islands.link(3, 0); // already one island: nothing changes
  EXPECT_EQ(islands.count(), 2U);
  const std::uint32_t chain = islands.islandOf(0);
  EXPECT_EQ(sorted(islands.bodies(chain)), (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_FALSE(islands.mayBeApart(chain));
  // The middle link goes: still one island until it is split.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges{{0, 1}, {2, 3}, {3, 0}};
  islands.unlink(1, 2);
  EXPECT_TRUE(islands.mayBeApart(chain));
  EXPECT_EQ(islands.islandOf(2), chain);
  const auto neighbours = [&](std::uint32_t body, const auto& visit) {
    for (const auto& [a, b] : edges) {
      if (a == body) {
        visit(b);
      } else if (b == body) {
        visit(a);
      }
    }
  };
  std::vector<std::uint32_t> pieces;
  islands.split(chain, neighbours, pieces);
  // 0-1 and 2-3 are still joined through 3-0: one piece.
  EXPECT_EQ(pieces.size(), 1U);
  EXPECT_FALSE(islands.mayBeApart(chain));
  // Without 3-0 the chain is two pieces, the first keeping the island.
  edges = {{0, 1}, {2, 3}};
  islands.unlink(3, 0);
  islands.split(chain, neighbours, pieces);
  ASSERT_EQ(pieces.size(), 2U);
  EXPECT_EQ(pieces[0], chain);
  EXPECT_EQ(islands.islandOf(1), chain);
  EXPECT_EQ(islands.islandOf(2), islands.islandOf(3));
  EXPECT_NE(islands.islandOf(2), chain);
  EXPECT_EQ(islands.count(), 3U);
  // A body leaving takes nothing else with it; the last one frees the island.
  islands.removeBody(4);
  EXPECT_EQ(islands.islandOf(4), solver::Islands::none);
  EXPECT_EQ(islands.count(), 2U);
  islands.removeBody(0);
  EXPECT_EQ(sorted(islands.bodies(chain)), (std::vector<std::uint32_t>{1}));
}

TEST(Islands, the_larger_island_takes_the_smaller_whatever_the_order) {
  solver::Islands first;
  solver::Islands second;
  for (std::uint32_t body = 0; body < 4; ++body) {
    first.addBody(body);
    second.addBody(body);
  }
  first.link(1, 2);
  second.link(1, 2);
  first.link(0, 1);  // the lone 0 joins {1, 2}
  second.link(1, 0); // the same, the other way round
  EXPECT_EQ(first.islandOf(0), second.islandOf(0));
  EXPECT_EQ(sorted(first.bodies(first.islandOf(0))), sorted(second.bodies(second.islandOf(0))));
}

// Each stack is an island: knocking one wakes it alone, and the other is not stepped at all.
TEST(Sleep2D, waking_is_per_island) {
  World world;
  addGround(world);
  const std::vector<BodyId> left = addStack(world, -10.0f, 4);
  const std::vector<BodyId> right = addStack(world, 10.0f, 6);
  stepN(world, 240);
  ASSERT_EQ(world.awakeBodyCount(), 0U);
  std::vector<Transform2f> rightAtRest;
  for (const BodyId b : right) {
    rightAtRest.push_back(world.transform(b));
  }
  world.applyLinearImpulse(left.back(), {2.0f, 0.0f}, world.worldCenterOfMass(left.back()));
  EXPECT_EQ(world.awakeBodyCount(), left.size()); // the whole stack, nothing else
  for (const BodyId b : left) {
    EXPECT_TRUE(world.isAwake(b));
  }
  stepN(world, 60);
  for (std::size_t i = 0; i < right.size(); ++i) {
    EXPECT_FALSE(world.isAwake(right[i]));
    EXPECT_EQ(world.transform(right[i]), rightAtRest[i]); // bit for bit
  }
  EXPECT_EQ(world.awakeBodyCount(), left.size());
}

// A box taken off a stack and put down alone: the stack and the box touched, so they were one
// island; once both rest they sleep as two, and knocking the box leaves the stack asleep.
TEST(Sleep2D, islands_that_came_apart_sleep_and_wake_apart) {
  World world;
  addGround(world);
  const std::vector<BodyId> stack = addStack(world, 0.0f, 3);
  stepN(world, 30);
  world.setTransform(stack.back(), {8.0f, 0.5f}, 0.0f); // off the stack, on the ground
  stepN(world, 240);
  ASSERT_EQ(world.awakeBodyCount(), 0U);
  world.applyLinearImpulse(stack.back(), {1.0f, 0.0f}, world.worldCenterOfMass(stack.back()));
  EXPECT_TRUE(world.isAwake(stack.back()));
  EXPECT_FALSE(world.isAwake(stack[0]));
  EXPECT_FALSE(world.isAwake(stack[1]));
  EXPECT_EQ(world.awakeBodyCount(), 1U);
}

// A box that touched a never-sleeping slider and was left behind: their island is split for the
// box to sleep while the slider goes on (the sleepiest body's island is split each step).
TEST(Sleep2D, a_resting_body_is_not_kept_awake_by_one_that_once_touched_it) {
  World world;
  addGround(world, 0.0f);
  const BodyId box = addBox(world, {0.0f, 0.5f}, 0.6f);
  const BodyId slider = addBox(world, {1.0f, 0.5f}, 0.0f, false); // touching the box's side
  stepN(world, 10);
  world.setLinearVelocity(slider, {1.0f, 0.0f}); // away on frictionless ground, for ever
  stepN(world, 120);
  EXPECT_TRUE(world.isAwake(slider));
  EXPECT_FALSE(world.isAwake(box));
  EXPECT_NEAR(world.linearVelocity(slider).x, 1.0f, 1e-3f);
}

// Putting a body to sleep puts its island to sleep (as Box2D v3), and waking restores the state
// it fell asleep with, bit for bit.
TEST(Sleep2D, set_awake_acts_on_the_island_and_loses_nothing) {
  World world;
  addGround(world);
  const std::vector<BodyId> stack = addStack(world, 0.0f, 3);
  stepN(world, 20);
  world.setAwake(stack.back(), false);
  for (const BodyId b : stack) {
    EXPECT_FALSE(world.isAwake(b));
  }
  std::vector<Transform2f> asleep;
  for (const BodyId b : stack) {
    asleep.push_back(world.transform(b));
  }
  const std::uint64_t hashAsleep = world.stateHash();
  stepN(world, 100);
  EXPECT_EQ(world.stateHash(), hashAsleep); // a sleeping island is not stepped
  world.setAwake(stack[0], true);
  for (std::size_t i = 0; i < stack.size(); ++i) {
    EXPECT_TRUE(world.isAwake(stack[i]));
    EXPECT_EQ(world.transform(stack[i]), asleep[i]);
    EXPECT_EQ(world.linearVelocity(stack[i]), (Vec2f{}));
  }
}

// A snapshot holds the islands (with a split pending) and the awake set's order: the replay from
// it is the run it was taken from.
TEST(Sleep2D, a_snapshot_replays_islands_and_their_pending_splits) {
  World world;
  addGround(world);
  const std::vector<BodyId> stack = addStack(world, 0.0f, 4);
  const std::vector<BodyId> other = addStack(world, 5.0f, 2);
  stepN(world, 30);
  world.setTransform(stack.back(), {-6.0f, 0.5f}, 0.0f); // a split pending from here
  world.step(dt);
  WorldSnapshot snapshot;
  world.saveState(snapshot);
  const auto run = [&] {
    stepN(world, 200);
    world.applyLinearImpulse(other.back(), {1.0f, 0.0f}, world.worldCenterOfMass(other.back()));
    stepN(world, 100);
    return std::pair{world.stateHash(), world.awakeBodyCount()};
  };
  const auto original = run();
  world.restoreState(snapshot);
  EXPECT_EQ(run(), original);
}

} // namespace
} // namespace impetus::rigid2d
