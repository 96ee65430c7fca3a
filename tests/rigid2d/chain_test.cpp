// Chain segments: building chains (ghost vertices, bad input), their one-sided bounding boxes and
// ray casts, and their manifolds against polygons and circles. The central property is the
// absence of ghost collisions: a shape sliding along a straight chain only ever gets the surface
// normal, also exactly over the vertex between two segments.
//
// Tolerances: coordinates are of order 1-3 m in float, so one rounding is ~2e-7 m; the manifold
// arithmetic chains a handful of them, so separations and points are checked to 1e-5 m (500 times
// below linearSlop, the smallest length the world cares about) and unit normals to 1e-6.
#include "support/error_field.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/chain.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace impetus::rigid2d {
namespace {

constexpr float lengthTolerance = 1e-5f;
constexpr float normalTolerance = 1e-6f;

Transform2f at(float x, float y, float angle = 0.0f) { return {{x, y}, Rot2f::fromAngle(angle)}; }

/// Flat ground y = 0 from x = 3 to x = -3 in three 2 m segments, listed right to left so the free
/// side (right-hand normal) is up; seams at x = 1 and x = -1.
std::vector<ChainSegment> flatGround() {
  const std::vector<Vec2f> points{{3, 0}, {1, 0}, {-1, 0}, {-3, 0}};
  return makeChainSegments(points, false);
}

void expectVec(const Vec2f& actual, const Vec2f& expected, float tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
}

Vec2f unitAt(float degrees) {
  const float r = degrees * pi<float> / 180.0f;
  return {std::cos(r), std::sin(r)};
}

TEST(Chain, open_chain_ghosts_extrapolate_the_ends_and_link_neighbours) {
  const std::vector<Vec2f> p{{0, 0}, {1, 0}, {2, 1}, {3, 1}};
  const std::vector<ChainSegment> s = makeChainSegments(p, false);
  ASSERT_EQ(s.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(s[i].segment.point1, p[i]);
    EXPECT_EQ(s[i].segment.point2, p[i + 1]);
  }
  // Ends: straight on, one segment length beyond.
  EXPECT_EQ(s[0].ghost1, (Vec2f{-1, 0}));
  EXPECT_EQ(s[2].ghost2, (Vec2f{4, 1}));
  // Inside: the neighbours' far ends.
  EXPECT_EQ(s[0].ghost2, p[2]);
  EXPECT_EQ(s[1].ghost1, p[0]);
  EXPECT_EQ(s[1].ghost2, p[3]);
  EXPECT_EQ(s[2].ghost1, p[1]);

  // The smallest open chain: one segment, ghosts on both sides of it on its line.
  const std::vector<Vec2f> two{{1, 1}, {2, 3}};
  const std::vector<ChainSegment> one = makeChainSegments(two, false);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].ghost1, (Vec2f{0, -1}));
  EXPECT_EQ(one[0].ghost2, (Vec2f{3, 5}));
  // ChainDef forwards.
  EXPECT_EQ(makeChainSegments(ChainDef{p, false}).size(), 3u);
}

TEST(Chain, loop_wraps_around) {
  const std::vector<Vec2f> p{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<ChainSegment> s = makeChainSegments(p, true);
  ASSERT_EQ(s.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(s[i].ghost1, p[(i + 3) % 4]);
    EXPECT_EQ(s[i].segment.point1, p[i]);
    EXPECT_EQ(s[i].segment.point2, p[(i + 1) % 4]);
    EXPECT_EQ(s[i].ghost2, p[(i + 2) % 4]);
  }
  // A triangle is the smallest loop.
  const std::vector<Vec2f> triangle{{0, 0}, {1, 0}, {0, 1}};
  EXPECT_EQ(makeChainSegments(triangle, true).size(), 3u);
}

TEST(Chain, bad_points_name_the_field_and_index) {
  const std::vector<Vec2f> single{{0, 0}};
  expectErrorField([&] { (void)makeChainSegments(single, false); }, "points.size");
  const std::vector<Vec2f> pair{{0, 0}, {1, 0}};
  expectErrorField([&] { (void)makeChainSegments(pair, true); }, "points.size");
  const std::vector<Vec2f> nan{{0, 0}, {std::nanf(""), 0}, {2, 0}};
  expectErrorField([&] { (void)makeChainSegments(nan, false); }, "points[1].x");
  const std::vector<Vec2f> inf{{0, 0}, {1, 0}, {2, std::numeric_limits<float>::infinity()}};
  expectErrorField([&] { (void)makeChainSegments(inf, false); }, "points[2].y");
  // Consecutive points closer than linearSlop: the later one is named, and the message says which
  // neighbour it is too close to.
  const std::vector<Vec2f> repeated{{0, 0}, {1, 0}, {1.0f + 0.5f * linearSlop, 0}, {2, 0}};
  expectErrorField([&] { (void)makeChainSegments(repeated, false); }, "points[2]");
  try {
    (void)makeChainSegments(repeated, false);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("points[1]"), std::string::npos) << e.what();
  }
  // A loop must not repeat its first point at the end: the closing pair is checked too.
  const std::vector<Vec2f> closed{{0, 0}, {1, 0}, {1, 1}, {0, 0}};
  expectErrorField([&] { (void)makeChainSegments(closed, true); }, "points[0]");
  // ... while an open chain may come back to its start (a closed outline without wrap).
  EXPECT_EQ(makeChainSegments(closed, false).size(), 3u);
  // Exactly linearSlop apart is allowed.
  const std::vector<Vec2f> slop{{0, 0}, {linearSlop, 0}};
  EXPECT_EQ(makeChainSegments(slop, false).size(), 1u);
}

TEST(Chain, free_side_is_right_hand_so_a_ccw_loop_keeps_shapes_outside) {
  const std::vector<Vec2f> ccw{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const std::vector<Vec2f> cw{{-1, -1}, {-1, 1}, {1, 1}, {1, -1}};
  const Circle ball{{0, 0}, 0.25f};
  // Bottom edge of each loop is its segment 0; a ball just outside (below) and just inside
  // (above) it, both 0.01 m from the line.
  const ChainSegment ccwBottom = makeChainSegments(ccw, true)[0];
  const ChainSegment cwBottom = makeChainSegments(cw, true)[3]; // (1,-1) -> (-1,-1)
  const Transform2f outside = at(0, -1.26f);
  const Transform2f inside = at(0, -0.74f);

  const Manifold ccwOut = collideChainSegmentAndCircle(ccwBottom, at(0, 0), ball, outside);
  ASSERT_EQ(ccwOut.pointCount, 1);
  expectVec(ccwOut.normal, {0, -1}, normalTolerance); // pushes the ball away, outward
  EXPECT_NEAR(ccwOut.points[0].separation, 0.01f, lengthTolerance);
  EXPECT_EQ(collideChainSegmentAndCircle(ccwBottom, at(0, 0), ball, inside).pointCount, 0);

  const Manifold cwIn = collideChainSegmentAndCircle(cwBottom, at(0, 0), ball, inside);
  ASSERT_EQ(cwIn.pointCount, 1);
  expectVec(cwIn.normal, {0, 1}, normalTolerance); // pushes the ball back inside
  EXPECT_NEAR(cwIn.points[0].separation, 0.01f, lengthTolerance);
  EXPECT_EQ(collideChainSegmentAndCircle(cwBottom, at(0, 0), ball, outside).pointCount, 0);
}

TEST(Chain, aabb_encloses_the_segment_only) {
  const std::vector<Vec2f> p{{0, 0}, {1, 2}, {3, -1}};
  const Transform2f xf = at(0.5f, -2.0f, 0.7f);
  for (const ChainSegment& s : makeChainSegments(p, false)) {
    const AABB box = computeAABB(s, xf);
    const Vec2f a = transformPoint(xf, s.segment.point1);
    const Vec2f b = transformPoint(xf, s.segment.point2);
    // Tight: the box's corners are the ends' coordinate extremes (ghosts are not part of it).
    expectVec(box.lower, min(a, b), 1e-6f);
    expectVec(box.upper, max(a, b), 1e-6f);
    EXPECT_TRUE(isValid(box));
  }
}

TEST(Chain, ray_cast_hits_from_the_front_and_misses_from_behind) {
  const ChainSegment middle = flatGround()[1]; // (1,0) -> (-1,0), normal (0,1)
  // Straight down from 2 m above: hits halfway along the ray.
  const CastOutput down = rayCast(middle, {{0.5f, 2.0f}, {0.0f, -4.0f}, 1.0f});
  ASSERT_TRUE(down.hit);
  EXPECT_NEAR(down.fraction, 0.5f, 1e-6f);
  expectVec(down.point, {0.5f, 0.0f}, 1e-6f);
  expectVec(down.normal, {0, 1}, 0.0f);
  // Oblique: from (-1, 1) towards (1, -1) crosses y = 0 at x = 0, half way.
  const CastOutput oblique = rayCast(middle, {{-1.0f, 1.0f}, {2.0f, -2.0f}, 1.0f});
  ASSERT_TRUE(oblique.hit);
  EXPECT_NEAR(oblique.fraction, 0.5f, 1e-6f);
  expectVec(oblique.point, {0.0f, 0.0f}, 1e-6f);
  // From behind, straight up through the segment: no hit (one-sided).
  EXPECT_FALSE(rayCast(middle, {{0.5f, -2.0f}, {0.0f, 4.0f}, 1.0f}).hit);
  // Too short, beyond the ends, parallel: no hit.
  EXPECT_FALSE(rayCast(middle, {{0.5f, 2.0f}, {0.0f, -4.0f}, 0.4f}).hit);
  EXPECT_FALSE(rayCast(middle, {{1.5f, 2.0f}, {0.0f, -4.0f}, 1.0f}).hit);
  EXPECT_FALSE(rayCast(middle, {{-3.0f, 0.5f}, {6.0f, 0.0f}, 1.0f}).hit);
  // Bad rays name their field.
  expectErrorField([&] { (void)rayCast(middle, {{std::nanf(""), 0.0f}, {0.0f, -1.0f}, 1.0f}); }, "origin.x");
  expectErrorField([&] { (void)rayCast(middle, {{0.0f, 1.0f}, {0.0f, -1.0f}, -1.0f}); }, "maxFraction");
}

/// Collides `shape` with every segment of `chain` and returns the non-empty manifolds.
template <class Collide> std::vector<Manifold> collideAll(const std::vector<ChainSegment>& chain, Collide&& collide) {
  std::vector<Manifold> out;
  for (const ChainSegment& s : chain) {
    const Manifold m = collide(s);
    if (m.pointCount > 0) {
      out.push_back(m);
    }
  }
  return out;
}

TEST(Chain, box_resting_on_a_segment_gets_two_points_at_the_gap) {
  const std::vector<ChainSegment> ground = flatGround();
  const Polygon box = makeBox(0.5f, 0.5f);
  // Overlap, touching, and a speculative gap (kept below speculativeDistance = 0.02 m, dropped
  // beyond).
  for (const float gap : {-0.01f, 0.0f, 0.0003f, 0.01f, 0.019f}) {
    const Manifold m = collideChainSegmentAndPolygon(ground[1], at(0, 0), box, at(0.2f, 0.5f + gap));
    ASSERT_EQ(m.pointCount, 2) << gap;
    expectVec(m.normal, {0, 1}, normalTolerance);
    for (int i = 0; i < 2; ++i) {
      const ManifoldPoint& p = m.points[static_cast<std::size_t>(i)];
      EXPECT_NEAR(p.separation, gap, lengthTolerance);
      EXPECT_NEAR(p.point.y, 0.5f * gap, lengthTolerance); // midway between ground and box
    }
    EXPECT_NEAR(std::min(m.points[0].point.x, m.points[1].point.x), -0.3f, lengthTolerance);
    EXPECT_NEAR(std::max(m.points[0].point.x, m.points[1].point.x), 0.7f, lengthTolerance);
    EXPECT_NE(m.points[0].id, m.points[1].id);
  }
  EXPECT_EQ(collideChainSegmentAndPolygon(ground[1], at(0, 0), box, at(0.2f, 0.5f + 0.03f)).pointCount, 0);
  // Same features a step later: same ids (warm starting).
  const Manifold before = collideChainSegmentAndPolygon(ground[1], at(0, 0), box, at(0.2f, 0.495f));
  const Manifold after = collideChainSegmentAndPolygon(ground[1], at(0, 0), box, at(0.23f, 0.497f));
  ASSERT_EQ(after.pointCount, 2);
  EXPECT_EQ(before.points[0].id, after.points[0].id);
  EXPECT_EQ(before.points[1].id, after.points[1].id);
}

TEST(Chain, box_sliding_across_the_seams_never_gets_a_ghost_normal) {
  // The ghost-collision test: a box resting on the flat chain slides from one end to the other in
  // 5 mm steps, and at the exact positions where its corners are over a seam. Every manifold from
  // every segment must have the surface normal (0, 1), every point the gap as separation, and the
  // points together must span the box's bottom face (it is supported over its whole width).
  const std::vector<ChainSegment> ground = flatGround();
  const Polygon box = makeBox(0.5f, 0.5f);
  std::vector<float> xs;
  for (int i = 0; i <= 1000; ++i) {
    xs.push_back(-2.5f + 0.005f * static_cast<float>(i));
  }
  for (const float seam : {-1.0f, 1.0f}) {
    for (const float offset : {-0.5f, 0.0f, 0.5f}) {
      xs.push_back(seam + offset); // a corner exactly over the seam, or the centre
      xs.push_back(std::nextafter(seam + offset, 10.0f));
      xs.push_back(std::nextafter(seam + offset, -10.0f));
    }
  }
  // Gaps on both sides of the touching threshold (0.1 linearSlop), so both the separating-axis
  // path (touching or overlapping) and the closest-feature path (apart) are exercised.
  for (const float gap : {-0.01f, -0.0002f, 0.0f, 0.0003f, 0.002f, 0.015f}) {
    for (const float x : xs) {
      const Transform2f xfB = at(x, 0.5f + gap);
      const std::vector<Manifold> ms = collideAll(
          ground, [&](const ChainSegment& s) { return collideChainSegmentAndPolygon(s, at(0, 0), box, xfB); });
      ASSERT_FALSE(ms.empty()) << "x " << x << " gap " << gap;
      float lowest = 10.0f;
      float highest = -10.0f;
      int twoPointManifolds = 0;
      for (const Manifold& m : ms) {
        ASSERT_NEAR(m.normal.x, 0.0f, normalTolerance) << "ghost normal at x " << x << " gap " << gap;
        ASSERT_NEAR(m.normal.y, 1.0f, normalTolerance) << "ghost normal at x " << x << " gap " << gap;
        twoPointManifolds += m.pointCount == 2 ? 1 : 0;
        for (int i = 0; i < m.pointCount; ++i) {
          const ManifoldPoint& p = m.points[static_cast<std::size_t>(i)];
          ASSERT_NEAR(p.separation, gap, lengthTolerance) << "x " << x;
          lowest = std::min(lowest, p.point.x);
          highest = std::max(highest, p.point.x);
        }
      }
      EXPECT_GE(twoPointManifolds, 1) << "x " << x;
      EXPECT_NEAR(lowest, x - 0.5f, lengthTolerance) << "x " << x << " gap " << gap;
      EXPECT_NEAR(highest, x + 0.5f, lengthTolerance) << "x " << x << " gap " << gap;
    }
  }
}

TEST(Chain, tilted_box_corner_and_rounded_shapes_slide_across_a_seam_on_the_surface_normal) {
  // A box tilted by 0.3 rad touches with one corner; a capsule and a rounded box touch with their
  // rounded bottoms. Slide each across the seam at x = 1: the normal stays (0, 1), the smallest
  // separation stays the surface gap, and every point's separation is the true gap under it.
  const std::vector<ChainSegment> ground = flatGround();
  const float angle = 0.3f;
  const Polygon box = makeBox(0.5f, 0.5f);
  // Height of the tilted box's lowest corner below its centre: 0.5 (cos + sin).
  const float corner = 0.5f * (std::cos(angle) + std::sin(angle));
  const Polygon capsule = asPolygon(Capsule{{-0.4f, 0.0f}, {0.4f, 0.0f}, 0.2f});
  const std::vector<Vec2f> square{{-0.3f, -0.3f}, {0.3f, -0.3f}, {0.3f, 0.3f}, {-0.3f, 0.3f}};
  const Polygon rounded = makePolygon(square, 0.1f);
  struct Case {
    const Polygon* shape;
    float angle;
    float bottom; ///< depth of the shape's lowest surface point below its origin
  };
  for (const Case& c : {Case{&box, angle, corner}, Case{&capsule, 0.0f, 0.2f}, Case{&rounded, 0.0f, 0.4f}}) {
    for (const float gap : {-0.005f, 0.0f, 0.01f}) {
      for (int i = 0; i <= 400; ++i) {
        const float x = 0.0f + 0.005f * static_cast<float>(i);
        const Transform2f xfB = at(x, c.bottom + gap, c.angle);
        const std::vector<Manifold> ms = collideAll(
            ground, [&](const ChainSegment& s) { return collideChainSegmentAndPolygon(s, at(0, 0), *c.shape, xfB); });
        ASSERT_FALSE(ms.empty()) << x;
        float lowest = 10.0f;
        for (const Manifold& m : ms) {
          ASSERT_NEAR(m.normal.x, 0.0f, normalTolerance) << "x " << x << " gap " << gap;
          ASSERT_NEAR(m.normal.y, 1.0f, normalTolerance) << "x " << x << " gap " << gap;
          for (int k = 0; k < m.pointCount; ++k) {
            // The true gap under the point: the flat bottoms are `gap` above the ground
            // everywhere; the tilted box's faces rise from its lowest corner, the bottom face to
            // the right with slope tan(angle) and the left face to the left with slope
            // 1 / tan(angle), and a point clipped at a seam is that far up its face.
            const ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
            const float lowestX = x - 0.5f * (std::cos(c.angle) - std::sin(c.angle));
            const float run = p.point.x - lowestX;
            const float rise = run >= 0.0f ? run * std::tan(c.angle) : -run / std::tan(c.angle);
            const float expected = c.angle == 0.0f ? gap : gap + rise;
            EXPECT_NEAR(p.separation, expected, lengthTolerance) << "x " << x << " gap " << gap;
            lowest = std::min(lowest, p.separation);
          }
        }
        EXPECT_NEAR(lowest, gap, lengthTolerance) << "x " << x << " gap " << gap;
      }
    }
  }
}

TEST(Chain, shapes_behind_the_chain_get_no_contact) {
  const std::vector<ChainSegment> ground = flatGround();
  const Polygon box = makeBox(0.5f, 0.5f);
  const Circle ball{{0, 0}, 0.5f};
  // Coming up from below: apart, touching the underside, and half through (centroid still below).
  for (const float y : {-0.52f, -0.5f, -0.4f, -0.1f}) {
    for (const float x : {-2.0f, -1.0f, 0.0f, 0.7f, 1.0f}) {
      for (const ChainSegment& s : ground) {
        EXPECT_EQ(collideChainSegmentAndPolygon(s, at(0, 0), box, at(x, y)).pointCount, 0) << x << " " << y;
        EXPECT_EQ(collideChainSegmentAndCircle(s, at(0, 0), ball, at(x, y)).pointCount, 0) << x << " " << y;
      }
    }
  }
  // Far above: nothing either.
  EXPECT_EQ(collideChainSegmentAndPolygon(ground[1], at(0, 0), box, at(0, 2)).pointCount, 0);
  EXPECT_EQ(collideChainSegmentAndCircle(ground[1], at(0, 0), ball, at(0, 2)).pointCount, 0);
}

/// A chain bending down at the origin: flat top from (2,0) to (0,0) (normal up, 90 degrees), then a
/// 45-degree slope down to (-2,-2) (normal up-left, 135 degrees). The origin is a convex corner
/// whose normals are the arc from 90 to 135 degrees.
std::vector<ChainSegment> hill() {
  const std::vector<Vec2f> points{{2, 0}, {0, 0}, {-2, -2}};
  return makeChainSegments(points, false);
}

TEST(Chain, circle_on_a_convex_corner_gets_the_vertex_normal_once) {
  const std::vector<ChainSegment> chain = hill();
  const Circle ball{{0, 0}, 0.5f};
  const float gap = 0.01f;
  // Roll the ball over the corner: at every direction in the arc the contact normal is that
  // direction (it is the corner, not a face, that touches), reported by exactly one segment.
  for (int i = 0; i <= 45; ++i) {
    const float degrees = 90.0f + static_cast<float>(i);
    const Vec2f d = unitAt(degrees);
    const Transform2f xfB = at(d.x * (0.5f + gap), d.y * (0.5f + gap));
    const std::vector<Manifold> ms =
        collideAll(chain, [&](const ChainSegment& s) { return collideChainSegmentAndCircle(s, at(0, 0), ball, xfB); });
    ASSERT_EQ(ms.size(), 1u) << degrees;
    ASSERT_EQ(ms[0].pointCount, 1);
    expectVec(ms[0].normal, d, 1e-5f);
    EXPECT_NEAR(ms[0].points[0].separation, gap, lengthTolerance);
    expectVec(ms[0].points[0].point, d * (0.5f * gap), lengthTolerance); // midway, off the corner
  }
  // Over either face the face's normal.
  const Manifold top = collideChainSegmentAndCircle(chain[0], at(0, 0), ball, at(1.0f, 0.5f + gap));
  ASSERT_EQ(top.pointCount, 1);
  expectVec(top.normal, {0, 1}, normalTolerance);
  const Vec2f slopeNormal = unitAt(135.0f);
  const Vec2f onSlope = Vec2f{-1, -1} + slopeNormal * (0.5f + gap);
  const Manifold slope = collideChainSegmentAndCircle(chain[1], at(0, 0), ball, at(onSlope.x, onSlope.y));
  ASSERT_EQ(slope.pointCount, 1);
  expectVec(slope.normal, slopeNormal, 1e-5f);
  EXPECT_NEAR(slope.points[0].separation, gap, lengthTolerance);
}

TEST(Chain, circle_centred_on_the_chain_gets_a_unit_normal_and_minus_its_radius) {
  // fuzz regression narrowphase/tiny-normal-chain-circle: a centre 1e-21 m from a corner got a
  // normal of length 1.0014 (the squared distance underflows: the division was by an inexact
  // length). A centre on the chain, or within 1e-10 m of it (under the spacing of floats at 1 cm),
  // is touching it at its centre: the separation is -radius, and the normal must still be a unit
  // vector of the corner's arc, between the slope's normal (135 degrees) and up (90 degrees).
  const std::vector<ChainSegment> chain = hill();
  const float radius = 0.5f;
  const Circle ball{{0, 0}, radius};
  std::vector<Vec2f> centres{{0, 0}, {1, 0}, {1, 1e-10f}, {-1, -1}};
  for (const float offset : {1e-10f, 1e-21f, 1e-30f, std::numeric_limits<float>::denorm_min()}) {
    for (const float degrees : {90.0f, 100.0f, 112.5f, 135.0f}) {
      centres.push_back(unitAt(degrees) * offset); // off the corner, within its arc
    }
  }
  for (const Vec2f& c : centres) {
    const std::vector<Manifold> ms = collideAll(
        chain, [&](const ChainSegment& s) { return collideChainSegmentAndCircle(s, at(0, 0), ball, at(c.x, c.y)); });
    ASSERT_EQ(ms.size(), 1u) << c.x << " " << c.y; // one segment reports
    const Manifold& m = ms[0];
    ASSERT_EQ(m.pointCount, 1);
    ASSERT_TRUE(std::isfinite(m.normal.x) && std::isfinite(m.normal.y));
    EXPECT_NEAR(length(m.normal), 1.0f, normalTolerance) << c.x << " " << c.y;
    // In the arc: no more than 90 degrees from up and from the slope's normal (both >= 0 within
    // a rounding).
    EXPECT_GE(dot(m.normal, Vec2f{0, 1}), -normalTolerance);
    EXPECT_GE(dot(m.normal, unitAt(135.0f)), -normalTolerance);
    EXPECT_NEAR(m.points[0].separation, -radius, lengthTolerance) << c.x << " " << c.y;
    // Midway between the chain (the centre) and the far side of the ball's surface along -normal.
    EXPECT_TRUE(std::isfinite(m.points[0].point.x) && std::isfinite(m.points[0].point.y));
    expectVec(m.points[0].point, c - m.normal * (0.5f * radius), lengthTolerance);
  }
}

TEST(Chain, circle_across_a_flat_seam_keeps_the_surface_normal) {
  const std::vector<ChainSegment> ground = flatGround();
  const Circle ball{{0, 0}, 0.25f};
  for (const float gap : {-0.01f, 0.0f, 0.01f}) {
    std::vector<float> xs{1.0f, std::nextafter(1.0f, 2.0f), std::nextafter(1.0f, 0.0f)};
    for (int i = 0; i <= 200; ++i) {
      xs.push_back(0.5f + 0.005f * static_cast<float>(i));
    }
    for (const float x : xs) {
      const Transform2f xfB = at(x, 0.25f + gap);
      const std::vector<Manifold> ms = collideAll(
          ground, [&](const ChainSegment& s) { return collideChainSegmentAndCircle(s, at(0, 0), ball, xfB); });
      // Exactly one segment reports, with the surface normal and the gap.
      ASSERT_EQ(ms.size(), 1u) << x;
      expectVec(ms[0].normal, {0, 1}, normalTolerance);
      EXPECT_NEAR(ms[0].points[0].separation, gap, lengthTolerance) << x;
      expectVec(ms[0].points[0].point, {x, 0.5f * gap}, lengthTolerance);
    }
  }
}

TEST(Chain, circle_in_a_concave_valley_touches_both_walls) {
  // A V: (2,2) -> (0,0) -> (-2,2), listed so the free side is up. A ball of radius 0.5 sitting in
  // it touches both walls at distance 0.5 from each, its centre sqrt(2)/2 above the bottom.
  const std::vector<Vec2f> points{{2, 2}, {0, 0}, {-2, 2}};
  const std::vector<ChainSegment> valley = makeChainSegments(points, false);
  const Circle ball{{0, 0}, 0.5f};
  const float centre = 0.5f * std::sqrt(2.0f) - 0.01f * std::sqrt(2.0f); // 1 cm into each wall
  const std::vector<Manifold> ms = collideAll(
      valley, [&](const ChainSegment& s) { return collideChainSegmentAndCircle(s, at(0, 0), ball, at(0, centre)); });
  ASSERT_EQ(ms.size(), 2u);
  expectVec(ms[0].normal, unitAt(135.0f), 1e-5f); // right wall (2,2)->(0,0): normal up-left
  expectVec(ms[1].normal, unitAt(45.0f), 1e-5f);  // left wall (0,0)->(-2,2): normal up-right
  for (const Manifold& m : ms) {
    EXPECT_NEAR(m.points[0].separation, -0.01f, lengthTolerance);
  }
  // A concave corner has no vertex region in front of the chain. In a V sharper than a right
  // angle, a centre below the bottom, through the right wall but in front of the left wall's
  // line, must not get a contact from the bottom vertex (its normal would point down, through
  // the chain).
  const std::vector<Vec2f> sharp{{1, 2}, {0, 0}, {-1, 2}};
  const std::vector<ChainSegment> narrow = makeChainSegments(sharp, false);
  for (const ChainSegment& s : narrow) {
    EXPECT_EQ(collideChainSegmentAndCircle(s, at(0, 0), ball, at(0.3f, -0.3f)).pointCount, 0);
  }
}

TEST(Chain, box_at_a_convex_corner_gets_admissible_normals_only) {
  const std::vector<ChainSegment> chain = hill();
  const Polygon box = makeBox(0.25f, 0.25f);
  const float gap = 0.01f;
  // Corner against corner: the box turned so that one of its corners points at the chain's
  // corner along the direction d (inside the arc); its adjacent edges open away from both
  // segments, so the closest features are the two corners and the normal is d.
  for (const float degrees : {95.0f, 112.5f, 130.0f}) {
    const Vec2f d = unitAt(degrees);
    const float boxAngle = (degrees + 180.0f - 225.0f) * pi<float> / 180.0f; // corner (-,-) points along -d
    const float reach = 0.25f * std::sqrt(2.0f) + gap;
    const Transform2f xfB = at(d.x * reach, d.y * reach, boxAngle);
    const std::vector<Manifold> ms =
        collideAll(chain, [&](const ChainSegment& s) { return collideChainSegmentAndPolygon(s, at(0, 0), box, xfB); });
    ASSERT_FALSE(ms.empty()) << degrees;
    for (const Manifold& m : ms) {
      ASSERT_EQ(m.pointCount, 1);
      expectVec(m.normal, d, 1e-5f);
      EXPECT_NEAR(m.points[0].separation, gap, lengthTolerance);
    }
  }
  // Resting flat on the top and overhanging the corner by 0.1 m: the top segment carries it with
  // the surface normal (two points, the left one where the top ends); the slope gives nothing (its
  // own normal is not the separating axis, and the top's is).
  for (const float sink : {0.0f, 0.004f}) {
    const Transform2f xfB = at(0.15f, 0.25f - sink);
    const Manifold top = collideChainSegmentAndPolygon(chain[0], at(0, 0), box, xfB);
    ASSERT_EQ(top.pointCount, 2);
    expectVec(top.normal, {0, 1}, normalTolerance);
    EXPECT_NEAR(std::min(top.points[0].point.x, top.points[1].point.x), 0.0f, lengthTolerance);
    EXPECT_NEAR(std::max(top.points[0].point.x, top.points[1].point.x), 0.4f, lengthTolerance);
    EXPECT_NEAR(top.points[0].separation, -sink, lengthTolerance);
    EXPECT_EQ(collideChainSegmentAndPolygon(chain[1], at(0, 0), box, xfB).pointCount, 0);
  }
}

TEST(Chain, capsule_across_a_convex_corner_touches_with_its_facing_side) {
  // A capsule lying across the corner of the hill, its core perpendicular to a direction d in the
  // corner's arc: the corner is nearest to the inside of the core, so the normal is d and the
  // separation the surface gap. A capsule is a 2-vertex polygon whose two edges are the same
  // segment facing opposite ways; either order of its centres must give the same contact.
  const std::vector<ChainSegment> chain = hill();
  const float radius = 0.2f;
  const float gap = 0.01f;
  for (const float degrees : {100.0f, 125.0f}) {
    const Vec2f d = unitAt(degrees);
    const Vec2f along{-d.y, d.x};
    const Vec2f middle = d * (radius + gap);
    for (const bool reversed : {false, true}) {
      const Vec2f c1 = middle - along * 0.4f;
      const Vec2f c2 = middle + along * 0.3f;
      const Polygon capsule = asPolygon(reversed ? Capsule{c2, c1, radius} : Capsule{c1, c2, radius});
      const std::vector<Manifold> ms = collideAll(
          chain, [&](const ChainSegment& s) { return collideChainSegmentAndPolygon(s, at(0, 0), capsule, at(0, 0)); });
      ASSERT_FALSE(ms.empty()) << degrees << " reversed " << reversed;
      float lowest = 1.0f;
      for (const Manifold& m : ms) {
        expectVec(m.normal, d, 1e-5f);
        for (int k = 0; k < m.pointCount; ++k) {
          lowest = std::min(lowest, m.points[static_cast<std::size_t>(k)].separation);
        }
      }
      EXPECT_NEAR(lowest, gap, lengthTolerance) << degrees << " reversed " << reversed;
    }
  }
}

TEST(Chain, interior_contact_matches_the_plain_segment_manifold) {
  // Over the middle of a segment, away from its ends, the chain segment is just a one-sided
  // segment: its manifold must equal collidePolygons with the segment as a 2-vertex polygon.
  const std::vector<ChainSegment> ground = flatGround();
  const Polygon segmentPolygon = asPolygon(ground[1].segment);
  const Polygon box = makeOffsetBox(0.3f, 0.2f, {0.05f, -0.02f}, 0.0f);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> xDist(-0.4f, 0.4f);
  std::uniform_real_distribution<float> angleDist(-0.3f, 0.3f);
  std::uniform_real_distribution<float> gapDist(-0.01f, 0.015f);
  for (int trial = 0; trial < 200; ++trial) {
    const float angle = angleDist(rng);
    const float gap = gapDist(rng);
    Transform2f xfB = at(xDist(rng), 0.0f, angle);
    // Lift the box so that its lowest vertex is `gap` above the ground.
    float lowest = 10.0f;
    for (int i = 0; i < box.count; ++i) {
      lowest = std::min(lowest, transformPoint(xfB, box.vertices[static_cast<std::size_t>(i)]).y);
    }
    xfB.p.y += gap - lowest;
    const Manifold chain = collideChainSegmentAndPolygon(ground[1], at(0, 0), box, xfB);
    const Manifold plain = collidePolygons(segmentPolygon, at(0, 0), box, xfB);
    ASSERT_EQ(chain.pointCount, plain.pointCount) << trial;
    ASSERT_GE(chain.pointCount, 1);
    expectVec(chain.normal, plain.normal, normalTolerance);
    for (int i = 0; i < chain.pointCount; ++i) {
      // Same points, in either order.
      const ManifoldPoint& c = chain.points[static_cast<std::size_t>(i)];
      const ManifoldPoint* match = nullptr;
      for (int j = 0; j < plain.pointCount; ++j) {
        const ManifoldPoint& p = plain.points[static_cast<std::size_t>(j)];
        if (distance(p.point, c.point) < lengthTolerance) {
          match = &p;
        }
      }
      ASSERT_NE(match, nullptr) << trial;
      EXPECT_NEAR(c.separation, match->separation, lengthTolerance);
    }
  }
}

TEST(Chain, manifold_follows_the_bodies_and_keeps_the_anchor_conventions) {
  // The same box-on-ground contact, with the whole scene rotated by 0.6 rad and shifted: the
  // normal rotates with it, separations are unchanged, and anchors are the point relative to
  // each body's origin.
  const std::vector<ChainSegment> ground = flatGround();
  const Polygon box = makeBox(0.5f, 0.5f);
  const Transform2f scene = at(4.0f, -1.5f, 0.6f);
  const Transform2f localB = at(0.2f, 0.49f, 0.0f);
  const Manifold reference = collideChainSegmentAndPolygon(ground[1], at(0, 0), box, localB);
  const Transform2f xfA = scene;
  const Transform2f xfB = mul(scene, localB);
  const Manifold m = collideChainSegmentAndPolygon(ground[1], xfA, box, xfB);
  ASSERT_EQ(m.pointCount, 2);
  expectVec(m.normal, rotate(scene.q, Vec2f{0, 1}), normalTolerance);
  for (int i = 0; i < 2; ++i) {
    const ManifoldPoint& p = m.points[static_cast<std::size_t>(i)];
    EXPECT_NEAR(p.separation, -0.01f, lengthTolerance);
    expectVec(p.point, transformPoint(scene, reference.points[static_cast<std::size_t>(i)].point), lengthTolerance);
    expectVec(p.anchorA, p.point - xfA.p, 1e-6f);
    expectVec(p.anchorB, p.point - xfB.p, 1e-6f);
  }
  // A circle the same way.
  const Circle ball{{0.1f, 0.0f}, 0.3f};
  const Manifold c = collideChainSegmentAndCircle(ground[1], xfA, ball, mul(scene, at(0.0f, 0.29f)));
  ASSERT_EQ(c.pointCount, 1);
  expectVec(c.normal, rotate(scene.q, Vec2f{0, 1}), normalTolerance);
  EXPECT_NEAR(c.points[0].separation, -0.01f, lengthTolerance);
  expectVec(c.points[0].point, transformPoint(scene, Vec2f{0.1f, -0.005f}), lengthTolerance);
}

TEST(Chain, one_vertex_polygon_is_collided_as_a_circle) {
  const std::vector<ChainSegment> chain = hill();
  const Circle ball{{0.1f, 0.0f}, 0.4f};
  for (const Transform2f& xfB : {at(0.5f, 0.39f), at(-0.2f, 0.3f), at(-1.0f, -0.5f)}) {
    for (const ChainSegment& s : chain) {
      const Manifold a = collideChainSegmentAndCircle(s, at(0, 0), ball, xfB);
      const Manifold b = collideChainSegmentAndPolygon(s, at(0, 0), asPolygon(ball), xfB);
      ASSERT_EQ(a.pointCount, b.pointCount);
      if (a.pointCount == 1) {
        expectVec(a.normal, b.normal, 0.0f);
        EXPECT_EQ(a.points[0].separation, b.points[0].separation);
      }
    }
  }
}

} // namespace
} // namespace impetus::rigid2d
