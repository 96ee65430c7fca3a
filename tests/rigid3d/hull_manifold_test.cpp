// The manifold of two hulls against geometry placed by hand (a cube resting on, turned on,
// overhanging, standing on an edge on and lying across the edge of a box, turned on a cube of
// its size; two boxes crossed edge on edge; cubes apart corner to corner), the reference face's
// hysteresis, the manifold against itself with A and B swapped and both bodies moved together,
// its ids under small shifts, and random pairs against GJK's distance and the overlap of the two
// hulls along the normal.
#include <impetus/math/scalar.hpp>
#include <impetus/rigid3d/constants.hpp>
#include <impetus/rigid3d/distance.hpp>
#include <impetus/rigid3d/manifold.hpp>

#include "test_random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <set>
#include <span>
#include <tuple>
#include <vector>

namespace impetus::rigid3d {
namespace {

Transform3f at(const Vec3f& p, const Quatf& q = Quatf::identity()) { return {p, q}; }

void expectNear(const Vec3f& a, const Vec3f& b, float tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

std::vector<Vec3f> worldPoints(const Hull& hull, const Transform3f& xf) {
  std::vector<Vec3f> points;
  for (const Vec3f& p : hull.points) {
    points.push_back(transformPoint(xf, p));
  }
  return points;
}

/// Each expected point is one of the manifold's points (within `tolerance`, m), each matched once,
/// and there are no others.
void expectPoints(const Manifold& m, const std::vector<Vec3f>& expected, float tolerance) {
  ASSERT_EQ(m.pointCount, static_cast<int>(expected.size()));
  std::vector<bool> used(expected.size(), false);
  for (int k = 0; k < m.pointCount; ++k) {
    const Vec3f& p = m.points[static_cast<std::size_t>(k)].point;
    bool found = false;
    for (std::size_t e = 0; e < expected.size() && !found; ++e) {
      if (!used[e] && length(p - expected[e]) <= tolerance) {
        used[e] = true;
        found = true;
      }
    }
    EXPECT_TRUE(found) << "point " << k << " at (" << p.x << ", " << p.y << ", " << p.z << ") is not expected";
  }
}

std::set<std::uint32_t> ids(const Manifold& m) {
  std::set<std::uint32_t> result;
  for (int k = 0; k < m.pointCount; ++k) {
    result.insert(m.points[static_cast<std::size_t>(k)].id);
  }
  return result;
}

// A 4 x 1 x 4 m box whose top face is y = 0, and a 1 m cube.
const Hull bigBox = makeBoxHull({2.0f, 0.5f, 2.0f});
const Transform3f bigBoxPose = at({0.0f, -0.5f, 0.0f});
const Hull cube = makeBoxHull({0.5f, 0.5f, 0.5f});
const float halfDiagonal = 0.5f * std::sqrt(2.0f); // of the cube's faces, m

TEST(Rigid3dHullManifold, a_cube_resting_on_a_box_touches_at_its_four_bottom_corners) {
  for (const float gap : {-0.01f, 0.0f, 0.015f}) {
    const Vec3f c{0.3f, 0.5f + gap, -0.2f};
    const Manifold m = collideHulls(bigBox, bigBoxPose, cube, at(c));
    SCOPED_TRACE(gap);
    expectNear(m.normal, {0.0f, 1.0f, 0.0f}, 1e-6f);
    // Midway between the cube's corner and the box's top: at half the gap.
    expectPoints(m,
                 {{c.x - 0.5f, 0.5f * gap, c.z - 0.5f},
                  {c.x + 0.5f, 0.5f * gap, c.z - 0.5f},
                  {c.x + 0.5f, 0.5f * gap, c.z + 0.5f},
                  {c.x - 0.5f, 0.5f * gap, c.z + 0.5f}},
                 1e-5f);
    for (int k = 0; k < m.pointCount; ++k) {
      const ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
      EXPECT_NEAR(p.separation, gap, 1e-5f);
      expectNear(p.anchorA, p.point - bigBoxPose.p, 1e-6f);
      expectNear(p.anchorB, p.point - c, 1e-6f);
    }
    EXPECT_EQ(ids(m).size(), 4U);
  }
  // 5 cm apart, beyond the speculative distance: no points, the gap reported.
  const Manifold apart = collideHulls(bigBox, bigBoxPose, cube, at({0.3f, 0.55f, -0.2f}));
  EXPECT_EQ(apart.pointCount, 0);
  EXPECT_NEAR(apart.separationBound, 0.05f, 1e-5f);
}

TEST(Rigid3dHullManifold, a_cube_turned_about_the_vertical_touches_at_its_turned_corners) {
  // Turned 45 degrees about y, its bottom corners lie on the x and z axes through its centre,
  // half a face diagonal out.
  const Vec3f c{-0.4f, 0.5f - 0.004f, 0.6f};
  const Manifold m =
      collideHulls(bigBox, bigBoxPose, cube, at(c, Quatf::fromAxisAngle({0.0f, 1.0f, 0.0f}, pi<float> / 4.0f)));
  expectNear(m.normal, {0.0f, 1.0f, 0.0f}, 1e-6f);
  expectPoints(m,
               {{c.x + halfDiagonal, -0.002f, c.z},
                {c.x - halfDiagonal, -0.002f, c.z},
                {c.x, -0.002f, c.z + halfDiagonal},
                {c.x, -0.002f, c.z - halfDiagonal}},
               1e-5f);
  for (int k = 0; k < m.pointCount; ++k) {
    EXPECT_NEAR(m.points[static_cast<std::size_t>(k)].separation, -0.004f, 1e-5f);
  }
}

TEST(Rigid3dHullManifold, of_eight_clipped_points_the_four_spanning_the_most_area_are_kept) {
  // A cube turned 45 degrees about y on a cube of the same size: their faces overlap in a regular
  // octagon, its corners where x or z = +-0.5 meets the turned edge |x| + |z| = halfDiagonal (the
  // other coordinate +-(halfDiagonal - 0.5)), a circumradius r from the centre. The deepest
  // corner (all are equally deep), the one across from it, and the two a quarter turn from those
  // make the largest quad: a square of area 2 r^2 (any other choice of four corners has less).
  const float gap = -0.002f;
  const Manifold m = collideHulls(
      cube, at({}), cube, at({0.0f, 1.0f + gap, 0.0f}, Quatf::fromAxisAngle({0.0f, 1.0f, 0.0f}, pi<float> / 4.0f)));
  ASSERT_EQ(m.pointCount, 4);
  const float other = halfDiagonal - 0.5f;
  const float r = std::sqrt(0.25f + other * other);
  for (int k = 0; k < 4; ++k) {
    const ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
    EXPECT_NEAR(p.separation, gap, 1e-5f);
    EXPECT_NEAR(p.point.y, 0.5f + 0.5f * gap, 1e-5f);
    // An octagon corner: one coordinate +-0.5, the other +-(halfDiagonal - 0.5).
    const float big = std::max(std::abs(p.point.x), std::abs(p.point.z));
    const float small = std::min(std::abs(p.point.x), std::abs(p.point.z));
    EXPECT_NEAR(big, 0.5f, 1e-5f);
    EXPECT_NEAR(small, other, 1e-5f);
  }
  // The points come in convex order: the shoelace formula gives the quad's area.
  float twiceArea = 0.0f;
  for (int k = 0; k < 4; ++k) {
    const Vec3f& p = m.points[static_cast<std::size_t>(k)].point;
    const Vec3f& q = m.points[static_cast<std::size_t>((k + 1) % 4)].point;
    twiceArea += p.z * q.x - p.x * q.z;
  }
  EXPECT_NEAR(std::abs(0.5f * twiceArea), 2.0f * r * r, 1e-5f);
  EXPECT_EQ(ids(m).size(), 4U);
}

TEST(Rigid3dHullManifold, a_cube_overhanging_the_edge_touches_at_the_corners_of_the_overlap) {
  // The cube spans x in [1.3, 2.3] and z in [-0.7, 0.3]; the box ends at x = 2: the overlap is
  // [1.3, 2] x [-0.7, 0.3], two of its corners the cube's, two cut by the box's side plane.
  const Vec3f c{1.8f, 0.5f - 0.005f, -0.2f};
  const Manifold m = collideHulls(bigBox, bigBoxPose, cube, at(c));
  expectNear(m.normal, {0.0f, 1.0f, 0.0f}, 1e-6f);
  expectPoints(m, {{1.3f, -0.0025f, -0.7f}, {2.0f, -0.0025f, -0.7f}, {2.0f, -0.0025f, 0.3f}, {1.3f, -0.0025f, 0.3f}},
               1e-5f);
  for (int k = 0; k < m.pointCount; ++k) {
    EXPECT_NEAR(m.points[static_cast<std::size_t>(k)].separation, -0.005f, 1e-5f);
  }
}

TEST(Rigid3dHullManifold, a_cube_standing_on_an_edge_touches_at_the_ends_of_the_edge) {
  // Turned 45 degrees about z, its lowest edge runs along z, halfDiagonal under its centre;
  // tilted then by alpha about x, the edge's end at z = +0.5 sinks by 0.5 sin(alpha) and the
  // other rises as much, to heights (from the centre) -halfDiagonal cos(alpha) -+ 0.5 sin(alpha)
  // at z = -+ halfDiagonal sin(alpha) + 0.5 cos(alpha). The lower end is placed 5 mm deep.
  const float alpha = 0.01f;
  const Quatf q =
      Quatf::fromAxisAngle({1.0f, 0.0f, 0.0f}, alpha) * Quatf::fromAxisAngle({0.0f, 0.0f, 1.0f}, pi<float> / 4.0f);
  const float lowY = -halfDiagonal * std::cos(alpha) - 0.5f * std::sin(alpha);
  const float highY = -halfDiagonal * std::cos(alpha) + 0.5f * std::sin(alpha);
  const Vec3f c{0.2f, -0.005f - lowY, 0.1f};
  const Manifold m = collideHulls(bigBox, bigBoxPose, cube, at(c, q));
  expectNear(m.normal, {0.0f, 1.0f, 0.0f}, 1e-6f);
  const float deep = -0.005f;
  const float shallow = c.y + highY; // 2 sin(alpha) 0.5 higher: about 5 mm over the top
  const float zLow = c.z - halfDiagonal * std::sin(alpha) + 0.5f * std::cos(alpha);
  const float zHigh = c.z - halfDiagonal * std::sin(alpha) - 0.5f * std::cos(alpha);
  expectPoints(m, {{c.x, 0.5f * deep, zLow}, {c.x, 0.5f * shallow, zHigh}}, 1e-5f);
  ASSERT_EQ(m.pointCount, 2);
  const ManifoldPoint& first = m.points[0];
  const ManifoldPoint& second = m.points[1];
  const bool firstLow = first.point.z > second.point.z;
  EXPECT_NEAR((firstLow ? first : second).separation, deep, 1e-5f);
  EXPECT_NEAR((firstLow ? second : first).separation, shallow, 1e-5f);
  EXPECT_NEAR(shallow - deep, std::sin(alpha), 1e-6f);
}

TEST(Rigid3dHullManifold, two_boxes_crossed_edge_on_edge_touch_at_one_point) {
  // A turned 45 degrees about x: its top edge runs along x at height halfDiagonal. B turned 45
  // degrees about z: its bottom edge runs along z, halfDiagonal under its centre. The edges
  // cross at (0.1, ., 0); the normal is along x cross z, from A up to B.
  const Transform3f xfA = at({0.0f, 0.0f, 0.0f}, Quatf::fromAxisAngle({1.0f, 0.0f, 0.0f}, pi<float> / 4.0f));
  for (const float gap : {-0.01f, 0.0f, 0.015f}) {
    SCOPED_TRACE(gap);
    const Transform3f xfB =
        at({0.1f, 2.0f * halfDiagonal + gap, -0.2f}, Quatf::fromAxisAngle({0.0f, 0.0f, 1.0f}, pi<float> / 4.0f));
    const Manifold m = collideHulls(cube, xfA, cube, xfB);
    ASSERT_EQ(m.pointCount, 1);
    expectNear(m.normal, {0.0f, 1.0f, 0.0f}, 1e-5f);
    EXPECT_NEAR(m.points[0].separation, gap, 1e-5f);
    expectNear(m.points[0].point, {0.1f, halfDiagonal + 0.5f * gap, 0.0f}, 1e-5f);
  }
  const Manifold apart = collideHulls(
      cube, xfA, cube,
      at({0.1f, 2.0f * halfDiagonal + 0.03f, -0.2f}, Quatf::fromAxisAngle({0.0f, 0.0f, 1.0f}, pi<float> / 4.0f)));
  EXPECT_EQ(apart.pointCount, 0);
  EXPECT_NEAR(apart.separationBound, 0.03f, 1e-5f);
}

TEST(Rigid3dHullManifold, a_cube_flush_on_a_cube_keeps_its_corners_when_shifted_by_a_rounding) {
  // Two cubes of one size, one on the other, both turned alike (so their corners' coordinates
  // are not round numbers): the upper's bottom corners lie on the lower's top face's side planes.
  // Shifted sideways by 2 um either way, within the side tolerance (5 um), they stay the four
  // points, with their ids, not cuts a rounding away from them.
  const Quatf q = Quatf::fromAxisAngle({0.3f, 1.0f, -0.2f}, 0.7f);
  const Transform3f xfA = at({0.3f, 0.1f, -0.7f}, q);
  const Vec3f up = rotate(q, Vec3f{0.0f, 1.0f, 0.0f});
  const Vec3f side = rotate(q, Vec3f{1.0f, 0.0f, 1.0f});
  const Manifold flush = collideHulls(cube, xfA, cube, at(xfA.p + up * 0.999f, q));
  ASSERT_EQ(flush.pointCount, 4);
  for (const float shift : {-2e-6f, 2e-6f}) {
    SCOPED_TRACE(shift);
    const Manifold shifted = collideHulls(cube, xfA, cube, at(xfA.p + up * 0.999f + side * shift, q));
    ASSERT_EQ(shifted.pointCount, 4);
    EXPECT_EQ(ids(shifted), ids(flush));
  }
}

TEST(Rigid3dHullManifold, a_face_of_a_is_kept_over_a_face_of_b_nearly_as_good) {
  // Two cubes, the upper turned by theta about z and moved dx along x: the lower's top face
  // separates them by the upper's lowest corner's height, the upper's bottom face by the lower's
  // corner farthest under it, which dx raises by -dx sin(theta). B's face is the reference only
  // when better by 2% of A's separation plus 0.5 mm: the normal is then B's, turned by theta.
  const float theta = 0.01f;
  const Quatf q = Quatf::fromAxisAngle({0.0f, 0.0f, 1.0f}, theta);
  const Vec3f bottomNormalB = rotate(q, Vec3f{0.0f, -1.0f, 0.0f});
  for (const float dx : {-0.035f, -0.1f}) {
    SCOPED_TRACE(dx);
    const Vec3f c{dx, 1.0f + 0.5f * (std::cos(theta) + std::sin(theta)) - 0.5f - 0.002f, 0.0f};
    // Both faces' separations, from the corners.
    float separationA = std::numeric_limits<float>::max();
    for (const Vec3f& p : worldPoints(cube, at(c, q))) {
      separationA = std::min(separationA, p.y - 0.5f);
    }
    float separationB = std::numeric_limits<float>::max();
    for (const Vec3f& p : cube.points) {
      separationB = std::min(separationB, dot(bottomNormalB, p - c) - 0.5f);
    }
    const Manifold m = collideHulls(cube, at({}), cube, at(c, q));
    ASSERT_GT(m.pointCount, 0);
    if (dx == -0.035f) {
      EXPECT_GT(separationB, separationA + 1e-4f);
      EXPECT_LT(separationB, separationA + 0.02f * std::abs(separationA) + 0.1f * linearSlop - 1e-4f);
      expectNear(m.normal, {0.0f, 1.0f, 0.0f}, 1e-6f);
    } else {
      EXPECT_GT(separationB, separationA + 0.02f * std::abs(separationA) + 0.1f * linearSlop + 1e-4f);
      expectNear(m.normal, -bottomNormalB, 1e-6f);
    }
  }
}

TEST(Rigid3dHullManifold, an_edge_across_the_box_edge_stays_a_face_contact_until_the_edge_axis_is_clearly_better) {
  // A cube turned 45 degrees about x stands on its edge along x, across the box's edge x = 2,
  // its edge tilted by beta about z (falling toward +x): at x = 2 it is 2 mm deep, at its far end
  // (over nothing) deeper by 0.6 tan(beta). The box's top face separates the pair by that far
  // end's height; the axis across the two edges, (sin beta, cos beta, 0), by 2 mm cos(beta).
  const float depthAtEdge = -0.002f;
  for (const float beta : {0.002f, 0.02f}) {
    SCOPED_TRACE(beta);
    const Quatf q =
        Quatf::fromAxisAngle({0.0f, 0.0f, 1.0f}, -beta) * Quatf::fromAxisAngle({1.0f, 0.0f, 0.0f}, pi<float> / 4.0f);
    // The edge's ends, relative to the centre: the corners (+-0.5, -0.5, 0.5) turned.
    const Vec3f end0 = rotate(q, Vec3f{-0.5f, -0.5f, 0.5f});
    const Vec3f end1 = rotate(q, Vec3f{0.5f, -0.5f, 0.5f});
    const float cx = 2.1f;
    // The centre's height that puts the edge at depthAtEdge where it crosses x = 2.
    const float fraction = (2.0f - cx - end0.x) / (end1.x - end0.x);
    const Vec3f c{cx, depthAtEdge - (end0.y + (end1.y - end0.y) * fraction), 0.0f};
    const Manifold m = collideHulls(bigBox, bigBoxPose, cube, at(c, q));
    const Vec3f crossing = c + end0 + (end1 - end0) * fraction; // on B's edge, at x = 2
    if (beta == 0.002f) {
      // The edge axis is better by 0.6 tan(beta) = 1.2 mm, short of 10% of the face's 3.2 mm
      // plus 2.5 mm: the face contact, two points: the edge's near end and its cut at x = 2.
      expectNear(m.normal, {0.0f, 1.0f, 0.0f}, 1e-6f);
      const Vec3f near = c + end0;
      expectPoints(m, {{near.x, 0.5f * near.y, near.z}, {2.0f, 0.5f * depthAtEdge, crossing.z}}, 1e-5f);
    } else {
      // Better by 12 mm: the edge contact, one point at the crossing, at 2 mm cos(beta).
      ASSERT_EQ(m.pointCount, 1);
      expectNear(m.normal, {std::sin(beta), std::cos(beta), 0.0f}, 1e-5f);
      EXPECT_NEAR(m.points[0].separation, depthAtEdge * std::cos(beta), 1e-5f);
      // Midway between the edges' closest points: (2, 0, z) on the box's, that plus the normal
      // times the separation on the cube's.
      const float separation = depthAtEdge * std::cos(beta);
      expectNear(m.points[0].point,
                 {2.0f + 0.5f * separation * std::sin(beta), 0.5f * separation * std::cos(beta), crossing.z}, 1e-5f);
    }
  }
}

TEST(Rigid3dHullManifold, cubes_apart_corner_to_corner_meet_at_their_closest_points) {
  // B's corner nearest A lies at (0.5 + s)(1, 1, 1), A's at 0.5 (1, 1, 1): s sqrt(3) apart, while
  // every face and edge axis separates them by s alone, and no face of one lies over a face of
  // the other: the closest points, by GJK.
  const float s = 0.01f;
  const Manifold m = collideHulls(cube, at({}), cube, at(Vec3f{1.0f, 1.0f, 1.0f} * (1.0f + s)));
  ASSERT_EQ(m.pointCount, 1);
  const Vec3f diagonal = Vec3f{1.0f, 1.0f, 1.0f} * (1.0f / std::sqrt(3.0f));
  expectNear(m.normal, diagonal, 1e-5f);
  EXPECT_NEAR(m.points[0].separation, s * std::sqrt(3.0f), 1e-5f);
  expectNear(m.points[0].point, Vec3f{1.0f, 1.0f, 1.0f} * (0.5f + 0.5f * s), 1e-5f);
  // 1.5 cm on each axis: 2.6 cm apart, beyond reach, though each axis separates by less.
  const Manifold apart = collideHulls(cube, at({}), cube, at(Vec3f{1.0f, 1.0f, 1.0f} * 1.015f));
  EXPECT_EQ(apart.pointCount, 0);
  EXPECT_NEAR(apart.separationBound, 0.015f * std::sqrt(3.0f), 1e-5f);
}

/// Pairs placed by hand: a face contact with two of its points cut, an edge standing on a face,
/// crossed edges, and a cube turned every way sunk into a box's top.
struct Pose {
  const Hull* a;
  Transform3f xfA;
  const Hull* b;
  Transform3f xfB;
};

std::vector<Pose> handPlacedPairs() {
  const Quatf edgeDown =
      Quatf::fromAxisAngle({1.0f, 0.0f, 0.0f}, 0.01f) * Quatf::fromAxisAngle({0.0f, 0.0f, 1.0f}, pi<float> / 4.0f);
  return {
      {&bigBox, bigBoxPose, &cube, at({1.8f, 0.495f, -0.2f})},
      {&bigBox, bigBoxPose, &cube, at({0.2f, halfDiagonal - 0.004f, 0.1f}, edgeDown)},
      {&cube, at({}, Quatf::fromAxisAngle({1.0f, 0.0f, 0.0f}, pi<float> / 4.0f)), &cube,
       at({0.1f, 2.0f * halfDiagonal - 0.01f, -0.2f}, Quatf::fromAxisAngle({0.0f, 0.0f, 1.0f}, pi<float> / 4.0f))},
      {&bigBox, bigBoxPose, &cube, at({-0.3f, 0.6f, 0.4f}, Quatf::fromAxisAngle({1.0f, 2.0f, 3.0f}, 0.3f))},
  };
}

TEST(Rigid3dHullManifold, swapping_the_hulls_flips_the_normal_and_keeps_the_points) {
  for (const Pose& pose : handPlacedPairs()) {
    const Manifold ab = collideHulls(*pose.a, pose.xfA, *pose.b, pose.xfB);
    const Manifold ba = collideHulls(*pose.b, pose.xfB, *pose.a, pose.xfA);
    ASSERT_GT(ab.pointCount, 0);
    expectNear(ba.normal, -ab.normal, 1e-5f);
    std::vector<Vec3f> points;
    for (int k = 0; k < ab.pointCount; ++k) {
      points.push_back(ab.points[static_cast<std::size_t>(k)].point);
    }
    expectPoints(ba, points, 1e-5f);
    for (int k = 0; k < ba.pointCount; ++k) {
      const ManifoldPoint& p = ba.points[static_cast<std::size_t>(k)];
      // The same point's separation in the other manifold.
      float separation = std::numeric_limits<float>::max();
      for (int j = 0; j < ab.pointCount; ++j) {
        if (length(ab.points[static_cast<std::size_t>(j)].point - p.point) <= 1e-5f) {
          separation = ab.points[static_cast<std::size_t>(j)].separation;
        }
      }
      EXPECT_NEAR(p.separation, separation, 1e-5f);
      expectNear(p.anchorA, p.point - pose.xfB.p, 1e-6f);
      expectNear(p.anchorB, p.point - pose.xfA.p, 1e-6f);
    }
  }
}

TEST(Rigid3dHullManifold, the_manifold_moves_with_both_bodies) {
  const Transform3f world = at({10.0f, -3.0f, 5.0f}, Quatf::fromAxisAngle({0.0f, 1.0f, 1.0f}, 1.1f));
  for (const Pose& pose : handPlacedPairs()) {
    const Manifold here = collideHulls(*pose.a, pose.xfA, *pose.b, pose.xfB);
    const Manifold there = collideHulls(*pose.a, mul(world, pose.xfA), *pose.b, mul(world, pose.xfB));
    ASSERT_GT(here.pointCount, 0);
    expectNear(there.normal, rotate(world.q, here.normal), 1e-4f);
    std::vector<Vec3f> moved;
    for (int k = 0; k < here.pointCount; ++k) {
      moved.push_back(transformPoint(world, here.points[static_cast<std::size_t>(k)].point));
    }
    expectPoints(there, moved, 1e-4f);
    EXPECT_EQ(ids(here), ids(there));
  }
}

TEST(Rigid3dHullManifold, a_small_shift_keeps_the_ids) {
  // 1 mm sideways and 1 mm down: the same features touch, the same ids, each point its own.
  const Transform3f shift = at({0.001f, -0.001f, 0.001f});
  for (const Pose& pose : handPlacedPairs()) {
    const Manifold before = collideHulls(*pose.a, pose.xfA, *pose.b, pose.xfB);
    const Manifold after = collideHulls(*pose.a, pose.xfA, *pose.b, mul(shift, pose.xfB));
    ASSERT_GT(before.pointCount, 0);
    EXPECT_EQ(ids(before).size(), static_cast<std::size_t>(before.pointCount));
    EXPECT_EQ(ids(before), ids(after));
  }
}

/// The overlap of the two point sets' projections on n (A's highest less B's lowest): how deep
/// they interpenetrate along n, m; the most any point's separation along n can be below zero.
float overlapAlong(const Vec3f& n, const std::vector<Vec3f>& a, const std::vector<Vec3f>& b) {
  float highestA = -std::numeric_limits<float>::max();
  float lowestB = std::numeric_limits<float>::max();
  for (const Vec3f& p : a) {
    highestA = std::max(highestA, dot(n, p));
  }
  for (const Vec3f& p : b) {
    lowestB = std::min(lowestB, dot(n, p));
  }
  return highestA - lowestB;
}

float distanceToHull(const Vec3f& point, const std::vector<Vec3f>& hull) {
  const DistanceOutput d = coreDistance({hull, 0.0f}, {std::span<const Vec3f>(&point, 1), 0.0f});
  return d.overlap ? 0.0f : d.distance;
}

Vec3f randomUnit(Lcg& random) {
  for (;;) {
    const Vec3f v{random.next(), random.next(), random.next()};
    if (const float l = length(v); l > 0.1f && l <= 1.0f) {
      return v * (1.0f / l);
    }
  }
}

TEST(Rigid3dHullManifold, random_pairs_agree_with_their_distance_and_their_overlap) {
  // A box and the hull of 16 random points (centred: their mean, inside the hull, at its body
  // origin), turned at random, B moved from A's centre along a random direction to a chosen GJK
  // distance (bisection: the distance grows along the ray once positive), or past the first
  // touch by a chosen depth.
  Lcg random{0x2545f4914f6cdd1dULL};
  int overlapping = 0;
  int near = 0;
  int far = 0;
  int singlePoint = 0;
  for (int trial = 0; trial < 400; ++trial) {
    SCOPED_TRACE(trial);
    const Hull box =
        makeBoxHull({0.4f + 0.3f * random.next(), 0.4f + 0.3f * random.next(), 0.4f + 0.3f * random.next()});
    std::vector<Vec3f> cloud;
    Vec3f mean;
    for (int k = 0; k < 16; ++k) {
      cloud.push_back({0.5f * random.next(), 0.5f * random.next(), 0.5f * random.next()});
      mean += cloud.back();
    }
    for (Vec3f& p : cloud) {
      p -= mean * (1.0f / 16.0f);
    }
    const Hull blob = computeHull(cloud);
    const bool boxFirst = trial % 2 == 0;
    const Hull& a = boxFirst ? box : blob;
    const Hull& b = boxFirst ? blob : box;
    const Transform3f xfA = at({random.next(), random.next(), random.next()},
                               Quatf::fromAxisAngle(randomUnit(random), 3.0f * random.next()));
    const Quatf qB = Quatf::fromAxisAngle(randomUnit(random), 3.0f * random.next());
    const Vec3f u = randomUnit(random);
    const std::vector<Vec3f> pointsA = worldPoints(a, xfA);
    const auto distanceAt = [&](float t) {
      const DistanceOutput d = coreDistance({pointsA, 0.0f}, {worldPoints(b, at(xfA.p + u * t, qB)), 0.0f});
      return d.overlap ? 0.0f : d.distance;
    };
    const auto firstAt = [&](float target) { // the least t whose distance exceeds target
      float lo = 0.0f;
      float hi = 4.0f;
      for (int k = 0; k < 40; ++k) {
        const float mid = 0.5f * (lo + hi);
        (distanceAt(mid) > target ? hi : lo) = mid;
      }
      return hi;
    };
    const float target = 0.05f * random.next() - 0.01f; // m: depths to 6 cm, gaps to 4 cm
    const float t = target >= 0.0f ? firstAt(target) : firstAt(0.0f) + target;
    const Transform3f xfB = at(xfA.p + u * t, qB);
    const std::vector<Vec3f> pointsB = worldPoints(b, xfB);
    const DistanceOutput gjk = coreDistance({pointsA, 0.0f}, {pointsB, 0.0f});
    const Manifold m = collideHulls(a, xfA, b, xfB);

    EXPECT_LE(m.pointCount, 4);
    EXPECT_EQ(ids(m).size(), static_cast<std::size_t>(m.pointCount));
    if (m.pointCount == 0) {
      // No points: a valid lower bound on the distance, beyond reach.
      ASSERT_FALSE(gjk.overlap);
      EXPECT_GT(m.separationBound, speculativeDistance);
      EXPECT_LE(m.separationBound, gjk.distance + 1e-4f);
      ++far;
      continue;
    }
    EXPECT_NEAR(length(m.normal), 1.0f, 1e-4f);
    const float overlap = overlapAlong(m.normal, pointsA, pointsB);
    for (int k = 0; k < m.pointCount; ++k) {
      const ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
      EXPECT_LE(p.separation, speculativeDistance + 1e-6f);
      // No point deeper than the hulls overlap along the normal.
      EXPECT_GE(p.separation, -overlap - 1e-4f);
      // Midway between the surfaces: at most half its separation from each hull.
      EXPECT_LE(distanceToHull(p.point, pointsA), 0.5f * std::abs(p.separation) + 1e-4f);
      EXPECT_LE(distanceToHull(p.point, pointsB), 0.5f * std::abs(p.separation) + 1e-4f);
      expectNear(p.anchorA, p.point - xfA.p, 1e-5f);
      expectNear(p.anchorB, p.point - xfB.p, 1e-5f);
    }
    if (!gjk.overlap) {
      // Apart: no point claims a gap smaller than the distance (a contact would stop the pair
      // short of touching).
      ++near;
      for (int k = 0; k < m.pointCount; ++k) {
        EXPECT_GE(m.points[static_cast<std::size_t>(k)].separation, gjk.distance - 1e-3f);
      }
      continue;
    }
    ++overlapping;
    singlePoint += m.pointCount == 1 ? 1 : 0;
    // The normal is the axis of least overlap among the faces of both hulls (or an edge axis of
    // less), within the tolerances that keep the choice from flickering: A's face is kept unless
    // B's is 2% plus 0.1 linearSlop shallower, so it may be deeper by (least + 0.1 slop) / 0.98.
    float leastFaceOverlap = std::numeric_limits<float>::max();
    for (const auto& [hull, xf, sign] : {std::tuple{&a, xfA, 1.0f}, std::tuple{&b, xfB, -1.0f}}) {
      for (const HullPlane& plane : hull->planes) {
        leastFaceOverlap =
            std::min(leastFaceOverlap, overlapAlong(rotate(xf.q, plane.normal) * sign, pointsA, pointsB));
      }
    }
    EXPECT_LE(overlap, (leastFaceOverlap + 0.1f * linearSlop) / 0.98f + 1e-4f);
  }
  // Each kind of pair was met often enough to mean something.
  EXPECT_GT(overlapping, 100);
  EXPECT_GT(near, 40);
  EXPECT_GT(far, 40);
  EXPECT_GT(singlePoint, 5);
}

} // namespace
} // namespace impetus::rigid3d
