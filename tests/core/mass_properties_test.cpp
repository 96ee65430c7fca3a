// Composite mass properties (ch. 1) against references the library did not produce: tensors
// summed by their definition over point clouds, numerical integration of a rotated box, closed
// forms, and the book's Ex 1.1 (car, driver and fuel) with the spec's recomputed numbers.
#include <impetus/core/mass_properties.hpp>
#include <impetus/core/solid.hpp>
#include <impetus/error.hpp>
#include <impetus/math/quat.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <vector>

namespace impetus {
namespace {

constexpr double pi = std::numbers::pi;

// SplitMix64: a tiny deterministic generator, so the point clouds are the same on every
// platform (std::uniform_real_distribution is not specified bit-for-bit).
class Random {
public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  double uniform(double lo, double hi) {
    state_ += 0x9E3779B97F4A7C15ULL;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
    z ^= z >> 31U;
    return lo + (hi - lo) * static_cast<double>(z >> 11U) * 0x1.0p-53;
  }
  Vec3d vec(double lo, double hi) {
    const double x = uniform(lo, hi);
    const double y = uniform(lo, hi);
    return {x, y, uniform(lo, hi)};
  }

private:
  std::uint64_t state_;
};

struct Particle {
  double mass;
  Vec3d position;
};

double totalMass(const std::vector<Particle>& cloud) {
  double m = 0.0;
  for (const Particle& p : cloud) {
    m += p.mass;
  }
  return m;
}

Vec3d centroidOf(const std::vector<Particle>& cloud) {
  Vec3d moment{};
  for (const Particle& p : cloud) {
    moment += p.position * p.mass;
  }
  return moment / totalMass(cloud);
}

// The inertia tensor of point masses about `about`, by the definition (ch. 1, item 13):
// Ixx = sum m (y^2 + z^2), ..., Ixy = sum m x y, stored negated off the diagonal.
Mat33d tensorByDefinition(const std::vector<Particle>& cloud, const Vec3d& about) {
  double ixx = 0.0, iyy = 0.0, izz = 0.0, ixy = 0.0, ixz = 0.0, iyz = 0.0;
  for (const Particle& p : cloud) {
    const double x = p.position.x - about.x;
    const double y = p.position.y - about.y;
    const double z = p.position.z - about.z;
    ixx += p.mass * (y * y + z * z);
    iyy += p.mass * (z * z + x * x);
    izz += p.mass * (x * x + y * y);
    ixy += p.mass * x * y;
    ixz += p.mass * x * z;
    iyz += p.mass * y * z;
  }
  return {ixx, -ixy, -ixz, -ixy, iyy, -iyz, -ixz, -iyz, izz};
}

// A uniform box sampled at the midpoints of an n^3 grid in its own frame, then rotated and moved.
void appendBoxSamples(std::vector<Particle>& cloud, const Vec3d& size, double mass, const Mat33d& rotation,
                      const Vec3d& position, int n) {
  const double dm = mass / (static_cast<double>(n) * n * n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const Vec3d local{size.x * ((i + 0.5) / n - 0.5), size.y * ((j + 0.5) / n - 0.5),
                          size.z * ((k + 0.5) / n - 0.5)};
        cloud.push_back({dm, rotation * local + position});
      }
    }
  }
}

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

void expectVecNear(const Vec3d& actual, const Vec3d& expected, double tol) {
  EXPECT_NEAR(actual.x, expected.x, tol);
  EXPECT_NEAR(actual.y, expected.y, tol);
  EXPECT_NEAR(actual.z, expected.z, tol);
}

// A rotation about a skew axis, so that every element of a rotated tensor is non-zero.
Mat33d skewRotation() { return toMat33(Quatd::fromAxisAngle({1.0, 2.0, -0.5}, 0.9)); }

// --- Parallel-axis theorem ---------------------------------------------------------------------

TEST(MassProperties, parallel_axis_scalar_moves_a_rod_to_its_end) {
  // A rod of mass m and length L about its end: integral of x^2 m/L dx over [0, L] = m L^2 / 3.
  const double m = 2.5;
  const double length = 1.8;
  EXPECT_NEAR(parallelAxis(m * length * length / 12.0, m, length / 2.0), m * length * length / 3.0, 1e-14);
  // The sign of the distance does not matter.
  EXPECT_EQ(parallelAxis(1.0, 2.0, -3.0), parallelAxis(1.0, 2.0, 3.0));
}

TEST(MassProperties, parallel_axis_scalar_rejects_bad_input) {
  EXPECT_EQ(thrownField([] { static_cast<void>(parallelAxis(1.0, -1.0, 1.0)); }), "mass");
  EXPECT_EQ(thrownField([] { static_cast<void>(parallelAxis(-1.0, 1.0, 1.0)); }), "inertia");
  EXPECT_EQ(thrownField([] { static_cast<void>(parallelAxis(1.0, 1.0, std::nan(""))); }), "distance");
  EXPECT_EQ(thrownField([] { static_cast<void>(parallelAxis(Mat33d::identity(), -1.0, Vec3d{})); }), "mass");
  const Vec3d nanOffset{0.0, std::nan(""), 0.0};
  EXPECT_EQ(thrownField([&] { static_cast<void>(parallelAxis(Mat33d::identity(), 1.0, nanOffset)); }), "offset.y");
}

TEST(MassProperties, parallel_axis_tensor_moves_the_products_of_a_point_mass) {
  // A point mass m at d = (1, 2, 3) from the reference point: Ixx = m (4 + 9), Iyy = m (9 + 1),
  // Izz = m (1 + 4), Ixy = m x y = 2 m, Ixz = 3 m, Iyz = 6 m, stored negated (book convention).
  const double m = 1.5;
  const Mat33d expected = Mat33d{13.0, -2.0, -3.0, -2.0, 10.0, -6.0, -3.0, -6.0, 5.0} * m;
  expectMatNear(parallelAxis(Mat33d::zero(), m, {1.0, 2.0, 3.0}), expected, 1e-14);
}

TEST(MassProperties, parallel_axis_tensor_matches_direct_summation_over_point_masses) {
  Random random(7);
  std::vector<Particle> cloud;
  for (int i = 0; i < 50; ++i) {
    const double mass = random.uniform(0.1, 3.0);
    cloud.push_back({mass, random.vec(-2.0, 2.0)});
  }
  const double mass = totalMass(cloud);
  const Vec3d com = centroidOf(cloud);
  const Mat33d aboutCom = tensorByDefinition(cloud, com);
  // About another point, summed directly: the transfer must reproduce it, products included.
  const Vec3d point{3.0, -1.0, 0.5};
  const Mat33d aboutPoint = tensorByDefinition(cloud, point);
  // Both sides are sums of ~50 terms of magnitude ~10: rounding is ~1e-13.
  expectMatNear(parallelAxis(aboutCom, mass, com - point), aboutPoint, 1e-11 * maxAbs(aboutPoint));
  // The products really moved (the test is not passing on a diagonal-only case).
  EXPECT_GT(std::abs(aboutPoint(0, 1) - aboutCom(0, 1)), 1.0);
}

// --- Composites --------------------------------------------------------------------------------

TEST(MassProperties, center_of_mass_of_point_masses) {
  const std::array<PointMass, 3> points{
      {{1.0, {0.0, 0.0, 0.0}, {}}, {3.0, {4.0, 0.0, 0.0}, {}}, {4.0, {0.0, 2.0, -1.0}, {}}}};
  // (1*0 + 3*4 + 4*0, 4*2, -4) / 8.
  expectVecNear(centerOfMass(points), {1.5, 1.0, -0.5}, 1e-15);
}

TEST(MassProperties, combine_point_masses_matches_direct_summation) {
  Random random(42);
  std::vector<Particle> cloud;
  std::vector<PointMass> points;
  Vec3d localSum{};
  for (int i = 0; i < 50; ++i) {
    const double mass = random.uniform(0.1, 3.0);
    const Vec3d position = random.vec(-5.0, 5.0);
    const Vec3d local = random.vec(0.0, 0.2);
    cloud.push_back({mass, position});
    points.push_back({mass, position, local});
    localSum += local;
  }
  const MassProperties3 result = combine(points);
  const Vec3d com = centroidOf(cloud);
  // Local inertias are about axes parallel to the body's: they add to the diagonal only.
  const Mat33d expected = tensorByDefinition(cloud, com) + Mat33d::diagonal(localSum);
  EXPECT_NEAR(result.mass, totalMass(cloud), 1e-12 * result.mass);
  expectVecNear(result.centerOfMass, com, 1e-13);
  expectMatNear(result.inertia, expected, 1e-12 * maxAbs(expected));
}

TEST(MassProperties, rotated_box_part_matches_numerical_integration) {
  const Vec3d size{0.4, 1.0, 2.2};
  const double boxMass = 30.0;
  const Mat33d rotation = skewRotation();
  const Vec3d boxPosition{1.0, -2.0, 0.5};
  const double pointMass = 12.0;
  const Vec3d pointPosition{-1.5, 0.5, 2.0};

  const std::array<MassPart, 2> parts{{{boxMass, boxPosition, inertiaTensor(Box{size}, boxMass), rotation},
                                       {pointMass, pointPosition, Mat33d::zero(), Mat33d::identity()}}};
  const MassProperties3 result = combine(parts);

  // Reference: the box sampled on an n^3 grid in its own frame, rotated, and summed with the
  // point mass by the definition. The grid's second moments along a box edge a are exactly
  // m a^2 (1 - 1/n^2) / 12, low by m a^2 / (12 n^2); each tensor element combines at most two
  // such terms (rotated), so the discretisation error is below m max(a)^2 / (6 n^2) = 0.015 kg m^2
  // for n = 40, against moments of ~ 13 + 60 kg m^2. The centre of mass of the grid is exact.
  constexpr int n = 40;
  std::vector<Particle> cloud;
  appendBoxSamples(cloud, size, boxMass, rotation, boxPosition, n);
  cloud.push_back({pointMass, pointPosition});
  const Vec3d com = centroidOf(cloud);
  const Mat33d expected = tensorByDefinition(cloud, com);
  const double maxEdge = std::fmax(size.x, std::fmax(size.y, size.z));

  EXPECT_NEAR(result.mass, boxMass + pointMass, 1e-12);
  expectVecNear(result.centerOfMass, com, 1e-12);
  expectMatNear(result.inertia, expected, boxMass * maxEdge * maxEdge / (6.0 * n * n));
  // The products are far from zero here, so the comparison exercises the rotation.
  EXPECT_GT(std::abs(result.inertia(0, 1)), 1.0);
  EXPECT_GT(std::abs(result.inertia(1, 2)), 1.0);
}

TEST(MassProperties, rotated_box_part_equals_rotated_tensor_transferred) {
  const Vec3d size{0.6, 1.5, 0.9};
  const double m = 4.0;
  const Mat33d rotation = skewRotation();
  const Mat33d local = inertiaTensor(Box{size}, m);
  const Vec3d position{2.0, 1.0, -1.0};
  const std::array<MassPart, 2> parts{{{m, position, local, rotation}, {m, -position, local, Mat33d::identity()}}};
  const MassProperties3 result = combine(parts);
  EXPECT_NEAR(result.mass, 2.0 * m, 1e-15);
  expectVecNear(result.centerOfMass, Vec3d{}, 1e-15);

  // R I R^T written out element by element, then each part moved to the common centre (the
  // origin) by the point-mass rule m (|d|^2 delta_ij - d_i d_j).
  Mat33d expected{};
  const std::array<Mat33d, 2> rotations{rotation, Mat33d::identity()};
  const std::array<Vec3d, 2> offsets{position, -position};
  for (std::size_t p = 0; p < 2; ++p) {
    const Mat33d& r = rotations[p];
    const Vec3d& d = offsets[p];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        double rotated = 0.0;
        for (int k = 0; k < 3; ++k) {
          for (int l = 0; l < 3; ++l) {
            rotated += r(i, k) * local(k, l) * r(j, l);
          }
        }
        const double transfer = m * ((i == j ? lengthSquared(d) : 0.0) - d[i] * d[j]);
        expected(i, j) += rotated + transfer;
      }
    }
  }
  expectMatNear(result.inertia, expected, 1e-13 * maxAbs(expected));
  // rotateInertia is the same R I R^T.
  Mat33d rotatedOnly{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        for (int l = 0; l < 3; ++l) {
          rotatedOnly(i, j) += rotation(i, k) * local(k, l) * rotation(j, l);
        }
      }
    }
  }
  expectMatNear(rotateInertia(local, rotation), rotatedOnly, 1e-14 * maxAbs(local));
}

TEST(MassProperties, quarter_turn_about_z_swaps_box_moments) {
  // A box a x b x c turned 90 degrees about z is a box b x a x c.
  const double m = 3.0;
  const Mat33d quarter = toMat33(Quatd::fromAxisAngle(Vec3d::unitZ(), pi / 2.0));
  const std::array<MassPart, 1> parts{{{m, {1.0, 2.0, 3.0}, inertiaTensor(Box{{0.5, 2.0, 1.0}}, m), quarter}}};
  const MassProperties3 result = combine(parts);
  expectVecNear(result.centerOfMass, {1.0, 2.0, 3.0}, 1e-15);
  const Mat33d expected = inertiaTensor(Box{{2.0, 0.5, 1.0}}, m);
  expectMatNear(result.inertia, expected, 1e-14 * maxAbs(expected));
}

TEST(MassProperties, two_half_boxes_make_one_full_box) {
  // Box 2 x 0.6 x 0.8 of mass 5 = two boxes 1 x 0.6 x 0.8 of mass 2.5 centred at x = -0.5, +0.5.
  const double m = 5.0;
  const Mat33d half = inertiaTensor(Box{{1.0, 0.6, 0.8}}, m / 2.0);
  const std::array<MassPart, 2> parts{
      {{m / 2.0, {-0.5, 0.0, 0.0}, half, Mat33d::identity()}, {m / 2.0, {0.5, 0.0, 0.0}, half, Mat33d::identity()}}};
  const MassProperties3 result = combine(parts);
  const Mat33d full = inertiaTensor(Box{{2.0, 0.6, 0.8}}, m);
  EXPECT_DOUBLE_EQ(result.mass, m);
  expectVecNear(result.centerOfMass, Vec3d{}, 1e-15);
  expectMatNear(result.inertia, full, 1e-14 * maxAbs(full));
}

TEST(MassProperties, combine_rejects_empty_negative_and_zero_mass) {
  const MassPart good{1.0, {0.0, 0.0, 0.0}, Mat33d::identity(), Mat33d::identity()};
  EXPECT_EQ(thrownField([] { static_cast<void>(combine(std::span<const MassPart>{})); }), "parts.size");
  EXPECT_EQ(thrownField([] { static_cast<void>(combine(std::span<const PointMass>{})); }), "parts.size");
  const std::array<MassPart, 2> negative{{good, {-1.0, {1.0, 0.0, 0.0}, Mat33d::zero(), Mat33d::identity()}}};
  EXPECT_EQ(thrownField([&] { static_cast<void>(combine(negative)); }), "parts[1].mass");
  const std::array<MassPart, 2> weightless{
      {{0.0, {}, Mat33d::zero(), Mat33d::identity()}, {0.0, {1.0, 0.0, 0.0}, Mat33d::zero(), Mat33d::identity()}}};
  EXPECT_EQ(thrownField([&] { static_cast<void>(combine(weightless)); }), "total mass");
  const std::array<MassPart, 1> nanPosition{{{1.0, {0.0, std::nan(""), 0.0}, Mat33d::zero(), Mat33d::identity()}}};
  EXPECT_EQ(thrownField([&] { static_cast<void>(combine(nanPosition)); }), "parts[0].position.y");
  const std::array<PointMass, 2> negativePoint{{{1.0, {}, {}}, {-2.0, {}, {}}}};
  EXPECT_EQ(thrownField([&] { static_cast<void>(combine(negativePoint)); }), "parts[1].mass");
  EXPECT_EQ(thrownField([&] { static_cast<void>(centerOfMass(negativePoint)); }), "parts[1].mass");
}

// --- Principal axes ------------------------------------------------------------------------------

void expectRightHandedOrthonormal(const Mat33d& axes) {
  expectMatNear(transpose(axes) * axes, Mat33d::identity(), 1e-12);
  EXPECT_NEAR(determinant(axes), 1.0, 1e-12);
}

void expectReconstructs(const PrincipalInertia& principal, const Mat33d& tensor) {
  const Mat33d rebuilt = principal.axes * Mat33d::diagonal(principal.moments) * transpose(principal.axes);
  expectMatNear(rebuilt, tensor, 1e-12 * maxAbs(tensor));
}

TEST(MassProperties, principal_axes_recover_a_rotated_box) {
  const Vec3d size{0.5, 1.3, 2.1};
  const double m = 7.0;
  const Mat33d local = inertiaTensor(Box{size}, m);
  const Mat33d rotation = skewRotation();
  const Mat33d tensor = rotation * local * transpose(rotation);
  const PrincipalInertia principal = principalAxes(tensor);

  // The box's own moments, sorted ascending, with the box axis each belongs to.
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return local(a, a) < local(b, b); });
  for (int i = 0; i < 3; ++i) {
    const int boxAxis = order[static_cast<std::size_t>(i)];
    EXPECT_NEAR(principal.moments[i], local(boxAxis, boxAxis), 1e-12 * local(boxAxis, boxAxis));
    // Parallel up to sign to the rotated box axis (R's column).
    EXPECT_NEAR(std::abs(dot(principal.axes.column(i), rotation.column(boxAxis))), 1.0, 1e-12) << "axis " << i;
  }
  expectRightHandedOrthonormal(principal.axes);
  expectReconstructs(principal, tensor);
}

TEST(MassProperties, principal_axes_with_repeated_moments_stay_orthonormal_and_right_handed) {
  const Mat33d rotation = skewRotation();
  // A long cylinder (Izz < Ixx = Iyy) and a flat disc (Ixx = Iyy < Izz): the repeated pair has
  // no unique axes, but the matrix must still be a rotation and the odd axis must be R's z.
  for (const SolidCylinder cylinder : {SolidCylinder{0.3, 2.0}, SolidCylinder{1.0, 0.2}}) {
    const Mat33d local = inertiaTensor(cylinder, 3.0);
    const Mat33d tensor = rotation * local * transpose(rotation);
    const PrincipalInertia principal = principalAxes(tensor);
    const bool longCylinder = local(2, 2) < local(0, 0);
    const int odd = longCylinder ? 0 : 2;
    EXPECT_NEAR(principal.moments[odd], local(2, 2), 1e-12 * local(0, 0));
    for (int i = 0; i < 3; ++i) {
      if (i != odd) {
        EXPECT_NEAR(principal.moments[i], local(0, 0), 1e-12 * local(0, 0));
        EXPECT_NEAR(dot(principal.axes.column(i), rotation.cz), 0.0, 1e-12);
      }
    }
    EXPECT_NEAR(std::abs(dot(principal.axes.column(odd), rotation.cz)), 1.0, 1e-12);
    expectRightHandedOrthonormal(principal.axes);
    expectReconstructs(principal, tensor);
  }
  // A sphere: all three moments equal. Rotating c E leaves rounding-level off-diagonals.
  const double moment = inertiaTensor(SolidSphere{0.4}, 2.0)(0, 0);
  const Mat33d sphere = rotation * Mat33d::diagonal({moment, moment, moment}) * transpose(rotation);
  const SymmetricEigen3d eigen = symmetricEigen(sphere);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(eigen.values[i], moment, 1e-12 * moment);
  }
  expectRightHandedOrthonormal(eigen.vectors);
  const PrincipalInertia principal = principalAxes(sphere);
  expectRightHandedOrthonormal(principal.axes);
  expectReconstructs(principal, sphere);
}

TEST(MassProperties, principal_axes_of_a_diagonal_tensor_in_any_order_are_right_handed) {
  // Already principal: the axes are the coordinate axes, permuted to sort the moments. Half of
  // the six orders need an odd permutation, which must get a sign flip to stay right-handed.
  const std::array<Vec3d, 6> orders{
      {{1.0, 2.0, 3.0}, {1.0, 3.0, 2.0}, {2.0, 1.0, 3.0}, {2.0, 3.0, 1.0}, {3.0, 1.0, 2.0}, {3.0, 2.0, 1.0}}};
  for (const Vec3d& diagonal : orders) {
    const PrincipalInertia principal = principalAxes(Mat33d::diagonal(diagonal));
    EXPECT_EQ(principal.moments, (Vec3d{1.0, 2.0, 3.0}));
    for (int i = 0; i < 3; ++i) {
      // Moment i + 1 sits on the coordinate axis whose diagonal entry it was.
      const int axis = diagonal.x == i + 1.0 ? 0 : (diagonal.y == i + 1.0 ? 1 : 2);
      EXPECT_EQ(std::abs(principal.axes(axis, i)), 1.0);
    }
    expectRightHandedOrthonormal(principal.axes);
  }
}

TEST(MassProperties, principal_axes_reject_a_non_finite_tensor) {
  Mat33d tensor = Mat33d::identity();
  tensor(1, 2) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(thrownField([&] { static_cast<void>(principalAxes(tensor)); }), "inertia(1,2)");
}

// --- Physical plausibility ------------------------------------------------------------------------

TEST(MassProperties, require_physical_inertia_accepts_real_bodies) {
  const Mat33d rotation = skewRotation();
  const Mat33d box = inertiaTensor(Box{{0.5, 1.3, 2.1}}, 7.0);
  EXPECT_NO_THROW(requirePhysicalInertia(box, "box"));
  EXPECT_NO_THROW(requirePhysicalInertia(rotation * box * transpose(rotation), "rotated box"));
  // The boundary cases: a rod (0, I, I) and a thin plate (Ixx + Iyy = Izz) obey the triangle
  // inequality with equality, also after a rotation adds rounding; a point has no inertia.
  EXPECT_NO_THROW(requirePhysicalInertia(inertiaTensor(Rod{2.0}, 3.0), "rod"));
  const Mat33d plate = inertiaTensor(Box{{1.0, 2.0, 0.0}}, 3.0);
  EXPECT_NEAR(plate(0, 0) + plate(1, 1), plate(2, 2), 1e-15);
  EXPECT_NO_THROW(requirePhysicalInertia(plate, "plate"));
  EXPECT_NO_THROW(requirePhysicalInertia(rotation * plate * transpose(rotation), "rotated plate"));
  EXPECT_NO_THROW(requirePhysicalInertia(Mat33d::zero(), "point"));
}

TEST(MassProperties, require_physical_inertia_rejects_impossible_tensors) {
  const auto field = [](const Mat33d& tensor) {
    return thrownField([&] { requirePhysicalInertia(tensor, "body.inertia"); });
  };
  // Asymmetric.
  EXPECT_EQ(field({2.0, 0.1, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 2.0}), "body.inertia(0,1)");
  // A negative moment on the diagonal, and one hidden behind a large product: eigenvalues
  // of [[1, 2, 0], [2, 1, 0], [0, 0, 2]] are -1, 2, 3.
  EXPECT_EQ(field(Mat33d::diagonal({-1.0, 2.0, 2.0})), "body.inertia principal moment");
  // (A negative smallest moment always breaks the triangle inequality too; the message says
  // which requirement failed.)
  const auto message = [](const Mat33d& tensor) -> std::string {
    try {
      requirePhysicalInertia(tensor, "body.inertia");
    } catch (const Error& e) {
      return e.what();
    }
    return "<nothing thrown>";
  };
  EXPECT_NE(message(Mat33d::diagonal({-1.0, 2.0, 2.0})).find("must be non-negative"), std::string::npos);
  EXPECT_NE(message(Mat33d::diagonal({1.0, 1.0, 3.0})).find("triangle inequality"), std::string::npos);
  EXPECT_EQ(field({1.0, 2.0, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0, 2.0}), "body.inertia principal moment");
  // The triangle inequality I1 + I2 >= I3: diag(1, 1, 3) is violated.
  EXPECT_EQ(field(Mat33d::diagonal({1.0, 1.0, 3.0})), "body.inertia principal moment");
  // The same tensor turned 45 degrees about x has the diagonal (1, 2, 2), which looks fine:
  // only the principal moments reveal it.
  const Mat33d turned = rotationX(pi / 4.0) * Mat33d::diagonal({1.0, 1.0, 3.0}) * transpose(rotationX(pi / 4.0));
  EXPECT_NEAR(turned(1, 1), 2.0, 1e-15);
  EXPECT_NEAR(turned(2, 2), 2.0, 1e-15);
  EXPECT_EQ(field(turned), "body.inertia principal moment");
  // Non-finite.
  EXPECT_EQ(field(Mat33d::diagonal({1.0, std::nan(""), 1.0})), "body.inertia(1,1)");
}

// --- The book's Ex 1.1: car, driver and fuel (Table 1-2), g = 9.8 as in the book -----------------

constexpr double kBookGravity = 9.8;
constexpr double kFuelDensity = 750.0;

struct BookPart {
  double weight; // N
  Vec3d size;    // length (x), width (y), height (out of the screen)
  Vec3d centroid;
};

double fuelWeight() { return kFuelDensity * kBookGravity * volume(Box{{0.5, 0.9, 0.3}}); }

std::array<BookPart, 3> carDriverFuel(double fuelWeightNewton) {
  return {{{17'500.0, {4.70, 1.80, 1.25}, {30.5, 30.5, 0.0}},
           {850.0, {0.90, 0.50, 1.10}, {31.50, 31.00, 0.0}},
           {fuelWeightNewton, {0.50, 0.90, 0.30}, {28.00, 30.50, 0.0}}}};
}

std::array<MassPart, 3> massParts(const std::array<BookPart, 3>& book) {
  std::array<MassPart, 3> parts{};
  for (std::size_t i = 0; i < 3; ++i) {
    const double mass = book[i].weight / kBookGravity;
    parts[i] = {mass, book[i].centroid, inertiaTensor(Box{book[i].size}, mass), Mat33d::identity()};
  }
  return parts;
}

// I_local / (m d^2) of part i, d from the part's centroid to the composite CG.
double localToTransferRatio(const std::array<MassPart, 3>& parts, const MassProperties3& body, std::size_t i) {
  const Vec3d d = parts[i].position - body.centerOfMass;
  return parts[i].inertia(2, 2) / (parts[i].mass * lengthSquared(d));
}

TEST(CarDriverFuel, fuel_weight_is_density_times_g_times_volume) {
  // V = 0.5 * 0.9 * 0.3 = 0.135 m^3, m = 101.25 kg, W = 992.25 N (spec, recomputed).
  EXPECT_NEAR(volume(Box{{0.5, 0.9, 0.3}}), 0.135, 1e-15);
  EXPECT_NEAR(fuelWeight(), 992.25, 1e-10);
}

TEST(CarDriverFuel, total_weight_mass_and_centre_of_gravity) {
  const MassProperties3 body = combine(massParts(carDriverFuel(fuelWeight())));
  // The spec's values, rounded to the digits it prints (half a unit in the last place).
  EXPECT_NEAR(body.mass * kBookGravity, 19'342.25, 1e-9);
  EXPECT_NEAR(body.mass, 1973.70, 0.005);
  EXPECT_NEAR(body.centerOfMass.x, 30.4157, 1e-4);
  EXPECT_NEAR(body.centerOfMass.y, 30.5220, 1e-4);
  EXPECT_EQ(body.centerOfMass.z, 0.0);
}

TEST(CarDriverFuel, yaw_inertia_about_the_centre_of_gravity) {
  const std::array<MassPart, 3> parts = massParts(carDriverFuel(fuelWeight()));
  const MassProperties3 body = combine(parts);
  EXPECT_NEAR(body.inertia(2, 2), 4512.20, 0.01);
  // The spec's per-part table (3 decimals): I_local and m d^2 for car, driver, fuel.
  const std::array<double, 3> local{3769.345, 7.662, 8.944};
  const std::array<double, 3> transfer{13.553, 121.795, 590.902};
  for (std::size_t i = 0; i < 3; ++i) {
    const Vec3d d = parts[i].position - body.centerOfMass;
    EXPECT_NEAR(parts[i].inertia(2, 2), local[i], 0.001) << "part " << i;
    EXPECT_NEAR(parts[i].mass * lengthSquared(d), transfer[i], 0.001) << "part " << i;
  }
}

TEST(CarDriverFuel, local_inertia_is_small_next_to_the_transfer_term) {
  const std::array<MassPart, 3> parts = massParts(carDriverFuel(fuelWeight()));
  const MassProperties3 body = combine(parts);
  // Spec: driver 6.3 %, fuel 1.5 % (to 0.1 percentage point).
  EXPECT_NEAR(100.0 * localToTransferRatio(parts, body, 1), 6.3, 0.1);
  EXPECT_NEAR(100.0 * localToTransferRatio(parts, body, 2), 1.5, 0.1);
}

TEST(CarDriverFuel, book_fuel_weight_and_ratios_cannot_be_reproduced) {
  // Book error (spec section 6, item 1): it states 920.6 N for the fuel, but rho g V = 992.25 N.
  constexpr double bookFuelWeight = 920.6;
  EXPECT_GT(std::abs(fuelWeight() - bookFuelWeight), 70.0);
  // Item 2: its ratios 2.7 % (driver) and 2.1 % (fuel) come out 6.3 % and 1.5 %, and using its
  // 920.6 N does not rescue them (6.4 % and 1.5 %).
  for (double weight : {fuelWeight(), bookFuelWeight}) {
    const std::array<MassPart, 3> parts = massParts(carDriverFuel(weight));
    const MassProperties3 body = combine(parts);
    EXPECT_GT(std::abs(100.0 * localToTransferRatio(parts, body, 1) - 2.7), 3.0) << "fuel " << weight << " N";
    EXPECT_GT(std::abs(100.0 * localToTransferRatio(parts, body, 2) - 2.1), 0.5) << "fuel " << weight << " N";
  }
  const std::array<MassPart, 3> parts = massParts(carDriverFuel(bookFuelWeight));
  const MassProperties3 body = combine(parts);
  EXPECT_NEAR(100.0 * localToTransferRatio(parts, body, 1), 6.4, 0.1);
  EXPECT_NEAR(100.0 * localToTransferRatio(parts, body, 2), 1.5, 0.1);
  // The spec's numbers for the book's fuel weight: W = 19,270.6 N, m = 1,966.39 kg,
  // CG = (30.4247, 30.5221) m, I = 4468.73 kg m^2.
  EXPECT_NEAR(body.mass * kBookGravity, 19'270.6, 1e-9);
  EXPECT_NEAR(body.mass, 1966.39, 0.005);
  EXPECT_NEAR(body.centerOfMass.x, 30.4247, 1e-4);
  EXPECT_NEAR(body.centerOfMass.y, 30.5221, 1e-4);
  EXPECT_NEAR(body.inertia(2, 2), 4468.73, 0.01);
}

} // namespace
} // namespace impetus
