// Closed triangle meshes against closed forms: a cube and a box (m (b^2 + c^2) / 12), the corner
// tetrahedron (whose products of inertia are non-zero), and a finely tessellated sphere against
// 4/3 pi r^3 and 2/5 m r^2; rigid motions transform the result as R I R^T.
#include <impetus/core/mesh_mass.hpp>
#include <impetus/core/solid.hpp>
#include <impetus/error.hpp>
#include <impetus/math/quat.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace impetus {
namespace {

constexpr double pi = std::numbers::pi;

struct Mesh {
  std::vector<Vec3d> vertices;
  std::vector<TriangleIndices> triangles;
};

double maxAbs(const Mat33d& m) {
  double r = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      r = std::fmax(r, std::abs(m(i, j)));
    }
  }
  return r;
}

void expectMatNear(const Mat33d& actual, const Mat33d& expected, double tol) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(actual(r, c), expected(r, c), tol) << "element (" << r << "," << c << ")";
    }
  }
}

// A box [min, min + size] as 12 triangles, counter-clockwise seen from outside. Corner i has
// coordinates (i & 1, i & 2, i & 4) scaled by the size.
Mesh boxMesh(const Vec3d& min, const Vec3d& size) {
  Mesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.push_back(
        min + Vec3d{(i & 1) != 0 ? size.x : 0.0, (i & 2) != 0 ? size.y : 0.0, (i & 4) != 0 ? size.z : 0.0});
  }
  mesh.triangles = {{0, 2, 3}, {0, 3, 1},  // z = min (normal -z)
                    {4, 5, 7}, {4, 7, 6},  // z = max (+z)
                    {0, 1, 5}, {0, 5, 4},  // y = min (-y)
                    {2, 6, 7}, {2, 7, 3},  // y = max (+y)
                    {0, 4, 6}, {0, 6, 2},  // x = min (-x)
                    {1, 3, 7}, {1, 7, 5}}; // x = max (+x)
  return mesh;
}

// The corner tetrahedron O, a ex, b ey, c ez, outward-wound.
Mesh tetrahedronMesh(double a, double b, double c) {
  return {{{0.0, 0.0, 0.0}, {a, 0.0, 0.0}, {0.0, b, 0.0}, {0.0, 0.0, c}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
}

// A right square pyramid: base a x a centred on the origin in the plane z = 0, apex at height h,
// outward-wound. Its vertex average (z = h/5) is not its centroid (z = h/4).
Mesh pyramidMesh(double a, double h) {
  const double s = a / 2.0;
  return {{{-s, -s, 0.0}, {s, -s, 0.0}, {s, s, 0.0}, {-s, s, 0.0}, {0.0, 0.0, h}},
          {{0, 2, 1}, {0, 3, 2}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}};
}

// An icosahedron subdivided `levels` times (each triangle into four at its edge midpoints),
// every vertex projected onto the sphere of radius r. The mesh keeps the icosahedron's full
// symmetry group, so its inertia tensor is exactly isotropic (up to rounding).
Mesh icosphere(int levels, double radius) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh mesh;
  mesh.vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3d& v : mesh.vertices) {
    v = normalize(v);
  }
  mesh.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                    {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    const auto midpoint = [&](std::uint32_t i, std::uint32_t j) {
      const auto key = std::make_pair(std::min(i, j), std::max(i, j));
      const auto found = midpoints.find(key);
      if (found != midpoints.end()) {
        return found->second;
      }
      const auto index = static_cast<std::uint32_t>(mesh.vertices.size());
      mesh.vertices.push_back(normalize((mesh.vertices[i] + mesh.vertices[j]) * 0.5));
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<TriangleIndices> finer;
    finer.reserve(mesh.triangles.size() * 4);
    for (const TriangleIndices& tri : mesh.triangles) {
      const std::uint32_t ab = midpoint(tri[0], tri[1]);
      const std::uint32_t bc = midpoint(tri[1], tri[2]);
      const std::uint32_t ca = midpoint(tri[2], tri[0]);
      finer.push_back({tri[0], ab, ca});
      finer.push_back({tri[1], bc, ab});
      finer.push_back({tri[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    mesh.triangles = std::move(finer);
  }
  for (Vec3d& v : mesh.vertices) {
    v = v * radius;
  }
  return mesh;
}

MassProperties3 massOf(const Mesh& mesh, double density) {
  return meshMassProperties(mesh.vertices, mesh.triangles, density);
}

// --- Closed forms ---------------------------------------------------------------------------------

TEST(MeshMass, unit_cube) {
  const double density = 3.0;
  const MassProperties3 result = massOf(boxMesh({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}), density);
  EXPECT_NEAR(result.mass, density, 1e-14);
  EXPECT_NEAR(result.centerOfMass.x, 0.5, 1e-15);
  EXPECT_NEAR(result.centerOfMass.y, 0.5, 1e-15);
  EXPECT_NEAR(result.centerOfMass.z, 0.5, 1e-15);
  // m (1 + 1) / 12 = m / 6 on the diagonal, no products.
  expectMatNear(result.inertia, Mat33d::diagonal({density / 6.0, density / 6.0, density / 6.0}), 1e-14);
}

TEST(MeshMass, box_matches_the_solid_box) {
  const Vec3d size{0.4, 1.1, 2.3};
  const double density = 640.0;
  const MassProperties3 result = massOf(boxMesh({-3.0, 1.0, 0.5}, size), density);
  const double mass = density * size.x * size.y * size.z;
  EXPECT_NEAR(result.mass, mass, 1e-12 * mass);
  EXPECT_NEAR(result.centerOfMass.x, -3.0 + 0.2, 1e-14);
  EXPECT_NEAR(result.centerOfMass.y, 1.0 + 0.55, 1e-14);
  EXPECT_NEAR(result.centerOfMass.z, 0.5 + 1.15, 1e-14);
  const Mat33d expected = inertiaTensor(Box{size}, mass);
  expectMatNear(result.inertia, expected, 1e-12 * maxAbs(expected));
}

TEST(MeshMass, corner_tetrahedron_matches_closed_form) {
  // Tetrahedron O, a ex, b ey, c ez: V = abc/6, centroid (a, b, c)/4. Over the simplex,
  // E[x^2] = a^2/10 and E[xy] = ab/20, so about the centroid E[x^2] - (a/4)^2 = 3a^2/80 and
  // E[xy] - ab/16 = -ab/80: Ixx = 3m (b^2 + c^2)/80, and the product Ixy = -m ab/80, stored
  // negated as +m ab/80.
  const double a = 1.0;
  const double b = 2.0;
  const double c = 3.0;
  const double density = 5.0;
  const MassProperties3 result = massOf(tetrahedronMesh(a, b, c), density);
  const double m = density * a * b * c / 6.0;
  EXPECT_NEAR(result.mass, m, 1e-14);
  EXPECT_NEAR(result.centerOfMass.x, a / 4.0, 1e-15);
  EXPECT_NEAR(result.centerOfMass.y, b / 4.0, 1e-15);
  EXPECT_NEAR(result.centerOfMass.z, c / 4.0, 1e-15);
  const Mat33d expected{3.0 * m * (b * b + c * c) / 80.0, m * a * b / 80.0, m * a * c / 80.0, m * a * b / 80.0,
                        3.0 * m * (c * c + a * a) / 80.0, m * b * c / 80.0, m * a * c / 80.0, m * b * c / 80.0,
                        3.0 * m * (a * a + b * b) / 80.0};
  expectMatNear(result.inertia, expected, 1e-14 * maxAbs(expected));
}

TEST(MeshMass, square_pyramid_matches_closed_form) {
  // Cross-section at height z: side a (1 - z/h). Integrating, V = a^2 h / 3, E[x^2] = a^2 / 20,
  // E[z] = h/4 and E[z^2] = h^2 / 10, so about the centroid var(z) = 3 h^2 / 80:
  // Ixx = Iyy = m (a^2/20 + 3 h^2/80), Izz = m a^2 / 10, no products.
  const double a = 1.2;
  const double h = 2.0;
  const double density = 4.0;
  const MassProperties3 result = massOf(pyramidMesh(a, h), density);
  const double m = density * a * a * h / 3.0;
  EXPECT_NEAR(result.mass, m, 1e-14 * m);
  EXPECT_NEAR(result.centerOfMass.x, 0.0, 1e-15);
  EXPECT_NEAR(result.centerOfMass.y, 0.0, 1e-15);
  EXPECT_NEAR(result.centerOfMass.z, h / 4.0, 1e-15);
  const double ixx = m * (a * a / 20.0 + 3.0 * h * h / 80.0);
  expectMatNear(result.inertia, Mat33d::diagonal({ixx, ixx, m * a * a / 10.0}), 1e-14 * ixx);
}

// --- The tessellated sphere -----------------------------------------------------------------------

TEST(MeshMass, icosphere_matches_solid_sphere_within_one_percent) {
  const double radius = 0.75;
  const double density = 1200.0;
  const Mesh mesh = icosphere(5, radius); // 20 * 4^5 = 20,480 triangles
  ASSERT_EQ(mesh.triangles.size(), 20480U);
  const MassProperties3 result = massOf(mesh, density);
  const double sphereMass = density * 4.0 / 3.0 * pi * radius * radius * radius;
  const double sphereInertia = 0.4 * sphereMass * radius * radius;

  // The requirement: mass and inertia within 1 % of the solid sphere's.
  EXPECT_NEAR(result.mass, sphereMass, 0.01 * sphereMass);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(result.inertia(axis, axis), sphereInertia, 0.01 * sphereInertia) << "axis " << axis;
  }
  // Inscribed in the sphere (a convex hull of points on it), the polyhedron is a subset of the
  // ball: with the same density, less mass and less inertia about every axis through the centre.
  EXPECT_LT(result.mass, sphereMass);
  EXPECT_LT(result.inertia(0, 0), sphereInertia);
  // Against the mesh's own mass the radial mass distribution is what is tested: within 0.5 %
  // (the actual deficit is ~0.04 %, since the missing caps lie where r^2 is largest).
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(result.inertia(axis, axis), 0.4 * result.mass * radius * radius,
                0.005 * 0.4 * result.mass * radius * radius);
  }
  // Icosahedral symmetry makes the tensor isotropic: equal moments, zero products, centre at
  // the origin, to rounding over 20,480 terms (worst case N eps ~ 2e-12 relative).
  EXPECT_NEAR(result.inertia(1, 1), result.inertia(0, 0), 1e-11 * sphereInertia);
  EXPECT_NEAR(result.inertia(2, 2), result.inertia(0, 0), 1e-11 * sphereInertia);
  for (int r = 0; r < 3; ++r) {
    for (int c = r + 1; c < 3; ++c) {
      EXPECT_NEAR(result.inertia(r, c), 0.0, 1e-11 * sphereInertia);
    }
    EXPECT_NEAR(result.centerOfMass[r], 0.0, 1e-12 * radius);
  }
}

TEST(MeshMass, icosphere_error_shrinks_quadratically_with_edge_length) {
  // Each subdivision halves the edges, so the volume deficit (the caps cut off by the flat
  // faces, of height ~ edge^2 / r) should shrink by a factor of ~4.
  const double radius = 1.0;
  const double sphereVolume = 4.0 / 3.0 * pi;
  const double coarse = sphereVolume - massOf(icosphere(3, radius), 1.0).mass;
  const double fine = sphereVolume - massOf(icosphere(4, radius), 1.0).mass;
  EXPECT_GT(fine, 0.0);
  EXPECT_NEAR(coarse / fine, 4.0, 0.2);
}

// --- Rigid motions ----------------------------------------------------------------------------------

void expectRigidMotionTransforms(const Mesh& mesh) {
  const double density = 5.0;
  const MassProperties3 original = massOf(mesh, density);
  const Mat33d rotation = toMat33(Quatd::fromAxisAngle({0.3, -1.0, 0.7}, 2.1));
  const Vec3d shift{10.0, -5.0, 3.0};
  Mesh moved = mesh;
  for (Vec3d& v : moved.vertices) {
    v = rotation * v + shift;
  }
  const MassProperties3 result = massOf(moved, density);
  EXPECT_NEAR(result.mass, original.mass, 1e-13 * original.mass);
  const Vec3d center = rotation * original.centerOfMass + shift;
  EXPECT_NEAR(result.centerOfMass.x, center.x, 1e-13);
  EXPECT_NEAR(result.centerOfMass.y, center.y, 1e-13);
  EXPECT_NEAR(result.centerOfMass.z, center.z, 1e-13);
  // R I R^T, element by element.
  Mat33d expected{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        for (int l = 0; l < 3; ++l) {
          expected(i, j) += rotation(i, k) * original.inertia(k, l) * rotation(j, l);
        }
      }
    }
  }
  expectMatNear(result.inertia, expected, 1e-12 * maxAbs(expected));
}

TEST(MeshMass, rigid_motion_rotates_the_tensor_and_moves_the_centre) {
  // A tetrahedron (non-zero products) and a pyramid (vertex average off its centroid), turned
  // about a skew axis and moved.
  for (const Mesh& mesh : {tetrahedronMesh(1.0, 2.0, 3.0), pyramidMesh(1.2, 2.0)}) {
    expectRigidMotionTransforms(mesh);
  }
}

TEST(MeshMass, far_from_the_origin_keeps_its_precision) {
  // The unit cube at 1e6: about the origin the second moments would be ~1e12 and cancel to
  // 1/6; the result must match the cube at the origin to 1e-9.
  const MassProperties3 result = massOf(boxMesh({1e6, -1e6, 2e6}, {1.0, 1.0, 1.0}), 1.0);
  EXPECT_NEAR(result.mass, 1.0, 1e-9);
  EXPECT_NEAR(result.centerOfMass.x, 1e6 + 0.5, 1e-9);
  EXPECT_NEAR(result.centerOfMass.y, -1e6 + 0.5, 1e-9);
  EXPECT_NEAR(result.centerOfMass.z, 2e6 + 0.5, 1e-9);
  expectMatNear(result.inertia, Mat33d::diagonal({1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0}), 1e-9);
}

// --- Invalid meshes --------------------------------------------------------------------------------

TEST(MeshMass, open_mesh_is_rejected) {
  Mesh mesh = boxMesh({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0});
  mesh.triangles.pop_back();
  const std::string field = thrownField([&] { static_cast<void>(massOf(mesh, 1.0)); });
  EXPECT_EQ(field.rfind("triangles edge", 0), 0U) << field;
}

TEST(MeshMass, inconsistently_wound_mesh_is_rejected) {
  // One triangle flipped: its edges now run the same way as their neighbours'.
  Mesh mesh = boxMesh({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0});
  std::swap(mesh.triangles[3][1], mesh.triangles[3][2]);
  const std::string field = thrownField([&] { static_cast<void>(massOf(mesh, 1.0)); });
  EXPECT_EQ(field.rfind("triangles edge", 0), 0U) << field;
}

TEST(MeshMass, doubled_surface_is_rejected) {
  // Every triangle twice: each directed edge has a reverse, but is shared by four triangles.
  Mesh mesh = boxMesh({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0});
  const std::vector<TriangleIndices> once = mesh.triangles;
  mesh.triangles.insert(mesh.triangles.end(), once.begin(), once.end());
  const std::string field = thrownField([&] { static_cast<void>(massOf(mesh, 1.0)); });
  EXPECT_EQ(field.rfind("triangles edge", 0), 0U) << field;
}

TEST(MeshMass, degenerate_triangle_is_rejected) {
  // A triangle with a repeated corner (i, i, j) next to the closed cube: its edges i -> i and the
  // pair i -> j, j -> i cancel among themselves, so only the degenerate-edge check catches it.
  Mesh mesh = boxMesh({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0});
  mesh.triangles.push_back({0, 0, 7});
  const std::string field = thrownField([&] { static_cast<void>(massOf(mesh, 1.0)); });
  EXPECT_EQ(field.rfind("triangles edge", 0), 0U) << field;
}

TEST(MeshMass, inward_winding_is_rejected) {
  // Every triangle flipped: still closed and consistent, but it encloses negative volume.
  Mesh mesh = boxMesh({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0});
  for (TriangleIndices& t : mesh.triangles) {
    std::swap(t[1], t[2]);
  }
  EXPECT_EQ(thrownField([&] { static_cast<void>(massOf(mesh, 1.0)); }), "volume");
}

TEST(MeshMass, bad_indices_vertices_and_density_are_rejected) {
  Mesh outOfRange = boxMesh({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0});
  outOfRange.triangles[3][1] = 8;
  EXPECT_EQ(thrownField([&] { static_cast<void>(massOf(outOfRange, 1.0)); }), "triangles[3] index");
  Mesh withNan = boxMesh({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0});
  withNan.vertices[2].x = std::nan("");
  EXPECT_EQ(thrownField([&] { static_cast<void>(massOf(withNan, 1.0)); }), "vertices[2].x");
  const Mesh cube = boxMesh({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0});
  EXPECT_EQ(thrownField([&] { static_cast<void>(massOf(cube, 0.0)); }), "density");
  Mesh tooFew = tetrahedronMesh(1.0, 1.0, 1.0);
  tooFew.triangles.pop_back();
  EXPECT_EQ(thrownField([&] { static_cast<void>(massOf(tooFew, 1.0)); }), "triangles.size");
}

} // namespace
} // namespace impetus
