// Box2D v3's own benchmark scenes as bench/box2d3_benchmark_scenes.cpp describes them (v3's
// counts, positions, densities and sleep settings), and how they behave in Impetus: pyramids
// stand on their segment floors, the motor turns the tumbler's drum at its speed, and the smash
// sleeps until it is hit and conserves momentum after.
#include "rigid2d_scenes.hpp"
#include "scene_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace {

using impetus::Transform2f;
using impetus::Vec2f;
using impetus::rigid2d::BodyType;
namespace bench = impetus::bench;
using bench::test::countOf;
using bench::test::startTransforms;
using bench::test::step;

TEST(ManyPyramids, is_box2d_v3s_four_hundred_pyramids_on_twenty_segment_floors) {
  const bench::Rigid2dScene scene = bench::manyPyramidsScene();
  EXPECT_EQ(scene.name, "many_pyramids");
  EXPECT_EQ(countOf(scene, BodyType::dynamicBody), 20u * 20u * 55u); // v3's 22,000 boxes
  EXPECT_EQ(countOf(scene, BodyType::staticBody), 1u);
  EXPECT_EQ(scene.defaultSteps, 200);
  EXPECT_FALSE(scene.enableSleep);
  std::size_t segments = 0;
  for (const bench::SceneShape& s : scene.shapes) {
    if (s.kind == bench::SceneShape::Kind::segment) {
      ++segments;
      EXPECT_FLOAT_EQ(s.point1.x, -110.0f); // 2 x 0.5 m x 20 columns x (10 + 1) boxes wide
      EXPECT_FLOAT_EQ(s.point2.x, 110.0f);
      EXPECT_FLOAT_EQ(s.point1.y, s.point2.y);
    }
  }
  EXPECT_EQ(segments, 20u);
  // v3's first box: x = (i + 1) e + 2 (j - i) e + centerX - 0.5 with i = j = 0, e = 0.5 and the
  // first column's centerX = -110 + 2 e: -109.
  EXPECT_FLOAT_EQ(scene.bodies[1].position.x, -109.0f);
  EXPECT_FLOAT_EQ(scene.bodies[1].position.y, 0.5f);
  EXPECT_EQ(scene.tops.size(), 400u);
  // The pyramids stand on their floors without overlap (a small grid: the sweep is quadratic in
  // a row's width).
  const bench::Rigid2dScene small = bench::manyPyramidsScene(2, 3);
  EXPECT_LT(bench::largestOverlap(small, startTransforms(small)), 1.0e-5f);
}

TEST(ManyPyramids, built_in_impetus_stand_on_their_segment_floors) {
  const bench::Rigid2dScene scene = bench::manyPyramidsScene(2, 3);
  bench::ImpetusScene built = bench::buildImpetusScene(scene);
  step(built, 60);
  const std::vector<Transform2f> xf = bench::bodyTransforms(built);
  ASSERT_TRUE(bench::allFinite(xf));
  EXPECT_LT(bench::topSink(scene, xf), 0.05f);
  EXPECT_LT(bench::largestOverlap(scene, xf), 0.02f);
}

TEST(Tumbler, is_box2d_v3s_motor_driven_drum_of_density_fifty) {
  const bench::Rigid2dScene scene = bench::tumblerScene();
  EXPECT_EQ(scene.name, "tumbler");
  EXPECT_TRUE(scene.enableSleep);
  EXPECT_EQ(scene.defaultSteps, 750);
  EXPECT_EQ(countOf(scene, BodyType::staticBody), 1u);
  EXPECT_EQ(countOf(scene, BodyType::dynamicBody), 1u + 45u * 45u);
  ASSERT_EQ(scene.joints.size(), 1u);
  EXPECT_TRUE(scene.joints[0].enableMotor);
  EXPECT_FLOAT_EQ(scene.joints[0].motorSpeed, bench::tumblerSpeed);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_FLOAT_EQ(scene.shapes[k].density, bench::tumblerDrumDensity);
  }
  EXPECT_FLOAT_EQ(bench::largestOverlap(scene, startTransforms(scene)), 0.0f);
}

TEST(Tumbler, built_in_impetus_the_motor_turns_the_loaded_drum_at_its_speed) {
  const bench::Rigid2dScene scene = bench::tumblerScene(10);
  bench::ImpetusScene built = bench::buildImpetusScene(scene);
  step(built, 120);
  const std::vector<Transform2f> xf = bench::bodyTransforms(built);
  ASSERT_TRUE(bench::allFinite(xf));
  // A motor of 10^8 N m against a drum of about 2 x 10^5 kg m^2 and a few kilograms of boxes
  // holds its speed: within 1%.
  const impetus::rigid2d::BodyId drum = built.bodies[1];
  EXPECT_NEAR(built.world.angularVelocity(drum), bench::tumblerSpeed, 0.01f * bench::tumblerSpeed);
  // The pin holds the drum's centre (the joint's anchor) at (0, 10), and the boxes stay inside.
  EXPECT_LT(impetus::length(xf[1].p - Vec2f{0.0f, 10.0f}), 0.01f);
  for (std::size_t i = 2; i < xf.size(); ++i) {
    EXPECT_LT(impetus::length(xf[i].p - Vec2f{0.0f, 10.0f}), 9.5f * std::sqrt(2.0f));
  }
}

TEST(Smash, is_box2d_v3s_sleeping_block_and_heavy_box) {
  const bench::Rigid2dScene scene = bench::smashScene();
  EXPECT_EQ(scene.name, "smash");
  EXPECT_TRUE(scene.enableSleep);
  EXPECT_FLOAT_EQ(scene.gravity.y, 0.0f);
  EXPECT_EQ(countOf(scene, BodyType::dynamicBody), 1u + 120u * 80u);
  const bench::SceneBody& projectile = scene.bodies[0];
  EXPECT_TRUE(projectile.awake);
  EXPECT_FALSE(projectile.bullet);
  EXPECT_FLOAT_EQ(projectile.linearVelocity.x, 40.0f);
  EXPECT_FLOAT_EQ(scene.shapes[0].halfWidth, 4.0f);
  EXPECT_FLOAT_EQ(scene.shapes[0].density, 8.0f);
  for (std::size_t i = 1; i < scene.bodies.size(); ++i) {
    EXPECT_FALSE(scene.bodies[i].awake);
  }
  const bench::Rigid2dScene small = bench::smashScene(20, 10);
  EXPECT_LT(bench::largestOverlap(small, startTransforms(small)), 1.0e-5f);
}

TEST(Smash, built_in_impetus_sleeps_until_hit_then_conserves_momentum) {
  const bench::Rigid2dScene scene = bench::smashScene(20, 10);
  bench::ImpetusScene built = bench::buildImpetusScene(scene);
  const auto momentum = [&] {
    double p = 0.0;
    for (const impetus::rigid2d::BodyId b : built.bodies) {
      p += static_cast<double>(built.world.linearVelocity(b).x * built.world.mass(b));
    }
    return p;
  };
  const double before = momentum(); // 512 kg at 40 m/s
  EXPECT_NEAR(before, 512.0 * 40.0, 1e-2);
  step(built, 30); // 0.5 s: the box's face (x = -16 m) is 45.8 m from the block: it hits at 1.15 s
  EXPECT_FALSE(built.world.isAwake(built.bodies[1]));
  step(built, 60);
  EXPECT_TRUE(built.world.isAwake(built.bodies[1]));
  ASSERT_TRUE(bench::allFinite(bench::bodyTransforms(built)));
  // Equal and opposite contact impulses: momentum kept to float sums' accuracy.
  EXPECT_NEAR(momentum(), before, 1e-3 * before);
  EXPECT_LT(built.world.linearVelocity(built.bodies[0]).x, 39.0f); // it gave some away
}

} // namespace
