// Planar polygon mass properties against closed forms: rectangles (m (a^2 + b^2) / 12), right
// and equilateral triangles, regular polygons and their disc limit (m r^2 / 2), and a
// non-convex L-shape assembled from two rectangles with the parallel-axis theorem.
#include <impetus/core/polygon_mass.hpp>
#include <impetus/error.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace impetus {
namespace {

constexpr double pi = std::numbers::pi;

std::vector<Vec2d> rectangle(Vec2d corner, double width, double height) {
  return {corner, corner + Vec2d{width, 0.0}, corner + Vec2d{width, height}, corner + Vec2d{0.0, height}};
}

std::vector<Vec2d> regularPolygon(int sides, double circumradius, Vec2d center) {
  std::vector<Vec2d> vertices;
  for (int i = 0; i < sides; ++i) {
    const double angle = 2.0 * pi * i / sides + 0.3; // an arbitrary phase
    vertices.push_back(center + Vec2d{circumradius * std::cos(angle), circumradius * std::sin(angle)});
  }
  return vertices;
}

// Results from the same polygon given differently must agree to rounding.
void expectSame(const PolygonMass& a, const PolygonMass& b) {
  EXPECT_NEAR(a.area, b.area, 1e-13 * b.area);
  EXPECT_NEAR(a.mass, b.mass, 1e-13 * b.mass);
  EXPECT_NEAR(a.centroid.x, b.centroid.x, 1e-13);
  EXPECT_NEAR(a.centroid.y, b.centroid.y, 1e-13);
  EXPECT_NEAR(a.inertia, b.inertia, 1e-13 * b.inertia);
}

TEST(PolygonMass, unit_square) {
  const std::vector<Vec2d> square = rectangle({0.0, 0.0}, 1.0, 1.0);
  const PolygonMass result = polygonMass(square, 2.0);
  EXPECT_NEAR(result.area, 1.0, 1e-15);
  EXPECT_NEAR(result.mass, 2.0, 1e-15);
  EXPECT_NEAR(result.centroid.x, 0.5, 1e-15);
  EXPECT_NEAR(result.centroid.y, 0.5, 1e-15);
  // m (a^2 + b^2) / 12 = m / 6 for a unit square.
  EXPECT_NEAR(result.inertia, 2.0 / 6.0, 1e-15);
}

TEST(PolygonMass, rectangle_matches_closed_form) {
  const double width = 3.0;
  const double height = 0.5;
  const double density = 7.5;
  const PolygonMass result = polygonMass(rectangle({-4.0, 2.0}, width, height), density);
  const double mass = density * width * height;
  EXPECT_NEAR(result.area, width * height, 1e-14);
  EXPECT_NEAR(result.mass, mass, 1e-13);
  EXPECT_NEAR(result.centroid.x, -2.5, 1e-14);
  EXPECT_NEAR(result.centroid.y, 2.25, 1e-14);
  EXPECT_NEAR(result.inertia, mass * (width * width + height * height) / 12.0, 1e-13);
}

TEST(PolygonMass, right_triangle_matches_closed_form) {
  // Legs a = 3 (x), b = 2 (y). About the centroid the area moments are a b^3 / 36 (x axis) and
  // b a^3 / 36 (y axis), so J = a b (a^2 + b^2) / 36 = m (a^2 + b^2) / 18 with m = rho a b / 2.
  const double a = 3.0;
  const double b = 2.0;
  const double density = 1.5;
  const std::vector<Vec2d> triangle{{0.0, 0.0}, {a, 0.0}, {0.0, b}};
  const PolygonMass result = polygonMass(triangle, density);
  const double mass = density * a * b / 2.0;
  EXPECT_NEAR(result.area, a * b / 2.0, 1e-15);
  EXPECT_NEAR(result.centroid.x, a / 3.0, 1e-15);
  EXPECT_NEAR(result.centroid.y, b / 3.0, 1e-15);
  EXPECT_NEAR(result.inertia, mass * (a * a + b * b) / 18.0, 1e-14);
  EXPECT_NEAR(result.inertia, density * (a * b * b * b + b * a * a * a) / 36.0, 1e-14);
}

TEST(PolygonMass, regular_polygons_match_closed_form_and_approach_a_disc) {
  // Regular N-gon of circumradius R: area N/2 R^2 sin(2 pi / N), J = m R^2 / 6 (2 + cos(2 pi / N)).
  // Cross-checks of that form: N = 3 gives m a^2 / 12 for an equilateral triangle of side a,
  // N = 4 the square's m s^2 / 6, N = 6 the hexagon's 5/12 m s^2, and N -> infinity m R^2 / 2.
  const double radius = 0.8;
  const double density = 3.0;
  const Vec2d center{2.0, -1.0};
  for (int sides : {3, 4, 5, 6, 12, 64}) {
    const PolygonMass result = polygonMass(regularPolygon(sides, radius, center), density);
    const double area = sides / 2.0 * radius * radius * std::sin(2.0 * pi / sides);
    const double mass = density * area;
    EXPECT_NEAR(result.area, area, 1e-13 * area) << sides << " sides";
    EXPECT_NEAR(result.centroid.x, center.x, 1e-13) << sides << " sides";
    EXPECT_NEAR(result.centroid.y, center.y, 1e-13) << sides << " sides";
    EXPECT_NEAR(result.inertia, mass * radius * radius / 6.0 * (2.0 + std::cos(2.0 * pi / sides)),
                1e-12 * result.inertia)
        << sides << " sides";
  }
  const double side = radius * std::sqrt(3.0);
  const PolygonMass triangle = polygonMass(regularPolygon(3, radius, center), density);
  EXPECT_NEAR(triangle.inertia, triangle.mass * side * side / 12.0, 1e-12 * triangle.inertia);
  const PolygonMass hexagon = polygonMass(regularPolygon(6, radius, center), density);
  EXPECT_NEAR(hexagon.inertia, 5.0 / 12.0 * hexagon.mass * radius * radius, 1e-12 * hexagon.inertia);
  // The disc limit: J / (m R^2 / 2) = (2 + cos(2 pi / N)) / 3 = 1 - (2/3) (pi / N)^2 + ...,
  // i.e. 3.9e-7 below 1 for N = 4096, approached from below.
  const PolygonMass disc = polygonMass(regularPolygon(4096, radius, center), density);
  const double ratio = disc.inertia / (disc.mass * radius * radius / 2.0);
  EXPECT_LT(ratio, 1.0);
  EXPECT_NEAR(ratio, 1.0, 1e-6);
  EXPECT_NEAR(disc.area, pi * radius * radius, 1e-6 * disc.area);
}

TEST(PolygonMass, non_convex_l_shape_equals_its_two_rectangles) {
  // L-shape = A [0,3] x [0,1] + B [0,1] x [1,3], combined with the parallel-axis theorem.
  const std::vector<Vec2d> shape{{0.0, 0.0}, {3.0, 0.0}, {3.0, 1.0}, {1.0, 1.0}, {1.0, 3.0}, {0.0, 3.0}};
  const double density = 2.0;
  const double massA = density * 3.0;
  const double massB = density * 2.0;
  const Vec2d centroidA{1.5, 0.5};
  const Vec2d centroidB{0.5, 2.0};
  const double mass = massA + massB;
  const Vec2d centroid = (centroidA * massA + centroidB * massB) / mass; // (1.1, 1.1)
  const double inertia = massA * (9.0 + 1.0) / 12.0 + massA * lengthSquared(centroidA - centroid) +
                         massB * (1.0 + 4.0) / 12.0 + massB * lengthSquared(centroidB - centroid);

  // Start the vertex list at every vertex: fans from the reflex vertex (1, 1) or from its
  // neighbours contain triangles of negative area, which must cancel correctly.
  for (std::size_t start = 0; start < shape.size(); ++start) {
    std::vector<Vec2d> rotated = shape;
    std::rotate(rotated.begin(), rotated.begin() + static_cast<std::ptrdiff_t>(start), rotated.end());
    const PolygonMass result = polygonMass(rotated, density);
    EXPECT_NEAR(result.area, 5.0, 1e-14) << "start " << start;
    EXPECT_NEAR(result.mass, mass, 1e-14) << "start " << start;
    EXPECT_NEAR(result.centroid.x, 1.1, 1e-14) << "start " << start;
    EXPECT_NEAR(result.centroid.y, 1.1, 1e-14) << "start " << start;
    EXPECT_NEAR(result.inertia, inertia, 1e-13 * inertia) << "start " << start;
  }
}

TEST(PolygonMass, clockwise_winding_gives_identical_results) {
  for (const std::vector<Vec2d>& polygon :
       {rectangle({1.0, 2.0}, 3.0, 4.0), regularPolygon(7, 1.3, {0.5, -0.5}),
        std::vector<Vec2d>{{0.0, 0.0}, {3.0, 0.0}, {3.0, 1.0}, {1.0, 1.0}, {1.0, 3.0}, {0.0, 3.0}}}) {
    const std::vector<Vec2d> reversed(polygon.rbegin(), polygon.rend());
    const PolygonMass ccw = polygonMass(polygon, 1.7);
    const PolygonMass cw = polygonMass(reversed, 1.7);
    EXPECT_GT(cw.area, 0.0);
    EXPECT_GT(cw.inertia, 0.0);
    expectSame(cw, ccw);
  }
}

TEST(PolygonMass, far_from_the_origin_keeps_its_precision) {
  // A unit square at (1e6, -2e6). Summed about the origin, the polar moment (~5e12) and the
  // transfer term m |c|^2 would cancel to leave 1/6, losing ~5e12 * 1e-16 = 5e-4 absolute; the
  // result must match the square at the origin to 1e-9 relative.
  const double density = 1.0;
  const Vec2d offset{1e6, -2e6};
  const PolygonMass far = polygonMass(rectangle(offset, 1.0, 1.0), density);
  EXPECT_NEAR(far.area, 1.0, 1e-9);
  EXPECT_NEAR(far.centroid.x, offset.x + 0.5, 1e-9);
  EXPECT_NEAR(far.centroid.y, offset.y + 0.5, 1e-9);
  EXPECT_NEAR(far.inertia, 1.0 / 6.0, 1e-9 / 6.0);
  // And a non-convex shape far away equals the same shape at the origin, shifted.
  const std::vector<Vec2d> shape{{0.0, 0.0}, {3.0, 0.0}, {3.0, 1.0}, {1.0, 1.0}, {1.0, 3.0}, {0.0, 3.0}};
  std::vector<Vec2d> moved;
  for (const Vec2d& v : shape) {
    moved.push_back(v + offset);
  }
  const PolygonMass near = polygonMass(shape, density);
  const PolygonMass away = polygonMass(moved, density);
  EXPECT_NEAR(away.area, near.area, 1e-9 * near.area);
  EXPECT_NEAR(away.centroid.x - offset.x, near.centroid.x, 1e-9);
  EXPECT_NEAR(away.centroid.y - offset.y, near.centroid.y, 1e-9);
  EXPECT_NEAR(away.inertia, near.inertia, 1e-9 * near.inertia);
}

TEST(PolygonMass, invalid_polygons_throw_naming_the_field) {
  const std::vector<Vec2d> two{{0.0, 0.0}, {1.0, 0.0}};
  EXPECT_EQ(thrownField([&] { static_cast<void>(polygonMass(two, 1.0)); }), "vertices.size");
  const std::vector<Vec2d> collinear{{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}, {3.0, 3.0}};
  EXPECT_EQ(thrownField([&] { static_cast<void>(polygonMass(collinear, 1.0)); }), "area");
  // Collinear in exact arithmetic, but 0.1 and 0.3 are not representable: the summed area is
  // 5.6e-17 of rounding noise next to an extent of ~2 m, and must still be refused.
  const std::vector<Vec2d> nearlyCollinear{{0.1, 0.3}, {0.7, 2.1}, {1.3, 3.9}, {0.3, 0.9}};
  EXPECT_EQ(thrownField([&] { static_cast<void>(polygonMass(nearlyCollinear, 1.0)); }), "area");
  const std::vector<Vec2d> repeated{{0.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}};
  EXPECT_EQ(thrownField([&] { static_cast<void>(polygonMass(repeated, 1.0)); }), "area");
  const std::vector<Vec2d> withNan{{0.0, 0.0}, {1.0, std::nan("")}, {0.0, 1.0}};
  EXPECT_EQ(thrownField([&] { static_cast<void>(polygonMass(withNan, 1.0)); }), "vertices[1].y");
  const std::vector<Vec2d> square = rectangle({0.0, 0.0}, 1.0, 1.0);
  EXPECT_EQ(thrownField([&] { static_cast<void>(polygonMass(square, 0.0)); }), "density");
  EXPECT_EQ(thrownField([&] { static_cast<void>(polygonMass(square, -1.0)); }), "density");
}

} // namespace
} // namespace impetus
