// Rollback: a world restored from a snapshot and stepped again must retrace its first run bit for
// bit (the same state hash), as lockstep games and replays need; snapshots are compact, and a
// snapshot that does not fit the world is refused without touching it.
#include "mixed_scene.hpp"

#include <impetus/error.hpp>

#include <gtest/gtest.h>

#include <iostream>

namespace impetus::rigid2d {
namespace {

using test::makeMixedScene;

constexpr float dt = 1.0f / 60.0f;

void stepN(World& world, int n) {
  for (int i = 0; i < n; ++i) {
    world.step(dt);
  }
}

TEST(Snapshot2D, restore_and_step_again_retraces_the_run_bit_for_bit) {
  World world = makeMixedScene();
  stepN(world, 45); // mid-fall: contacts beginning and ending, joints swinging
  WorldSnapshot snapshot;
  world.saveState(snapshot);
  const std::uint64_t atSave = world.stateHash();
  stepN(world, 75);
  const std::uint64_t first = world.stateHash();
  ASSERT_NE(first, atSave);
  for (int rollback = 0; rollback < 3; ++rollback) {
    world.restoreState(snapshot);
    EXPECT_EQ(world.stateHash(), atSave);
    stepN(world, 75);
    EXPECT_EQ(world.stateHash(), first) << "rollback " << rollback;
  }
  // The same as a world that never rolled back.
  World straight = makeMixedScene();
  stepN(straight, 120);
  EXPECT_EQ(straight.stateHash(), first);
}

TEST(Snapshot2D, a_snapshot_restores_into_a_world_built_the_same_way) {
  // A replay: the snapshot of one world continues in another built by the same code.
  World original = makeMixedScene();
  stepN(original, 30);
  WorldSnapshot snapshot;
  original.saveState(snapshot);
  stepN(original, 30);
  World replica = makeMixedScene();
  replica.restoreState(snapshot);
  stepN(replica, 30);
  EXPECT_EQ(replica.stateHash(), original.stateHash());
}

TEST(Snapshot2D, sleeping_islands_wake_and_sleep_as_they_did) {
  World world;
  const BodyId ground = world.createBody({});
  world.createShape(ground, {}, makeOffsetBox(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
  BodyDef box;
  box.type = BodyType::dynamicBody;
  std::vector<BodyId> stack;
  for (int i = 0; i < 8; ++i) {
    box.position = {0.0f, 0.5f + static_cast<float>(i)};
    stack.push_back(world.createBody(box));
    world.createShape(stack.back(), {}, makeBox(0.5f, 0.5f));
  }
  stepN(world, 240); // asleep by now
  ASSERT_FALSE(world.isAwake(stack.back()));
  WorldSnapshot snapshot;
  world.saveState(snapshot);
  world.applyLinearImpulse(stack.back(), {3.0f, 0.0f}, world.transform(stack.back()).p); // knock the top box off
  stepN(world, 120);
  const std::uint64_t knocked = world.stateHash();
  world.restoreState(snapshot);
  EXPECT_FALSE(world.isAwake(stack.back()));
  world.applyLinearImpulse(stack.back(), {3.0f, 0.0f}, world.transform(stack.back()).p);
  stepN(world, 120);
  EXPECT_EQ(world.stateHash(), knocked);
}

// That saving again reuses the storage (allocates nothing) is checked where allocations are
// counted: tests/rigid2d/allocation_test.cpp.
TEST(Snapshot2D, is_compact) {
  World world = makeMixedScene();
  stepN(world, 60);
  WorldSnapshot snapshot;
  world.saveState(snapshot);
  std::vector<BodyId> bodies;
  world.bodyIds(bodies);
  const double perBody = static_cast<double>(snapshot.sizeBytes()) / static_cast<double>(bodies.size());
  std::cout << "snapshot: " << snapshot.sizeBytes() << " bytes for " << bodies.size() << " bodies (" << perBody
            << " bytes per body, contacts and joints included)\n";
  // 61 bytes of motion, sleep and the contact list's head per body, 16 per shape, its share of
  // the contacts (here about 2.6 per body, each about 230 bytes with its manifold, warm-start
  // impulses, the manifold's frame for reuse and its places in the two bodies' lists), and of
  // the awake set and the islands (4 bytes per awake body and contact, 4 per body and 9 per
  // island).
  EXPECT_LT(perBody, 920.0);
  world.saveState(snapshot); // the same state again: the same bytes
  const std::size_t size = snapshot.sizeBytes();
  world.saveState(snapshot);
  EXPECT_EQ(snapshot.sizeBytes(), size);
}

TEST(Snapshot2D, refuses_a_snapshot_that_does_not_fit_and_leaves_the_world_alone) {
  World world = makeMixedScene();
  WorldSnapshot empty;
  EXPECT_THROW(world.restoreState(empty), Error);
  stepN(world, 10);
  WorldSnapshot snapshot;
  world.saveState(snapshot);
  BodyDef extra;
  extra.type = BodyType::dynamicBody;
  extra.position = {0.0f, 50.0f};
  world.createShape(world.createBody(extra), {}, Circle{{}, 0.5f});
  const std::uint64_t before = world.stateHash();
  try {
    world.restoreState(snapshot);
    FAIL() << "a snapshot of another structure was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("snapshot"), std::string::npos) << e.what();
  }
  EXPECT_EQ(world.stateHash(), before);
}

} // namespace
} // namespace impetus::rigid2d
