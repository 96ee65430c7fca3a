#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/manifold.hpp>

#include "rigid2d/manifold_internal.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <span>
#include <vector>

namespace impetus::rigid2d {
namespace {

Transform2f at(float x, float y, float angle = 0.0f) { return {{x, y}, Rot2f::fromAngle(angle)}; }

TEST(Manifold, circles_separation_normal_and_speculative_range) {
  const Circle unit{{0, 0}, 0.5f};
  const Manifold overlap = collideCircles(unit, at(0, 0), unit, at(0.9f, 0));
  ASSERT_EQ(overlap.pointCount, 1);
  EXPECT_NEAR(overlap.points[0].separation, -0.1f, 1e-6f);
  EXPECT_NEAR(overlap.normal.x, 1.0f, 1e-6f);
  EXPECT_NEAR(overlap.points[0].point.x, 0.45f, 1e-6f); // midway between the surfaces
  // Kept while closer than the speculative distance, dropped beyond.
  EXPECT_EQ(collideCircles(unit, at(0, 0), unit, at(1.0f + 0.5f * speculativeDistance, 0)).pointCount, 1);
  EXPECT_EQ(collideCircles(unit, at(0, 0), unit, at(1.0f + 2.0f * speculativeDistance, 0)).pointCount, 0);
}

TEST(Manifold, box_resting_on_box_has_two_points_along_the_face) {
  const Polygon ground = makeBox(5.0f, 0.5f);
  const Polygon box = makeBox(0.5f, 0.5f);
  const Manifold m = collidePolygons(ground, at(0, 0), box, at(1.0f, 0.99f)); // 1 cm overlap
  ASSERT_EQ(m.pointCount, 2);
  EXPECT_NEAR(m.normal.y, 1.0f, 1e-6f);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[static_cast<std::size_t>(i)].separation, -0.01f, 1e-5f);
    EXPECT_NEAR(m.points[static_cast<std::size_t>(i)].point.y, 0.495f, 1e-5f);
  }
  EXPECT_NEAR(std::abs(m.points[0].point.x - m.points[1].point.x), 1.0f, 1e-5f);
  EXPECT_NE(m.points[0].id, m.points[1].id);
  // The same features give the same ids a step later.
  const Manifold later = collidePolygons(ground, at(0, 0), box, at(1.02f, 0.985f));
  ASSERT_EQ(later.pointCount, 2);
  EXPECT_EQ(later.points[0].id, m.points[0].id);
  EXPECT_EQ(later.points[1].id, m.points[1].id);
}

TEST(Manifold, tilted_box_touches_with_one_corner) {
  const Polygon ground = makeBox(5.0f, 0.5f);
  const Polygon box = makeBox(0.5f, 0.5f);
  const float half = 0.5f * std::sqrt(2.0f); // corner distance at 45 degrees
  const Manifold m = collidePolygons(ground, at(0, 0), box, at(0, 0.5f + half - 0.01f, pi<float> / 4));
  ASSERT_EQ(m.pointCount, 1);
  EXPECT_NEAR(m.points[0].separation, -0.01f, 1e-5f);
  EXPECT_NEAR(m.points[0].point.x, 0.0f, 1e-5f);
}

TEST(Manifold, polygon_and_circle_face_and_vertex_regions) {
  const Polygon box = makeBox(1.0f, 1.0f);
  const Circle ball{{0, 0}, 0.5f};
  const Manifold face = collidePolygonAndCircle(box, at(0, 0), ball, at(0.3f, 1.4f));
  ASSERT_EQ(face.pointCount, 1);
  EXPECT_NEAR(face.normal.y, 1.0f, 1e-6f);
  EXPECT_NEAR(face.points[0].separation, -0.1f, 1e-6f);
  // Off the corner: the normal points from the corner to the centre.
  const Manifold corner = collidePolygonAndCircle(box, at(0, 0), ball, at(1.3f, 1.3f));
  ASSERT_EQ(corner.pointCount, 1);
  EXPECT_NEAR(corner.normal.x, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(corner.points[0].separation, std::sqrt(0.18f) - 0.5f, 1e-6f);
}

TEST(Manifold, parallel_capsules_touch_along_a_segment) {
  const Polygon capsule = asPolygon(Capsule{{-1, 0}, {1, 0}, 0.25f});
  const Manifold m = collidePolygons(capsule, at(0, 0), capsule, at(0.5f, 0.49f));
  ASSERT_EQ(m.pointCount, 2);
  EXPECT_NEAR(std::abs(m.normal.y), 1.0f, 1e-6f);
  EXPECT_NEAR(m.points[0].separation, -0.01f, 1e-5f);
  EXPECT_NEAR(m.points[1].separation, -0.01f, 1e-5f);
}

// Swapping A and B flips the normal and keeps the separations.
TEST(Manifold, swapping_the_shapes_flips_the_normal) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int touching = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const Polygon a = makeOffsetBox(0.6f, 0.3f, {}, u(rng));
    const Polygon b = asPolygon(Capsule{{-0.4f, 0.0f}, {0.4f, 0.1f}, 0.2f});
    const Transform2f xa = at(u(rng) * 0.2f, u(rng) * 0.2f, u(rng) * 3.0f);
    const Transform2f xb = at(u(rng), u(rng), u(rng) * 3.0f);
    const Manifold ab = collidePolygons(a, xa, b, xb);
    const Manifold ba = collidePolygons(b, xb, a, xa);
    ASSERT_EQ(ab.pointCount > 0, ba.pointCount > 0) << trial;
    if (ab.pointCount == 0) {
      continue;
    }
    ++touching;
    // Deep overlaps (which the solver never lets happen) can have two near-equal faces, and
    // the reference face prefers A within 0.1 linearSlop for frame-to-frame stability: there
    // the two orders may pick different faces. Below 5 cm of overlap they must agree.
    if (std::min(ab.points[0].separation, ab.pointCount > 1 ? ab.points[1].separation : 0.0f) < -0.05f) {
      continue;
    }
    EXPECT_NEAR(dot(ab.normal, ba.normal), -1.0f, 1e-4f) << trial;
    float minAB = 1e9f, minBA = 1e9f;
    for (int i = 0; i < ab.pointCount; ++i) {
      minAB = std::min(minAB, ab.points[static_cast<std::size_t>(i)].separation);
      EXPECT_TRUE(isFinite(ab.points[static_cast<std::size_t>(i)].point));
    }
    for (int i = 0; i < ba.pointCount; ++i) {
      minBA = std::min(minBA, ba.points[static_cast<std::size_t>(i)].separation);
    }
    EXPECT_NEAR(minAB, minBA, 1e-4f) << trial;
  }
  EXPECT_GT(touching, 50);
}

// collidePolygons' shortcuts (two plain boxes; an axis-aligned rectangle against anything) must
// give the general path's manifold: the same points, features and reference face, and the same
// floats within 1e-5 of the scale. The shortcuts are built to run the same float operations
// as the general path (fewer of them), so in fact not one float may differ: counted apart.
struct ShortcutChecker {
  int checked = 0;
  std::array<int, 3> pointCounts{};
  int flipped = 0; // B's face is the reference
  int clipped = 0; // a point on a side plane of the reference face (ids 8, 9)
  int corners = 0; // cores apart: vertex against vertex (ids 10, 11)
  int inexact = 0; // some float differs (by the design, none: the same operations run)

  void check(const Polygon& a, const Transform2f& xa, const Polygon& b, const Transform2f& xb, detail::PolygonPath path,
             int trial) {
    ASSERT_EQ(detail::polygonPath(a, b), path) << trial;
    const Manifold fast = collidePolygons(a, xa, b, xb);
    const Manifold general = detail::collidePolygonsGeneral(a, xa, b, xb);
    ASSERT_EQ(fast.pointCount, general.pointCount) << trial;
    ++checked;
    bool same = fast.pointCount == 0 || fast.normal == general.normal;
    for (std::size_t i = 0; i < static_cast<std::size_t>(fast.pointCount); ++i) {
      const ManifoldPoint& f = fast.points[i];
      const ManifoldPoint& g = general.points[i];
      same = same && f.point == g.point && f.anchorA == g.anchorA && f.anchorB == g.anchorB &&
             f.separation == g.separation;
    }
    inexact += same ? 0 : 1;
    ++pointCounts[static_cast<std::size_t>(fast.pointCount)];
    if (fast.pointCount == 0) {
      return;
    }
    const float scale = std::max({1.0f, std::abs(xa.p.x), std::abs(xa.p.y), std::abs(xb.p.x), std::abs(xb.p.y)});
    const float tolerance = 1e-5f * scale;
    EXPECT_NEAR(fast.normal.x, general.normal.x, 1e-5f) << trial;
    EXPECT_NEAR(fast.normal.y, general.normal.y, 1e-5f) << trial;
    for (std::size_t i = 0; i < static_cast<std::size_t>(fast.pointCount); ++i) {
      const ManifoldPoint& f = fast.points[i];
      const ManifoldPoint& g = general.points[i];
      EXPECT_EQ(f.id, g.id) << trial;
      EXPECT_NEAR(f.separation, g.separation, tolerance) << trial;
      EXPECT_NEAR(f.point.x, g.point.x, tolerance) << trial;
      EXPECT_NEAR(f.point.y, g.point.y, tolerance) << trial;
      EXPECT_NEAR(f.anchorA.x, g.anchorA.x, tolerance) << trial;
      EXPECT_NEAR(f.anchorA.y, g.anchorA.y, tolerance) << trial;
      EXPECT_NEAR(f.anchorB.x, g.anchorB.x, tolerance) << trial;
      EXPECT_NEAR(f.anchorB.y, g.anchorB.y, tolerance) << trial;
      flipped += (f.id & 0x8000) != 0 ? 1 : 0;
      const int feature = f.id & 0xf;
      clipped += feature == 8 || feature == 9 ? 1 : 0;
      corners += feature >= 10 ? 1 : 0;
    }
  }
};

/// A rotation by `quarterTurns` right angles, exactly ((1, 0), (0, 1), ...; Rot2f::fromAngle is
/// off by a rounding), then by `angle` more.
Rot2f quarterTurnsAnd(int quarterTurns, float angle) {
  constexpr std::array<Rot2f, 4> exact{Rot2f{1, 0}, Rot2f{0, 1}, Rot2f{-1, 0}, Rot2f{0, -1}};
  const Rot2f q = exact[static_cast<std::size_t>(quarterTurns & 3)];
  return angle == 0.0f ? q : mul(q, Rot2f::fromAngle(angle));
}

TEST(Manifold, box_shortcut_matches_the_general_path) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * unit(rng); };
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  ShortcutChecker checker;
  for (int trial = 0; trial < 40000; ++trial) {
    // Sizes 0.05 to 5 m (log-uniform); three pairs in eight equal boxes, one of them the
    // pyramid's 0.5 m boxes.
    const int kind = pick(8);
    const bool pyramid = kind == 0;
    const float ax = pyramid ? 0.5f : std::exp(uniform(std::log(0.05f), std::log(5.0f)));
    const float ay = pyramid ? 0.5f : std::exp(uniform(std::log(0.05f), std::log(5.0f)));
    const bool equal = pyramid || kind < 3;
    const float bx = equal ? ax : std::exp(uniform(std::log(0.05f), std::log(5.0f)));
    const float by = equal ? ay : std::exp(uniform(std::log(0.05f), std::log(5.0f)));
    // A: a plain box, centred or not (makeOffsetBox at angle 0); B: makeBox.
    const Vec2f aCenter = pick(3) == 0 ? Vec2f{uniform(-1, 1), uniform(-1, 1)} : Vec2f{};
    const Polygon a = aCenter == Vec2f{} ? makeBox(ax, ay) : makeOffsetBox(ax, ay, aCenter, 0.0f);
    const Polygon b = makeBox(bx, by);
    // Relative rotation: exact right angles, right angles and a hair, or anything.
    float hair = 0.0f;
    switch (pick(4)) {
    case 0:
      break;
    case 1:
      hair = uniform(-1e-3f, 1e-3f);
      break;
    case 2:
      hair = uniform(-1e-6f, 1e-6f);
      break;
    default:
      hair = uniform(-0.8f, 0.8f);
      break;
    }
    const Rot2f relative = quarterTurnsAnd(pick(4), hair);
    // A anywhere (at exactly 0 now and then), B placed in A's frame.
    const Transform2f xa =
        pick(4) == 0 ? Transform2f{{uniform(-50, 50), uniform(-50, 50)}, Rot2f{}}
                     : Transform2f{{uniform(-50, 50), uniform(-50, 50)}, Rot2f::fromAngle(uniform(-3.2f, 3.2f))};
    // B's half-extents along A's axes (exact at right angles).
    const bool turned = (std::abs(relative.s) > std::abs(relative.c));
    const float reachX = turned ? by : bx;
    const float reachY = turned ? bx : by;
    Vec2f offset;
    const float depth = std::min({ax, ay, bx, by});
    const float gap = pick(4) == 0 ? 0.0f : uniform(-0.6f * depth, 2.0f * speculativeDistance);
    switch (pick(4)) {
    case 0: // side by side (the pyramid's rows: exactly touching when gap is 0)
      offset = {(pick(2) == 0 ? 1.0f : -1.0f) * (ax + reachX + gap),
                pyramid ? 0.0f : uniform(-(ay + reachY), ay + reachY)};
      break;
    case 1: // stacked (the pyramid: half a box to the side)
      offset = {pyramid ? (pick(2) == 0 ? 0.5f : -0.5f) : uniform(-(ax + reachX), ax + reachX),
                (pick(2) == 0 ? 1.0f : -1.0f) * (ay + reachY + gap)};
      break;
    case 2: // corner to corner
      offset = {(pick(2) == 0 ? 1.0f : -1.0f) * (ax + reachX + gap),
                (pick(2) == 0 ? 1.0f : -1.0f) * (ay + reachY + gap)};
      break;
    default: // anywhere from deep overlap to out of reach
      offset = {uniform(-1.2f, 1.2f) * (ax + reachX + 2.0f * speculativeDistance),
                uniform(-1.2f, 1.2f) * (ay + reachY + 2.0f * speculativeDistance)};
      break;
    }
    if (pick(3) == 0) { // a hair off the exact arrangement
      offset += Vec2f{uniform(-1e-4f, 1e-4f), uniform(-1e-4f, 1e-4f)};
    }
    offset += aCenter;
    const Transform2f xb{transformPoint(xa, offset), mul(xa.q, relative)};
    checker.check(a, xa, b, xb, detail::PolygonPath::boxes, trial);
    if (HasFatalFailure()) {
      return;
    }
  }
  EXPECT_EQ(checker.inexact, 0);
  // Every branch of the clip was taken, many times.
  EXPECT_GT(checker.pointCounts[0], 1000);
  EXPECT_GT(checker.pointCounts[1], 1000);
  EXPECT_GT(checker.pointCounts[2], 1000);
  EXPECT_GT(checker.flipped, 1000);
  EXPECT_GT(checker.clipped, 1000);
  EXPECT_GT(checker.corners, 10);
}

TEST(Manifold, rectangle_shortcut_matches_the_general_path) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * unit(rng); };
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  ShortcutChecker checker;
  for (int trial = 0; trial < 20000; ++trial) {
    const float ax = uniform(0.05f, 3.0f);
    const float ay = uniform(0.05f, 3.0f);
    // A: an axis-aligned rectangle, rounded now and then (not a plain box then).
    const Polygon plain = makeOffsetBox(ax, ay, {uniform(-0.5f, 0.5f), uniform(-0.5f, 0.5f)}, 0.0f);
    const Polygon a =
        pick(3) == 0 ? makePolygon(std::span<const Vec2f>(plain.vertices.data(), 4), uniform(0.0f, 0.3f)) : plain;
    // B: anything but a centred plain box: an offset or turned box, a rounded box, a convex
    // polygon of 3 to 8 points, a capsule or a segment.
    Polygon b;
    switch (pick(5)) {
    case 0:
      b = makeOffsetBox(uniform(0.05f, 3.0f), uniform(0.05f, 3.0f), {uniform(-1, 1), uniform(-1, 1)},
                        pick(2) == 0 ? 0.0f : uniform(-3, 3));
      break;
    case 1: {
      const Polygon box = makeBox(uniform(0.05f, 3.0f), uniform(0.05f, 3.0f));
      b = makePolygon(std::span<const Vec2f>(box.vertices.data(), 4), uniform(0.01f, 0.3f));
      break;
    }
    case 2: {
      // 3 to 8 points around a circle, each in its own sector: never collinear.
      std::vector<Vec2f> points(static_cast<std::size_t>(3 + pick(6)));
      const float sector = 2.0f * pi<float> / static_cast<float>(points.size());
      for (std::size_t i = 0; i < points.size(); ++i) {
        const float angle = sector * (static_cast<float>(i) + uniform(0.1f, 0.9f));
        const float r = uniform(0.5f, 2.0f);
        points[i] = {r * std::cos(angle), r * std::sin(angle)};
      }
      b = makePolygon(points, pick(2) == 0 ? 0.0f : uniform(0.0f, 0.2f));
      break;
    }
    case 3:
      b = asPolygon(Capsule{{uniform(-1, 1), uniform(-1, 1)}, {uniform(-1, 1), uniform(-1, 1)}, uniform(0.05f, 0.5f)});
      break;
    default:
      b = asPolygon(Segment{{uniform(-1, 1), uniform(-1, 1)}, {uniform(-1, 1), uniform(-1, 1)}});
      break;
    }
    const Transform2f xa{{uniform(-20, 20), uniform(-20, 20)}, Rot2f::fromAngle(uniform(-3.2f, 3.2f))};
    const Rot2f relative = quarterTurnsAnd(pick(4), pick(2) == 0 ? 0.0f : uniform(-0.8f, 0.8f));
    const Vec2f offset{uniform(-1.2f, 1.2f) * (ax + 2.0f), uniform(-1.2f, 1.2f) * (ay + 2.0f)};
    const Transform2f xb{transformPoint(xa, offset), mul(xa.q, relative)};
    checker.check(a, xa, b, xb, detail::PolygonPath::rectangle, trial);
    if (HasFatalFailure()) {
      return;
    }
  }
  EXPECT_EQ(checker.inexact, 0);
  EXPECT_GT(checker.pointCounts[1], 500);
  EXPECT_GT(checker.pointCounts[2], 500);
  EXPECT_GT(checker.flipped, 500);
  EXPECT_GT(checker.corners, 50);
}

TEST(Manifold, polygons_take_the_shortcuts_only_when_they_apply) {
  const Polygon box = makeBox(0.5f, 0.25f);
  const Polygon offset = makeOffsetBox(0.5f, 0.25f, {0.1f, 0.2f}, 0.0f);
  const Polygon turned = makeOffsetBox(0.5f, 0.25f, {}, 0.3f);
  const std::array<Vec2f, 4> corners{Vec2f{-0.5f, -0.25f}, Vec2f{0.5f, -0.25f}, Vec2f{0.5f, 0.25f},
                                     Vec2f{-0.5f, 0.25f}};
  const Polygon rounded = makePolygon(corners, 0.1f);
  const Polygon capsule = asPolygon(Capsule{{-0.5f, 0}, {0.5f, 0}, 0.1f});
  EXPECT_EQ(detail::polygonPath(box, box), detail::PolygonPath::boxes);
  EXPECT_EQ(detail::polygonPath(offset, box), detail::PolygonPath::boxes);
  EXPECT_EQ(detail::polygonPath(box, offset), detail::PolygonPath::rectangle); // B must be centred
  EXPECT_EQ(detail::polygonPath(box, rounded), detail::PolygonPath::rectangle);
  EXPECT_EQ(detail::polygonPath(rounded, box), detail::PolygonPath::rectangle);
  EXPECT_EQ(detail::polygonPath(box, capsule), detail::PolygonPath::rectangle);
  EXPECT_EQ(detail::polygonPath(turned, box), detail::PolygonPath::general);
  EXPECT_EQ(detail::polygonPath(capsule, box), detail::PolygonPath::general);
  // A hand-made polygon that only looks like a box (normals not the axes) takes no shortcut.
  Polygon skewed = box;
  skewed.normals[1] = normalize(Vec2f{1.0f, 0.01f});
  EXPECT_EQ(detail::polygonPath(skewed, box), detail::PolygonPath::general);
  EXPECT_EQ(detail::polygonPath(box, skewed), detail::PolygonPath::rectangle);
}

} // namespace
} // namespace impetus::rigid2d
