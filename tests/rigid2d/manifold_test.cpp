#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/manifold.hpp>

#include <gtest/gtest.h>

#include <random>

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

} // namespace
} // namespace impetus::rigid2d
