// Same inputs, same bits: a busy scene (a pyramid, a rain of circles and capsules, a spinning
// kinematic paddle) stepped with no task runner and with thread pools of 1, 2 and 4 threads
// must end in bit-identical states, and so must two runs of the same configuration.
#include <impetus/core/task_runner.hpp>
#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

namespace impetus::rigid2d {
namespace {

/// FNV-1a over the exact bits of every body's transform and velocities.
std::uint64_t stateHash(const World& world, const std::vector<BodyId>& bodies) {
  std::uint64_t hash = 14695981039346656037ULL;
  const auto mix = [&](float x) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    for (int i = 0; i < 4; ++i) {
      hash = (hash ^ ((bits >> (8 * i)) & 0xffU)) * 1099511628211ULL;
    }
  };
  for (BodyId b : bodies) {
    const Transform2f xf = world.transform(b);
    mix(xf.p.x);
    mix(xf.p.y);
    mix(xf.q.c);
    mix(xf.q.s);
    mix(world.linearVelocity(b).x);
    mix(world.linearVelocity(b).y);
    mix(world.angularVelocity(b));
  }
  return hash;
}

std::uint64_t runScene(TaskRunner* runner) {
  WorldDef def;
  def.taskRunner = runner;
  def.enableSleep = false;
  World world(def);
  std::vector<BodyId> bodies;
  const BodyId ground = world.createBody({});
  world.createShape(ground, {}, makeOffsetBox(40.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
  world.createShape(ground, {}, Segment{{-40.0f, 0.0f}, {-40.0f, 30.0f}});
  world.createShape(ground, {}, Segment{{40.0f, 0.0f}, {40.0f, 30.0f}});
  BodyDef dynamic;
  dynamic.type = BodyType::dynamicBody;
  for (int row = 0; row < 15; ++row) {
    for (int i = 0; i < 15 - row; ++i) {
      dynamic.position = {-20.0f + static_cast<float>(i) - 0.5f * static_cast<float>(14 - row),
                          0.5f + static_cast<float>(row)};
      const BodyId b = world.createBody(dynamic);
      world.createShape(b, {}, makeBox(0.5f, 0.5f));
      bodies.push_back(b);
    }
  }
  ShapeDef bouncy;
  bouncy.restitution = 0.3f;
  bouncy.rollingResistance = 0.05f;
  for (int i = 0; i < 400; ++i) {
    dynamic.position = {5.0f + 0.61f * static_cast<float>(i % 40), 2.0f + 0.7f * static_cast<float>(i / 40)};
    const BodyId b = world.createBody(dynamic);
    if (i % 3 == 0) {
      world.createShape(b, bouncy, Capsule{{-0.2f, 0.0f}, {0.2f, 0.0f}, 0.15f});
    } else {
      world.createShape(b, bouncy, Circle{{}, 0.25f});
    }
    bodies.push_back(b);
  }
  BodyDef paddle;
  paddle.type = BodyType::kinematicBody;
  paddle.position = {15.0f, 3.0f};
  paddle.angularVelocity = 1.5f;
  const BodyId p = world.createBody(paddle);
  world.createShape(p, {}, makeBox(4.0f, 0.2f));
  bodies.push_back(p);
  for (int step = 0; step < 120; ++step) {
    world.step(1.0f / 60.0f);
  }
  return stateHash(world, bodies);
}

TEST(Determinism2D, identical_run_after_run_and_at_any_thread_count) {
  const std::uint64_t reference = runScene(nullptr);
  EXPECT_EQ(runScene(nullptr), reference) << "two runs differ";
  for (int threads : {1, 2, 4}) {
    ThreadPool pool(threads);
    EXPECT_EQ(runScene(&pool), reference) << threads << " threads";
  }
}

} // namespace
} // namespace impetus::rigid2d
