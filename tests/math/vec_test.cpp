// Vec2 and Vec3 (appendix A): the spec's oracles, hand-computed values and the vector identities
// over seeded random inputs.
#include "math_test_util.hpp"

#include <impetus/math/math.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace impetus {
namespace {

using test::isNear;

const Vec3d u{1.0, 2.0, 3.0};
const Vec3d v{4.0, 5.0, 6.0};
const Vec3d w{7.0, 8.0, 10.0};

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------------------
// Vec3: appendix A oracles. Small integers are exact in floating point, so these compare exactly.

TEST(Vec3, cross_product_matches_appendix_a_oracle) { EXPECT_EQ(cross(u, v), (Vec3d{-3.0, 6.0, -3.0})); }

TEST(Vec3, dot_product_matches_appendix_a_oracle) { EXPECT_EQ(dot(u, v), 32.0); }

TEST(Vec3, triple_scalar_product_matches_appendix_a_oracle) { EXPECT_EQ(tripleScalarProduct(u, v, w), -3.0); }

TEST(Vec3, length_of_1_2_3_is_sqrt_14) {
  EXPECT_EQ(lengthSquared(u), 14.0);
  EXPECT_DOUBLE_EQ(length(u), std::sqrt(14.0));
  EXPECT_NEAR(length(u), 3.741657, 5e-7); // the spec's 7-digit value
}

TEST(Vec3, normalize_3_4_0_gives_0_6_0_8_0) {
  // |(3,4,0)| = 5 exactly, so each component is one correctly rounded division.
  EXPECT_EQ(normalize(Vec3d{3.0, 4.0, 0.0}), (Vec3d{0.6, 0.8, 0.0}));
}

TEST(Vec3, normalize_of_zero_vector_returns_zero_not_nan) {
  const Vec3d n = normalize(Vec3d::zero());
  EXPECT_TRUE(isFinite(n));
  EXPECT_EQ(n, Vec3d::zero());
}

TEST(Vec3, normalize_of_vector_below_tolerance_returns_zero) {
  const Vec3d n = normalize(Vec3d{1e-200, -1e-200, 0.0});
  EXPECT_TRUE(isFinite(n));
  EXPECT_EQ(n, Vec3d::zero());
}

TEST(Vec3, normalize_of_tiny_vector_above_tolerance_keeps_full_precision) {
  // 1e-140 squared is 1e-280, still a normal double: the direction survives.
  EXPECT_TRUE(isNear(normalize(Vec3d{3e-140, 4e-140, 0.0}), Vec3d{0.6, 0.8, 0.0}, 1e-15));
}

TEST(Vec3, normalize_of_nan_or_infinite_input_stays_non_finite) {
  EXPECT_FALSE(isFinite(normalize(Vec3d{kNaN, 1.0, 2.0})));
  EXPECT_FALSE(isFinite(normalize(Vec3d{1.0, kNaN, 0.0})));
  EXPECT_FALSE(isFinite(normalize(Vec3d{kInf, 0.0, 0.0})));
}

// sqrt(dot(v, v)) overflows for finite vectors longer than ~1.3e154 (double) or ~1.8e19
// (float); normalize must still return the unit vector (regression: it used to return zero).
TEST(Vec3, normalize_of_huge_finite_vector_gives_unit_vector) {
  EXPECT_TRUE(isNear(normalize(Vec3d{3e200, 4e200, 0.0}), Vec3d{0.6, 0.8, 0.0}, 1e-15));
  EXPECT_TRUE(isNear(normalize(Vec3f{3e20f, 4e20f, 0.0f}), Vec3f{0.6f, 0.8f, 0.0f}, 1e-6f));
  EXPECT_TRUE(isNear(normalize(Vec2d{3e200, 4e200}), Vec2d{0.6, 0.8}, 1e-15));
  EXPECT_TRUE(isNear(normalize(Vec2f{3e20f, 4e20f}), Vec2f{0.6f, 0.8f}, 1e-6f));
}

TEST(Vec3, cross_products_of_basis_vectors_follow_right_hand_rule) {
  EXPECT_EQ(cross(Vec3d::unitX(), Vec3d::unitY()), Vec3d::unitZ());
  EXPECT_EQ(cross(Vec3d::unitY(), Vec3d::unitZ()), Vec3d::unitX());
  EXPECT_EQ(cross(Vec3d::unitZ(), Vec3d::unitX()), Vec3d::unitY());
  EXPECT_EQ(cross(Vec3d::unitY(), Vec3d::unitX()), -Vec3d::unitZ());
}

TEST(Vec3, dot_product_is_cosine_of_angle_times_lengths) {
  const double theta = pi<double> / 3.0;
  const Vec3d a{2.0, 0.0, 0.0};
  const Vec3d b = 3.0 * Vec3d{std::cos(theta), std::sin(theta), 0.0};
  EXPECT_NEAR(dot(a, b), 2.0 * 3.0 * 0.5, 1e-14);
  EXPECT_NEAR(length(cross(a, b)), 2.0 * 3.0 * std::sin(theta), 1e-14);
  EXPECT_EQ(dot(Vec3d::unitX(), Vec3d::unitY()), 0.0);
}

TEST(Vec3, arithmetic_operators_are_component_wise) {
  EXPECT_EQ(u + v, (Vec3d{5.0, 7.0, 9.0}));
  EXPECT_EQ(v - u, (Vec3d{3.0, 3.0, 3.0}));
  EXPECT_EQ(-u, (Vec3d{-1.0, -2.0, -3.0}));
  EXPECT_EQ(u * 2.0, (Vec3d{2.0, 4.0, 6.0}));
  EXPECT_EQ(2.0 * u, (Vec3d{2.0, 4.0, 6.0}));
  EXPECT_EQ(v / 2.0, (Vec3d{2.0, 2.5, 3.0}));
  EXPECT_EQ(hadamard(u, v), (Vec3d{4.0, 10.0, 18.0}));
  EXPECT_NE(u, v);
}

TEST(Vec3, compound_assignments_modify_in_place_and_chain) {
  Vec3d a = u;
  (a += v) += w; // returns a reference, so the second += applies to a as well
  EXPECT_EQ(a, (Vec3d{12.0, 15.0, 19.0}));
  (a -= w) -= v;
  EXPECT_EQ(a, u);
  (a *= 4.0) /= 2.0;
  EXPECT_EQ(a, (Vec3d{2.0, 4.0, 6.0}));
}

TEST(Vec3, index_operator_reads_and_writes_x_y_z) {
  Vec3d a = u;
  EXPECT_EQ(a[0], 1.0);
  EXPECT_EQ(a[1], 2.0);
  EXPECT_EQ(a[2], 3.0);
  a[1] = -5.0;
  EXPECT_EQ(a, (Vec3d{1.0, -5.0, 3.0}));
}

TEST(Vec3, default_vector_is_zero_and_basis_vectors_are_unit_axes) {
  EXPECT_EQ(Vec3d{}, (Vec3d{0.0, 0.0, 0.0}));
  EXPECT_EQ(Vec3d::unitX(), (Vec3d{1.0, 0.0, 0.0}));
  EXPECT_EQ(Vec3d::unitY(), (Vec3d{0.0, 1.0, 0.0}));
  EXPECT_EQ(Vec3d::unitZ(), (Vec3d{0.0, 0.0, 1.0}));
}

TEST(Vec3, distance_lerp_min_max_abs_match_hand_values) {
  EXPECT_DOUBLE_EQ(distance(u, v), std::sqrt(27.0));
  EXPECT_EQ(lerp(u, v, 0.0), u);
  EXPECT_EQ(lerp(u, v, 1.0), v);
  EXPECT_EQ(lerp(u, w, 0.5), (Vec3d{4.0, 5.0, 6.5}));
  const Vec3d a{1.0, -7.0, 3.0};
  const Vec3d b{-2.0, 5.0, 3.5};
  EXPECT_EQ(min(a, b), (Vec3d{-2.0, -7.0, 3.0}));
  EXPECT_EQ(max(a, b), (Vec3d{1.0, 5.0, 3.5}));
  EXPECT_EQ(abs(a), (Vec3d{1.0, 7.0, 3.0}));
}

TEST(Vec3, is_finite_rejects_nan_and_infinity_in_any_component) {
  EXPECT_TRUE(isFinite(u));
  EXPECT_FALSE(isFinite(Vec3d{kNaN, 0.0, 0.0}));
  EXPECT_FALSE(isFinite(Vec3d{0.0, kInf, 0.0}));
  EXPECT_FALSE(isFinite(Vec3d{0.0, 0.0, -kInf}));
}

// ---------------------------------------------------------------------------------------------
// Vec3 identities over seeded random vectors with components in [-10, 10]. Rounding errors scale
// with the magnitudes involved, so the tolerances are relative: 1e-13 is about 450 ulps, far
// above the handful of roundings in each expression and far below any real error.

TEST(Vec3, cross_product_is_orthogonal_to_both_operands) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Vec3d a = rng.vec3();
    const Vec3d b = rng.vec3();
    const Vec3d c = cross(a, b);
    const double scale = length(a) * length(b);
    EXPECT_NEAR(dot(c, a), 0.0, 1e-13 * scale * length(a)) << "case " << i;
    EXPECT_NEAR(dot(c, b), 0.0, 1e-13 * scale * length(b)) << "case " << i;
  }
}

TEST(Vec3, cross_and_dot_satisfy_lagrange_identity) {
  // |a x b|^2 + (a . b)^2 = |a|^2 |b|^2, i.e. sin^2 + cos^2 = 1.
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Vec3d a = rng.vec3();
    const Vec3d b = rng.vec3();
    const double d = dot(a, b);
    const double rhs = lengthSquared(a) * lengthSquared(b);
    EXPECT_NEAR(lengthSquared(cross(a, b)) + d * d, rhs, 1e-13 * rhs) << "case " << i;
  }
}

TEST(Vec3, cross_product_is_anti_commutative) {
  // fl(p - q) = -fl(q - p) in IEEE arithmetic, so this holds exactly.
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Vec3d a = rng.vec3();
    const Vec3d b = rng.vec3();
    EXPECT_EQ(cross(a, b), -cross(b, a)) << "case " << i;
  }
}

TEST(Vec3, cross_product_of_parallel_vectors_is_zero) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Vec3d a = rng.vec3();
    EXPECT_EQ(cross(a, a), Vec3d::zero()) << "case " << i;
    EXPECT_TRUE(isNear(cross(a, -2.5 * a), Vec3d::zero(), 1e-13 * lengthSquared(a))) << "case " << i;
  }
}

TEST(Vec3, cross_product_is_distributive_over_addition) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Vec3d a = rng.vec3();
    const Vec3d b = rng.vec3();
    const Vec3d c = rng.vec3();
    EXPECT_TRUE(isNear(cross(a, b + c), cross(a, b) + cross(a, c), 1e-13 * 300.0)) << "case " << i;
  }
}

TEST(Vec3, triple_scalar_product_is_cyclic_and_changes_sign_on_swap) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Vec3d a = rng.vec3();
    const Vec3d b = rng.vec3();
    const Vec3d c = rng.vec3();
    const double t = tripleScalarProduct(a, b, c);
    const double tol = 1e-13 * length(a) * length(b) * length(c);
    EXPECT_NEAR(tripleScalarProduct(b, c, a), t, tol) << "case " << i;
    EXPECT_NEAR(tripleScalarProduct(c, a, b), t, tol) << "case " << i;
    EXPECT_NEAR(tripleScalarProduct(b, a, c), -t, tol) << "case " << i;
  }
}

TEST(Vec3, normalize_gives_unit_vector_in_same_direction) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Vec3d a = rng.vec3();
    const Vec3d n = normalize(a);
    EXPECT_NEAR(length(n), 1.0, 1e-14) << "case " << i;
    EXPECT_NEAR(dot(n, a), length(a), 1e-14 * length(a)) << "case " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Vec2

TEST(Vec2, arithmetic_operators_are_component_wise) {
  const Vec2d a{1.0, 2.0};
  const Vec2d b{4.0, -6.0};
  EXPECT_EQ(a + b, (Vec2d{5.0, -4.0}));
  EXPECT_EQ(a - b, (Vec2d{-3.0, 8.0}));
  EXPECT_EQ(-a, (Vec2d{-1.0, -2.0}));
  EXPECT_EQ(3.0 * a, (Vec2d{3.0, 6.0}));
  EXPECT_EQ(a * 3.0, (Vec2d{3.0, 6.0}));
  EXPECT_EQ(b / 2.0, (Vec2d{2.0, -3.0}));
  Vec2d c = a;
  (c += b) *= 2.0;
  EXPECT_EQ(c, (Vec2d{10.0, -8.0}));
  (c -= b) /= 2.0;
  EXPECT_EQ(c, (Vec2d{3.0, -1.0}));
}

TEST(Vec2, dot_cross_and_length_match_hand_values) {
  const Vec2d a{1.0, 2.0};
  const Vec2d b{4.0, -6.0};
  EXPECT_EQ(dot(a, b), -8.0);
  EXPECT_EQ(cross(a, b), -14.0); // 1*(-6) - 2*4
  EXPECT_EQ(cross(b, a), 14.0);
  EXPECT_EQ(lengthSquared(a), 5.0);
  EXPECT_DOUBLE_EQ(length(a), std::sqrt(5.0));
  EXPECT_DOUBLE_EQ(distance(a, b), std::sqrt(9.0 + 64.0));
  EXPECT_EQ(cross(Vec2d{1.0, 0.0}, Vec2d{0.0, 1.0}), 1.0); // x to y is counter-clockwise
}

TEST(Vec2, scalar_cross_products_match_3d_cross_with_z_axis) {
  // cross(w, v) = (0,0,w) x (v,0) and cross(v, w) = (v,0) x (0,0,w).
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Vec2d a = rng.vec2();
    const Vec2d b = rng.vec2();
    const double s = rng.uniform(-10.0, 10.0);
    const Vec3d a3{a.x, a.y, 0.0};
    const Vec3d b3{b.x, b.y, 0.0};
    const Vec3d ws{0.0, 0.0, s};
    EXPECT_EQ(cross(a, b), cross(a3, b3).z) << "case " << i;
    const Vec3d left = cross(ws, a3);
    const Vec3d right = cross(a3, ws);
    EXPECT_EQ(cross(s, a), (Vec2d{left.x, left.y})) << "case " << i;
    EXPECT_EQ(cross(a, s), (Vec2d{right.x, right.y})) << "case " << i;
  }
  EXPECT_EQ(cross(2.0, Vec2d{1.0, 0.0}), (Vec2d{0.0, 2.0})); // spin +z moves +x toward +y
}

TEST(Vec2, perp_rotates_counter_clockwise_by_90_degrees) {
  EXPECT_EQ(perp(Vec2d{1.0, 0.0}), (Vec2d{0.0, 1.0}));
  EXPECT_EQ(perp(Vec2d{0.0, 1.0}), (Vec2d{-1.0, 0.0}));
  EXPECT_EQ(perp(Vec2d{3.0, -2.0}), (Vec2d{2.0, 3.0}));
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Vec2d a = rng.vec2();
    EXPECT_EQ(dot(perp(a), a), 0.0) << "case " << i; // -y*x + x*y cancels exactly
    EXPECT_EQ(cross(a, perp(a)), lengthSquared(a)) << "case " << i;
  }
}

TEST(Vec2, normalize_handles_regular_zero_and_nan_vectors) {
  EXPECT_EQ(normalize(Vec2d{3.0, 4.0}), (Vec2d{0.6, 0.8}));
  EXPECT_EQ(normalize(Vec2d{}), Vec2d::zero());
  EXPECT_TRUE(isFinite(normalize(Vec2d{1e-200, 1e-200})));
  EXPECT_FALSE(isFinite(normalize(Vec2d{kNaN, 1.0})));
  EXPECT_FALSE(isFinite(normalize(Vec2d{1.0, kInf})));
}

TEST(Vec2, lerp_min_max_abs_match_hand_values) {
  const Vec2d a{1.0, -7.0};
  const Vec2d b{-2.0, 5.0};
  EXPECT_EQ(lerp(a, b, 0.0), a);
  EXPECT_EQ(lerp(a, b, 1.0), b);
  EXPECT_EQ(lerp(a, b, 0.5), (Vec2d{-0.5, -1.0}));
  EXPECT_EQ(min(a, b), (Vec2d{-2.0, -7.0}));
  EXPECT_EQ(max(a, b), (Vec2d{1.0, 5.0}));
  EXPECT_EQ(abs(a), (Vec2d{1.0, 7.0}));
}

// ---------------------------------------------------------------------------------------------
// float instantiations: float has ~7 significant digits, so 1e-5 on O(1) values.

TEST(Vec3f, float_operations_match_double_oracles) {
  const Vec3f a{1.0f, 2.0f, 3.0f};
  const Vec3f b{4.0f, 5.0f, 6.0f};
  const Vec3f c{7.0f, 8.0f, 10.0f};
  EXPECT_EQ(cross(a, b), (Vec3f{-3.0f, 6.0f, -3.0f}));
  EXPECT_EQ(dot(a, b), 32.0f);
  EXPECT_EQ(tripleScalarProduct(a, b, c), -3.0f);
  EXPECT_NEAR(length(a), 3.741657f, 1e-5f);
  EXPECT_TRUE(isNear(normalize(Vec3f{3.0f, 4.0f, 0.0f}), Vec3f{0.6f, 0.8f, 0.0f}, 1e-6f));
  EXPECT_EQ(normalize(Vec3f{}), Vec3f::zero());
  EXPECT_FALSE(isFinite(normalize(Vec3f{std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f})));
  EXPECT_TRUE(isNear(lerp(a, b, 0.5f) * 2.0f - (a + b), Vec3f{}, 1e-5f));
}

TEST(Vec2f, float_operations_match_hand_values) {
  const Vec2f a{1.0f, 2.0f};
  const Vec2f b{4.0f, -6.0f};
  EXPECT_EQ(cross(a, b), -14.0f);
  EXPECT_EQ(dot(a, b), -8.0f);
  EXPECT_EQ(cross(2.0f, Vec2f{1.0f, 0.0f}), (Vec2f{0.0f, 2.0f}));
  EXPECT_TRUE(isNear(normalize(Vec2f{3.0f, 4.0f}), Vec2f{0.6f, 0.8f}, 1e-6f));
  EXPECT_NEAR(distance(a, b), std::sqrt(73.0f), 1e-5f);
}

} // namespace
} // namespace impetus
