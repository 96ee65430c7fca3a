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

/// A manifold noted at (xfA, start) and carried to (xfA, moved), beside a fresh one at moved:
/// `collideAt(xfB)` collides the pair with B at xfB; `radiusB` is B's rounding.
struct CarriedAndFresh {
  detail::Contact carried;
  Manifold fresh;
  bool wasCarried = false;
};

template <class CollideAt> CarriedAndFresh carryAndCollide(const CollideAt& collideAt, float radiusB,
                                                           const Transform2f& xfA, const Transform2f& start,
                                                           const Transform2f& moved) {
  CarriedAndFresh r;
  r.carried.frame.radiusB = radiusB;
  r.carried.manifold = collideAt(start);
  detail::recordManifoldFrame(r.carried, xfA, start);
  r.wasCarried = detail::carryManifold(r.carried, xfA, moved, 0.001f, std::sin(0.0087f));
  r.fresh = collideAt(moved);
  return r;
}

// A ball resting on a slab: carried while its centre moves less than the tolerance across,
// however it turns, its contact stays straight under the centre (no lever arm for the slab's
// push), and matches a fresh manifold's separation and point.
TEST(ManifoldReuse, a_carried_ball_contact_stays_under_the_ball_however_it_turns) {
  const Polygon ground = makeBox(5.0f, 0.5f);
  const Circle ball{{}, 0.25f};
  const Transform2f xfA = at(0.3f, -0.2f, 0.05f);
  const auto collideAt = [&](const Transform2f& xfB) { return collidePolygonAndCircle(ground, xfA, ball, xfB); };
  // 0.4 mm across, 0.2 mm down, a quarter degree turned (within half a degree).
  const CarriedAndFresh r = carryAndCollide(collideAt, ball.radius, xfA, mul(xfA, at(1.0f, 0.749f)),
                                            mul(xfA, at(1.0004f, 0.7488f, 0.25f * pi<float> / 180.0f)));
  ASSERT_TRUE(r.wasCarried);
  ASSERT_EQ(r.carried.manifold.pointCount, 1);
  ASSERT_EQ(r.fresh.pointCount, 1);
  const ManifoldPoint& p = r.carried.manifold.points[0];
  const ManifoldPoint& q = r.fresh.points[0];
  EXPECT_NEAR(p.separation, q.separation, 2e-6f);
  EXPECT_LT(distance(p.point, q.point), 2e-6f);
  // The point relative to the ball's centre lies along the normal: the push has no lever arm.
  EXPECT_LT(std::abs(cross(p.anchorB, r.carried.manifold.normal)), 1e-6f);
  // The centre 2 mm across: computed again.
  detail::Contact again = r.carried;
  EXPECT_FALSE(detail::carryManifold(again, xfA, mul(xfA, at(1.002f, 0.749f)), 0.001f, std::sin(0.0087f)));
}

// A rounded box (corners of radius 5 cm) resting on a slab: carried by its cores' corners, its
// two points match a fresh manifold's.
TEST(ManifoldReuse, a_carried_rounded_box_matches_a_fresh_manifold) {
  const Polygon ground = makeBox(5.0f, 0.5f);
  const std::array<Vec2f, 4> corners{{{-0.45f, -0.45f}, {0.45f, -0.45f}, {0.45f, 0.45f}, {-0.45f, 0.45f}}};
  const Polygon rounded = makePolygon(corners, 0.05f);
  const Transform2f xfA = at(0.3f, -0.2f, 0.05f);
  const auto collideAt = [&](const Transform2f& xfB) { return collidePolygons(ground, xfA, rounded, xfB); };
  const CarriedAndFresh r = carryAndCollide(collideAt, rounded.radius, xfA, mul(xfA, at(1.0f, 0.999f)),
                                            mul(xfA, at(1.0003f, 0.9986f, 0.03f * pi<float> / 180.0f)));
  ASSERT_TRUE(r.wasCarried);
  ASSERT_EQ(r.carried.manifold.pointCount, 2);
  ASSERT_EQ(r.fresh.pointCount, 2);
  for (std::size_t k = 0; k < 2; ++k) {
    const ManifoldPoint& p = r.carried.manifold.points[k];
    const ManifoldPoint& q = r.fresh.points[k];
    EXPECT_EQ(p.id, q.id);
    EXPECT_NEAR(p.separation, q.separation, 2e-6f) << k;
    // Under the corners' centres, which moved with the box: within float rounding of fresh.
    EXPECT_LT(distance(p.point, q.point), 1e-5f) << k;
  }
}

/// How far a polygon reaches from its frame's origin (ManifoldFrame::reachB), m.
float reachOf(const Polygon& p) {
  float reach = 0.0f;
  for (int i = 0; i < p.count; ++i) {
    reach = std::max(reach, length(p.vertices[static_cast<std::size_t>(i)]));
  }
  return reach + p.radius;
}

// A pair noted apart is not collided again while B's shape moved less than the gap allows; the
// collision it skips must find nothing. Swept over shape pairs, gaps, moves and turns: every pair
// that staysApart says cannot touch has no points when collided, and the bound is not so loose
// that it never lets a pair go uncollided.
TEST(ManifoldReuse, a_pair_kept_apart_would_have_collided_to_nothing) {
  const Polygon box = makeBox(0.5f, 0.5f);
  const Polygon slab = makeBox(5.0f, 0.5f);
  const std::array<Vec2f, 6> hexagonPoints{
      {{0.4f, 0.0f}, {0.2f, 0.35f}, {-0.2f, 0.35f}, {-0.4f, 0.0f}, {-0.2f, -0.35f}, {0.2f, -0.35f}}};
  const Polygon hexagon = makePolygon(hexagonPoints, 0.0f);
  const Polygon roundedHexagon = makePolygon(hexagonPoints, 0.1f);
  const Polygon capsule = asPolygon(Capsule{{-0.4f, 0.0f}, {0.4f, 0.0f}, 0.15f});
  const Polygon ball = asPolygon(Circle{{0.1f, 0.0f}, 0.3f}); // off its body's origin
  const std::array<Polygon, 6> shapes{box, slab, hexagon, roundedHexagon, capsule, ball};
  const auto collideAny = [](const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB) {
    if (b.count == 1) {
      const Circle circle{b.vertices[0], b.radius};
      return a.count == 1 ? collideCircles({a.vertices[0], a.radius}, xfA, circle, xfB)
                          : collidePolygonAndCircle(a, xfA, circle, xfB);
    }
    return collidePolygons(a, xfA, b, xfB);
  };
  int kept = 0, collidedAgain = 0;
  std::uint32_t seed = 12345;
  const auto uniform = [&seed](float lo, float hi) {
    seed = seed * 1664525u + 1013904223u;
    return lo + (hi - lo) * static_cast<float>(seed >> 8) / static_cast<float>(1u << 24);
  };
  for (const Polygon& a : shapes) {
    if (a.count == 1) {
      continue; // circles go second (collidePolygonAndCircle's order)
    }
    for (const Polygon& b : shapes) {
      for (int trial = 0; trial < 200; ++trial) {
        const Transform2f xfA = at(uniform(-1.0f, 1.0f), uniform(-1.0f, 1.0f), uniform(-3.0f, 3.0f));
        const Transform2f xfB = mul(xfA, at(uniform(-2.0f, 2.0f), uniform(-2.0f, 2.0f), uniform(-3.0f, 3.0f)));
        detail::Contact c;
        c.manifold = collideAny(a, xfA, b, xfB);
        if (c.manifold.pointCount > 0) {
          continue;
        }
        c.frame.reachB = reachOf(b);
        detail::recordSeparation(c, xfA, xfB);
        for (int move = 0; move < 20; ++move) {
          const float step = uniform(0.0f, 0.3f);
          const Transform2f movedB =
              mul(xfB, at(uniform(-step, step), uniform(-step, step), uniform(-0.5f, 0.5f) * step));
          const Transform2f movedA =
              mul(xfA, at(uniform(-step, step), uniform(-step, step), uniform(-0.5f, 0.5f) * step));
          if (detail::staysApart(c, movedA, movedB)) {
            ++kept;
            ASSERT_EQ(collideAny(a, movedA, b, movedB).pointCount, 0) << "shapes " << a.count << ", " << b.count;
          } else {
            ++collidedAgain;
          }
        }
      }
    }
  }
  EXPECT_GT(kept, 1000);
  EXPECT_GT(collidedAgain, 1000);
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

// A round shape's manifold is carried by its core (a ball's centre), not its surface point,
// which does not turn with the ball (a point that did would put the support's push off the
// centre and roll the ball on). A ball resting a millimetre off the middle of a box stays there.
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

// Capsules carried by their cores: a capsule lying on the ground and a shorter one lying on it,
// off its middle, stay where they settle, 10 s on.
TEST(ManifoldReuse, capsules_resting_on_each_other_stay_put) {
  WorldDef def;
  def.enableSleep = false;
  World world(def);
  addGround(world);
  BodyDef bodyDef;
  bodyDef.type = BodyType::dynamicBody;
  bodyDef.position = {0.0f, 0.2f};
  const BodyId lower = world.createBody(bodyDef);
  world.createShape(lower, {}, Capsule{{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.2f});
  bodyDef.position = {0.15f, 0.6f};
  const BodyId upper = world.createBody(bodyDef);
  world.createShape(upper, {}, Capsule{{-0.3f, 0.0f}, {0.3f, 0.0f}, 0.2f});
  for (int i = 0; i < 60; ++i) {
    world.step(1.0f / 60.0f);
  }
  const Vec2f lowerAt = world.position(lower);
  const Vec2f upperAt = world.position(upper);
  for (int i = 0; i < 600; ++i) {
    world.step(1.0f / 60.0f);
  }
  EXPECT_LT(distance(world.position(lower), lowerAt), 1e-3f);
  EXPECT_LT(distance(world.position(upper), upperAt), 1e-3f);
  EXPECT_LT(std::abs(world.angularVelocity(lower)), 1e-2f);
  EXPECT_LT(std::abs(world.angularVelocity(upper)), 1e-2f);
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
