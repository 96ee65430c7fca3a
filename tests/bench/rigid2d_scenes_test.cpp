// The 2D benchmark scenes are built as bench/rigid2d_scenes.hpp describes them (counts, sizes,
// no initial overlap) and behave in Impetus: finite, standing, falling where they should. The
// quality figures the benchmark prints (sink, overlap) measure what they say.
#include "rigid2d_scenes.hpp"
#include "scene_checks.hpp"

#include <impetus/error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace {

using impetus::Transform2f;
using impetus::Vec2f;
using impetus::rigid2d::BodyType;
namespace bench = impetus::bench;
using bench::test::countOf;
using bench::test::startTransforms;
using bench::test::step;

TEST(LargePyramid, is_5050_boxes_of_half_size_half_a_metre_on_a_200_by_2_ground_box) {
  const bench::Rigid2dScene scene = bench::largePyramidScene();
  EXPECT_EQ(scene.name, "large_pyramid");
  EXPECT_EQ(scene.bodies.size(), 5051u);
  EXPECT_EQ(scene.shapes.size(), 5051u);
  EXPECT_EQ(countOf(scene, BodyType::dynamicBody), 5050u);
  EXPECT_EQ(countOf(scene, BodyType::staticBody), 1u);
  EXPECT_EQ(scene.defaultSteps, 500);
  const bench::SceneShape& ground = scene.shapes[0];
  EXPECT_EQ(ground.kind, bench::SceneShape::Kind::box);
  EXPECT_FLOAT_EQ(ground.halfWidth, 100.0f);
  EXPECT_FLOAT_EQ(ground.halfHeight, 1.0f);
  EXPECT_FLOAT_EQ(scene.bodies[0].position.y + ground.center.y + ground.halfHeight, 0.0f); // top at y = 0
  for (std::size_t i = 1; i < scene.shapes.size(); ++i) {
    EXPECT_FLOAT_EQ(scene.shapes[i].halfWidth, 0.5f);
    EXPECT_FLOAT_EQ(scene.shapes[i].halfHeight, 0.5f);
  }
  // The base row spans x in [-50, 50] on the ground; the top box stands on x = 0 at y = 99.5.
  EXPECT_FLOAT_EQ(scene.bodies[1].position.x, -49.5f);
  EXPECT_FLOAT_EQ(scene.bodies[1].position.y, 0.5f);
  EXPECT_FLOAT_EQ(scene.bodies[100].position.x, 49.5f);
  ASSERT_EQ(scene.tops.size(), 1u);
  EXPECT_FLOAT_EQ(scene.bodies[scene.tops[0]].position.x, 0.0f);
  EXPECT_FLOAT_EQ(scene.bodies[scene.tops[0]].position.y, 99.5f);
}

TEST(LargePyramid, starts_touching_without_overlap) {
  const bench::Rigid2dScene scene = bench::largePyramidScene(30);
  const std::vector<Transform2f> start = startTransforms(scene);
  EXPECT_LT(bench::largestOverlap(scene, start), 1.0e-5f);
  EXPECT_FLOAT_EQ(bench::topSink(scene, start), 0.0f);
}

TEST(LargePyramid, built_in_impetus_stays_finite_and_standing) {
  // A smaller pyramid of the same construction keeps the test fast.
  const bench::Rigid2dScene scene = bench::largePyramidScene(20);
  bench::ImpetusScene built = bench::buildImpetusScene(scene);
  EXPECT_EQ(built.world.bodyCount(), 211u);
  EXPECT_EQ(built.world.shapeCount(), 211u);
  EXPECT_EQ(built.world.settings().substeps, 4);
  EXPECT_FLOAT_EQ(built.world.settings().gravity.y, -10.0f);
  EXPECT_FLOAT_EQ(built.world.mass(built.bodies[1]), 1.0f); // 1 m^2 at 1 kg/m^2
  step(built, 60);
  const std::vector<Transform2f> xf = bench::bodyTransforms(built);
  ASSERT_TRUE(bench::allFinite(xf));
  EXPECT_LT(bench::topSink(scene, xf), 0.05f);
  EXPECT_LT(bench::largestOverlap(scene, xf), 0.02f);
  EXPECT_GT(built.world.contactCount(), 200u);
}

TEST(PyramidRow, is_ten_pyramids_of_base_twenty_side_by_side) {
  const bench::Rigid2dScene scene = bench::pyramidRowScene();
  EXPECT_EQ(scene.name, "pyramid_row");
  EXPECT_EQ(countOf(scene, BodyType::dynamicBody), 10u * 210u);
  EXPECT_EQ(countOf(scene, BodyType::staticBody), 1u);
  ASSERT_EQ(scene.tops.size(), 10u);
  const std::vector<Transform2f> start = startTransforms(scene);
  EXPECT_LT(bench::largestOverlap(scene, start), 1.0e-5f);
  // Every box stands on the ground: the ground's top is y = 0 and it is wider than the row.
  const bench::SceneShape& ground = scene.shapes[0];
  for (const bench::SceneBody& b : scene.bodies) {
    if (b.type == BodyType::dynamicBody) {
      EXPECT_LT(std::abs(b.position.x), ground.halfWidth);
    }
  }
}

TEST(PyramidRow, built_in_impetus_stay_finite_and_standing) {
  const bench::Rigid2dScene scene = bench::pyramidRowScene(3, 10);
  bench::ImpetusScene built = bench::buildImpetusScene(scene);
  EXPECT_EQ(built.world.bodyCount(), 1u + 3u * 55u);
  step(built, 60);
  const std::vector<Transform2f> xf = bench::bodyTransforms(built);
  ASSERT_TRUE(bench::allFinite(xf));
  EXPECT_LT(bench::topSink(scene, xf), 0.05f);
}

TEST(Rain, has_the_requested_circles_in_an_open_box_as_wide_as_the_columns) {
  for (const std::size_t count : {1u, 10u, 1000u, 10000u, 100000u}) {
    const bench::Rigid2dScene scene = bench::circleRainScene(count);
    EXPECT_EQ(countOf(scene, BodyType::dynamicBody), count);
    EXPECT_EQ(countOf(scene, BodyType::staticBody), 1u);
    EXPECT_EQ(scene.shapes.size(), count + 3u); // floor, two walls
    EXPECT_TRUE(scene.tops.empty());
    const float wallInner = scene.shapes[2].center.x - scene.shapes[2].halfWidth;
    for (std::size_t i = 3; i < scene.shapes.size(); ++i) {
      const bench::SceneShape& s = scene.shapes[i];
      EXPECT_EQ(s.kind, bench::SceneShape::Kind::circle);
      EXPECT_FLOAT_EQ(s.radius, bench::rainRadius);
      const Vec2f p = scene.bodies[s.body].position;
      EXPECT_LT(std::abs(p.x) + bench::rainRadius, wallInner);
      EXPECT_GE(p.y, 1.0f);
    }
  }
  EXPECT_EQ(bench::circleRainScene(1000).name, "circle_rain_1k");
  EXPECT_EQ(bench::circleRainScene(100000).name, "circle_rain_100k");
  // The box grows with the count, so the pile is equally deep: 10 times the circles, about 10
  // times the width.
  const float w1 = bench::circleRainScene(1000).shapes[0].halfWidth;
  const float w10 = bench::circleRainScene(10000).shapes[0].halfWidth;
  EXPECT_NEAR(w10 / w1, 10.0f, 0.5f);
}

TEST(Rain, circles_land_and_stay_in_the_box) {
  const bench::Rigid2dScene scene = bench::circleRainScene(500);
  const std::vector<Transform2f> start = startTransforms(scene);
  EXPECT_FLOAT_EQ(bench::largestOverlap(scene, start), 0.0f);
  bench::ImpetusScene built = bench::buildImpetusScene(scene);
  step(built, 150); // 2.5 s: the top row (7.75 m up) has landed
  const std::vector<Transform2f> xf = bench::bodyTransforms(built);
  ASSERT_TRUE(bench::allFinite(xf));
  const float wallInner = scene.shapes[2].center.x - scene.shapes[2].halfWidth;
  float highest = 0.0f;
  for (std::size_t i = 1; i < xf.size(); ++i) {
    EXPECT_GT(xf[i].p.y, bench::rainRadius - 0.02f);
    EXPECT_LT(std::abs(xf[i].p.x), wallInner);
    highest = std::max(highest, xf[i].p.y);
  }
  EXPECT_LT(highest, 6.0f); // a pile of about 8 layers (0.43 m each), not the initial 7.75 m
  EXPECT_LT(bench::largestOverlap(scene, xf), 0.05f);
}

TEST(KinematicTumbler, is_a_turning_kinematic_drum_holding_a_grid_of_small_boxes) {
  const bench::Rigid2dScene scene = bench::kinematicTumblerScene();
  EXPECT_EQ(countOf(scene, BodyType::kinematicBody), 1u);
  EXPECT_EQ(countOf(scene, BodyType::dynamicBody), 45u * 45u);
  EXPECT_EQ(scene.shapes.size(), 4u + 45u * 45u);
  EXPECT_GT(scene.bodies[0].angularVelocity, 0.4f);
  const std::vector<Transform2f> start = startTransforms(scene);
  EXPECT_FLOAT_EQ(bench::largestOverlap(scene, start), 0.0f);

  const bench::Rigid2dScene small = bench::kinematicTumblerScene(10);
  bench::ImpetusScene built = bench::buildImpetusScene(small);
  step(built, 120);
  const std::vector<Transform2f> xf = bench::bodyTransforms(built);
  ASSERT_TRUE(bench::allFinite(xf));
  // The drum turned at its speed for 2 s; every box is still inside it (distance from its
  // centre < the half-diagonal of the inner square).
  EXPECT_NEAR(built.world.angle(built.bodies[0]), 2.0f * bench::tumblerSpeed, 1.0e-3f);
  const Vec2f center{0.0f, 10.0f};
  for (std::size_t i = 1; i < xf.size(); ++i) {
    EXPECT_LT(impetus::length(xf[i].p - center), 9.5f * std::sqrt(2.0f));
  }
}

TEST(SmashAwake, is_a_block_of_small_boxes_and_a_fast_big_box_in_zero_gravity) {
  const bench::Rigid2dScene scene = bench::smashAwakeScene(20);
  EXPECT_EQ(scene.name, "smash_awake");
  EXPECT_EQ(countOf(scene, BodyType::dynamicBody), 20u * 20u + 1u);
  EXPECT_FLOAT_EQ(scene.gravity.y, 0.0f);
  EXPECT_FLOAT_EQ(scene.bodies.back().linearVelocity.x, 40.0f);
  EXPECT_TRUE(scene.bodies.back().bullet);
  const std::vector<Transform2f> start = startTransforms(scene);
  EXPECT_LT(bench::largestOverlap(scene, start), 1.0e-5f);
}

// Nothing is static and there is no gravity: the smash conserves linear momentum (contact
// impulses come in equal and opposite pairs), whatever the solver does with energy.
TEST(SmashAwake, built_in_impetus_conserves_momentum) {
  const bench::Rigid2dScene scene = bench::smashAwakeScene(20);
  bench::ImpetusScene built = bench::buildImpetusScene(scene);
  const auto momentum = [&] {
    impetus::Vec2d p;
    for (impetus::rigid2d::BodyId b : built.bodies) {
      const impetus::Vec2f v = built.world.linearVelocity(b) * built.world.mass(b);
      p += impetus::Vec2d{v.x, v.y};
    }
    return p;
  };
  const impetus::Vec2d before = momentum(); // 16 kg at 40 m/s: 640 kg m/s
  step(built, 120);
  const impetus::Vec2d after = momentum();
  ASSERT_TRUE(bench::allFinite(bench::bodyTransforms(built)));
  // Float sums of impulses over 400 bodies and 120 steps: 1e-3 relative is generous.
  EXPECT_NEAR(after.x, before.x, 1e-3 * before.x);
  EXPECT_NEAR(after.y, 0.0, 1e-3 * before.x);
  // The projectile gave momentum away: the block moves.
  EXPECT_LT(built.world.linearVelocity(built.bodies.back()).x, 35.0f);
}

TEST(JointGrid, is_a_net_of_circles_hanging_from_seven_pins_and_holds_together) {
  const bench::Rigid2dScene scene = bench::jointGridScene(10);
  EXPECT_EQ(scene.bodies.size(), 100u);
  EXPECT_EQ(countOf(scene, BodyType::staticBody), 7u);
  EXPECT_EQ(scene.joints.size(), 2u * 10u * 9u); // down and left links
  bench::ImpetusScene built = bench::buildImpetusScene(scene);
  EXPECT_EQ(built.world.jointCount(), scene.joints.size());
  const std::vector<Transform2f> start = startTransforms(scene);
  EXPECT_LT(bench::largestJointGap(scene, start), 1e-6f);
  step(built, 120);
  const std::vector<Transform2f> xf = bench::bodyTransforms(built);
  ASSERT_TRUE(bench::allFinite(xf));
  EXPECT_LT(bench::largestJointGap(scene, xf), 0.02f); // a small net: the pins hold within 2 cm
}

TEST(Ragdolls, land_in_their_box_with_their_joints_holding) {
  const bench::Rigid2dScene scene = bench::ragdollScene(3, 2);
  EXPECT_EQ(countOf(scene, BodyType::dynamicBody), 6u * 10u);
  EXPECT_EQ(scene.joints.size(), 6u * 9u);
  bench::ImpetusScene built = bench::buildImpetusScene(scene);
  step(built, 180);
  const std::vector<Transform2f> xf = bench::bodyTransforms(built);
  ASSERT_TRUE(bench::allFinite(xf));
  EXPECT_LT(bench::largestJointGap(scene, xf), 0.02f);
  for (std::size_t i = 1; i < xf.size(); ++i) {
    EXPECT_GT(xf[i].p.y, -0.1f) << "body " << i << " fell through the floor";
  }
}

TEST(Scenes, are_found_by_name_and_an_unknown_name_is_an_error) {
  for (const std::string& name : bench::rigid2dSceneNames()) {
    EXPECT_EQ(bench::makeRigid2dScene(name).name, name);
  }
  EXPECT_THROW((void)bench::makeRigid2dScene("pyramid"), impetus::Error);
}

TEST(Quality, overlap_and_sink_measure_what_they_say) {
  const bench::Rigid2dScene scene = bench::largePyramidScene(2); // ground, two boxes, one on top
  ASSERT_EQ(scene.bodies.size(), 4u);
  std::vector<Transform2f> xf;
  for (const bench::SceneBody& b : scene.bodies) {
    xf.push_back({b.position, impetus::Rot2f::identity()});
  }
  xf[3].p.y -= 0.03f; // the top box sinks 3 cm into the two below
  EXPECT_NEAR(bench::topSink(scene, xf), 0.03f, 1.0e-6f);
  EXPECT_NEAR(bench::largestOverlap(scene, xf), 0.03f, 1.0e-5f);
  xf[1].p.y -= 0.1f; // a base box 10 cm into the ground
  EXPECT_NEAR(bench::largestOverlap(scene, xf), 0.1f, 1.0e-5f);
  xf[1].p.x = std::nanf("");
  EXPECT_FALSE(bench::allFinite(xf));
}

} // namespace
