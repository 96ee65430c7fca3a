// Mat22 and Mat33 (appendix B): the spec's oracles, hand-computed products, rotation conventions
// and the matrix identities over seeded random matrices.
#include "math_test_util.hpp"

#include <impetus/error.hpp>
#include <impetus/math/math.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace impetus {
namespace {

using test::errorMessageOf;
using test::isNear;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The appendix B oracle matrix, rows [4,7,2], [3,6,1], [2,5,3].
const Mat33d kM{4.0, 7.0, 2.0, 3.0, 6.0, 1.0, 2.0, 5.0, 3.0};
const Vec3d kU{1.0, 2.0, 3.0};

// ---------------------------------------------------------------------------------------------
// Mat33: layout and accessors

TEST(Mat33, row_major_constructor_agrees_with_rows_columns_and_elements) {
  const Mat33d m{11.0, 12.0, 13.0, 21.0, 22.0, 23.0, 31.0, 32.0, 33.0}; // value = 10 r + c, e_rc
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      const double expected = 10.0 * (r + 1) + (c + 1);
      EXPECT_EQ(m(r, c), expected) << "e" << r + 1 << c + 1;
      EXPECT_EQ(m.row(r)[c], expected) << "row " << r << " col " << c;
      EXPECT_EQ(m.column(c)[r], expected) << "row " << r << " col " << c;
    }
  }
  EXPECT_EQ(m.cx, (Vec3d{11.0, 21.0, 31.0}));
  EXPECT_EQ(m.cz, (Vec3d{13.0, 23.0, 33.0}));
  EXPECT_EQ(Mat33d::fromRows({11.0, 12.0, 13.0}, {21.0, 22.0, 23.0}, {31.0, 32.0, 33.0}), m);
  EXPECT_EQ(Mat33d(m.cx, m.cy, m.cz), m);
}

TEST(Mat33, element_and_column_writes_land_in_the_right_place) {
  Mat33d m = Mat33d::zero();
  m(2, 0) = 5.0; // row 3, column 1: e31
  m.column(1) = Vec3d{1.0, 2.0, 3.0};
  EXPECT_EQ(m, (Mat33d{0.0, 1.0, 0.0, 0.0, 2.0, 0.0, 5.0, 3.0, 0.0}));
}

TEST(Mat33, default_is_zero_and_identity_and_diagonal_have_expected_elements) {
  EXPECT_EQ(Mat33d{}, (Mat33d{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}));
  EXPECT_EQ(Mat33d::zero(), Mat33d{});
  EXPECT_EQ(Mat33d::identity(), (Mat33d{1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0}));
  EXPECT_EQ(Mat33d::diagonal({2.0, -3.0, 5.0}), (Mat33d{2.0, 0.0, 0.0, 0.0, -3.0, 0.0, 0.0, 0.0, 5.0}));
  EXPECT_EQ(Mat33d::identity() * kU, kU);
  EXPECT_EQ(Mat33d::identity() * kM, kM);
  EXPECT_EQ(kM * Mat33d::identity(), kM);
}

// ---------------------------------------------------------------------------------------------
// Mat33: appendix B oracles

TEST(Mat33, determinant_matches_appendix_b_oracle) {
  EXPECT_EQ(determinant(kM), 9.0); // integer arithmetic, exact
  EXPECT_EQ(determinant(Mat33d::identity()), 1.0);
  EXPECT_EQ(determinant(Mat33d::diagonal({2.0, -3.0, 5.0})), -30.0);
}

TEST(Mat33, inverse_matches_appendix_b_oracle) {
  const Mat33d expected = Mat33d{13.0, -11.0, -5.0, -7.0, 8.0, 2.0, 3.0, -6.0, 3.0} / 9.0;
  // The cofactors are exact integers; each element then takes two roundings (1/9, the product)
  // against the oracle's one: a couple of ulps of values below 1.5.
  EXPECT_TRUE(isNear(inverse(kM), expected, 1e-15));
}

TEST(Mat33, matrix_times_inverse_is_identity_for_appendix_b_matrix) {
  EXPECT_TRUE(isNear(kM * inverse(kM), Mat33d::identity(), 1e-14));
  EXPECT_TRUE(isNear(inverse(kM) * kM, Mat33d::identity(), 1e-14));
}

TEST(Mat33, column_and_row_vector_products_match_appendix_b_oracle) {
  EXPECT_EQ(kM * kU, (Vec3d{24.0, 18.0, 21.0}));
  EXPECT_EQ(kU * kM, (Vec3d{16.0, 34.0, 13.0}));
  EXPECT_EQ(kU * kM, transpose(kM) * kU);
}

TEST(Mat33, inverse_of_singular_matrix_throws_error_naming_determinant) {
  const Mat33d singular{1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0}; // rows in arithmetic progression
  ASSERT_EQ(determinant(singular), 0.0);
  EXPECT_THROW((void)inverse(singular), Error);
  const std::string message = errorMessageOf([&] { (void)inverse(singular); });
  EXPECT_NE(message.find("determinant"), std::string::npos) << message;
  try {
    (void)inverse(Mat33d::zero());
    ADD_FAILURE() << "inverse of the zero matrix did not throw";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "determinant");
  }
  EXPECT_THROW((void)solve(singular, kU), Error);
}

TEST(Mat33, inverse_of_non_finite_matrix_throws_error) {
  Mat33d m = kM;
  m(1, 1) = kNaN;
  EXPECT_THROW((void)inverse(m), Error);
  m(1, 1) = std::numeric_limits<double>::infinity();
  EXPECT_THROW((void)inverse(m), Error);
  EXPECT_FALSE(isFinite(m));
  EXPECT_TRUE(isFinite(kM));
}

TEST(Mat33, solve_recovers_the_vector_that_produced_the_right_hand_side) {
  EXPECT_TRUE(isNear(solve(kM, Vec3d{24.0, 18.0, 21.0}), kU, 1e-14));
}

// ---------------------------------------------------------------------------------------------
// Mat33: hand-computed arithmetic

TEST(Mat33, matrix_product_matches_hand_computed_value_and_is_not_commutative) {
  const Mat33d b{1.0, 0.0, 2.0, 0.0, 1.0, 0.0, 3.0, 0.0, 1.0};
  EXPECT_EQ(kM * b, (Mat33d{10.0, 7.0, 10.0, 6.0, 6.0, 7.0, 11.0, 5.0, 7.0}));
  EXPECT_EQ(b * kM, (Mat33d{8.0, 17.0, 8.0, 3.0, 6.0, 1.0, 14.0, 26.0, 9.0}));
}

TEST(Mat33, element_wise_operators_match_hand_values) {
  const Mat33d a{1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0};
  const Mat33d ones{1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0};
  EXPECT_EQ(a + ones, (Mat33d{2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0}));
  EXPECT_EQ(a - ones, (Mat33d{0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0}));
  EXPECT_EQ(-a, (Mat33d{-1.0, -2.0, -3.0, -4.0, -5.0, -6.0, -7.0, -8.0, -9.0}));
  EXPECT_EQ(2.0 * a, (Mat33d{2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0, 18.0}));
  EXPECT_EQ(a * 2.0, 2.0 * a);
  EXPECT_EQ(a / 2.0, (Mat33d{0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5}));
  Mat33d c = a;
  (c += ones) *= 2.0;
  EXPECT_EQ(c, (Mat33d{4.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0, 18.0, 20.0}));
  (c /= 2.0) -= ones;
  EXPECT_EQ(c, a);
}

TEST(Mat33, transpose_and_trace_match_hand_values) {
  EXPECT_EQ(transpose(kM), (Mat33d{4.0, 3.0, 2.0, 7.0, 6.0, 5.0, 2.0, 1.0, 3.0}));
  EXPECT_EQ(trace(kM), 13.0);
}

TEST(Mat33, skew_matrix_times_vector_is_cross_product) {
  EXPECT_EQ(skew(Vec3d{1.0, 2.0, 3.0}), (Mat33d{0.0, -3.0, 2.0, 3.0, 0.0, -1.0, -2.0, 1.0, 0.0}));
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Vec3d a = rng.vec3();
    const Vec3d b = rng.vec3();
    // Same two products per component as cross(); only the summation order may differ.
    EXPECT_TRUE(isNear(skew(a) * b, cross(a, b), 1e-13)) << "case " << i;
    EXPECT_EQ(transpose(skew(a)), -skew(a)) << "case " << i;
  }
}

TEST(Mat33, outer_product_has_elements_a_r_times_b_c) {
  const Vec3d a{1.0, 2.0, 3.0};
  const Vec3d b{4.0, 5.0, 6.0};
  EXPECT_EQ(outer(a, b), (Mat33d{4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 12.0, 15.0, 18.0}));
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Vec3d p = rng.vec3();
    const Vec3d q = rng.vec3();
    const Vec3d r = rng.vec3();
    // (p q^T) r = p (q . r); values up to ~3000, so 1e-11 is ~1000 ulps.
    EXPECT_TRUE(isNear(outer(p, q) * r, p * dot(q, r), 1e-11)) << "case " << i;
  }
}

TEST(Mat33, triple_scalar_product_equals_determinant_of_columns) {
  const Vec3d w{7.0, 8.0, 10.0};
  EXPECT_EQ(determinant(Mat33d(kU, Vec3d{4.0, 5.0, 6.0}, w)), -3.0);
  EXPECT_EQ(determinant(Mat33d::fromRows(kU, Vec3d{4.0, 5.0, 6.0}, w)), -3.0);
}

// ---------------------------------------------------------------------------------------------
// Mat33: rotation matrices

TEST(Mat33, rotation_matrices_follow_right_hand_sign_conventions) {
  const double quarter = pi<double> / 2.0;
  // cos(pi/2) rounds to 6e-17, not 0.
  EXPECT_TRUE(isNear(rotationZ(quarter) * Vec3d::unitX(), Vec3d::unitY(), 1e-14));
  EXPECT_TRUE(isNear(rotationX(quarter) * Vec3d::unitY(), Vec3d::unitZ(), 1e-14));
  EXPECT_TRUE(isNear(rotationY(quarter) * Vec3d::unitZ(), Vec3d::unitX(), 1e-14));
  EXPECT_TRUE(isNear(rotationZ(quarter) * Vec3d::unitY(), -Vec3d::unitX(), 1e-14));
  EXPECT_TRUE(isNear(rotationX(quarter) * Vec3d::unitZ(), -Vec3d::unitY(), 1e-14));
  EXPECT_TRUE(isNear(rotationY(quarter) * Vec3d::unitX(), -Vec3d::unitZ(), 1e-14));
  // The rotation axis itself stays fixed.
  EXPECT_EQ(rotationX(0.7) * Vec3d::unitX(), Vec3d::unitX());
  EXPECT_EQ(rotationY(0.7) * Vec3d::unitY(), Vec3d::unitY());
  EXPECT_EQ(rotationZ(0.7) * Vec3d::unitZ(), Vec3d::unitZ());
}

TEST(Mat33, rotation_matrices_are_orthonormal_and_compose_by_adding_angles) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const double a = rng.uniform(-pi<double>, pi<double>);
    const double b = rng.uniform(-pi<double>, pi<double>);
    for (const auto rot : {&rotationX<double>, &rotationY<double>, &rotationZ<double>}) {
      const Mat33d r = rot(a);
      EXPECT_TRUE(isNear(r * transpose(r), Mat33d::identity(), 1e-14)) << "case " << i;
      EXPECT_NEAR(determinant(r), 1.0, 1e-14) << "case " << i;
      EXPECT_TRUE(isNear(rot(a) * rot(b), rot(a + b), 1e-14)) << "case " << i;
      // cos is even and sin odd; libm keeps that symmetry to within an ulp.
      EXPECT_TRUE(isNear(transpose(r), rot(-a), std::numeric_limits<double>::epsilon())) << "case " << i;
    }
  }
}

TEST(Mat33, orthonormalize_repairs_a_perturbed_rotation) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Mat33d r = toMat33(rng.unitQuat());
    const Mat33d drifted = r + 1e-3 * rng.mat33();
    const Mat33d fixed = orthonormalize(drifted);
    EXPECT_TRUE(isNear(fixed * transpose(fixed), Mat33d::identity(), 1e-14)) << "case " << i;
    EXPECT_NEAR(determinant(fixed), 1.0, 1e-14) << "case " << i;
    // Gram-Schmidt keeps the first column's direction, and moves the rest only by about the
    // size of the perturbation.
    EXPECT_TRUE(isNear(fixed.cx, normalize(drifted.cx), 1e-14)) << "case " << i;
    EXPECT_TRUE(isNear(fixed, r, 1e-2)) << "case " << i;
  }
  // An exact rotation is a fixed point.
  const Mat33d r = rotationZ(0.3) * rotationX(-1.1);
  EXPECT_TRUE(isNear(orthonormalize(r), r, 1e-14));
}

// ---------------------------------------------------------------------------------------------
// Mat33 identities over seeded random matrices. Entries are O(1) and the matrices well
// conditioned (see test::Random::wellConditioned33), so 1e-12 is a few thousand ulps: room for
// the rounding of two products and an inverse, and nowhere near a wrong formula.

TEST(Mat33, transpose_is_an_involution) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Mat33d m = rng.mat33();
    EXPECT_EQ(transpose(transpose(m)), m) << "case " << i;
    EXPECT_EQ(transpose(m)(0, 1), m(1, 0)) << "case " << i;
    EXPECT_EQ(transpose(m)(2, 0), m(0, 2)) << "case " << i;
  }
}

TEST(Mat33, transpose_of_product_is_reversed_product_of_transposes) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Mat33d a = rng.mat33();
    const Mat33d b = rng.mat33();
    EXPECT_TRUE(isNear(transpose(a * b), transpose(b) * transpose(a), 1e-14)) << "case " << i;
    EXPECT_TRUE(isNear(transpose(a + b), transpose(a) + transpose(b), 0.0)) << "case " << i;
  }
}

TEST(Mat33, matrix_product_is_associative) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Mat33d a = rng.mat33();
    const Mat33d b = rng.mat33();
    const Mat33d c = rng.mat33();
    EXPECT_TRUE(isNear((a * b) * c, a * (b * c), 1e-14)) << "case " << i;
    EXPECT_TRUE(isNear((a * b) * kU, a * (b * kU), 1e-14)) << "case " << i;
  }
}

TEST(Mat33, inverse_of_product_is_reversed_product_of_inverses) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Mat33d a = rng.wellConditioned33();
    const Mat33d b = rng.wellConditioned33();
    EXPECT_TRUE(isNear(inverse(a * b), inverse(b) * inverse(a), 1e-12)) << "case " << i;
  }
}

TEST(Mat33, inverse_times_matrix_is_identity_and_inverse_is_an_involution) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Mat33d m = rng.wellConditioned33();
    EXPECT_TRUE(isNear(m * inverse(m), Mat33d::identity(), 1e-12)) << "case " << i;
    EXPECT_TRUE(isNear(inverse(m) * m, Mat33d::identity(), 1e-12)) << "case " << i;
    EXPECT_TRUE(isNear(inverse(inverse(m)), m, 1e-12)) << "case " << i;
    const Vec3d x = rng.vec3();
    EXPECT_TRUE(isNear(solve(m, m * x), x, 1e-12)) << "case " << i;
  }
}

TEST(Mat33, determinant_of_product_is_product_of_determinants) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Mat33d a = rng.wellConditioned33();
    const Mat33d b = rng.wellConditioned33();
    const double expected = determinant(a) * determinant(b); // between ~1 and ~10^5
    EXPECT_NEAR(determinant(a * b), expected, 1e-13 * std::abs(expected)) << "case " << i;
    EXPECT_NEAR(determinant(transpose(a)), determinant(a), 1e-13 * std::abs(determinant(a))) << "case " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Mat22

TEST(Mat22, row_major_constructor_agrees_with_elements_and_columns) {
  const Mat22d m{11.0, 12.0, 21.0, 22.0};
  EXPECT_EQ(m(0, 0), 11.0);
  EXPECT_EQ(m(0, 1), 12.0);
  EXPECT_EQ(m(1, 0), 21.0);
  EXPECT_EQ(m(1, 1), 22.0);
  EXPECT_EQ(m.cx, (Vec2d{11.0, 21.0}));
  EXPECT_EQ(m.cy, (Vec2d{12.0, 22.0}));
  EXPECT_EQ(Mat22d(Vec2d{11.0, 21.0}, Vec2d{12.0, 22.0}), m);
  EXPECT_EQ(Mat22d{}, Mat22d::zero());
  EXPECT_EQ(Mat22d::identity(), (Mat22d{1.0, 0.0, 0.0, 1.0}));
}

TEST(Mat22, arithmetic_matches_hand_computed_values) {
  const Mat22d a{1.0, 2.0, 3.0, 4.0};
  const Mat22d b{5.0, 6.0, 7.0, 8.0};
  EXPECT_EQ(a * b, (Mat22d{19.0, 22.0, 43.0, 50.0}));
  EXPECT_EQ(b * a, (Mat22d{23.0, 34.0, 31.0, 46.0}));
  EXPECT_EQ(a * Vec2d(1.0, 2.0), (Vec2d{5.0, 11.0}));
  EXPECT_EQ(a + b, (Mat22d{6.0, 8.0, 10.0, 12.0}));
  EXPECT_EQ(b - a, (Mat22d{4.0, 4.0, 4.0, 4.0}));
  EXPECT_EQ(2.0 * a, (Mat22d{2.0, 4.0, 6.0, 8.0}));
  EXPECT_EQ(a * 2.0, 2.0 * a);
  EXPECT_EQ(a / 2.0, (Mat22d{0.5, 1.0, 1.5, 2.0}));
  EXPECT_EQ(transpose(a), (Mat22d{1.0, 3.0, 2.0, 4.0}));
}

TEST(Mat22, determinant_inverse_and_solve_match_hand_values) {
  const Mat22d m{4.0, 7.0, 2.0, 6.0};
  EXPECT_EQ(determinant(m), 10.0);
  // (1/10) [[6, -7], [-2, 4]]; two roundings per element against the oracle's one.
  EXPECT_TRUE(isNear(inverse(m), Mat22d{0.6, -0.7, -0.2, 0.4}, 1e-14));
  EXPECT_TRUE(isNear(m * inverse(m), Mat22d::identity(), 1e-14));
  EXPECT_EQ(m * Vec2d(1.0, 2.0), (Vec2d{18.0, 14.0}));
  EXPECT_TRUE(isNear(solve(m, Vec2d{18.0, 14.0}), Vec2d{1.0, 2.0}, 1e-14));
}

TEST(Mat22, inverse_of_singular_matrix_throws_error_naming_determinant) {
  const Mat22d singular{1.0, 2.0, 2.0, 4.0};
  ASSERT_EQ(determinant(singular), 0.0);
  EXPECT_THROW((void)inverse(singular), Error);
  const std::string message = errorMessageOf([&] { (void)inverse(singular); });
  EXPECT_NE(message.find("determinant"), std::string::npos) << message;
  EXPECT_THROW((void)inverse(Mat22d::zero()), Error);
  EXPECT_THROW((void)solve(singular, Vec2d{1.0, 1.0}), Error);
  EXPECT_THROW((void)inverse(Mat22d{kNaN, 0.0, 0.0, 1.0}), Error);
}

TEST(Mat22, rotation22_turns_counter_clockwise_and_composes_by_adding_angles) {
  EXPECT_TRUE(isNear(rotation22(pi<double> / 2.0) * Vec2d(1.0, 0.0), Vec2d{0.0, 1.0}, 1e-14));
  EXPECT_TRUE(isNear(rotation22(pi<double> / 2.0) * Vec2d(0.0, 1.0), Vec2d{-1.0, 0.0}, 1e-14));
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const double a = rng.uniform(-pi<double>, pi<double>);
    const double b = rng.uniform(-pi<double>, pi<double>);
    const Mat22d r = rotation22(a);
    EXPECT_NEAR(determinant(r), 1.0, 1e-14) << "case " << i;
    EXPECT_TRUE(isNear(r * transpose(r), Mat22d::identity(), 1e-14)) << "case " << i;
    EXPECT_TRUE(isNear(inverse(r), transpose(r), 1e-14)) << "case " << i;
    EXPECT_TRUE(isNear(rotation22(a) * rotation22(b), rotation22(a + b), 1e-14)) << "case " << i;
  }
}

TEST(Mat22, matrix_identities_hold_for_random_matrices) {
  // Well-conditioned (diagonally dominant) O(1) matrices: 1e-13 is ~500 ulps.
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Mat22d a = rng.wellConditioned22();
    const Mat22d b = rng.wellConditioned22();
    EXPECT_EQ(transpose(transpose(a)), a) << "case " << i;
    EXPECT_TRUE(isNear(transpose(a * b), transpose(b) * transpose(a), 1e-14)) << "case " << i;
    EXPECT_TRUE(isNear(inverse(a * b), inverse(b) * inverse(a), 1e-13)) << "case " << i;
    EXPECT_TRUE(isNear(a * inverse(a), Mat22d::identity(), 1e-13)) << "case " << i;
    const double expected = determinant(a) * determinant(b);
    EXPECT_NEAR(determinant(a * b), expected, 1e-13 * std::abs(expected)) << "case " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// float instantiations: ~7 significant digits, so 1e-5 on O(1) values.

TEST(Mat33f, float_inverse_determinant_and_products_match_oracle) {
  const Mat33f m{4.0f, 7.0f, 2.0f, 3.0f, 6.0f, 1.0f, 2.0f, 5.0f, 3.0f};
  const Vec3f a{1.0f, 2.0f, 3.0f};
  EXPECT_EQ(determinant(m), 9.0f);
  EXPECT_TRUE(isNear(inverse(m) * 9.0f, Mat33f{13.0f, -11.0f, -5.0f, -7.0f, 8.0f, 2.0f, 3.0f, -6.0f, 3.0f}, 1e-5f));
  EXPECT_TRUE(isNear(m * inverse(m), Mat33f::identity(), 1e-5f));
  EXPECT_EQ(m * a, (Vec3f{24.0f, 18.0f, 21.0f}));
  EXPECT_EQ(a * m, (Vec3f{16.0f, 34.0f, 13.0f}));
  EXPECT_THROW((void)inverse(Mat33f::zero()), Error);
  EXPECT_TRUE(isNear(rotationZ(pi<float> / 2.0f) * Vec3f::unitX(), Vec3f::unitY(), 1e-6f));
  EXPECT_TRUE(isNear(rotationX(pi<float> / 2.0f) * Vec3f::unitY(), Vec3f::unitZ(), 1e-6f));
  EXPECT_TRUE(isNear(rotationY(pi<float> / 2.0f) * Vec3f::unitZ(), Vec3f::unitX(), 1e-6f));
  EXPECT_TRUE(isNear(skew(a) * Vec3f{4.0f, 5.0f, 6.0f}, Vec3f{-3.0f, 6.0f, -3.0f}, 0.0f));
  const Mat33f r = orthonormalize(rotationZ(0.5f) + 1e-3f * outer(a, a));
  EXPECT_TRUE(isNear(r * transpose(r), Mat33f::identity(), 1e-5f));
}

TEST(Mat22f, float_inverse_and_solve_match_hand_values) {
  const Mat22f m{4.0f, 7.0f, 2.0f, 6.0f};
  EXPECT_EQ(determinant(m), 10.0f);
  EXPECT_TRUE(isNear(inverse(m), Mat22f{0.6f, -0.7f, -0.2f, 0.4f}, 1e-6f));
  EXPECT_TRUE(isNear(solve(m, Vec2f{18.0f, 14.0f}), Vec2f{1.0f, 2.0f}, 1e-5f));
  EXPECT_THROW((void)inverse(Mat22f{1.0f, 2.0f, 2.0f, 4.0f}), Error);
  EXPECT_TRUE(isNear(rotation22(pi<float> / 2.0f) * Vec2f(1.0f, 0.0f), Vec2f{0.0f, 1.0f}, 1e-6f));
}

} // namespace
} // namespace impetus
