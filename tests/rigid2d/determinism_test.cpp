// Same inputs, same bits: the mixed scene stepped with no task runner and with thread pools of
// 1, 2 and 4 threads must end in bit-identical states, and so must two runs of the same
// configuration; and the baseline lane width (SSE2: four contacts at once) must match the widest
// the CPU runs (AVX2: eight).
#include "mixed_scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace impetus::rigid2d {
namespace {

using test::runMixedScene;

TEST(Determinism2D, identical_run_after_run_and_at_any_thread_count) {
  const std::uint64_t reference = runMixedScene(nullptr);
  EXPECT_EQ(runMixedScene(nullptr), reference) << "two runs differ";
  for (int threads : {1, 2, 4}) {
    ThreadPool pool(threads);
    EXPECT_EQ(runMixedScene(&pool), reference) << threads << " threads";
  }
}

/// A hanging cloth of `side` x `side` small discs, each pinned to its right and lower neighbours
/// (the top row to the ground), swung by gravity for `steps` steps; the state hash at the end.
std::uint64_t runJointGrid(TaskRunner* runner, int side, int steps, ConstraintGraphCounts* graph = nullptr) {
  WorldDef def;
  def.taskRunner = runner;
  World world(def);
  const BodyId ground = world.createBody({});
  std::vector<BodyId> bodies;
  ShapeDef shape;
  shape.filter.group = -1; // the cloth does not collide with itself
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      BodyDef body;
      body.type = BodyType::dynamicBody;
      body.position = {0.5f * static_cast<float>(j), -0.5f * static_cast<float>(i)};
      const BodyId id = world.createBody(body);
      world.createShape(id, shape, Circle{{}, 0.2f});
      RevoluteJointDef pin;
      pin.localAnchorB = {};
      if (j > 0) {
        pin.bodyA = bodies.back();
        pin.bodyB = id;
        pin.localAnchorA = {0.5f, 0.0f};
        world.createJoint(pin);
      }
      if (i > 0) {
        pin.bodyA = bodies[bodies.size() - static_cast<std::size_t>(side)];
        pin.bodyB = id;
        pin.localAnchorA = {0.0f, -0.5f};
        world.createJoint(pin);
      } else if (j == 0 || j == side - 1) {
        pin.bodyA = ground;
        pin.bodyB = id;
        pin.localAnchorA = body.position;
        world.createJoint(pin);
      }
      bodies.push_back(id);
    }
  }
  for (int k = 0; k < steps; ++k) {
    world.step(1.0f / 60.0f);
  }
  if (graph != nullptr) {
    *graph = world.constraintGraph();
  }
  return world.stateHash();
}

TEST(Determinism2D, joints_are_coloured_and_identical_at_any_thread_count) {
  ConstraintGraphCounts graph;
  const std::uint64_t reference = runJointGrid(nullptr, 40, 30, &graph);
  // The 3,122 joints are spread over colours (a disc is in four joints at most: four or five
  // colours suffice), hundreds to a colour, so that the pool runs them on several threads.
  std::uint32_t coloured = 0;
  std::uint32_t largest = 0;
  for (const std::uint32_t n : graph.colourJoints) {
    coloured += n;
    largest = std::max(largest, n);
  }
  EXPECT_EQ(coloured + graph.overflowJoints, 3122u);
  EXPECT_EQ(graph.overflowJoints, 0u);
  EXPECT_GT(largest, 500u);
  for (int threads : {1, 2, 4}) {
    ThreadPool pool(threads);
    EXPECT_EQ(runJointGrid(&pool, 40, 30), reference) << threads << " threads";
  }
}

TEST(Determinism2D, the_reference_scene_hash_is_pinned) {
  // The value and when to change it: test::pinnedMixedSceneHash (mixed_scene.hpp).
  EXPECT_EQ(runMixedScene(nullptr), test::pinnedMixedSceneHash) << std::hex << "now 0x" << runMixedScene(nullptr);
  EXPECT_EQ(runMixedScene(nullptr, SimdLevel::baseline), test::pinnedMixedSceneHash) << "SSE2";
}

TEST(Determinism2D, the_state_hash_sees_one_bit_of_one_body) {
  World world;
  BodyDef def;
  def.type = BodyType::dynamicBody;
  const BodyId a = world.createBody(def);
  def.position = {2.0f, 0.0f};
  world.createBody(def);
  const std::uint64_t before = world.stateHash();
  EXPECT_EQ(world.stateHash(), before);
  world.setLinearVelocity(a, {std::nextafter(0.0f, 1.0f), 0.0f}); // the smallest float
  EXPECT_NE(world.stateHash(), before);
  world.setLinearVelocity(a, {});
  EXPECT_EQ(world.stateHash(), before);
}

TEST(Determinism2D, identical_at_any_simd_width) {
  WorldDef baselineDef;
  baselineDef.simd = SimdLevel::baseline;
  const World baseline(baselineDef);
  const World widest;
  EXPECT_EQ(baseline.contactLanes(), 4);
  EXPECT_GE(widest.contactLanes(), baseline.contactLanes());
  if (widest.contactLanes() == baseline.contactLanes()) {
    // Without AVX2 both worlds run the same kernels: comparing them would prove nothing.
    GTEST_SKIP() << "this CPU has no wider lanes than the baseline (" << baseline.contactSimd() << ")";
  }
  EXPECT_EQ(runMixedScene(nullptr, SimdLevel::baseline), runMixedScene(nullptr, SimdLevel::widest))
      << "baseline (" << baseline.contactSimd() << ") and widest (" << widest.contactSimd() << ") differ";
}

} // namespace
} // namespace impetus::rigid2d
