// The 3D world's queries and filters: ray casts against a row of shapes at known distances,
// overlap tests a millimetre either side of touching, and filters that keep shapes apart.
#include <impetus/rigid3d/world.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

namespace impetus::rigid3d {
namespace {

struct Row {
  World world;
  ShapeId sphere, box, capsule;
};

/// Along +x from the origin: a ball of radius 0.5 at x = 2, a box of half width 0.25 at x = 5
/// (turned about x, which leaves its face toward the ray), a capsule across the ray at x = 8.
void build(Row& r) {
  r.world.setGravity({0.0f, 0.0f, 0.0f});
  const auto place = [&](const Vec3f& p, const ShapeGeometry& g, std::uint64_t category) {
    BodyDef def;
    def.type = BodyType::dynamicBody;
    def.position = p;
    def.rotation = Quatf::fromAxisAngle(Vec3f{1.0f, 0.0f, 0.0f}, 0.3f);
    ShapeDef shape;
    shape.filter.category = category;
    return r.world.createShape(r.world.createBody(def), shape, g);
  };
  r.sphere = place({2.0f, 0.0f, 0.0f}, Sphere{{}, 0.5f}, 2);
  r.box = place({5.0f, 0.0f, 0.0f}, makeBoxHull({0.25f, 0.25f, 0.25f}), 1);
  r.capsule = place({8.0f, 0.0f, 0.0f}, Capsule{{0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.1f}, 1);
}

TEST(Rigid3dQuery, a_ray_finds_the_nearest_shape_and_all_of_them_in_order) {
  Row r;
  build(r);
  const std::optional<RayHit> hit = r.world.castRayClosest({0.0f, 0.0f, 0.0f}, {10.0f, 0.0f, 0.0f});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->shape, r.sphere);
  EXPECT_NEAR(hit->fraction, 0.15f, 1e-6f); // (2 - 0.5) / 10
  EXPECT_NEAR(hit->normal.x, -1.0f, 1e-6f);
  const std::vector<RayHit> all = r.world.castRayAll({0.0f, 0.0f, 0.0f}, {10.0f, 0.0f, 0.0f});
  ASSERT_EQ(all.size(), 3U);
  EXPECT_EQ(all[1].shape, r.box);
  EXPECT_NEAR(all[1].fraction, 0.475f, 1e-6f); // (5 - 0.25) / 10
  EXPECT_EQ(all[2].shape, r.capsule);
  EXPECT_NEAR(all[2].fraction, 0.79f, 1e-6f); // (8 - 0.1) / 10
  // A filter whose mask leaves out the ball's category sees the box first.
  CollisionFilter noBalls;
  noBalls.mask = ~std::uint64_t{2};
  EXPECT_EQ(r.world.castRayClosest({0.0f, 0.0f, 0.0f}, {10.0f, 0.0f, 0.0f}, noBalls)->shape, r.box);
  // Short of the ball: nothing.
  EXPECT_FALSE(r.world.castRayClosest({0.0f, 0.0f, 0.0f}, {1.4f, 0.0f, 0.0f}).has_value());
  EXPECT_EQ(thrownField([&] { (void)r.world.castRayClosest({0.0f, NAN, 0.0f}, {1.0f, 0.0f, 0.0f}); }), "origin.y");
}

TEST(Rigid3dQuery, a_shape_overlaps_what_it_crosses_and_not_what_it_misses_by_a_millimetre) {
  Row r;
  build(r);
  const Sphere probe{{}, 0.2f};
  // The box's face toward -x is at x = 4.75: a probe centred 0.199 m before it crosses it, one
  // 0.201 m before it does not.
  const auto at = [](float x) { return Transform3f{{x, 0.0f, 0.0f}, Quatf::identity()}; };
  const std::vector<ShapeId> crossing = r.world.overlapShape(probe, at(4.75f - 0.199f));
  ASSERT_EQ(crossing.size(), 1U);
  EXPECT_EQ(crossing[0], r.box);
  EXPECT_TRUE(r.world.overlapShape(probe, at(4.75f - 0.201f)).empty());
  // A long capsule through all three.
  EXPECT_EQ(r.world.overlapShape(Capsule{{0.0f, 0.0f, 0.0f}, {9.0f, 0.0f, 0.0f}, 0.05f}, at(0.0f)).size(), 3U);
  EXPECT_EQ(thrownField([&] { (void)r.world.overlapShape(Sphere{{}, -1.0f}, at(0.0f)); }), "radius");
}

TEST(Rigid3dQuery, filters_keep_shapes_apart_that_would_otherwise_collide) {
  // Two boxes dropped onto each other: with each one's category outside the other's mask, or
  // in the same negative group, the upper falls through the lower; by default it rests on it.
  const auto drop = [](const CollisionFilter& upperFilter, const CollisionFilter& lowerFilter) {
    World world;
    BodyDef groundDef;
    groundDef.position = {0.0f, -0.5f, 0.0f};
    world.createShape(world.createBody(groundDef), ShapeDef{}, makeBoxHull({5.0f, 0.5f, 5.0f}));
    ShapeDef lower;
    lower.filter = lowerFilter;
    ShapeDef upper;
    upper.filter = upperFilter;
    BodyDef def;
    def.type = BodyType::dynamicBody;
    def.position = {0.0f, 0.5f, 0.0f};
    world.createShape(world.createBody(def), lower, makeBoxHull({0.5f, 0.5f, 0.5f}));
    def.position = {0.0f, 1.6f, 0.0f};
    const BodyId top = world.createBody(def);
    world.createShape(top, upper, makeBoxHull({0.5f, 0.5f, 0.5f}));
    for (int i = 0; i < 120; ++i) {
      world.step(1.0f / 60.0f);
    }
    return world.position(top).y;
  };
  EXPECT_NEAR(drop({}, {}), 1.5f, 0.01f);
  CollisionFilter a;
  a.category = 2;
  a.mask = ~std::uint64_t{4};
  CollisionFilter b;
  b.category = 4;
  EXPECT_NEAR(drop(a, b), 0.5f, 0.01f); // through the lower box, onto the ground
  CollisionFilter group;
  group.group = -1;
  EXPECT_NEAR(drop(group, group), 0.5f, 0.01f);
}

TEST(Rigid3dQuery, a_ball_falling_through_a_sensor_is_seen_entering_and_leaving_and_not_slowed) {
  World world;
  BodyDef triggerDef;
  triggerDef.position = {0.0f, 5.0f, 0.0f};
  ShapeDef sensorDef;
  sensorDef.isSensor = true;
  const ShapeId trigger = world.createShape(world.createBody(triggerDef), sensorDef, makeBoxHull({1.0f, 1.0f, 1.0f}));
  BodyDef ballDef;
  ballDef.type = BodyType::dynamicBody;
  ballDef.position = {0.0f, 7.0f, 0.0f};
  const BodyId ball = world.createBody(ballDef);
  const ShapeId ballShape = world.createShape(ball, ShapeDef{}, Sphere{{}, 0.25f});
  int entered = -1;
  int left = -1;
  for (int i = 0; i < 90; ++i) {
    world.step(1.0f / 60.0f);
    for (const SensorEvent& e : world.sensorEvents().begins) {
      EXPECT_EQ(e.sensor, trigger);
      EXPECT_EQ(e.visitor, ballShape);
      entered = i;
    }
    for (const SensorEvent& e : world.sensorEvents().ends) {
      EXPECT_EQ(e.sensor, trigger);
      left = i;
    }
    EXPECT_TRUE(world.contactEvents().begins.empty());
  }
  // In free fall the ball's bottom reaches the box's top (6 m) after sqrt(2 * 0.75 / g) =
  // 0.387 s and its top leaves the bottom (4 m) after sqrt(2 * 3.25 / g) = 0.806 s: within
  // steps 23 and 48 (ending at 0.400 s and 0.817 s). The collide stage runs at a step's start, on
  // the poses the last step left, so the events come with the step after.
  EXPECT_EQ(entered, 24);
  EXPECT_EQ(left, 49);
  // Not slowed: free fall all the way (symplectic Euler's substeps, within a millimetre).
  const float t = 1.5f;
  EXPECT_NEAR(world.position(ball).y, 7.0f - 0.5f * 10.0f * t * t - 0.5f * 10.0f * (1.0f / 240.0f) * t, 1e-3f);
  // Queries do not see sensors.
  EXPECT_FALSE(world.castRayClosest({0.0f, 5.0f, -3.0f}, {0.0f, 0.0f, 6.0f}).has_value());
}

} // namespace
} // namespace impetus::rigid3d
