// The primitive solids against a reference the library did not produce: the volume and the full
// inertia tensor of each solid integrated numerically over its volume (midpoint rule in
// spherical, cylindrical or Cartesian coordinates), the thin-shell and rod limits of the thick
// solids, surface and line integrals for the thin shapes, and the book's table (ch. 1, Figs 1-3 to
// 1-7) for concrete numbers.
#include <impetus/core/solid.hpp>
#include <impetus/error.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace impetus {
namespace {

constexpr double pi = std::numbers::pi;

// One quadrature node: a point of the solid and the Jacobian |d(x,y,z)/d(u,v,w)| of the map from
// the unit cube (for a surface or a line, the area or length element instead).
struct Node {
  Vec3d point;
  double jacobian;
};

// Volume, first moment and the inertia tensor about the origin, computed by the definition:
// Ixx = sum (y^2 + z^2) dm, and the products Ixy = sum x y dm stored negated off the diagonal.
struct Integral {
  double measure = 0.0; // volume (or area, length)
  Vec3d firstMoment{};  // integral of r d(measure)
  Mat33d inertia{};     // per unit density
};

// Midpoint rule with nu x nv x nw cells over the unit cube, mapped onto the solid by `map`.
template <class Map> Integral integrate(int nu, int nv, int nw, Map map) {
  Integral result;
  const double cell = 1.0 / (static_cast<double>(nu) * static_cast<double>(nv) * static_cast<double>(nw));
  for (int i = 0; i < nu; ++i) {
    const double u = (i + 0.5) / nu;
    for (int j = 0; j < nv; ++j) {
      const double v = (j + 0.5) / nv;
      for (int k = 0; k < nw; ++k) {
        const double w = (k + 0.5) / nw;
        const Node node = map(u, v, w);
        const double dv = node.jacobian * cell;
        const double x = node.point.x;
        const double y = node.point.y;
        const double z = node.point.z;
        result.measure += dv;
        result.firstMoment += node.point * dv;
        result.inertia(0, 0) += (y * y + z * z) * dv;
        result.inertia(1, 1) += (z * z + x * x) * dv;
        result.inertia(2, 2) += (x * x + y * y) * dv;
        result.inertia(0, 1) -= x * y * dv;
        result.inertia(0, 2) -= x * z * dv;
        result.inertia(1, 2) -= y * z * dv;
      }
    }
  }
  result.inertia(1, 0) = result.inertia(0, 1);
  result.inertia(2, 0) = result.inertia(0, 2);
  result.inertia(2, 1) = result.inertia(1, 2);
  return result;
}

// Grid for the curvilinear integrals: kRadial x kPolar x kAzimuthal = 409,600 samples per solid.
// The azimuthal integrands are trigonometric polynomials of degree <= 2, which the periodic
// midpoint rule integrates exactly for any n >= 3, so 16 azimuthal points cost no accuracy.
constexpr int kRadial = 160;
constexpr int kPolar = 160;
constexpr int kAzimuthal = 16;

// Tolerance of the curvilinear integrals. The midpoint rule's error on [0, 1] with n cells is
// -(h^2 / 24)(f'(1) - f'(0)) + O(h^4). The worst integrands here are r^4 dr (sphere moments:
// relative error k(k+1) h^2 / 24 = 0.83 h^2 for k = 4), sin(t) cos(t)^2 dt over [0, pi]
// (relative 1.23 / n^2) and (1 - v)^4 dv for the cone (0.83 h^2): at most ~2 / n^2 together. Ten
// times that, 20 / n^2 = 7.8e-4, is still far below the smallest error a wrong coefficient would
// make (e.g. 3/80 vs 1/20 in the cone, 25%).
constexpr double kCurvilinearTolerance = 20.0 / (kRadial * kRadial);

// Compares the library's volume and tensor (mass = density * its own volume) with the integral.
// Off-diagonals are compared against the same absolute tolerance, scaled by the largest moment.
void expectMatchesIntegral(const Solid& solid, const Integral& integral, double relTol) {
  const double v = volume(solid);
  EXPECT_NEAR(v, integral.measure, relTol * integral.measure) << solidName(solid) << " volume";
  // The frame is centred on the centroid: the first moment vanishes.
  const double size = std::cbrt(integral.measure);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(integral.firstMoment[a] / integral.measure, 0.0, relTol * size) << solidName(solid) << " centroid";
  }
  const double density = 850.0;
  const Mat33d expected = integral.inertia * density;
  const Mat33d actual = inertiaTensor(solid, density * v);
  const double scale = std::fmax(expected(0, 0), std::fmax(expected(1, 1), expected(2, 2)));
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(actual(r, c), expected(r, c), relTol * scale) << solidName(solid) << " I(" << r << "," << c << ")";
    }
  }
}

Vec3d spherical(double r, double theta, double phi) {
  return {r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi), r * std::cos(theta)};
}

// --- Thick solids against volume integrals -------------------------------------------------

TEST(Solid, solid_sphere_matches_numerical_integration) {
  const double radius = 0.7;
  const Integral integral = integrate(kRadial, kPolar, kAzimuthal, [&](double u, double v, double w) {
    const double r = radius * u;
    const double theta = pi * v;
    return Node{spherical(r, theta, 2.0 * pi * w), r * r * std::sin(theta) * radius * pi * 2.0 * pi};
  });
  expectMatchesIntegral(SolidSphere{radius}, integral, kCurvilinearTolerance);
}

TEST(Solid, hollow_sphere_matches_numerical_integration) {
  const double inner = 0.45;
  const double outer = 0.8;
  const Integral integral = integrate(kRadial, kPolar, kAzimuthal, [&](double u, double v, double w) {
    const double r = inner + (outer - inner) * u;
    const double theta = pi * v;
    return Node{spherical(r, theta, 2.0 * pi * w), r * r * std::sin(theta) * (outer - inner) * pi * 2.0 * pi};
  });
  expectMatchesIntegral(HollowSphere{inner, outer}, integral, kCurvilinearTolerance);
}

TEST(Solid, solid_cylinder_matches_numerical_integration) {
  const double radius = 0.3;
  const double length = 1.7;
  // u: radius, v: axial position, w: azimuth.
  const Integral integral = integrate(kRadial, kPolar, kAzimuthal, [&](double u, double v, double w) {
    const double r = radius * u;
    const double phi = 2.0 * pi * w;
    return Node{{r * std::cos(phi), r * std::sin(phi), length * (v - 0.5)}, r * radius * length * 2.0 * pi};
  });
  expectMatchesIntegral(SolidCylinder{radius, length}, integral, kCurvilinearTolerance);
}

TEST(Solid, hollow_cylinder_matches_numerical_integration) {
  const double inner = 0.25;
  const double outer = 0.4;
  const double length = 0.9;
  const Integral integral = integrate(kRadial, kPolar, kAzimuthal, [&](double u, double v, double w) {
    const double r = inner + (outer - inner) * u;
    const double phi = 2.0 * pi * w;
    return Node{{r * std::cos(phi), r * std::sin(phi), length * (v - 0.5)}, r * (outer - inner) * length * 2.0 * pi};
  });
  expectMatchesIntegral(HollowCylinder{inner, outer, length}, integral, kCurvilinearTolerance);
}

TEST(Solid, solid_cone_about_its_centroid_matches_numerical_integration) {
  const double radius = 0.5;
  const double height = 1.2;
  // The cone's base lies h/4 below its centroid (the frame's origin), the apex 3h/4 above it.
  // v runs from the base (v = 0) to the apex (v = 1), the local radius is R (1 - v), and
  // u scales that radius: r = u R (1 - v), so dV = r dr dphi dz = u (R (1 - v))^2 2 pi h du dv dw.
  const Integral integral = integrate(kRadial, kPolar, kAzimuthal, [&](double u, double v, double w) {
    const double local = radius * (1.0 - v);
    const double r = u * local;
    const double phi = 2.0 * pi * w;
    return Node{{r * std::cos(phi), r * std::sin(phi), -0.25 * height + height * v},
                u * local * local * 2.0 * pi * height};
  });
  expectMatchesIntegral(SolidCone{radius, height}, integral, kCurvilinearTolerance);
}

TEST(Solid, box_matches_numerical_integration) {
  const Vec3d size{0.4, 1.1, 2.3};
  // Cartesian midpoint rule, n cells per edge (216,000 samples). The samples of a box form a
  // discrete uniform distribution whose variance along an edge a is a^2 (1 - 1/n^2) / 12, so the
  // integrated moments are low by exactly the relative amount 1/n^2 = 2.8e-4: tolerance 2/n^2.
  constexpr int n = 60;
  const Integral integral = integrate(n, n, n, [&](double u, double v, double w) {
    return Node{{size.x * (u - 0.5), size.y * (v - 0.5), size.z * (w - 0.5)}, size.x * size.y * size.z};
  });
  expectMatchesIntegral(Box{size}, integral, 2.0 / (n * n));
}

// --- Thin shapes: surface and line integrals, and the limits of the thick solids -------------

TEST(Solid, spherical_shell_matches_surface_integral) {
  const double radius = 0.6;
  const double mass = 3.5;
  // Area element r^2 sin(theta) dtheta dphi; the mass is spread uniformly over the numerical
  // area. Polar error as for the solid sphere: <= 1.23 / n^2, tolerance 20 / n^2.
  constexpr int n = 400;
  const Integral integral = integrate(n, kAzimuthal, 1, [&](double u, double v, double) {
    const double theta = pi * u;
    return Node{spherical(radius, theta, 2.0 * pi * v), radius * radius * std::sin(theta) * pi * 2.0 * pi};
  });
  const Mat33d expected = integral.inertia * (mass / integral.measure);
  const Mat33d actual = inertiaTensor(SphericalShell{radius}, mass);
  const double tol = 20.0 / (n * n) * expected(0, 0);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(actual(r, c), expected(r, c), tol) << "I(" << r << "," << c << ")";
    }
  }
  EXPECT_NEAR(integral.measure, 4.0 * pi * radius * radius, 20.0 / (n * n) * integral.measure);
}

TEST(Solid, spherical_shell_is_the_limit_of_a_hollow_sphere) {
  const double radius = 0.6;
  const double mass = 3.5;
  const double shell = inertiaTensor(SphericalShell{radius}, mass)(0, 0);
  // Inner radius equal to the outer one: the thick formula's limit is exactly 2/3 m r^2.
  EXPECT_NEAR(inertiaTensor(HollowSphere{radius, radius}, mass)(0, 0), shell, 1e-14 * shell);
  // (ro^5 - ri^5) / (ro^3 - ri^3) = (5/3) r^2 (1 - eps + O(eps^2)) for ri = r (1 - eps): the thick
  // shell approaches the thin one linearly in the wall thickness.
  for (double eps : {1e-2, 1e-4, 1e-6}) {
    const double thick = inertiaTensor(HollowSphere{radius * (1.0 - eps), radius}, mass)(0, 0);
    EXPECT_LT(thick, shell);
    EXPECT_NEAR((shell - thick) / shell, eps, 0.1 * eps) << "eps = " << eps;
  }
}

TEST(Solid, cylindrical_shell_matches_surface_integral) {
  const double radius = 0.35;
  const double length = 1.4;
  const double mass = 2.0;
  // Area element r dphi dz; the z^2 integrand has midpoint error exactly 1/n^2 relative.
  constexpr int n = 400;
  const Integral integral = integrate(n, kAzimuthal, 1, [&](double u, double v, double) {
    const double phi = 2.0 * pi * v;
    return Node{{radius * std::cos(phi), radius * std::sin(phi), length * (u - 0.5)}, radius * 2.0 * pi * length};
  });
  const Mat33d expected = integral.inertia * (mass / integral.measure);
  const Mat33d actual = inertiaTensor(CylindricalShell{radius, length}, mass);
  const double tol = 2.0 / (n * n) * expected(0, 0);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(actual(r, c), expected(r, c), tol) << "I(" << r << "," << c << ")";
    }
  }
}

TEST(Solid, cylindrical_shell_is_the_limit_of_a_hollow_cylinder) {
  const double radius = 0.35;
  const double length = 1.4;
  const double mass = 2.0;
  const Mat33d shell = inertiaTensor(CylindricalShell{radius, length}, mass);
  const Mat33d same = inertiaTensor(HollowCylinder{radius, radius, length}, mass);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(same(a, a), shell(a, a), 1e-14 * shell(a, a));
  }
  // ri^2 + ro^2 = 2 r^2 (1 - eps + eps^2/2): Izz approaches m r^2 linearly in eps.
  for (double eps : {1e-2, 1e-4, 1e-6}) {
    const Mat33d thick = inertiaTensor(HollowCylinder{radius * (1.0 - eps), radius, length}, mass);
    EXPECT_NEAR((shell(2, 2) - thick(2, 2)) / shell(2, 2), eps, 0.01 * eps + 1e-15) << "eps = " << eps;
    EXPECT_LT(thick(0, 0), shell(0, 0));
    EXPECT_NEAR(thick(0, 0), shell(0, 0), 2.0 * eps * shell(0, 0));
  }
}

TEST(Solid, rod_matches_line_integral_and_thin_cylinder_limit) {
  const double length = 2.5;
  const double mass = 4.0;
  // Line integral along z: midpoint error of z^2 is exactly 1/n^2 relative.
  constexpr int n = 2000;
  const Integral integral = integrate(n, 1, 1, [&](double u, double, double) {
    return Node{{0.0, 0.0, length * (u - 0.5)}, length};
  });
  const Mat33d expected = integral.inertia * (mass / integral.measure);
  const Mat33d rod = inertiaTensor(Rod{length}, mass);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(rod(r, c), expected(r, c), 2.0 / (n * n) * expected(0, 0)) << "I(" << r << "," << c << ")";
    }
  }
  // A solid cylinder of vanishing radius: Ixx = m (r^2/4 + l^2/12) -> m l^2/12, Izz = m r^2/2 -> 0.
  const double r = 1e-6 * length;
  const Mat33d thin = inertiaTensor(SolidCylinder{r, length}, mass);
  EXPECT_NEAR(thin(0, 0), rod(0, 0), mass * r * r);
  EXPECT_NEAR(thin(1, 1), rod(1, 1), mass * r * r);
  EXPECT_NEAR(thin(2, 2), rod(2, 2), mass * r * r);
  EXPECT_DOUBLE_EQ(rod(2, 2), 0.0);
}

// --- The book's table with concrete numbers ---------------------------------------------------

TEST(Solid, book_table_values_for_concrete_shapes) {
  // Values worked by hand from the table in ch. 1 (rounding only: 1e-12 relative).
  const auto near = [](double actual, double expected) { EXPECT_NEAR(actual, expected, 1e-12 * expected); };
  // Solid sphere r = 0.5, m = 10: 2/5 * 10 * 0.25 = 1.
  near(inertiaTensor(SolidSphere{0.5}, 10.0)(1, 1), 1.0);
  // Thin spherical shell r = 0.5, m = 6: 2/3 * 6 * 0.25 = 1.
  near(inertiaTensor(SphericalShell{0.5}, 6.0)(2, 2), 1.0);
  // Solid cylinder r = 0.2, l = 1.2, m = 12: Ixx = 12 (0.04/4 + 1.44/12) = 1.56, Izz = 6 * 0.04.
  const Mat33d cylinder = inertiaTensor(SolidCylinder{0.2, 1.2}, 12.0);
  near(cylinder(0, 0), 1.56);
  near(cylinder(1, 1), 1.56);
  near(cylinder(2, 2), 0.24);
  // Thin cylindrical shell r = 0.2, l = 1.2, m = 12: Ixx = 12 (0.04/2 + 0.12) = 1.68, Izz = 0.48.
  const Mat33d shell = inertiaTensor(CylindricalShell{0.2, 1.2}, 12.0);
  near(shell(0, 0), 1.68);
  near(shell(2, 2), 0.48);
  // "Rectangular cylinder" b = 2 (x), a = 3 (y), l = 4 (z), m = 12:
  // Ixx = m (a^2 + l^2)/12 = 25, Iyy = m (b^2 + l^2)/12 = 20, Izz = m (a^2 + b^2)/12 = 13.
  const Mat33d box = inertiaTensor(Box{{2.0, 3.0, 4.0}}, 12.0);
  near(box(0, 0), 25.0);
  near(box(1, 1), 20.0);
  near(box(2, 2), 13.0);
  // Rod l = 3, m = 4: m l^2 / 12 = 3.
  near(inertiaTensor(Rod{3.0}, 4.0)(0, 0), 3.0);
  // Cone r = 2, h = 4, m = 10: Ixx = 10 (3/20 * 4 + 3/80 * 16) = 12, Izz = 3/10 * 10 * 4 = 12.
  const Mat33d cone = inertiaTensor(SolidCone{2.0, 4.0}, 10.0);
  near(cone(0, 0), 12.0);
  near(cone(2, 2), 12.0);
  // Volumes: sphere r = 3 -> 36 pi; cone r = 3, h = 2 -> 6 pi; tube 1..2, l = 1 -> 3 pi.
  near(volume(SolidSphere{3.0}), 36.0 * pi);
  near(volume(SolidCone{3.0, 2.0}), 6.0 * pi);
  near(volume(HollowCylinder{1.0, 2.0, 1.0}), 3.0 * pi);
  near(volume(HollowSphere{1.0, 2.0}), 28.0 / 3.0 * pi);
}

TEST(Solid, point_and_thin_shapes_have_no_volume_and_a_point_no_inertia) {
  EXPECT_EQ(volume(PointSolid{}), 0.0);
  EXPECT_EQ(volume(SphericalShell{1.0}), 0.0);
  EXPECT_EQ(volume(CylindricalShell{1.0, 2.0}), 0.0);
  EXPECT_EQ(volume(Rod{2.0}), 0.0);
  EXPECT_EQ(inertiaTensor(PointSolid{}, 5.0), Mat33d::zero());
}

TEST(Solid, names_are_distinct_lower_case_words) {
  EXPECT_EQ(solidName(Box{{1.0, 1.0, 1.0}}), "box");
  EXPECT_EQ(solidName(SolidSphere{1.0}), "solid-sphere");
  EXPECT_EQ(solidName(SolidCone{1.0, 1.0}), "solid-cone");
  EXPECT_EQ(solidName(HollowCylinder{1.0, 2.0, 1.0}), "hollow-cylinder");
}

// --- Bad input ---------------------------------------------------------------------------------

TEST(Solid, invalid_dimensions_throw_naming_the_field) {
  const double nan = std::nan("");
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(thrownField([] { static_cast<void>(volume(SolidSphere{-1.0})); }), "radius");
  EXPECT_EQ(thrownField([&] { static_cast<void>(volume(SolidCylinder{1.0, nan})); }), "length");
  EXPECT_EQ(thrownField([] { static_cast<void>(volume(HollowSphere{2.0, 1.0})); }), "innerRadius");
  EXPECT_EQ(thrownField([] { static_cast<void>(volume(HollowCylinder{1.5, 1.0, 1.0})); }), "innerRadius");
  EXPECT_EQ(thrownField([] { static_cast<void>(volume(HollowSphere{-0.5, 1.0})); }), "innerRadius");
  EXPECT_EQ(thrownField([&] { static_cast<void>(volume(HollowSphere{0.5, inf})); }), "outerRadius");
  EXPECT_EQ(thrownField([] { static_cast<void>(volume(Box{{1.0, -1.0, 1.0}})); }), "size.y");
  EXPECT_EQ(thrownField([&] { static_cast<void>(volume(SolidCone{1.0, -inf})); }), "height");
  // The inertia validates the dimensions too, thin shapes included, and the mass.
  EXPECT_EQ(thrownField([] { static_cast<void>(inertiaTensor(SphericalShell{-1.0}, 1.0)); }), "radius");
  EXPECT_EQ(thrownField([&] { static_cast<void>(inertiaTensor(Rod{nan}, 1.0)); }), "length");
  EXPECT_EQ(thrownField([] { static_cast<void>(inertiaTensor(HollowCylinder{2.0, 1.0, 1.0}, 1.0)); }), "innerRadius");
  EXPECT_EQ(thrownField([] { static_cast<void>(inertiaTensor(SolidSphere{1.0}, -3.0)); }), "mass");
  EXPECT_EQ(thrownField([&] { static_cast<void>(inertiaTensor(Box{{1.0, 1.0, 1.0}}, nan)); }), "mass");
}

TEST(Solid, zero_sizes_and_zero_mass_are_accepted) {
  // Zero is a valid (degenerate) size and mass: non-negative is the documented requirement.
  EXPECT_EQ(volume(SolidSphere{0.0}), 0.0);
  EXPECT_EQ(inertiaTensor(SolidCylinder{1.0, 2.0}, 0.0), Mat33d::zero());
  EXPECT_EQ(inertiaTensor(HollowSphere{0.0, 0.0}, 1.0), Mat33d::zero());
}

} // namespace
} // namespace impetus
