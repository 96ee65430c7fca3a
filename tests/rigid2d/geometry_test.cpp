#include "support/error_field.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/geometry.hpp>

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace impetus::rigid2d {
namespace {

/// Area, centroid and polar moment of a shape by sampling its containsPoint on a fine grid over
/// `box`: an independent reference for computeMass (grid error ~ cell size / extent).
template <class Shape> MassData integrateOnGrid(const Shape& shape, const AABB& box, int cells, float density) {
  const float dx = (box.upper.x - box.lower.x) / static_cast<float>(cells);
  const float dy = (box.upper.y - box.lower.y) / static_cast<float>(cells);
  double m = 0.0, mx = 0.0, my = 0.0, mrr = 0.0;
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      const Vec2f p{box.lower.x + (static_cast<float>(i) + 0.5f) * dx,
                    box.lower.y + (static_cast<float>(j) + 0.5f) * dy};
      if (containsPoint(shape, p)) {
        const double dm = static_cast<double>(density) * dx * dy;
        m += dm;
        mx += dm * p.x;
        my += dm * p.y;
        mrr += dm * (static_cast<double>(p.x) * p.x + static_cast<double>(p.y) * p.y);
      }
    }
  }
  const double cx = mx / m, cy = my / m;
  return {static_cast<float>(m),
          {static_cast<float>(cx), static_cast<float>(cy)},
          static_cast<float>(mrr - m * (cx * cx + cy * cy))};
}

TEST(Hull, drops_interior_duplicate_and_collinear_points) {
  const std::vector<Vec2f> points{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5f, 0.5f}, {0.5f, 0.0f}, {1, 1.001f}};
  std::array<Vec2f, 8> storage{};
  const auto hull = computeHull(points, storage);
  ASSERT_EQ(hull.size(), 4U);
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2f e1 = hull[(i + 1) % 4] - hull[i];
    const Vec2f e2 = hull[(i + 2) % 4] - hull[(i + 1) % 4];
    EXPECT_GT(cross(e1, e2), 0.0f); // counter-clockwise and strictly convex
  }
}

TEST(Hull, random_hulls_are_convex_and_contain_their_points) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vec2f> points(8);
    for (Vec2f& p : points) {
      p = {u(rng), u(rng)};
    }
    const Polygon poly = makePolygon(points);
    ASSERT_GE(poly.count, 3);
    for (const Vec2f& p : points) {
      for (int i = 0; i < poly.count; ++i) {
        const auto k = static_cast<std::size_t>(i);
        // Welding and dropping nearly collinear vertices may leave a point up to linearSlop out.
        EXPECT_LE(dot(poly.normals[k], p - poly.vertices[k]), linearSlop);
      }
    }
    for (int i = 0; i < poly.count; ++i) {
      EXPECT_NEAR(length(poly.normals[static_cast<std::size_t>(i)]), 1.0f, 1e-6f);
    }
  }
}

TEST(Hull, degenerate_input_is_an_error) {
  const std::vector<Vec2f> line{{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  expectErrorField([&] { (void)makePolygon(line); }, "points");
  const std::vector<Vec2f> two{{0, 0}, {1, 1}};
  expectErrorField([&] { (void)makePolygon(two); }, "points.size");
  const std::vector<Vec2f> nine(9, Vec2f{});
  expectErrorField([&] { (void)makePolygon(nine); }, "points.size");
  const std::vector<Vec2f> nan{{0, 0}, {1, 0}, {std::nanf(""), 1}};
  expectErrorField([&] { (void)makePolygon(nan); }, "points[2].x");
  expectErrorField([&] { (void)makeBox(0.0f, 1.0f); }, "halfWidth");
}

TEST(ShapeMass, box_circle_and_offsets_match_closed_forms) {
  const MassData box = computeMass(makeBox(1.0f, 0.5f), 2.0f);
  EXPECT_NEAR(box.mass, 2.0f * 2.0f * 1.0f, 1e-5f);
  EXPECT_NEAR(box.rotationalInertia, box.mass * (4.0f + 1.0f) / 12.0f, 1e-5f);
  const MassData offset = computeMass(makeOffsetBox(1.0f, 0.5f, {3.0f, -1.0f}, 0.7f), 2.0f);
  EXPECT_NEAR(offset.center.x, 3.0f, 1e-5f);
  EXPECT_NEAR(offset.center.y, -1.0f, 1e-5f);
  EXPECT_NEAR(offset.rotationalInertia, box.rotationalInertia, 1e-4f); // about its own centre
  const MassData disc = computeMass(Circle{{1.0f, 2.0f}, 0.5f}, 3.0f);
  EXPECT_NEAR(disc.mass, 3.0f * pi<float> * 0.25f, 1e-5f);
  EXPECT_NEAR(disc.rotationalInertia, 0.5f * disc.mass * 0.25f, 1e-6f);
}

// The capsule's closed form (two half discs moved by the parallel-axis rule plus a rectangle)
// against integration over its area: a 1000 x 1000 grid over a 3 x 1 box, error ~ 0.1%.
TEST(ShapeMass, capsule_matches_grid_integration) {
  const Capsule capsule{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
  const MassData exact = computeMass(capsule, 1.5f);
  const MassData grid = integrateOnGrid(capsule, {{-1.5f, -0.5f}, {1.5f, 0.5f}}, 1000, 1.5f);
  EXPECT_NEAR(exact.mass, grid.mass, 2e-3f * exact.mass);
  EXPECT_NEAR(exact.rotationalInertia, grid.rotationalInertia, 3e-3f * exact.rotationalInertia);
}

// The rounded polygon's mass is an approximation (vertices pushed out along the bisectors);
// against the true rounded area A + P r + pi r^2 it is within 5% for r up to 1/5 of the size.
TEST(ShapeMass, rounded_polygon_is_close_to_the_true_rounded_area) {
  const std::vector<Vec2f> square{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const float r = 0.2f;
  const MassData rounded = computeMass(makePolygon(square, r), 1.0f);
  const float trueArea = 4.0f + 8.0f * r + pi<float> * r * r;
  EXPECT_NEAR(rounded.mass, trueArea, 0.05f * trueArea);
  const MassData grid = integrateOnGrid(makePolygon(square, r), {{-1.3f, -1.3f}, {1.3f, 1.3f}}, 1000, 1.0f);
  EXPECT_NEAR(grid.mass, trueArea, 2e-3f * trueArea); // containsPoint is exact
  EXPECT_NEAR(rounded.rotationalInertia, grid.rotationalInertia, 0.08f * grid.rotationalInertia);
}

TEST(ShapeAABB, bounds_the_transformed_shape) {
  const Transform2f xf{{2.0f, 1.0f}, Rot2f::fromAngle(0.6f)};
  const Polygon box = makeBox(1.0f, 0.5f);
  const AABB a = computeAABB(box, xf);
  for (int i = 0; i < box.count; ++i) {
    const Vec2f v = transformPoint(xf, box.vertices[static_cast<std::size_t>(i)]);
    EXPECT_TRUE(v.x >= a.lower.x - 1e-6f && v.x <= a.upper.x + 1e-6f && v.y >= a.lower.y - 1e-6f &&
                v.y <= a.upper.y + 1e-6f);
  }
  const AABB c = computeAABB(Capsule{{-1, 0}, {1, 0}, 0.25f}, Transform2f{});
  EXPECT_EQ(c, (AABB{{-1.25f, -0.25f}, {1.25f, 0.25f}}));
}

TEST(RayCast, circle_hit_point_normal_and_fraction) {
  const CastOutput out = rayCast(Circle{{0, 0}, 1.0f}, {{-3, 0}, {4, 0}, 1.0f});
  ASSERT_TRUE(out.hit);
  EXPECT_NEAR(out.fraction, 0.5f, 1e-6f);
  EXPECT_NEAR(out.point.x, -1.0f, 1e-6f);
  EXPECT_NEAR(out.normal.x, -1.0f, 1e-6f);
  EXPECT_FALSE(rayCast(Circle{{0, 0}, 1.0f}, {{-3, 2}, {4, 0}, 1.0f}).hit); // passes above
  EXPECT_FALSE(rayCast(Circle{{0, 0}, 1.0f}, {{0, 0}, {4, 0}, 1.0f}).hit);  // starts inside
  EXPECT_FALSE(rayCast(Circle{{0, 0}, 1.0f}, {{-3, 0}, {4, 0}, 0.4f}).hit); // too short
}

/// The first sample along the ray inside the shape: a brute-force reference for the ray casts.
template <class Shape> float firstInside(const Shape& shape, const RayCastInput& ray, int samples) {
  for (int i = 0; i <= samples; ++i) {
    const float t = ray.maxFraction * static_cast<float>(i) / static_cast<float>(samples);
    if (containsPoint(shape, ray.origin + ray.translation * t)) {
      return t;
    }
  }
  return -1.0f;
}

TEST(RayCast, polygons_and_capsules_agree_with_marching_along_the_ray) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  const Polygon box = makeOffsetBox(1.0f, 0.5f, {0.2f, -0.1f}, 0.4f);
  const Polygon rounded = makePolygon(std::vector<Vec2f>{{-1, -1}, {1, -0.5f}, {0.5f, 1}}, 0.3f);
  const Capsule capsule{{-1.0f, 0.3f}, {1.0f, -0.3f}, 0.4f};
  const int samples = 20000; // step 1/20000 of the ray: the reference's resolution
  for (int trial = 0; trial < 300; ++trial) {
    const RayCastInput ray{{u(rng), u(rng)}, {u(rng) * 2.0f, u(rng) * 2.0f}, 1.0f};
    const auto check = [&](const auto& shape) {
      const float reference = firstInside(shape, ray, samples);
      const CastOutput out = rayCast(shape, ray);
      if (reference == 0.0f) {
        EXPECT_FALSE(out.hit); // starts inside
        return;
      }
      ASSERT_EQ(out.hit, reference > 0.0f) << "trial " << trial;
      if (out.hit) {
        EXPECT_NEAR(out.fraction, reference, 2.0f / samples + 1e-5f);
        EXPECT_NEAR(length(out.normal), 1.0f, 1e-5f);
        EXPECT_LT(dot(out.normal, ray.translation), 0.0f); // faces the ray
      }
    };
    check(box);
    check(rounded);
    check(capsule);
  }
}

TEST(RayCast, segment_is_two_sided) {
  const Segment s{{0, -1}, {0, 1}};
  const CastOutput fromLeft = rayCast(s, {{-1, 0}, {2, 0}, 1.0f});
  ASSERT_TRUE(fromLeft.hit);
  EXPECT_NEAR(fromLeft.fraction, 0.5f, 1e-6f);
  EXPECT_NEAR(fromLeft.normal.x, -1.0f, 1e-6f);
  const CastOutput fromRight = rayCast(s, {{1, 0.5f}, {-2, 0}, 1.0f});
  ASSERT_TRUE(fromRight.hit);
  EXPECT_NEAR(fromRight.normal.x, 1.0f, 1e-6f);
  EXPECT_FALSE(rayCast(s, {{-1, 2}, {2, 0}, 1.0f}).hit);
}

} // namespace
} // namespace impetus::rigid2d
