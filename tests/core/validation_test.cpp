// The input validation audit of the core (docs/reliability.md, "Input validation"): mass
// properties, solids, polygon and mesh mass and the thread pool refuse NaN, infinity, negative
// and degenerate values with an impetus::Error naming the field and showing the value.
#include "support/validation_table.hpp"

#include <impetus/core/mass_properties.hpp>
#include <impetus/core/mesh_mass.hpp>
#include <impetus/core/polygon_mass.hpp>
#include <impetus/core/solid.hpp>
#include <impetus/core/task_runner.hpp>

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace impetus {
namespace {

using impetus::testing::expectAccepted;
using impetus::testing::expectRejected;
using impetus::testing::infd;
using impetus::testing::nand;

Mat33d withEntry(int r, int c, double v) {
  Mat33d m = Mat33d::identity();
  m(r, c) = v;
  return m;
}

TEST(CoreValidation, mass_properties) {
  const auto part = [](auto change) {
    return [change] {
      std::vector<MassPart> parts{{1.0, {}, Mat33d::identity(), Mat33d::identity()}, {2.0, {1, 0, 0}}};
      change(parts[1]);
      (void)combine(parts);
    };
  };
  expectRejected({
      {"inertia", "-1", [] { (void)parallelAxis(-1.0, 1.0, 1.0); }},
      {"mass", "nan", [] { (void)parallelAxis(1.0, nand, 1.0); }},
      {"distance", "inf", [] { (void)parallelAxis(1.0, 1.0, infd); }},
      {"mass", "-1", [] { (void)parallelAxis(Mat33d::identity(), -1.0, Vec3d{}); }},
      {"offset.y", "nan",
       [] {
         (void)parallelAxis(Mat33d::identity(), 1.0, Vec3d{0, nand, 0});
       }},
      {"inertia(1,2)", "inf", [] { (void)parallelAxis(withEntry(1, 2, infd), 1.0, Vec3d{}); }},
      {"inertia(0,0)", "nan", [] { (void)rotateInertia(withEntry(0, 0, nand), Mat33d::identity()); }},
      {"rotation(2,1)", "inf", [] { (void)rotateInertia(Mat33d::identity(), withEntry(2, 1, infd)); }},
      {"parts.size", "0", [] { (void)combine(std::vector<MassPart>{}); }},
      {"parts[1].mass", "-2", part([](MassPart& p) { p.mass = -2.0; })},
      {"parts[1].mass", "nan", part([](MassPart& p) { p.mass = nand; })},
      {"parts[1].position.z", "inf", part([](MassPart& p) { p.position.z = infd; })},
      {"parts[1].inertia(0,1)", "nan", part([](MassPart& p) { p.inertia(0, 1) = nand; })},
      {"parts[1].orientation(2,2)", "inf", part([](MassPart& p) { p.orientation(2, 2) = infd; })},
      {"total mass", "0",
       [] {
         (void)combine(std::vector<MassPart>{{0.0}, {0.0}});
       }},
      {"parts[0].localInertia.y", "-1",
       [] {
         (void)combine(std::vector<PointMass>{{1.0, {}, {1.0, -1.0, 1.0}}});
       }},
      {"parts[0].mass", "-1", [] { (void)centerOfMass(std::vector<PointMass>{{-1.0}}); }},
      {"inertia(2,2)", "nan", [] { (void)principalAxes(withEntry(2, 2, nand)); }},
      {"tensor(0,1)", "0.5", [] { requirePhysicalInertia(withEntry(0, 1, 0.5), "tensor"); }},
      {"tensor principal moment", "-1",
       [] {
         requirePhysicalInertia(Mat33d::diagonal({-1, 1, 1}), "tensor");
       }},
      {"tensor principal moment", "3",
       [] {
         requirePhysicalInertia(Mat33d::diagonal({1, 1, 3}), "tensor");
       }},
  });
  expectAccepted({
      {"a massless part beside a massive one, zero offset and inertia",
       [] {
         (void)combine(std::vector<MassPart>{{0.0}, {1.0}});
         (void)parallelAxis(0.0, 0.0, 0.0);
         (void)combine(std::vector<PointMass>{{1.0, {}, {0.0, 0.0, 0.0}}});
       }},
  });
}

TEST(CoreValidation, solids_polygons_meshes_and_threads) {
  const std::vector<Vec3d> tetra{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<TriangleIndices> faces{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  expectRejected({
      {"radius", "-1", [] { (void)volume(SolidSphere{-1.0}); }},
      {"radius", "nan", [] { (void)inertiaTensor(SphericalShell{nand}, 1.0); }},
      {"innerRadius", "3",
       [] {
         (void)volume(HollowSphere{3.0, 2.0});
       }},
      {"outerRadius", "inf",
       [] {
         (void)volume(HollowCylinder{1.0, infd, 1.0});
       }},
      {"length", "-1",
       [] {
         (void)inertiaTensor(SolidCylinder{1.0, -1.0}, 1.0);
       }},
      {"size.y", "nan",
       [] {
         (void)volume(Box{{1.0, nand, 1.0}});
       }},
      {"height", "inf",
       [] {
         (void)volume(SolidCone{1.0, infd});
       }},
      {"mass", "-1", [] { (void)inertiaTensor(Rod{1.0}, -1.0); }},
      {"mass", "nan", [] { (void)inertiaTensor(PointSolid{}, nand); }},
      {"density", "0",
       [] {
         (void)polygonMass(std::vector<Vec2d>{{0, 0}, {1, 0}, {0, 1}}, 0.0);
       }},
      {"vertices.size", "2",
       [] {
         (void)polygonMass(std::vector<Vec2d>{{0, 0}, {1, 0}}, 1.0);
       }},
      {"vertices[1].x", "nan",
       [] {
         (void)polygonMass(std::vector<Vec2d>{{0, 0}, {nand, 0}, {0, 1}}, 1.0);
       }},
      {"area", "0",
       [] {
         (void)polygonMass(std::vector<Vec2d>{{0, 0}, {1, 1}, {2, 2}}, 1.0);
       }},
      {"density", "-1", [&] { (void)meshMassProperties(tetra, faces, -1.0); }},
      {"triangles.size", "3",
       [&] { (void)meshMassProperties(tetra, std::vector<TriangleIndices>(faces.begin(), faces.begin() + 3), 1.0); }},
      {"vertices[2].z", "inf",
       [&] {
         std::vector<Vec3d> v = tetra;
         v[2].z = infd;
         (void)meshMassProperties(v, faces, 1.0);
       }},
      {"triangles[3] index", "9",
       [&] {
         std::vector<TriangleIndices> f = faces;
         f[3] = {1, 2, 9};
         (void)meshMassProperties(tetra, f, 1.0);
       }},
      {"threadCount", "0", [] { ThreadPool pool(0); }},
      {"threadCount", "257", [] { ThreadPool pool(257); }},
  });
  expectAccepted({
      {"zero-sized solids (a point), a massless body, one thread",
       [&] {
         (void)inertiaTensor(SolidSphere{0.0}, 0.0);
         (void)volume(HollowSphere{1.0, 1.0});
         (void)meshMassProperties(tetra, faces, 1.0);
         ThreadPool pool(1);
       }},
  });
}

} // namespace
} // namespace impetus
