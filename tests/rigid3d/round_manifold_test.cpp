// The round shapes' manifolds against their geometry: separations, normals and points of
// spheres and capsules placed by hand, the same in any frame.
#include <impetus/math/scalar.hpp>
#include <impetus/rigid3d/constants.hpp>
#include <impetus/rigid3d/manifold.hpp>

#include <gtest/gtest.h>

namespace impetus::rigid3d {
namespace {

const Transform3f identity{};

Transform3f at(const Vec3f& p, const Quatf& q = Quatf::identity()) { return {p, q}; }

void expectNear(const Vec3f& a, const Vec3f& b, float tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Rigid3dRoundManifold, two_spheres_touch_on_the_line_between_their_centres) {
  // Centres 1.2 m apart along (2, 1, 2)/3, radii 0.5 and 0.71: overlapping by 1 cm.
  const Vec3f direction = Vec3f{2.0f, 1.0f, 2.0f} * (1.0f / 3.0f);
  const Manifold m = collideSpheres(Sphere{{}, 0.5f}, at({1.0f, 2.0f, 3.0f}), Sphere{{}, 0.71f},
                                    at(Vec3f{1.0f, 2.0f, 3.0f} + direction * 1.2f));
  ASSERT_EQ(m.pointCount, 1);
  EXPECT_NEAR(m.points[0].separation, -0.01f, 1e-6f);
  expectNear(m.normal, direction, 1e-6f);
  // Midway between the surfaces: 0.5 - 0.005 along the normal from A's centre.
  expectNear(m.points[0].point, Vec3f{1.0f, 2.0f, 3.0f} + direction * 0.495f, 1e-6f);
  expectNear(m.points[0].anchorA, direction * 0.495f, 1e-6f);
}

TEST(Rigid3dRoundManifold, spheres_beyond_the_speculative_distance_report_their_gap) {
  const Manifold m = collideSpheres(Sphere{{}, 0.5f}, identity, Sphere{{}, 0.5f}, at({1.5f, 0.0f, 0.0f}));
  EXPECT_EQ(m.pointCount, 0);
  EXPECT_NEAR(m.separationBound, 0.5f, 1e-6f);
  // Within it: a point, before they touch.
  const Manifold near = collideSpheres(Sphere{{}, 0.5f}, identity, Sphere{{}, 0.5f}, at({1.01f, 0.0f, 0.0f}));
  ASSERT_EQ(near.pointCount, 1);
  EXPECT_NEAR(near.points[0].separation, 0.01f, 1e-6f);
  // Concentric: the world's up.
  const Manifold same = collideSpheres(Sphere{{}, 0.5f}, identity, Sphere{{}, 0.3f}, identity);
  expectNear(same.normal, {0.0f, 1.0f, 0.0f}, 0.0f);
  EXPECT_NEAR(same.points[0].separation, -0.8f, 1e-6f);
}

TEST(Rigid3dRoundManifold, a_sphere_meets_a_capsule_across_its_side_or_around_its_cap) {
  const Capsule capsule{{-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.2f};
  const Manifold side = collideCapsuleAndSphere(capsule, identity, Sphere{{}, 0.3f}, at({0.4f, 0.0f, 0.505f}));
  ASSERT_EQ(side.pointCount, 1);
  expectNear(side.normal, {0.0f, 0.0f, 1.0f}, 1e-6f);
  EXPECT_NEAR(side.points[0].separation, 0.005f, 1e-6f);
  const Manifold cap = collideCapsuleAndSphere(capsule, identity, Sphere{{}, 0.3f}, at({1.3f, 0.4f, 0.0f}));
  ASSERT_EQ(cap.pointCount, 1);
  expectNear(cap.normal, {0.6f, 0.8f, 0.0f}, 1e-6f);
  EXPECT_NEAR(cap.points[0].separation, 0.0f, 1e-6f);
}

TEST(Rigid3dRoundManifold, crossed_capsules_touch_at_one_point_side_by_side_at_two) {
  // One across the other, 0.39 m between their axes, radii 0.2: overlapping by 1 cm, one point.
  const Capsule alongX{{-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.2f};
  const Capsule alongZ{{0.0f, 0.0f, -1.0f}, {0.0f, 0.0f, 1.0f}, 0.2f};
  const Manifold crossed = collideCapsules(alongX, identity, alongZ, at({0.3f, 0.39f, 0.2f}));
  ASSERT_EQ(crossed.pointCount, 1);
  expectNear(crossed.normal, {0.0f, 1.0f, 0.0f}, 1e-6f);
  EXPECT_NEAR(crossed.points[0].separation, -0.01f, 1e-6f);
  expectNear(crossed.points[0].point, {0.3f, 0.195f, 0.0f}, 1e-6f);
  // Side by side, B shifted 1.5 m along: they overlap over [0.5, 1] of A's [-1, 1] span; a point
  // at each end of it, both 1 cm apart.
  const Manifold parallel = collideCapsules(alongX, identity, alongX, at({1.5f, 0.41f, 0.0f}));
  ASSERT_EQ(parallel.pointCount, 2);
  expectNear(parallel.normal, {0.0f, 1.0f, 0.0f}, 1e-6f);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(parallel.points[static_cast<std::size_t>(k)].separation, 0.01f, 1e-6f);
  }
  EXPECT_NEAR(parallel.points[0].point.x, 0.5f, 1e-6f);
  EXPECT_NEAR(parallel.points[1].point.x, 1.0f, 1e-6f);
  EXPECT_NE(parallel.points[0].id, parallel.points[1].id);
}

TEST(Rigid3dRoundManifold, the_manifold_is_the_same_in_any_frame) {
  // The same pair, both bodies turned and moved together: the same separations, the normal and
  // points turned and moved with them.
  const Capsule a{{-0.5f, 0.1f, 0.0f}, {0.7f, -0.2f, 0.3f}, 0.15f};
  const Capsule b{{0.0f, 0.0f, -0.6f}, {0.2f, 0.1f, 0.5f}, 0.1f};
  const Transform3f xfA = at({0.2f, -0.1f, 0.4f}, Quatf::fromAxisAngle({0.3f, 1.0f, 0.2f}, 0.4f));
  const Transform3f xfB = at({0.25f, -0.05f, 0.35f}, Quatf::fromAxisAngle({1.0f, 0.0f, 0.5f}, -0.7f));
  const Transform3f world = at({10.0f, -3.0f, 5.0f}, Quatf::fromAxisAngle({0.0f, 1.0f, 1.0f}, 1.1f));
  const Manifold here = collideCapsules(a, xfA, b, xfB);
  const Manifold there = collideCapsules(a, mul(world, xfA), b, mul(world, xfB));
  ASSERT_EQ(here.pointCount, there.pointCount);
  ASSERT_GT(here.pointCount, 0);
  EXPECT_NEAR(here.points[0].separation, there.points[0].separation, 1e-5f);
  expectNear(rotate(world.q, here.normal), there.normal, 1e-5f);
  expectNear(transformPoint(world, here.points[0].point), there.points[0].point, 1e-5f);
}

} // namespace
} // namespace impetus::rigid3d
