// A busy 2D scene and the hash of its exact state (World::stateHash): what the determinism tests step with different
// task runners and compare.
#pragma once

#include <impetus/core/task_runner.hpp>
#include <impetus/rigid2d/world.hpp>

#include <cstdint>
#include <vector>

namespace impetus::rigid2d::test {

/// A busy scene: a pyramid, a rain of circles and capsules with restitution and rolling
/// resistance, a spinning kinematic paddle, a jointed chain, a rope; built, not yet stepped.
inline World makeMixedScene(TaskRunner* runner = nullptr, SimdLevel simd = SimdLevel::widest) {
  WorldDef def;
  def.taskRunner = runner;
  def.simd = simd;
  def.enableSleep = false;
  World world(def);
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
  }
  // A chain of 10 links hanging from the left wall (revolute joints with limits), a rope and a
  // slider, so the joints take part too.
  BodyId previous = ground;
  for (int i = 0; i < 10; ++i) {
    dynamic.position = {-35.0f + 0.5f * static_cast<float>(i) + 0.25f, 20.0f};
    const BodyId link = world.createBody(dynamic);
    world.createShape(link, {}, makeBox(0.25f, 0.05f));
    RevoluteJointDef pin;
    pin.bodyA = previous;
    pin.bodyB = link;
    pin.localAnchorA = previous == ground ? Vec2f{-35.0f, 20.0f} : Vec2f{0.25f, 0.0f};
    pin.localAnchorB = {-0.25f, 0.0f};
    pin.enableLimit = true;
    pin.lowerAngle = -1.0f;
    pin.upperAngle = 1.0f;
    world.createJoint(pin);
    previous = link;
  }
  dynamic.position = {-25.0f, 15.0f};
  const BodyId weight = world.createBody(dynamic);
  world.createShape(weight, {}, Circle{{}, 0.3f});
  DistanceJointDef rope;
  rope.bodyA = ground;
  rope.bodyB = weight;
  rope.localAnchorA = {-28.0f, 18.0f};
  rope.length = 4.0f;
  rope.enableSpring = true;
  rope.enableLimit = true;
  rope.maxLength = 4.5f;
  world.createJoint(rope);
  BodyDef paddle;
  paddle.type = BodyType::kinematicBody;
  paddle.position = {15.0f, 3.0f};
  paddle.angularVelocity = 1.5f;
  const BodyId p = world.createBody(paddle);
  world.createShape(p, {}, makeBox(4.0f, 0.2f));
  return world;
}

/// The mixed scene's state hash after 120 steps (runMixedScene), pinned: x86-64, g++ 12 at -O1
/// to -O3 and clang 14 (CI checks both: Determinism2D.the_reference_scene_hash_is_pinned and
/// `./run fuzz`'s pinned_hash_check), under the sanitizers or not, SSE2 or AVX2: all agree. A
/// change of the solver's arithmetic changes it: when that is intended, update the value and say
/// why in the commit and in docs/reliability.md ("Pinned", where each earlier value is listed
/// with its reason); when it is not, the check caught it.
inline constexpr std::uint64_t pinnedMixedSceneHash = 0x56b38864452c15b7ULL;

/// The hash of the scene's state after 120 steps of 1/60 s.
inline std::uint64_t runMixedScene(TaskRunner* runner, SimdLevel simd = SimdLevel::widest) {
  World world = makeMixedScene(runner, simd);
  for (int step = 0; step < 120; ++step) {
    world.step(1.0f / 60.0f);
  }
  return world.stateHash();
}

} // namespace impetus::rigid2d::test
