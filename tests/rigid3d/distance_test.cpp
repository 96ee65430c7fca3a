// GJK distance and the hull-sphere manifold against closed forms: a point and a box (the point
// clamped into the box), two boxes face to face, a sphere inside a box.
#include <impetus/rigid3d/distance.hpp>
#include <impetus/rigid3d/manifold.hpp>

#include "test_random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace impetus::rigid3d {
namespace {

std::vector<Vec3f> worldPoints(const Hull& hull, const Transform3f& xf) {
  std::vector<Vec3f> points;
  for (const Vec3f& p : hull.points) {
    points.push_back(transformPoint(xf, p));
  }
  return points;
}

TEST(Rigid3dDistance, a_point_is_as_far_from_a_box_as_its_clamp_into_the_box) {
  // In the box's frame the closest point is the point clamped to the half extents.
  const Vec3f h{0.5f, 1.0f, 0.25f};
  const Transform3f xf{{1.0f, -2.0f, 0.5f}, Quatf::fromAxisAngle({1.0f, 2.0f, 3.0f}, 0.9f)};
  const std::vector<Vec3f> box = worldPoints(makeBoxHull(h), xf);
  Lcg random{0x853c49e6748fea9bULL};
  for (int i = 0; i < 200; ++i) {
    const Vec3f local{3.0f * random.next(), 3.0f * random.next(), 3.0f * random.next()};
    const Vec3f clamped{std::clamp(local.x, -h.x, h.x), std::clamp(local.y, -h.y, h.y), std::clamp(local.z, -h.z, h.z)};
    const float expected = length(local - clamped);
    const Vec3f point = transformPoint(xf, local);
    const DistanceOutput d = coreDistance({box, 0.0f}, {std::span<const Vec3f>(&point, 1), 0.0f});
    if (expected == 0.0f) {
      EXPECT_TRUE(d.overlap);
      continue;
    }
    ASSERT_FALSE(d.overlap) << i;
    EXPECT_NEAR(d.distance, expected, 1e-5f) << i;
    const Vec3f onBox = inverseTransformPoint(xf, d.pointA);
    EXPECT_NEAR(onBox.x, clamped.x, 1e-5f);
    EXPECT_NEAR(onBox.y, clamped.y, 1e-5f);
    EXPECT_NEAR(onBox.z, clamped.z, 1e-5f);
    EXPECT_LT(d.iterations, 10);
  }
}

TEST(Rigid3dDistance, two_boxes_face_to_face_are_their_gap_apart_and_overlapping_ones_overlap) {
  const std::vector<Vec3f> a = worldPoints(makeBoxHull({1.0f, 1.0f, 1.0f}), {});
  const Quatf turn = Quatf::fromAxisAngle({1.0f, 0.0f, 0.0f}, 0.6f); // turned about the gap's axis
  const std::vector<Vec3f> b = worldPoints(makeBoxHull({0.5f, 0.5f, 0.5f}), {{1.8f, 0.2f, -0.1f}, turn});
  // B's face toward A lies 1.8 - 0.5 = 1.3 from A's centre: 0.3 m from A's face.
  const DistanceOutput d = coreDistance({a, 0.0f}, {b, 0.0f});
  ASSERT_FALSE(d.overlap);
  EXPECT_NEAR(d.distance, 0.3f, 1e-5f);
  EXPECT_NEAR(d.pointA.x, 1.0f, 1e-5f);
  EXPECT_NEAR(d.pointB.x, 1.3f, 1e-5f);
  const std::vector<Vec3f> c = worldPoints(makeBoxHull({0.5f, 0.5f, 0.5f}), {{1.4f, 0.2f, -0.1f}, turn});
  EXPECT_TRUE(coreDistance({a, 0.0f}, {c, 0.0f}).overlap);
}

TEST(Rigid3dDistance, a_sphere_on_a_box_and_one_sunk_into_it) {
  const Hull box = makeBoxHull({1.0f, 0.5f, 1.0f});
  const Transform3f xfA{{0.0f, -0.5f, 0.0f}, Quatf::identity()};
  // Resting 5 mm above the top face (y = 0) with a radius of 0.3.
  const Manifold above = collideHullAndSphere(box, xfA, Sphere{{}, 0.3f}, {{0.2f, 0.305f, -0.4f}, Quatf::identity()});
  ASSERT_EQ(above.pointCount, 1);
  EXPECT_NEAR(above.normal.y, 1.0f, 1e-6f);
  EXPECT_NEAR(above.points[0].separation, 0.005f, 1e-6f);
  EXPECT_NEAR(above.points[0].point.y, 0.0025f, 1e-6f);
  // Its centre 0.1 m under the top face, nearer it than any other: pushed up, 0.4 m deep.
  const Manifold sunk = collideHullAndSphere(box, xfA, Sphere{{}, 0.3f}, {{0.2f, -0.1f, -0.4f}, Quatf::identity()});
  ASSERT_EQ(sunk.pointCount, 1);
  EXPECT_NEAR(sunk.normal.y, 1.0f, 1e-6f);
  EXPECT_NEAR(sunk.points[0].separation, -0.4f, 1e-6f);
  // Off the corner: the normal points from the corner to the centre.
  const Manifold corner = collideHullAndSphere(box, xfA, Sphere{{}, 0.3f}, {{1.2f, 0.2f, 1.1f}, Quatf::identity()});
  ASSERT_EQ(corner.pointCount, 1);
  const Vec3f toCenter = normalize(Vec3f{0.2f, 0.2f, 0.1f});
  EXPECT_NEAR(dot(corner.normal, toCenter), 1.0f, 1e-5f);
  EXPECT_NEAR(corner.points[0].separation, 0.3f - 0.3f, 1e-6f);
  // Far: the gap reported.
  const Manifold far = collideHullAndSphere(box, xfA, Sphere{{}, 0.3f}, {{0.0f, 2.0f, 0.0f}, Quatf::identity()});
  EXPECT_EQ(far.pointCount, 0);
  EXPECT_NEAR(far.separationBound, 1.7f, 1e-5f);
}

} // namespace
} // namespace impetus::rigid3d

namespace impetus::rigid3d {
namespace {

TEST(Rigid3dDistance, a_capsule_lying_on_a_box_touches_it_at_both_ends_standing_at_one) {
  // A box whose top face is y = 0 (2 x 2 m), a capsule of radius 0.1 lying 5 mm above it along
  // x, from x = -0.5 to 1.5: clipped to the face, points at x = -0.5 and x = 1.
  const Hull box = makeBoxHull({1.0f, 0.5f, 1.0f});
  const Transform3f xfA{{0.0f, -0.5f, 0.0f}, Quatf::identity()};
  const Capsule capsule{{-0.5f, 0.0f, 0.0f}, {1.5f, 0.0f, 0.0f}, 0.1f};
  const Manifold lying = collideHullAndCapsule(box, xfA, capsule, {{0.0f, 0.105f, 0.3f}, Quatf::identity()});
  ASSERT_EQ(lying.pointCount, 2);
  EXPECT_NEAR(lying.normal.y, 1.0f, 1e-6f);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(lying.points[static_cast<std::size_t>(k)].separation, 0.005f, 1e-6f);
    EXPECT_NEAR(lying.points[static_cast<std::size_t>(k)].point.z, 0.3f, 1e-6f);
  }
  EXPECT_NEAR(std::min(lying.points[0].point.x, lying.points[1].point.x), -0.5f, 1e-5f);
  EXPECT_NEAR(std::max(lying.points[0].point.x, lying.points[1].point.x), 1.0f, 1e-5f);
  // Sunk 2 cm into the face: the same two points, 2 cm deep.
  const Manifold sunk = collideHullAndCapsule(box, xfA, capsule, {{0.0f, 0.08f, 0.3f}, Quatf::identity()});
  ASSERT_EQ(sunk.pointCount, 2);
  EXPECT_NEAR(sunk.points[0].separation, -0.02f, 1e-6f);
  EXPECT_NEAR(sunk.points[1].separation, -0.02f, 1e-6f);
  // Standing on its end, 1 cm up: one point under it.
  const Capsule upright{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.1f};
  const Manifold standing = collideHullAndCapsule(box, xfA, upright, {{0.2f, 0.11f, -0.2f}, Quatf::identity()});
  ASSERT_EQ(standing.pointCount, 1);
  EXPECT_NEAR(standing.normal.y, 1.0f, 1e-6f);
  EXPECT_NEAR(standing.points[0].separation, 0.01f, 1e-6f);
  EXPECT_NEAR(standing.points[0].point.x, 0.2f, 1e-5f);
  // Tilted 30 degrees, its lower end 1 cm up: one point, under the lower end.
  const Quatf tilt = Quatf::fromAxisAngle({0.0f, 0.0f, 1.0f}, 0.5236f);
  const Manifold tilted = collideHullAndCapsule(box, xfA, capsule, {{0.0f, 0.11f + 0.25f, 0.0f}, tilt});
  ASSERT_EQ(tilted.pointCount, 1);
  EXPECT_NEAR(tilted.points[0].separation, 0.01f + 0.25f - 0.25f, 1e-3f);
}

TEST(Rigid3dDistance, the_hull_capsule_manifold_is_the_same_in_any_frame) {
  const Hull box = makeBoxHull({0.6f, 0.3f, 0.4f}, {0.1f, 0.0f, -0.1f}, Quatf::fromAxisAngle({1.0f, 1.0f, 0.0f}, 0.3f));
  const Capsule capsule{{-0.4f, 0.0f, 0.1f}, {0.5f, 0.05f, -0.2f}, 0.08f};
  const Transform3f xfA{{0.0f, -0.2f, 0.0f}, Quatf::fromAxisAngle({0.0f, 1.0f, 0.0f}, 0.2f)};
  const Transform3f xfB{{0.05f, 0.15f, 0.0f}, Quatf::fromAxisAngle({0.0f, 0.0f, 1.0f}, 0.1f)};
  const Transform3f world{{-20.0f, 4.0f, 7.0f}, Quatf::fromAxisAngle({1.0f, 0.0f, 1.0f}, 2.0f)};
  const Manifold here = collideHullAndCapsule(box, xfA, capsule, xfB);
  const Manifold there = collideHullAndCapsule(box, mul(world, xfA), capsule, mul(world, xfB));
  ASSERT_GT(here.pointCount, 0);
  ASSERT_EQ(here.pointCount, there.pointCount);
  for (int k = 0; k < here.pointCount; ++k) {
    const auto i = static_cast<std::size_t>(k);
    EXPECT_NEAR(here.points[i].separation, there.points[i].separation, 1e-5f);
    const Vec3f moved = transformPoint(world, here.points[i].point);
    EXPECT_NEAR(length(moved - there.points[i].point), 0.0f, 2e-5f);
  }
}

} // namespace
} // namespace impetus::rigid3d
