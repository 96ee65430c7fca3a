// Hulls: the half-edge structure, mass properties against closed forms (a turned box, the unit
// tetrahedron's integrals), and bad hulls refused.
#include <impetus/error.hpp>
#include <impetus/rigid3d/world.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace impetus::rigid3d {
namespace {

void expectConsistentHalfEdges(const Hull& hull) {
  for (std::size_t i = 0; i < hull.edges.size(); ++i) {
    const HullHalfEdge& e = hull.edges[i];
    EXPECT_EQ(hull.edges[e.twin].twin, i);
    EXPECT_EQ(hull.edges[e.twin].origin, hull.edges[e.next].origin); // the twin runs back
    EXPECT_NE(hull.edges[e.twin].face, e.face);
  }
  // Euler's formula for a convex polyhedron: V - E + F = 2.
  const auto v = static_cast<int>(hull.points.size());
  const auto e = static_cast<int>(hull.edges.size() / 2);
  const auto f = static_cast<int>(hull.faceEdges.size());
  EXPECT_EQ(v - e + f, 2);
}

TEST(Rigid3dHull, a_box_is_a_closed_hull_with_outward_planes) {
  const Hull box = makeBoxHull({1.0f, 2.0f, 3.0f});
  ASSERT_EQ(box.points.size(), 8U);
  ASSERT_EQ(box.faceEdges.size(), 6U);
  EXPECT_EQ(box.edges.size(), 24U);
  expectConsistentHalfEdges(box);
  for (const HullPlane& plane : box.planes) {
    // Each face's plane is 1, 2 or 3 m out along its axis.
    const Vec3f n = plane.normal;
    EXPECT_NEAR(plane.offset, std::abs(n.x) * 1.0f + std::abs(n.y) * 2.0f + std::abs(n.z) * 3.0f, 1e-6f);
    EXPECT_NEAR(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0f, 1e-6f);
  }
}

TEST(Rigid3dHull, a_turned_offset_box_has_the_box_tensor_turned) {
  // m = rho 8 a b c; about the centre R diag(m/3 (b^2 + c^2), ...) R^T (half extents a, b, c).
  const Quatf q = Quatf::fromAxisAngle({1.0f, 2.0f, -0.5f}, 0.8f);
  const Hull box = makeBoxHull({0.5f, 1.0f, 0.25f}, {2.0f, -1.0f, 0.5f}, q);
  const MassProperties3 m = massProperties(box, 100.0);
  const double mass = 100.0 * 8.0 * 0.5 * 1.0 * 0.25;
  EXPECT_NEAR(m.mass, mass, 1e-5 * mass);
  EXPECT_NEAR(m.centerOfMass.x, 2.0, 1e-6);
  EXPECT_NEAR(m.centerOfMass.y, -1.0, 1e-6);
  const Mat33d local = Mat33d::diagonal({mass / 3.0 * (1.0 + 0.0625), mass / 3.0 * (0.25 + 0.0625), mass / 3.0 * 1.25});
  const Quatd qd{q.w, q.x, q.y, q.z};
  const Mat33d r = toMat33(normalize(qd));
  const Mat33d expected = r * local * transpose(r);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(m.inertia(i, j), expected(i, j), 1e-5 * mass) << i << "," << j;
    }
  }
}

Hull unitTetrahedron() {
  return makeHullFromFaces({{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}},
                           {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
}

TEST(Rigid3dHull, the_unit_tetrahedron_has_the_moments_its_integrals_give) {
  // Corners at the origin and the three unit points, density rho: m = rho/6, centroid (1/4)^3;
  // about the origin Ixx = rho int (y^2 + z^2) = rho/30, Ixy = -rho int xy = -rho/120; moved to
  // the centroid, Ixx = rho/80 and Ixy = rho/480.
  const Hull tetra = unitTetrahedron();
  expectConsistentHalfEdges(tetra);
  const double rho = 240.0;
  const MassProperties3 m = massProperties(tetra, rho);
  EXPECT_NEAR(m.mass, rho / 6.0, 1e-9);
  EXPECT_NEAR(m.centerOfMass.z, 0.25, 1e-9);
  EXPECT_NEAR(m.inertia(0, 0), rho / 80.0, 1e-9);
  EXPECT_NEAR(m.inertia(1, 1), rho / 80.0, 1e-9);
  EXPECT_NEAR(m.inertia(0, 1), rho / 480.0, 1e-9);
  EXPECT_NEAR(m.inertia(1, 2), rho / 480.0, 1e-9);
}

TEST(Rigid3dHull, a_box_body_spun_about_its_middle_axis_flips) {
  // A box shape's body spun about its axis of middle inertia: the hull's tensor drives the same
  // intermediate-axis flip as explicit mass data.
  World world{WorldDef{{0.0f, 0.0f, 0.0f}}};
  BodyDef def;
  def.type = BodyType::dynamicBody;
  // Half extents (0.05, 0.2, 0.1) m: moments in the ratio 0.05 : 0.0125 : 0.0425 about x, y, z,
  // so z is the middle axis.
  def.angularVelocity = {0.01f, 0.01f, 8.0f};
  const BodyId body = world.createBody(def);
  world.createShape(body, {}, makeBoxHull({0.05f, 0.2f, 0.1f}));
  bool flipped = false;
  for (int i = 0; i < 600 && !flipped; ++i) {
    world.step(1.0f / 60.0f);
    flipped = rotate(world.rotation(body), Vec3f{0.0f, 0.0f, 1.0f}).z < -0.9f;
  }
  EXPECT_TRUE(flipped);
}

TEST(Rigid3dHull, bad_hulls_are_refused_naming_the_field) {
  EXPECT_NE(thrownMessage([] { (void)makeBoxHull({0.001f, 1.0f, 1.0f}); }).find("halfExtents.x"), std::string::npos);
  // A face missing: the hull is open.
  EXPECT_NE(thrownMessage([] {
              (void)makeHullFromFaces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}});
            }).find("twin"),
            std::string::npos);
  World world;
  BodyDef def;
  def.type = BodyType::dynamicBody;
  const BodyId body = world.createBody(def);
  // A box with a corner pushed in: its three faces are no longer flat.
  Hull dented = makeBoxHull({1.0f, 1.0f, 1.0f});
  dented.points[7] = {0.5f, 0.5f, 0.5f};
  EXPECT_NE(thrownMessage([&] { world.createShape(body, {}, dented); }).find("off its plane"), std::string::npos);
  // A point outside the faces: not the hull of its points.
  Hull outside = unitTetrahedron();
  outside.points.emplace_back(1.0f, 1.0f, 1.0f);
  EXPECT_NE(thrownMessage([&] { world.createShape(body, {}, outside); }).find("convex"), std::string::npos);
  // A tetrahedron wound inside out.
  const Hull inverted =
      makeHullFromFaces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
  EXPECT_FALSE(thrownMessage([&] { world.createShape(body, {}, inverted); }).empty());
  EXPECT_NO_THROW(world.createShape(body, {}, unitTetrahedron()));
}

} // namespace
} // namespace impetus::rigid3d
