// The 3D benchmark scenes are built as bench/rigid3d_scenes.hpp describes them (Box3D's
// large_pyramid, Jolt's Pyramid, pyramid_20: counts, sizes, layouts, tops, no initial overlap),
// the quality figures measure what they say, and pyramid_20 stands in Impetus.
#include "rigid3d_impetus_scene.hpp"
#include "rigid3d_scenes.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <map>
#include <vector>

namespace {

using impetus::Quatf;
using impetus::Transform3f;
using impetus::Vec3f;
namespace bench = impetus::bench;
using Type = bench::Scene3dBody::Type;
using Shape = bench::Scene3dBody::Shape;

/// How many dynamic boxes stand at each starting height (rounded to the millimetre), m.
std::map<long, std::size_t> boxesByHeight(const bench::Rigid3dScene& scene) {
  std::map<long, std::size_t> rows;
  for (const bench::Scene3dBody& b : scene.bodies) {
    if (b.type == Type::dynamicBody) {
      ++rows[std::lround(1000.0 * b.position.y)];
    }
  }
  return rows;
}

void expectGroundBox(const bench::Scene3dBody& ground, const Vec3f& halfExtents) {
  EXPECT_EQ(ground.type, Type::staticBody);
  EXPECT_EQ(ground.shape, Shape::box);
  EXPECT_FLOAT_EQ(ground.halfExtents.x, halfExtents.x);
  EXPECT_FLOAT_EQ(ground.halfExtents.y, halfExtents.y);
  EXPECT_FLOAT_EQ(ground.halfExtents.z, halfExtents.z);
  EXPECT_FLOAT_EQ(ground.position.y + ground.halfExtents.y, 0.0f); // top at y = 0
}

TEST(LargePyramid3d, is_box3ds_5050_cubes_of_a_metre_in_one_plane_on_a_ground_box) {
  const bench::Rigid3dScene scene = bench::largePyramid3dScene();
  EXPECT_EQ(scene.name, "large_pyramid");
  EXPECT_EQ(scene.defaultSteps, 200);
  ASSERT_EQ(scene.bodies.size(), 5051u);
  EXPECT_EQ(bench::dynamicBodyCount(scene), 5050u);
  expectGroundBox(scene.bodies[0], {400.0f, 1.0f, 400.0f});
  for (std::size_t i = 1; i < scene.bodies.size(); ++i) {
    const bench::Scene3dBody& b = scene.bodies[i];
    ASSERT_EQ(b.shape, Shape::box);
    EXPECT_FLOAT_EQ(b.halfExtents.x, 0.5f);
    EXPECT_FLOAT_EQ(b.halfExtents.y, 0.5f);
    EXPECT_FLOAT_EQ(b.halfExtents.z, 0.5f);
    EXPECT_FLOAT_EQ(b.position.z, 0.0f);
    EXPECT_FLOAT_EQ(b.density, 100.0f);
    EXPECT_FLOAT_EQ(b.friction, 0.6f);
  }
  // Row i holds 100 - i boxes at y = i + 0.5; the base spans x in [-50, 50] on the ground.
  const std::map<long, std::size_t> rows = boxesByHeight(scene);
  ASSERT_EQ(rows.size(), 100u);
  for (int i = 0; i < 100; ++i) {
    EXPECT_EQ(rows.at(1000L * i + 500L), static_cast<std::size_t>(100 - i)) << "row " << i;
  }
  EXPECT_FLOAT_EQ(scene.bodies[1].position.x, -49.5f);
  EXPECT_FLOAT_EQ(scene.bodies[1].position.y, 0.5f);
  EXPECT_FLOAT_EQ(scene.bodies[100].position.x, 49.5f);
  ASSERT_EQ(scene.tops.size(), 1u);
  ASSERT_EQ(scene.topRestHeights.size(), 1u);
  const bench::Scene3dBody& top = scene.bodies[scene.tops[0]];
  EXPECT_FLOAT_EQ(top.position.x, 0.0f);
  EXPECT_FLOAT_EQ(top.position.y, 99.5f);
  EXPECT_FLOAT_EQ(scene.topRestHeights[0], 99.5f);
}

TEST(JoltPyramid, is_jolts_1240_boxes_of_two_metres_in_fifteen_square_layers) {
  const bench::Rigid3dScene scene = bench::joltPyramidScene();
  EXPECT_EQ(scene.name, "jolt_pyramid");
  EXPECT_EQ(scene.defaultSteps, 500);
  ASSERT_EQ(scene.bodies.size(), 1241u);
  EXPECT_EQ(bench::dynamicBodyCount(scene), 1240u);
  expectGroundBox(scene.bodies[0], {50.0f, 1.0f, 50.0f});
  for (std::size_t i = 1; i < scene.bodies.size(); ++i) {
    const bench::Scene3dBody& b = scene.bodies[i];
    ASSERT_EQ(b.shape, Shape::box);
    EXPECT_FLOAT_EQ(b.halfExtents.x, 1.0f);
    EXPECT_FLOAT_EQ(b.halfExtents.y, 1.0f);
    EXPECT_FLOAT_EQ(b.halfExtents.z, 1.0f);
    EXPECT_FLOAT_EQ(b.density, 1000.0f);
    EXPECT_FLOAT_EQ(b.friction, 0.2f);
  }
  // Layer i: (15 - i)^2 boxes with their centres at y = 1 + 2.5 i (0.5 m gaps between layers).
  const std::map<long, std::size_t> layers = boxesByHeight(scene);
  ASSERT_EQ(layers.size(), 15u);
  for (int i = 0; i < 15; ++i) {
    EXPECT_EQ(layers.at(1000L + 2500L * i), static_cast<std::size_t>((15 - i) * (15 - i))) << "layer " << i;
  }
  // The bottom layer: 15 x 15 boxes side by side from -16 to 14 m in x and z (30 m a side);
  // layer 1 shifted by a half box, so each of its boxes stands on four.
  float lowX = 1.0e9f, highX = -1.0e9f, lowZ = 1.0e9f, highZ = -1.0e9f, lowX1 = 1.0e9f;
  for (std::size_t i = 1; i < scene.bodies.size(); ++i) {
    const bench::Scene3dBody& b = scene.bodies[i];
    if (b.position.y == 1.0f) {
      lowX = std::min(lowX, b.position.x - 1.0f);
      highX = std::max(highX, b.position.x + 1.0f);
      lowZ = std::min(lowZ, b.position.z - 1.0f);
      highZ = std::max(highZ, b.position.z + 1.0f);
    } else if (b.position.y == 3.5f) {
      lowX1 = std::min(lowX1, b.position.x);
    }
  }
  EXPECT_FLOAT_EQ(lowX, -16.0f);
  EXPECT_FLOAT_EQ(highX, 14.0f);
  EXPECT_FLOAT_EQ(lowZ, -16.0f);
  EXPECT_FLOAT_EQ(highZ, 14.0f);
  EXPECT_FLOAT_EQ(lowX1, -14.0f);
  // The top: one box at (-1, 36, -1), resting at y = 29 once the layers have fallen together.
  ASSERT_EQ(scene.tops.size(), 1u);
  const bench::Scene3dBody& top = scene.bodies[scene.tops[0]];
  EXPECT_FLOAT_EQ(top.position.x, -1.0f);
  EXPECT_FLOAT_EQ(top.position.y, 36.0f);
  EXPECT_FLOAT_EQ(top.position.z, -1.0f);
  EXPECT_FLOAT_EQ(scene.topRestHeights[0], 29.0f);
}

TEST(Pyramid20, is_a_plane_pyramid_of_base_twenty) {
  const bench::Rigid3dScene scene = bench::pyramid20Scene();
  EXPECT_EQ(scene.name, "pyramid_20");
  ASSERT_EQ(scene.bodies.size(), 211u);
  EXPECT_EQ(bench::dynamicBodyCount(scene), 210u);
  EXPECT_FLOAT_EQ(scene.bodies[1].position.x, -9.5f);
  EXPECT_FLOAT_EQ(scene.bodies[20].position.x, 9.5f);
  ASSERT_EQ(scene.tops.size(), 1u);
  EXPECT_FLOAT_EQ(scene.bodies[scene.tops[0]].position.x, 0.0f);
  EXPECT_FLOAT_EQ(scene.bodies[scene.tops[0]].position.y, 19.5f);
}

TEST(ShapeRain, is_a_thousand_spheres_cubes_and_flat_boxes_over_a_walled_bin) {
  const bench::Rigid3dScene scene = bench::shapeRainScene();
  EXPECT_EQ(scene.name, "shape_rain");
  ASSERT_EQ(scene.bodies.size(), 1005u);
  EXPECT_EQ(bench::dynamicBodyCount(scene), 1000u);
  EXPECT_TRUE(scene.tops.empty());
  std::size_t spheres = 0, cubes = 0, flat = 0;
  for (const bench::Scene3dBody& b : scene.bodies) {
    if (b.type == Type::staticBody) {
      continue;
    }
    spheres += b.shape == Shape::sphere ? 1 : 0;
    cubes += b.shape == Shape::box && b.halfExtents.y == 0.4f ? 1 : 0;
    flat += b.shape == Shape::box && b.halfExtents.y == 0.2f ? 1 : 0;
    // Inside the bin's 18 m square, above its floor.
    EXPECT_LT(std::abs(b.position.x), 8.0f);
    EXPECT_LT(std::abs(b.position.z), 8.0f);
    EXPECT_GE(b.position.y, 2.0f);
  }
  EXPECT_EQ(spheres, 334u);
  EXPECT_EQ(cubes, 333u);
  EXPECT_EQ(flat, 333u);
}

TEST(Rigid3dScenes, are_found_by_name_and_an_unknown_name_is_refused) {
  for (const std::string& name : bench::rigid3dSceneNames()) {
    EXPECT_EQ(bench::makeRigid3dScene(name).name, name);
  }
  EXPECT_THROW((void)bench::makeRigid3dScene("pyramid"), impetus::Error);
  EXPECT_THROW((void)bench::largePyramid3dScene(0), impetus::Error);
}

TEST(Rigid3dScenes, start_touching_or_apart_without_overlap) {
  for (const bench::Rigid3dScene& scene :
       {bench::pyramid20Scene(), bench::joltPyramidScene(), bench::shapeRainScene()}) {
    const std::vector<Transform3f> start = bench::startPoses(scene);
    EXPECT_LT(bench::largestOverlap(scene, start), 1.0e-5f) << scene.name;
    EXPECT_TRUE(bench::allFinite(start));
  }
  EXPECT_FLOAT_EQ(bench::topSink(bench::pyramid20Scene(), bench::startPoses(bench::pyramid20Scene())), 0.0f);
  // Jolt's top starts 14 gaps of 0.5 m above where it rests.
  EXPECT_FLOAT_EQ(bench::topSink(bench::joltPyramidScene(), bench::startPoses(bench::joltPyramidScene())), -7.0f);
}

TEST(Rigid3dQuality, box_overlap_is_the_penetration_depth_on_the_separating_axes) {
  const Vec3f half{0.5f, 0.5f, 0.5f};
  const Transform3f a{};
  EXPECT_NEAR(bench::boxOverlap(half, a, half, {{0.9f, 0.0f, 0.0f}, Quatf::identity()}), 0.1f, 1.0e-6f);
  EXPECT_NEAR(bench::boxOverlap(half, a, half, {{1.2f, 0.3f, 0.0f}, Quatf::identity()}), -0.2f, 1.0e-6f);
  // Turned 45 degrees about y, its edge 0.1 m into the face x = 0.5: along x the overlap is 0.1,
  // along every other axis more.
  const float reach = 0.5f * std::sqrt(2.0f);
  const Quatf turned = Quatf::fromAxisAngle({0.0f, 1.0f, 0.0f}, 0.25f * impetus::pi<float>);
  EXPECT_NEAR(bench::boxOverlap(half, a, half, {{0.5f + reach - 0.1f, 0.2f, 0.1f}, turned}), 0.1f, 1.0e-5f);
  // Edge across edge: B turned 45 degrees about x and then y; nothing face to face.
  const Quatf tilted = Quatf::fromAxisAngle({0.0f, 1.0f, 0.0f}, 0.25f * impetus::pi<float>) *
                       Quatf::fromAxisAngle({1.0f, 0.0f, 0.0f}, 0.25f * impetus::pi<float>);
  EXPECT_LT(bench::boxOverlap(half, a, half, {{0.0f, 2.0f, 0.0f}, tilted}), 0.0f);
}

TEST(Rigid3dQuality, largest_overlap_takes_the_deepest_pair_of_boxes_and_spheres) {
  bench::Rigid3dScene scene;
  bench::Scene3dBody ground;
  ground.type = Type::staticBody;
  ground.position = {0.0f, -1.0f, 0.0f};
  ground.halfExtents = {10.0f, 1.0f, 10.0f};
  bench::Scene3dBody box;
  box.position = {0.0f, 0.48f, 0.0f}; // 2 cm into the ground
  box.halfExtents = {0.5f, 0.5f, 0.5f};
  bench::Scene3dBody ball;
  ball.shape = Shape::sphere;
  ball.radius = 0.5f;
  ball.position = {3.0f, 0.45f, 0.0f}; // 5 cm into the ground
  bench::Scene3dBody ball2 = ball;
  ball2.position = {3.0f, 1.42f, 0.0f}; // 3 cm into the first ball
  scene.bodies = {ground, box, ball, ball2};
  const std::vector<Transform3f> poses = bench::startPoses(scene);
  EXPECT_NEAR(bench::largestOverlap(scene, poses), 0.05f, 1.0e-5f);
  scene.bodies[2].position.y = 0.49f; // 1 cm into the ground, and 7 cm into the second ball now
  EXPECT_NEAR(bench::largestOverlap(scene, bench::startPoses(scene)), 0.07f, 1.0e-5f);
}

TEST(Pyramid20, built_in_impetus_stands_for_300_steps) {
  const bench::Rigid3dScene scene = bench::pyramid20Scene();
  bench::Impetus3dScene built = bench::buildImpetus3dScene(scene);
  ASSERT_EQ(built.world.bodyCount(), 211u);
  EXPECT_FLOAT_EQ(built.world.massData(built.bodies[1]).mass, 100.0f); // 1 m^3 at 100 kg/m^3
  for (int i = 0; i < 300; ++i) {
    built.world.step(bench::scene3dTimeStep);
  }
  const std::vector<Transform3f> poses = bench::bodyPoses(built);
  ASSERT_TRUE(bench::allFinite(poses));
  EXPECT_LT(bench::topSink(scene, poses), 0.05f);
  EXPECT_GT(bench::topSink(scene, poses), -0.01f); // it did not rise either
  EXPECT_LT(bench::largestOverlap(scene, poses), 0.01f);
  EXPECT_GE(built.world.contactCount(), 500u); // every box still on its neighbours
}

} // namespace
