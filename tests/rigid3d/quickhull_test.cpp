// Hulls from point clouds (quickhull): the hull holds every point and is made of them, coplanar
// triangles merge into one face, the mass approaches a ball's as the points fill its surface,
// and clouds without volume are refused.
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/rigid3d/world.hpp>

#include "support/error_field.hpp"
#include "test_random.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace impetus::rigid3d {
namespace {

/// n points spread evenly over the unit sphere (a Fibonacci lattice).
std::vector<Vec3f> fibonacciSphere(int n) {
  std::vector<Vec3f> points;
  const double golden = impetus::pi<double> * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double y = 1.0 - 2.0 * (i + 0.5) / n;
    const double r = std::sqrt(1.0 - y * y);
    points.emplace_back(static_cast<float>(r * std::cos(golden * i)), static_cast<float>(y),
                        static_cast<float>(r * std::sin(golden * i)));
  }
  return points;
}

void expectHoldsEveryPoint(const Hull& hull, const std::vector<Vec3f>& cloud, float tolerance) {
  for (const Vec3f& p : cloud) {
    for (const HullPlane& plane : hull.planes) {
      EXPECT_LE(dot(plane.normal, p) - plane.offset, tolerance);
    }
  }
}

TEST(Rigid3dQuickHull, a_cube_with_points_inside_and_on_its_faces_is_the_cube) {
  std::vector<Vec3f> cloud;
  Lcg random{0x2545f4914f6cdd1dULL};
  for (int i = 0; i < 200; ++i) {
    cloud.emplace_back(random.next(), random.next(), random.next()); // inside
  }
  for (int i = 0; i < 50; ++i) {
    cloud.emplace_back(1.0f, random.next(), random.next()); // on the +x face
    cloud.emplace_back(random.next(), -1.0f, random.next());
  }
  for (int k = 0; k < 8; ++k) {
    const Vec3f corner{(k & 1) != 0 ? 1.0f : -1.0f, (k & 2) != 0 ? 1.0f : -1.0f, (k & 4) != 0 ? 1.0f : -1.0f};
    cloud.push_back(corner);
    cloud.push_back(corner); // twice
  }
  const Hull hull = computeHull(cloud);
  EXPECT_EQ(hull.points.size(), 8U);
  EXPECT_EQ(hull.faceEdges.size(), 6U); // two triangles a side, merged
  EXPECT_EQ(hull.edges.size(), 24U);
  expectHoldsEveryPoint(hull, cloud, 1e-6f);
  EXPECT_NEAR(massProperties(hull, 1.0).mass, 8.0, 1e-5);
  World world;
  BodyDef def;
  def.type = BodyType::dynamicBody;
  EXPECT_NO_THROW(world.createShape(world.createBody(def), {}, hull));
}

TEST(Rigid3dQuickHull, a_random_cloud_is_held_by_a_hull_of_its_own_points) {
  // 300 points in a box: their hull has a few dozen vertices, under the cap.
  std::vector<Vec3f> cloud;
  Lcg random{0x2545f4914f6cdd1dULL};
  for (int i = 0; i < 300; ++i) {
    cloud.emplace_back(2.0f * random.next(), random.next(), 0.5f * random.next());
  }
  const Hull hull = computeHull(cloud);
  EXPECT_LT(hull.points.size(), static_cast<std::size_t>(maxHullVertices));
  expectHoldsEveryPoint(hull, cloud, 1e-5f);
  for (const Vec3f& v : hull.points) {
    bool found = false;
    for (const Vec3f& p : cloud) {
      found = found || (p.x == v.x && p.y == v.y && p.z == v.z);
    }
    EXPECT_TRUE(found);
  }
  const auto v = static_cast<int>(hull.points.size());
  EXPECT_EQ(v - static_cast<int>(hull.edges.size() / 2) + static_cast<int>(hull.faceEdges.size()), 2);
  for (std::size_t i = 0; i < hull.edges.size(); ++i) {
    EXPECT_EQ(hull.edges[hull.edges[i].twin].twin, i);
  }
}

TEST(Rigid3dQuickHull, the_hull_of_points_on_a_sphere_approaches_the_ball) {
  // The inscribed polyhedron's volume falls short of the ball's by a relative error that
  // shrinks about as 1/n (0.34, 0.18, 0.089 for 16, 32, 64 points); its tensor stays isotropic.
  const double ball = 4.0 / 3.0 * impetus::pi<double>;
  double previous = 1.0;
  for (const int n : {16, 32, 64}) {
    const MassProperties3 m = massProperties(computeHull(fibonacciSphere(n)), 1.0);
    const double shortfall = 1.0 - m.mass / ball;
    EXPECT_GT(shortfall, 0.0);
    EXPECT_LT(shortfall, 0.6 * previous) << n; // about halves as n doubles
    previous = shortfall;
    EXPECT_NEAR(m.inertia(0, 0) / m.inertia(1, 1), 1.0, 2.0 * shortfall) << n;
  }
  EXPECT_LT(previous, 0.1); // 64 points: within 10% of the ball
}

TEST(Rigid3dQuickHull, the_vertex_cap_keeps_the_most_extreme_points) {
  const std::vector<Vec3f> cloud = fibonacciSphere(200);
  const Hull capped = computeHull(cloud, 32);
  EXPECT_EQ(capped.points.size(), 32U);
  const Hull full = computeHull(cloud);
  EXPECT_EQ(full.points.size(), static_cast<std::size_t>(maxHullVertices));
  // Whatever the cap, the hull is a valid solid shape.
  World world;
  BodyDef def;
  def.type = BodyType::dynamicBody;
  EXPECT_NO_THROW(world.createShape(world.createBody(def), {}, capped));
}

TEST(Rigid3dQuickHull, clouds_without_volume_are_refused) {
  EXPECT_NE(thrownMessage([] {
              (void)computeHull(std::vector<Vec3f>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
            }).find("at least four"),
            std::string::npos);
  EXPECT_NE(thrownMessage([] {
              (void)computeHull(std::vector<Vec3f>{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}});
            }).find("one place"),
            std::string::npos);
  EXPECT_NE(thrownMessage([] {
              (void)computeHull(std::vector<Vec3f>{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {-1, -1, -1}});
            }).find("one line"),
            std::string::npos);
  std::vector<Vec3f> flat;
  Lcg random{0x2545f4914f6cdd1dULL};
  for (int i = 0; i < 20; ++i) {
    flat.emplace_back(random.next(), 0.5f, random.next());
  }
  EXPECT_NE(thrownMessage([&] { (void)computeHull(flat); }).find("one plane"), std::string::npos);
  std::vector<Vec3f> bad = fibonacciSphere(10);
  bad[3].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(thrownMessage([&] { (void)computeHull(bad); }).find("points[3].y"), std::string::npos);
  EXPECT_NE(thrownMessage([] { (void)computeHull(fibonacciSphere(10), 3); }).find("maxVertices"), std::string::npos);
}

} // namespace
} // namespace impetus::rigid3d
