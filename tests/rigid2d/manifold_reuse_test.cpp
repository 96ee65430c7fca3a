// Manifold reuse (manifold_reuse.cpp): a carried manifold against a freshly computed one, and
// worlds with reuse on against the closed forms and against reuse off.
#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/geometry.hpp>
#include <impetus/rigid2d/manifold.hpp>
#include <impetus/rigid2d/world.hpp>

#include "rigid2d/world_impl.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace impetus::rigid2d {
namespace {

Transform2f at(float x, float y, float angle = 0.0f) { return {{x, y}, Rot2f::fromAngle(angle)}; }

/// A contact between a ground slab and a box, its manifold computed and noted at (xfA, xfB).
detail::Contact touching(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB) {
  detail::Contact c;
  c.manifold = collidePolygons(a, xfA, b, xfB);
  detail::recordManifoldFrame(c, xfA, xfB);
  return c;
}

TEST(ManifoldReuse, a_carried_manifold_matches_a_fresh_one_within_the_tolerance) {
  const Polygon ground = makeBox(5.0f, 0.5f);
  const Polygon box = makeBox(0.5f, 0.5f);
  const Transform2f xfA = at(0.3f, -0.2f, 0.05f); // neither frame the world's
  const Transform2f start = mul(xfA, at(1.0f, 0.99f));
  detail::Contact c = touching(ground, xfA, box, start);
  ASSERT_EQ(c.manifold.pointCount, 2);
  // The box moved 0.3 mm across and 0.4 mm down (into the ground) and turned 0.03 degree: within
  // 1 mm and half a degree at both corners.
  const Transform2f moved = mul(xfA, at(1.0003f, 0.9896f, 0.03f * pi<float> / 180.0f));
  ASSERT_TRUE(detail::carryManifold(c, xfA, moved, 0.001f, std::sin(0.0087f)));
  const Manifold fresh = collidePolygons(ground, xfA, box, moved);
  ASSERT_EQ(fresh.pointCount, 2);
  EXPECT_NEAR(dot(c.manifold.normal, fresh.normal), 1.0f, 1e-6f);
  for (std::size_t k = 0; k < 2; ++k) {
    const ManifoldPoint& p = c.manifold.points[k];
    const ManifoldPoint& q = fresh.points[k];
    EXPECT_EQ(p.id, q.id);
    // The box's corners are the same material points: separations agree to float rounding.
    EXPECT_NEAR(p.separation, q.separation, 2e-6f) << k;
    // The point midway keeps the ground's side where it was: off by at most half the motion.
    EXPECT_LT(distance(p.point, q.point), 0.0005f) << k;
    EXPECT_LT(distance(p.anchorA - p.point, q.anchorA - q.point), 1e-5f) << k; // anchors: point - origin
    EXPECT_LT(distance(p.anchorB - p.point, q.anchorB - q.point), 1e-5f) << k;
  }
  // 2 mm further, or a degree more, and the manifold is computed again.
  detail::Contact far = touching(ground, xfA, box, start);
  EXPECT_FALSE(detail::carryManifold(far, xfA, mul(xfA, at(1.002f, 0.99f)), 0.001f, std::sin(0.0087f)));
  EXPECT_FALSE(
      detail::carryManifold(far, xfA, mul(xfA, at(1.0f, 0.99f, pi<float> / 180.0f)), 0.001f, std::sin(0.0087f)));
}

BodyId addBox(World& world, const Vec2f& position, float half, float friction = 0.6f) {
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = position;
  const BodyId body = world.createBody(def);
  ShapeDef shape;
  shape.friction = friction;
  world.createShape(body, shape, makeBox(half, half));
  return body;
}

void addGround(World& world) {
  const BodyId ground = world.createBody({});
  world.createShape(ground, {}, makeOffsetBox(50.0f, 0.5f, {0.0f, -0.5f}, 0.0f)); // top at y = 0
}

// A box sliding on the ground stops after v0^2 / (2 mu g): its manifold moves by far more than
// the tolerance each step, then less and less, and is carried only once it has all but stopped.
TEST(ManifoldReuse, a_sliding_box_stops_where_coulomb_friction_says) {
  for (const float reuse : {0.0f, 0.001f}) {
    WorldDef def;
    def.contactReuseDistance = reuse;
    def.enableSleep = false;
    World world(def);
    addGround(world);
    const float mu = 0.4f, v0 = 4.0f, g = 10.0f;
    const BodyId box = addBox(world, {0.0f, 0.5f}, 0.5f, mu);
    for (int i = 0; i < 30; ++i) {
      world.step(1.0f / 60.0f); // settle first
    }
    const float x0 = world.position(box).x;
    world.setLinearVelocity(box, {v0, 0.0f});
    for (int i = 0; i < 180; ++i) {
      world.step(1.0f / 60.0f);
    }
    // sqrt(mu_box mu_ground) = sqrt(0.4 * 0.6): the ground's default friction is 0.6.
    const float muPair = std::sqrt(mu * 0.6f);
    const float expected = v0 * v0 / (2.0f * muPair * g);
    EXPECT_NEAR(world.position(box).x - x0, expected, 0.02f * expected) << "reuse " << reuse;
    EXPECT_LT(std::abs(world.angle(box)), 1e-3f) << "reuse " << reuse;
  }
}

// Round shapes never carry their manifolds: a ball's contact point does not turn with it (a
// carried one would, and the support under it would spin the ball on). A ball resting a
// millimetre off the middle of a box stays there.
TEST(ManifoldReuse, a_ball_resting_on_a_box_does_not_start_rolling) {
  WorldDef def;
  def.enableSleep = false;
  World world(def);
  addGround(world);
  addBox(world, {0.0f, 0.5f}, 0.5f);
  BodyDef ballDef;
  ballDef.type = BodyType::dynamicBody;
  ballDef.position = {-0.001f, 1.25f};
  const BodyId ball = world.createBody(ballDef);
  world.createShape(ball, {}, Circle{{}, 0.25f});
  for (int i = 0; i < 600; ++i) {
    world.step(1.0f / 60.0f);
  }
  EXPECT_LT(std::abs(world.position(ball).x + 0.001f), 1e-3f);
  EXPECT_LT(std::abs(world.angularVelocity(ball)), 1e-2f);
}

// A pyramid of twenty levels with reuse on settles as it does with reuse off: the top within
// 3 mm of where it settles without (it sinks about 3 cm under the soft contacts either way), and
// no box tilted more than without (about 0.005 rad without, 0.002 with).
TEST(ManifoldReuse, a_pyramid_settles_as_without_reuse) {
  std::array<Vec2f, 2> tops{};
  std::array<float, 2> spread{};
  for (std::size_t run = 0; run < 2; ++run) {
    WorldDef def;
    def.enableSleep = false;
    def.contactReuseDistance = run == 0 ? 0.0f : 0.001f;
    World world(def);
    addGround(world);
    std::vector<BodyId> boxes;
    constexpr int levels = 20;
    for (int row = 0; row < levels; ++row) {
      for (int i = 0; i < levels - row; ++i) {
        const float x = (static_cast<float>(i) - 0.5f * static_cast<float>(levels - row - 1)) * 1.0f;
        boxes.push_back(addBox(world, {x, 0.5f + static_cast<float>(row)}, 0.5f));
      }
    }
    for (int i = 0; i < 300; ++i) {
      world.step(1.0f / 60.0f);
    }
    tops[run] = world.position(boxes.back());
    for (const BodyId b : boxes) {
      spread[run] = std::max(spread[run], std::abs(world.angle(b)));
    }
  }
  EXPECT_LT(distance(tops[0], tops[1]), 0.003f);
  EXPECT_LE(spread[1], spread[0]);
  EXPECT_GT(tops[1].y, 19.5f - 0.1f);
}

} // namespace
} // namespace impetus::rigid2d
