// Box2D v3's rain as bench/rain_scene.cpp describes it: v3's ragdoll (bones of the right mass,
// joints where v3 puts them), the spawn schedule (a column every 8 steps, the oldest replaced
// once 40 stand), and in Impetus ragdolls that fall 40 m, land on their floor and stay whole.
#include "rigid2d_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace {

using impetus::Vec2f;
using impetus::rigid2d::BodyType;
namespace bench = impetus::bench;
using bench::SceneShape;

/// A spawner that only counts: what the script asks for, step by step.
class CountingSpawner final : public bench::SceneSpawner {
public:
  std::uint32_t spawn(const bench::SceneContent& group) override {
    groupBodies.push_back(group.bodies.size());
    ++live;
    ++spawned;
    return static_cast<std::uint32_t>(groupBodies.size() - 1);
  }
  void destroy(std::uint32_t group) override {
    EXPECT_LT(group, groupBodies.size());
    EXPECT_NE(groupBodies[group], 0u) << "group " << group << " destroyed twice";
    groupBodies[group] = 0;
    --live;
  }
  std::vector<std::size_t> groupBodies;
  int live = 0;
  int spawned = 0;
};

TEST(RagdollRain, ragdoll_is_box2d_v3s_human_with_capsule_bones_of_the_closed_form_mass) {
  const bench::SceneContent human = bench::humanRagdoll({3.0f, 40.0f}, -1);
  ASSERT_EQ(human.bodies.size(), 11u);
  ASSERT_EQ(human.joints.size(), 10u);
  ASSERT_EQ(human.shapes.size(), 13u);                 // 11 capsules and two feet
  EXPECT_FLOAT_EQ(human.bodies[0].position.y, 40.95f); // v3's hip: 0.95 m above the feet
  for (const bench::SceneJoint& j : human.joints) {
    EXPECT_TRUE(j.enableLimit && j.enableMotor && j.enableSpring);
    EXPECT_FLOAT_EQ(j.hertz, 5.0f);
    EXPECT_FLOAT_EQ(j.anchor.x, 3.0f);
    EXPECT_LE(j.lowerAngle, j.upperAngle);
  }
  // Built in Impetus, each bone weighs its capsule's area (pi r^2 + 2 r L at 1 kg/m^2), plus
  // the feet's rounded polygons on the lower legs.
  impetus::rigid2d::World world;
  const std::vector<impetus::rigid2d::BodyId> ids = bench::addToImpetusWorld(world, human);
  for (const SceneShape& s : human.shapes) {
    if (s.kind != SceneShape::Kind::capsule || s.body == 4 || s.body == 6) {
      continue;
    }
    const float length = impetus::length(s.point2 - s.point1);
    const float area = impetus::pi<float> * s.radius * s.radius + 2.0f * s.radius * length;
    EXPECT_NEAR(world.mass(ids[s.body]), area, 1e-5f * area) << "bone " << s.body;
  }
  EXPECT_GT(world.mass(ids[4]), 0.0f);
}

TEST(RagdollRain, spawns_a_column_every_eight_steps_and_then_replaces_the_oldest) {
  const bench::Rigid2dScene scene = bench::rainScene();
  EXPECT_EQ(scene.name, "rain");
  EXPECT_EQ(scene.defaultSteps, 1000);
  EXPECT_TRUE(scene.enableSleep);
  EXPECT_FALSE(scene.box2d241);
  EXPECT_EQ(scene.bodies.size(), 1u);
  EXPECT_EQ(scene.shapes.size(), 5u * 501u); // five floors of 501 boxes
  ASSERT_TRUE(scene.makeScript);
  const bench::SceneScript script = scene.makeScript();
  CountingSpawner spawner;
  for (int step = 0; step < scene.defaultSteps; ++step) {
    script(step, spawner);
    const int columns = std::min(step / bench::rainSpawnInterval + 1, bench::rainColumns);
    ASSERT_EQ(spawner.live, columns * bench::rainFloors) << "step " << step;
  }
  // 125 spawning steps of five groups of five ragdolls of 11 bones.
  EXPECT_EQ(spawner.spawned, 125 * bench::rainFloors);
  EXPECT_EQ(spawner.groupBodies[0], 0u);
  EXPECT_EQ(spawner.groupBodies.back(), 55u);
  // A fresh script starts again from nothing.
  CountingSpawner again;
  scene.makeScript()(0, again);
  EXPECT_EQ(again.live, bench::rainFloors);
}

TEST(RagdollRain, built_in_impetus_ragdolls_land_on_their_floors_whole) {
  const bench::Rigid2dScene scene = bench::rainScene();
  bench::ImpetusScene built = bench::buildImpetusScene(scene);
  bench::ImpetusSpawner spawner(built.world);
  scene.makeScript()(0, spawner); // the first column: one group above each floor
  ASSERT_EQ(spawner.liveBodies(), 5u * 55u);
  for (int i = 0; i < 240; ++i) { // 4 s: a 40 m fall takes 2.8 s
    built.world.step(bench::sceneTimeStep);
  }
  for (const impetus::rigid2d::BodyId b : spawner.bodies()) {
    const Vec2f p = built.world.position(b);
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
    // Resting on the floor below its spawn point: floors' tops at 45 k + 0.25 m.
    const float above = p.y - 0.25f;
    const float floorTop = 45.0f * std::floor(above / 45.0f) + 0.25f;
    EXPECT_GT(p.y, floorTop - 0.02f);
    EXPECT_LT(p.y, floorTop + 1.6f) << "a ragdoll still falling or standing on another";
  }
  // Whole: every pin's two anchors within 1 cm after the landing (v3's ragdolls stay within a
  // few millimetres too).
  std::vector<impetus::rigid2d::JointId> joints;
  built.world.jointIds(joints);
  ASSERT_EQ(joints.size(), 5u * 5u * 10u);
  for (const impetus::rigid2d::JointId j : joints) {
    EXPECT_LT(impetus::length(built.world.jointAnchorB(j) - built.world.jointAnchorA(j)), 0.01f);
  }
}

} // namespace
