// After warm-up, a world step allocates nothing: every per-step array is reused. This binary
// replaces the global operator new to count allocations (which is why it is its own test
// executable).
#include <impetus/core/task_runner.hpp>
#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> allocations{0};
} // namespace

void* operator new(std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) {
    return p;
  }
  throw std::bad_alloc();
}
// This replaces the global new and delete as a pair (malloc and free), which GCC cannot see
// when it inlines a test's `new` next to this `delete`.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace impetus::rigid2d {
namespace {

void buildScene(World& world) {
  const BodyId ground = world.createBody({});
  world.createShape(ground, {}, makeOffsetBox(30.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
  BodyDef def;
  def.type = BodyType::dynamicBody;
  for (int row = 0; row < 10; ++row) {
    for (int i = 0; i < 10 - row; ++i) {
      def.position = {static_cast<float>(i) - 0.5f * static_cast<float>(9 - row), 0.5f + static_cast<float>(row)};
      world.createShape(world.createBody(def), {}, makeBox(0.5f, 0.5f));
    }
  }
  // A hanging chain: joints must not allocate either.
  BodyId previous = ground;
  for (int i = 0; i < 6; ++i) {
    def.position = {-20.0f + 0.5f * static_cast<float>(i) + 0.25f, 8.0f};
    const BodyId link = world.createBody(def);
    world.createShape(link, {}, makeBox(0.25f, 0.05f));
    RevoluteJointDef pin;
    pin.bodyA = previous;
    pin.bodyB = link;
    pin.localAnchorA = previous == ground ? Vec2f{-20.0f, 8.0f} : Vec2f{0.25f, 0.0f};
    pin.localAnchorB = {-0.25f, 0.0f};
    world.createJoint(pin);
    previous = link;
  }
  ShapeDef bouncy;
  bouncy.restitution = 0.5f;
  for (int i = 0; i < 40; ++i) {
    def.position = {12.0f + 0.6f * static_cast<float>(i % 10), 1.0f + 0.6f * static_cast<float>(i / 10)};
    world.createShape(world.createBody(def), bouncy, Circle{{}, 0.25f});
  }
}

long allocationsOverSteps(World& world, int steps) {
  const long before = allocations.load();
  for (int i = 0; i < steps; ++i) {
    world.step(1.0f / 60.0f);
  }
  return allocations.load() - before;
}

TEST(Allocation2D, a_warmed_up_step_allocates_nothing) {
  WorldDef def;
  def.enableSleep = false;
  World world(def);
  const long beforeBuild = allocations.load();
  buildScene(world);
  ASSERT_GT(allocations.load(), beforeBuild) << "the counter must see the world being built";
  (void)allocationsOverSteps(world, 240); // contacts created, arrays grown, piles settled
  EXPECT_EQ(allocationsOverSteps(world, 120), 0);
}

TEST(Allocation2D, nor_with_sleeping_and_a_thread_pool) {
  ThreadPool pool(2);
  WorldDef def;
  def.taskRunner = &pool;
  World world(def);
  buildScene(world);
  (void)allocationsOverSteps(world, 240);
  EXPECT_EQ(allocationsOverSteps(world, 120), 0);
}

TEST(Allocation2D, saving_a_snapshot_again_reuses_its_storage) {
  World world;
  buildScene(world);
  (void)allocationsOverSteps(world, 240); // as above: contacts created, piles settled
  WorldSnapshot snapshot;
  world.saveState(snapshot);
  const long before = allocations.load();
  for (int i = 0; i < 10; ++i) {
    world.step(1.0f / 60.0f);
    world.saveState(snapshot); // the same bodies, shapes and joints: fits the bytes it holds
  }
  // The steps allocate nothing once warmed up (above), and neither do the saves.
  EXPECT_EQ(allocations.load() - before, 0);
  world.restoreState(snapshot);
  EXPECT_EQ(allocations.load() - before, 0);
}

} // namespace
} // namespace impetus::rigid2d
