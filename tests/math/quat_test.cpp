// Quat, EulerAngles, slerp and the quaternion derivative (appendix C): the spec's oracles,
// gimbal lock, the conversions between Euler angles, quaternions and matrices, and the quaternion
// identities over seeded random rotations.
#include "math_test_util.hpp"

#include <impetus/error.hpp>
#include <impetus/math/math.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

namespace impetus {
namespace {

using test::isNear;
using test::relativeAngle;
using test::sameRotation;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = pi<double>;

double deg(double degrees) { return degToRad(degrees); }

/// The appendix C oracle rotation: yaw 30, pitch 20, roll 10 degrees.
Quatd oracleQuat() { return Quatd::fromEuler(deg(30.0), deg(20.0), deg(10.0)); }

// ---------------------------------------------------------------------------------------------
// Scalar helpers (the book's DegreesToRadians and RadiansToDegrees, and nearlyEqual)

TEST(Scalar, degree_radian_conversions_match_hand_values) {
  EXPECT_DOUBLE_EQ(degToRad(180.0), kPi);
  EXPECT_DOUBLE_EQ(degToRad(-90.0), -kPi / 2.0);
  EXPECT_DOUBLE_EQ(radToDeg(kPi / 3.0), 60.0);
  EXPECT_DOUBLE_EQ(radToDeg(degToRad(35.8171)), 35.8171);
  EXPECT_FLOAT_EQ(degToRad(180.0f), pi<float>);
  EXPECT_FLOAT_EQ(radToDeg(pi<float> / 4.0f), 45.0f);
}

TEST(Scalar, nearly_equal_combines_absolute_and_relative_tolerance) {
  EXPECT_TRUE(nearlyEqual(1.0, 1.0 + 5e-7));  // within the absolute 1e-6 + relative 1e-6
  EXPECT_FALSE(nearlyEqual(1.0, 1.0 + 3e-6)); // 3e-6 > 1e-6 + 1e-6 * 1
  EXPECT_FALSE(nearlyEqual(0.0, 2e-6));
  EXPECT_TRUE(nearlyEqual(1e6, 1e6 + 0.5)); // relative part: 1e-6 * 1e6 = 1
  EXPECT_FALSE(nearlyEqual(1e6, 1e6 + 2.0));
  EXPECT_TRUE(nearlyEqual(1.0, 1.1, 0.2, 0.0));
  EXPECT_FALSE(nearlyEqual(kNaN, kNaN));
  EXPECT_TRUE(nearlyEqual(1.0f, 1.0f + 5e-7f));
}

// ---------------------------------------------------------------------------------------------
// Appendix C oracles

TEST(Quat, from_euler_matches_appendix_c_oracle) {
  const Quatd q = oracleQuat();
  EXPECT_NEAR(q.w, 0.9515485246, 1e-9);
  EXPECT_NEAR(q.x, 0.0381345765, 1e-9);
  EXPECT_NEAR(q.y, 0.1893078574, 1e-9);
  EXPECT_NEAR(q.z, 0.2392983377, 1e-9);
  EXPECT_NEAR(length(q), 1.0, 1e-14);
}

TEST(Quat, to_euler_round_trips_appendix_c_oracle) {
  const EulerAnglesd e = toEuler(oracleQuat());
  EXPECT_NEAR(radToDeg(e.yaw), 30.0, 1e-9);
  EXPECT_NEAR(radToDeg(e.pitch), 20.0, 1e-9);
  EXPECT_NEAR(radToDeg(e.roll), 10.0, 1e-9);
}

TEST(Quat, rotate_matches_appendix_c_oracle) {
  // The spec gives 7 decimals, so its own rounding is up to 5e-8.
  EXPECT_TRUE(isNear(rotate(oracleQuat(), Vec3d::unitX()), Vec3d{0.8137977, 0.4698463, -0.3420201}, 1e-7));
}

TEST(Quat, angle_and_axis_match_appendix_c_oracle) {
  const Quatd q = oracleQuat();
  EXPECT_NEAR(radToDeg(angle(q)), 35.8171, 1e-4);
  EXPECT_TRUE(isNear(axis(q), Vec3d{0.1240154, 0.6156381, 0.7782095}, 1e-7));
}

TEST(Quat, quarter_turn_about_z_rotates_x_to_y) {
  const double h = std::sqrt(0.5); // cos 45 = sin 45
  EXPECT_TRUE(isNear(rotate(Quatd{h, 0.0, 0.0, h}, Vec3d::unitX()), Vec3d::unitY(), 1e-14));
  EXPECT_TRUE(isNear(rotate(Quatd::fromAxisAngle(Vec3d::unitZ(), kPi / 2.0), Vec3d::unitX()), Vec3d::unitY(), 1e-14));
  EXPECT_TRUE(isNear(rotate(Quatd::fromEuler(kPi / 2.0, 0.0, 0.0), Vec3d::unitX()), Vec3d::unitY(), 1e-14));
}

TEST(Quat, hamilton_products_match_appendix_c_oracle) {
  // Small integers: exact.
  const Quatd a{1.0, 2.0, 3.0, 4.0};
  EXPECT_EQ(a * Quatd(5.0, 6.0, 7.0, 8.0), (Quatd{-60.0, 12.0, 30.0, 24.0}));
  EXPECT_EQ(a * Vec3d(5.0, 6.0, 7.0), (Quatd{-56.0, 2.0, 12.0, 4.0}));
  EXPECT_EQ(Vec3d(5.0, 6.0, 7.0) * a, (Quatd{-56.0, 8.0, 0.0, 10.0}));
  EXPECT_EQ(Quatd(5.0, 6.0, 7.0, 8.0) * a, (Quatd{-60.0, 20.0, 14.0, 32.0})); // not commutative
}

TEST(Quat, length_of_1_2_3_4_is_sqrt_30) {
  EXPECT_EQ(lengthSquared(Quatd{1.0, 2.0, 3.0, 4.0}), 30.0);
  EXPECT_DOUBLE_EQ(length(Quatd{1.0, 2.0, 3.0, 4.0}), std::sqrt(30.0));
  EXPECT_NEAR(length(Quatd{1.0, 2.0, 3.0, 4.0}), 5.4772256, 5e-8);
}

// ---------------------------------------------------------------------------------------------
// Basic algebra

TEST(Quat, constructor_takes_w_first_and_default_is_zero) {
  const Quatd q{1.0, 2.0, 3.0, 4.0};
  EXPECT_EQ(q.w, 1.0);
  EXPECT_EQ(q.scalar(), 1.0);
  EXPECT_EQ(q.vector(), (Vec3d{2.0, 3.0, 4.0}));
  EXPECT_EQ(Quatd(1.0, Vec3d{2.0, 3.0, 4.0}), q);
  EXPECT_EQ(Quatd{}, (Quatd{0.0, 0.0, 0.0, 0.0}));
  EXPECT_EQ(Quatd::identity(), (Quatd{1.0, 0.0, 0.0, 0.0}));
}

TEST(Quat, arithmetic_operators_are_component_wise_and_chain) {
  const Quatd a{1.0, 2.0, 3.0, 4.0};
  const Quatd b{5.0, 6.0, 7.0, 8.0};
  EXPECT_EQ(a + b, (Quatd{6.0, 8.0, 10.0, 12.0}));
  EXPECT_EQ(b - a, (Quatd{4.0, 4.0, 4.0, 4.0}));
  EXPECT_EQ(-a, (Quatd{-1.0, -2.0, -3.0, -4.0}));
  EXPECT_EQ(2.0 * a, (Quatd{2.0, 4.0, 6.0, 8.0}));
  EXPECT_EQ(a * 2.0, 2.0 * a);
  EXPECT_EQ(a / 2.0, (Quatd{0.5, 1.0, 1.5, 2.0}));
  Quatd c = a;
  (c += b) += b; // the book returns copies here; Impetus returns references, so both apply
  EXPECT_EQ(c, (Quatd{11.0, 14.0, 17.0, 20.0}));
  (c -= b) *= 2.0;
  EXPECT_EQ(c, (Quatd{12.0, 16.0, 20.0, 24.0}));
  (c /= 4.0) -= a;
  EXPECT_EQ(c, (Quatd{2.0, 2.0, 2.0, 2.0}));
}

TEST(Quat, identity_is_neutral_for_product_and_rotation) {
  const Quatd a{1.0, 2.0, 3.0, 4.0};
  EXPECT_EQ(Quatd::identity() * a, a);
  EXPECT_EQ(a * Quatd::identity(), a);
  EXPECT_EQ(rotate(Quatd::identity(), Vec3d{1.0, -2.0, 3.0}), (Vec3d{1.0, -2.0, 3.0}));
  EXPECT_EQ(toMat33(Quatd::identity()), Mat33d::identity());
}

TEST(Quat, conjugate_normalize_and_inverse_match_hand_values) {
  const Quatd a{1.0, 2.0, 3.0, 4.0};
  EXPECT_EQ(conjugate(a), (Quatd{1.0, -2.0, -3.0, -4.0}));
  EXPECT_TRUE(isNear(normalize(a), a / std::sqrt(30.0), 1e-14));
  EXPECT_TRUE(isNear(inverse(a), Quatd{1.0, -2.0, -3.0, -4.0} / 30.0, 1e-14));
  EXPECT_TRUE(isNear(a * inverse(a), Quatd::identity(), 1e-14));
  EXPECT_TRUE(isNear(inverse(a) * a, Quatd::identity(), 1e-14));
}

TEST(Quat, normalize_of_zero_quaternion_returns_identity) {
  EXPECT_EQ(normalize(Quatd{}), Quatd::identity()); // documented choice: no direction, no rotation
}

TEST(Quat, inverse_of_zero_or_non_finite_quaternion_throws_error) {
  EXPECT_THROW((void)inverse(Quatd{}), Error);
  EXPECT_THROW((void)inverse(Quatd{kNaN, 0.0, 0.0, 0.0}), Error);
}

TEST(Quat, is_finite_rejects_nan_and_infinity) {
  EXPECT_TRUE(isFinite(oracleQuat()));
  EXPECT_FALSE(isFinite(Quatd{1.0, kNaN, 0.0, 0.0}));
  EXPECT_FALSE(isFinite(Quatd{1.0, 0.0, 0.0, kInf}));
}

// ---------------------------------------------------------------------------------------------
// Identities over seeded random unit quaternions. Components and rotated vectors are O(1) (or
// O(10) for vectors in [-10, 10]); 1e-14 is ~50 ulps of 1, above the rounding of a few products.

TEST(Quat, quaternion_times_inverse_is_identity) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Quatd q = rng.unitQuat();
    EXPECT_TRUE(isNear(q * inverse(q), Quatd::identity(), 1e-14)) << "case " << i;
    EXPECT_TRUE(isNear(q * conjugate(q), Quatd::identity(), 1e-14)) << "case " << i;
    // Non-unit quaternions too: inverse divides by |q|^2.
    const Quatd p = q * rng.uniform(0.1, 10.0);
    EXPECT_TRUE(isNear(p * inverse(p), Quatd::identity(), 1e-14)) << "case " << i;
    EXPECT_TRUE(isNear(inverse(p) * p, Quatd::identity(), 1e-14)) << "case " << i;
  }
}

TEST(Quat, conjugate_of_product_is_reversed_product_of_conjugates) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Quatd p = rng.unitQuat();
    const Quatd q = rng.unitQuat();
    EXPECT_TRUE(isNear(conjugate(p * q), conjugate(q) * conjugate(p), 1e-14)) << "case " << i;
  }
}

TEST(Quat, hamilton_product_is_associative_and_preserves_unit_length) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Quatd a = rng.unitQuat();
    const Quatd b = rng.unitQuat();
    const Quatd c = rng.unitQuat();
    EXPECT_TRUE(isNear((a * b) * c, a * (b * c), 1e-14)) << "case " << i;
    EXPECT_NEAR(length(a * b), 1.0, 1e-14) << "case " << i;
  }
}

TEST(Quat, rotation_matrix_is_orthonormal_with_determinant_plus_one) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    // The random q is unit only to an ulp or two, and R R^T = |q|^4 I, so allow ~20 ulps of 1.
    const Mat33d r = toMat33(rng.unitQuat());
    EXPECT_TRUE(isNear(r * transpose(r), Mat33d::identity(), 5e-15)) << "case " << i;
    EXPECT_TRUE(isNear(transpose(r) * r, Mat33d::identity(), 5e-15)) << "case " << i;
    EXPECT_NEAR(determinant(r), 1.0, 5e-15) << "case " << i;
  }
}

TEST(Quat, rotate_agrees_with_matrix_and_with_sandwich_product) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Quatd q = rng.unitQuat();
    const Vec3d a = rng.vec3();
    const Vec3d r = rotate(q, a);
    EXPECT_TRUE(isNear(r, toMat33(q) * a, 1e-13)) << "case " << i;
    const Quatd sandwich = q * a * conjugate(q); // vector part of q [0, a] q*
    EXPECT_TRUE(isNear(r, sandwich.vector(), 1e-13)) << "case " << i;
    EXPECT_NEAR(sandwich.w, 0.0, 1e-13) << "case " << i;
    EXPECT_NEAR(length(r), length(a), 1e-13) << "case " << i; // rotations keep lengths
  }
}

TEST(Quat, inverse_rotate_undoes_rotate) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Quatd q = rng.unitQuat();
    const Vec3d a = rng.vec3();
    EXPECT_TRUE(isNear(inverseRotate(q, rotate(q, a)), a, 1e-13)) << "case " << i;
    EXPECT_TRUE(isNear(rotate(q, inverseRotate(q, a)), a, 1e-13)) << "case " << i;
    EXPECT_TRUE(isNear(inverseRotate(q, a), transpose(toMat33(q)) * a, 1e-13)) << "case " << i;
  }
}

TEST(Quat, product_composes_rotations_right_to_left) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Quatd p = rng.unitQuat();
    const Quatd q = rng.unitQuat();
    const Vec3d a = rng.vec3();
    EXPECT_TRUE(isNear(rotate(p * q, a), rotate(p, rotate(q, a)), 1e-13)) << "case " << i;
    EXPECT_TRUE(isNear(toMat33(p * q), toMat33(p) * toMat33(q), 1e-14)) << "case " << i;
  }
}

TEST(Quat, negated_quaternion_is_the_same_rotation) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Quatd q = rng.unitQuat();
    EXPECT_TRUE(isNear(toMat33(-q), toMat33(q), 0.0)) << "case " << i; // products of pairs: exact
    // angle() reports theta for q and 2 pi - theta for -q.
    EXPECT_NEAR(angle(-q), 2.0 * kPi - angle(q), 1e-12) << "case " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Axis-angle

TEST(Quat, from_axis_angle_matches_single_axis_rotation_matrices) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const double theta = rng.uniform(-2.0 * kPi, 2.0 * kPi);
    EXPECT_TRUE(isNear(toMat33(Quatd::fromAxisAngle(Vec3d::unitX(), theta)), rotationX(theta), 1e-14)) << i;
    EXPECT_TRUE(isNear(toMat33(Quatd::fromAxisAngle(Vec3d::unitY(), theta)), rotationY(theta), 1e-14)) << i;
    EXPECT_TRUE(isNear(toMat33(Quatd::fromAxisAngle(Vec3d::unitZ(), theta)), rotationZ(theta), 1e-14)) << i;
  }
}

TEST(Quat, from_axis_angle_normalizes_the_axis_and_round_trips_angle_and_axis) {
  EXPECT_TRUE(
      isNear(Quatd::fromAxisAngle(Vec3d{0.0, 0.0, 5.0}, 0.8), Quatd::fromAxisAngle(Vec3d::unitZ(), 0.8), 1e-14));
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Vec3d n = rng.unitVec3();
    const double theta = rng.uniform(0.01, 2.0 * kPi - 0.01);
    const Quatd q = Quatd::fromAxisAngle(n * rng.uniform(0.01, 100.0), theta);
    EXPECT_NEAR(length(q), 1.0, 1e-14) << "case " << i;
    // angle() is 2 acos(w): acos loses accuracy as w nears +-1 (theta near 0 or 2 pi), by
    // about eps / sin(theta / 2) <= 2e-14 in this range.
    EXPECT_NEAR(angle(q), theta, 1e-12) << "case " << i;
    EXPECT_TRUE(isNear(axis(q), n, 1e-14)) << "case " << i;
    // The axis is the rotation's fixed line.
    EXPECT_TRUE(isNear(rotate(q, n), n, 1e-14)) << "case " << i;
  }
}

TEST(Quat, from_axis_angle_with_zero_or_non_finite_axis_throws_error) {
  EXPECT_THROW((void)Quatd::fromAxisAngle(Vec3d::zero(), 1.0), Error);
  EXPECT_THROW((void)Quatd::fromAxisAngle(Vec3d{kNaN, 0.0, 1.0}, 1.0), Error);
  EXPECT_THROW((void)Quatd::fromAxisAngle(Vec3d{0.0, kInf, 0.0}, 1.0), Error);
  EXPECT_THROW((void)Quatd::fromAxisAngle(Vec3d::unitX(), kNaN), Error);
  EXPECT_THROW((void)Quatf::fromAxisAngle(Vec3f::zero(), 1.0f), Error);
}

// A finite axis longer than ~1.3e154 has sqrt(dot(axis, axis)) = inf; fromAxisAngle and
// normalize(Quat) must scale instead of overflowing (regression: they used to throw / return 0).
TEST(Quat, huge_finite_axis_and_quaternion_normalize_without_overflow) {
  EXPECT_NO_THROW((void)Quatd::fromAxisAngle(Vec3d{0.0, 0.0, 1e200}, 0.8));
  try {
    EXPECT_TRUE(
        isNear(Quatd::fromAxisAngle(Vec3d{0.0, 0.0, 1e200}, 0.8), Quatd::fromAxisAngle(Vec3d::unitZ(), 0.8), 1e-14));
  } catch (const Error& e) {
    ADD_FAILURE() << e.what();
  }
  EXPECT_TRUE(isNear(normalize(Quatd{1e200, 0.0, 0.0, 1e200}), Quatd{std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)}, 1e-14));
  EXPECT_TRUE(isNear(normalize(Quatf{2e19f, 0.0f, 0.0f, 0.0f}), Quatf::identity(), 1e-6f));
}

TEST(Quat, angle_of_identity_is_zero_and_axis_is_zero_vector) {
  EXPECT_EQ(angle(Quatd::identity()), 0.0);
  EXPECT_EQ(axis(Quatd::identity()), Vec3d::zero());
  // w rounded just above 1 must give 0, not NaN from acos.
  EXPECT_EQ(angle(Quatd{std::nextafter(1.0, 2.0), 0.0, 0.0, 0.0}), 0.0);
  EXPECT_NEAR(angle(Quatd{-std::nextafter(1.0, 2.0), 0.0, 0.0, 0.0}), 2.0 * kPi, 1e-14);
}

// ---------------------------------------------------------------------------------------------
// Matrix to quaternion (Shepperd)

TEST(Quat, from_mat33_of_to_mat33_recovers_quaternion_up_to_sign) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Quatd q = rng.unitQuat();
    const Quatd back = Quatd::fromMat33(toMat33(q));
    EXPECT_NEAR(std::abs(dot(back, q)), 1.0, 1e-14) << "case " << i;
    EXPECT_TRUE(sameRotation(back, q, 1e-14)) << "case " << i;
  }
}

TEST(Quat, from_mat33_handles_half_turns_on_every_shepperd_branch) {
  const double h = std::sqrt(0.5);
  // 180 degrees about x, y, z, (1,1,0)/sqrt2: trace -1, so w = 0 and each pivot x, y, z is used.
  const std::array<Quatd, 5> halfTurns{Quatd{0.0, 1.0, 0.0, 0.0}, Quatd{0.0, 0.0, 1.0, 0.0}, Quatd{0.0, 0.0, 0.0, 1.0},
                                       Quatd{0.0, h, h, 0.0}, Quatd{0.0, 0.0, h, -h}};
  for (const Quatd& q : halfTurns) {
    const Quatd back = Quatd::fromMat33(toMat33(q));
    EXPECT_NEAR(std::abs(dot(back, q)), 1.0, 1e-14) << ::testing::PrintToString(q);
    EXPECT_TRUE(sameRotation(back, q, 1e-14));
  }
  // The same half turns from the single-axis matrices (whose sin(pi) is 1.2e-16, not 0).
  EXPECT_TRUE(sameRotation(Quatd::fromMat33(rotationX(kPi)), Quatd{0.0, 1.0, 0.0, 0.0}, 1e-14));
  EXPECT_TRUE(sameRotation(Quatd::fromMat33(rotationY(kPi)), Quatd{0.0, 0.0, 1.0, 0.0}, 1e-14));
  EXPECT_TRUE(sameRotation(Quatd::fromMat33(rotationZ(kPi)), Quatd{0.0, 0.0, 0.0, 1.0}, 1e-14));
  EXPECT_TRUE(sameRotation(Quatd::fromMat33(Mat33d::diagonal({-1.0, -1.0, 1.0})), Quatd{0.0, 0.0, 0.0, 1.0}, 0.0));
}

TEST(Quat, from_mat33_is_accurate_near_half_turns_about_random_axes) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Quatd q = Quatd::fromAxisAngle(rng.unitVec3(), kPi - 1e-9 * rng.uniform(-1.0, 1.0));
    EXPECT_TRUE(sameRotation(Quatd::fromMat33(toMat33(q)), q, 1e-14)) << "case " << i;
  }
}

TEST(Quat, from_mat33_of_rotation_matrices_matches_axis_angle) {
  EXPECT_EQ(Quatd::fromMat33(Mat33d::identity()), Quatd::identity());
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const double theta = rng.uniform(-kPi, kPi);
    EXPECT_TRUE(sameRotation(Quatd::fromMat33(rotationX(theta)), Quatd::fromAxisAngle(Vec3d::unitX(), theta), 1e-14));
    EXPECT_TRUE(sameRotation(Quatd::fromMat33(rotationY(theta)), Quatd::fromAxisAngle(Vec3d::unitY(), theta), 1e-14));
    EXPECT_TRUE(sameRotation(Quatd::fromMat33(rotationZ(theta)), Quatd::fromAxisAngle(Vec3d::unitZ(), theta), 1e-14));
  }
}

TEST(Quat, from_mat33_of_non_finite_matrix_throws_error) {
  Mat33d m = Mat33d::identity();
  m(0, 2) = kNaN;
  EXPECT_THROW((void)Quatd::fromMat33(m), Error);
}

// ---------------------------------------------------------------------------------------------
// Euler angles

TEST(Quat, from_euler_equals_yaw_then_pitch_then_roll_products) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const double yaw = rng.uniform(-kPi, kPi);
    const double pitch = rng.uniform(-kPi / 2.0, kPi / 2.0);
    const double roll = rng.uniform(-kPi, kPi);
    const Quatd q = Quatd::fromEuler(yaw, pitch, roll);
    const Quatd product = Quatd::fromAxisAngle(Vec3d::unitZ(), yaw) * Quatd::fromAxisAngle(Vec3d::unitY(), pitch) *
                          Quatd::fromAxisAngle(Vec3d::unitX(), roll);
    EXPECT_TRUE(isNear(q, product, 1e-14)) << "case " << i;
    EXPECT_TRUE(isNear(toMat33(q), rotationZ(yaw) * rotationY(pitch) * rotationX(roll), 1e-14)) << "case " << i;
  }
}

TEST(Quat, single_euler_angles_rotate_about_z_y_x) {
  EXPECT_TRUE(isNear(Quatd::fromEuler(0.7, 0.0, 0.0), Quatd::fromAxisAngle(Vec3d::unitZ(), 0.7), 1e-14));
  EXPECT_TRUE(isNear(Quatd::fromEuler(0.0, 0.7, 0.0), Quatd::fromAxisAngle(Vec3d::unitY(), 0.7), 1e-14));
  EXPECT_TRUE(isNear(Quatd::fromEuler(0.0, 0.0, 0.7), Quatd::fromAxisAngle(Vec3d::unitX(), 0.7), 1e-14));
}

TEST(Quat, euler_to_quat_to_euler_round_trips_away_from_gimbal_lock) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const double yaw = rng.uniform(-kPi, kPi);
    const double pitch = rng.uniform(-kPi / 2.0, kPi / 2.0);
    const double roll = rng.uniform(-kPi, kPi);
    const EulerAnglesd e = toEuler(Quatd::fromEuler(yaw, pitch, roll));
    // Pitch comes from a well-conditioned atan2. Yaw and roll come from atan2 of matrix terms
    // of size cos(pitch) with absolute rounding ~1e-16, so their error grows like
    // 1e-16 / cos(pitch): the tolerance follows that conditioning.
    const double tol = 1e-14 + 1e-15 / std::cos(pitch);
    EXPECT_NEAR(e.pitch, pitch, 1e-14) << "case " << i;
    EXPECT_NEAR(test::angleDiff(e.yaw, yaw), 0.0, tol) << "case " << i;
    EXPECT_NEAR(test::angleDiff(e.roll, roll), 0.0, tol) << "case " << i;
  }
}

TEST(Quat, quat_to_euler_to_quat_gives_the_same_rotation) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Quatd q = rng.unitQuat();
    const EulerAnglesd e = toEuler(q);
    EXPECT_LE(std::abs(e.pitch), kPi / 2.0) << "case " << i;
    EXPECT_LE(std::abs(e.yaw), kPi) << "case " << i;
    EXPECT_LE(std::abs(e.roll), kPi) << "case " << i;
    // Error ~1e-16 / cos(pitch), as above; uniform random rotations have cos(pitch) > 1e-3
    // except with probability ~1e-6 per case.
    EXPECT_TRUE(sameRotation(Quatd::fromEuler(e.yaw, e.pitch, e.roll), q, 1e-12)) << "case " << i;
  }
}

TEST(Quat, euler_round_trip_holds_at_gimbal_lock) {
  const EulerAnglesd e = toEuler(Quatd::fromEuler(deg(30.0), deg(90.0), 0.0));
  EXPECT_NEAR(radToDeg(e.yaw), 30.0, 1e-9);
  EXPECT_NEAR(radToDeg(e.pitch), 90.0, 1e-9);
  EXPECT_NEAR(radToDeg(e.roll), 0.0, 1e-9);
}

TEST(Quat, gimbal_lock_at_plus_90_pitch_keeps_yaw_minus_roll) {
  // Appendix C: only yaw - roll survives at pitch +90, and roll is reported as 0.
  const EulerAnglesd e = toEuler(Quatd::fromEuler(deg(30.0), deg(90.0), deg(15.0)));
  EXPECT_NEAR(radToDeg(e.yaw), 15.0, 1e-9);
  EXPECT_NEAR(radToDeg(e.pitch), 90.0, 1e-9);
  EXPECT_NEAR(radToDeg(e.roll), 0.0, 1e-9);
}

TEST(Quat, gimbal_lock_at_minus_90_pitch_keeps_yaw_plus_roll) {
  // R = Rz(yaw) Ry(-90) Rx(roll) depends on yaw + roll only.
  const EulerAnglesd e = toEuler(Quatd::fromEuler(deg(30.0), deg(-90.0), deg(15.0)));
  EXPECT_NEAR(radToDeg(e.yaw), 45.0, 1e-9);
  EXPECT_NEAR(radToDeg(e.pitch), -90.0, 1e-9);
  EXPECT_NEAR(radToDeg(e.roll), 0.0, 1e-9);
}

TEST(Quat, from_euler_of_to_euler_preserves_rotation_at_gimbal_lock) {
  const std::array<Quatd, 4> locked{
      Quatd::fromEuler(deg(30.0), deg(90.0), 0.0), Quatd::fromEuler(deg(30.0), deg(90.0), deg(15.0)),
      Quatd::fromEuler(deg(30.0), deg(-90.0), deg(15.0)), Quatd::fromEuler(deg(-170.0), deg(-90.0), deg(120.0))};
  for (const Quatd& q : locked) {
    const EulerAnglesd e = toEuler(q);
    const Quatd back = Quatd::fromEuler(e.yaw, e.pitch, e.roll);
    EXPECT_TRUE(isNear(toMat33(back), toMat33(q), 1e-14)) << ::testing::PrintToString(e);
    EXPECT_TRUE(sameRotation(back, q, 1e-14)) << ::testing::PrintToString(e);
  }
}

TEST(Quat, from_euler_of_to_euler_preserves_rotation_near_gimbal_lock) {
  // Either branch of toEuler loses accuracy next to gimbal lock: the regular one by
  // ~1e-16 / cos(pitch), the gimbal one by ~cos(pitch). They switch at cos(pitch) = sqrt(eps)
  // = 1.5e-8, so the worst error is ~1.5e-8; 1e-7 leaves margin and still catches any wrong
  // sign or dropped term, which would be O(1).
  test::Random rng;
  for (const double offset : {1e-2, 1e-4, 1e-6, 1e-7, 1e-8, 2e-8, 1e-9, 1e-12, 0.0}) {
    for (const double sign : {1.0, -1.0}) {
      for (int i = 0; i < 20; ++i) {
        const Quatd q = Quatd::fromEuler(rng.uniform(-kPi, kPi), sign * (kPi / 2.0 - offset), rng.uniform(-kPi, kPi));
        const EulerAnglesd e = toEuler(q);
        EXPECT_TRUE(isNear(toMat33(Quatd::fromEuler(e.yaw, e.pitch, e.roll)), toMat33(q), 1e-7))
            << "offset " << offset << " sign " << sign << " case " << i;
        EXPECT_NEAR(e.pitch, sign * (kPi / 2.0 - offset), 1e-7) << "offset " << offset << " case " << i;
      }
    }
  }
}

TEST(Quat, euler_matrix_quaternion_round_trip_is_consistent) {
  // Euler -> matrix -> quaternion -> Euler, through Shepperd rather than fromEuler.
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const double yaw = rng.uniform(-kPi, kPi);
    const double pitch = rng.uniform(-1.5, 1.5); // cos(pitch) >= 0.07
    const double roll = rng.uniform(-kPi, kPi);
    const Quatd q = Quatd::fromMat33(rotationZ(yaw) * rotationY(pitch) * rotationX(roll));
    EXPECT_TRUE(sameRotation(q, Quatd::fromEuler(yaw, pitch, roll), 1e-14)) << "case " << i;
    const EulerAnglesd e = toEuler(q);
    EXPECT_NEAR(test::angleDiff(e.yaw, yaw), 0.0, 1e-13) << "case " << i;
    EXPECT_NEAR(e.pitch, pitch, 1e-13) << "case " << i;
    EXPECT_NEAR(test::angleDiff(e.roll, roll), 0.0, 1e-13) << "case " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// slerp

TEST(Quat, slerp_endpoints_equal_inputs) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Quatd a = rng.unitQuat();
    const Quatd b = rng.unitQuat();
    EXPECT_TRUE(isNear(slerp(a, b, 0.0), a, 1e-14)) << "case " << i;
    // b may come back as -b: slerp takes the shorter arc, which may flip b's sign.
    EXPECT_TRUE(sameRotation(slerp(a, b, 1.0), b, 1e-14)) << "case " << i;
  }
}

TEST(Quat, slerp_moves_at_constant_angular_rate) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Quatd a = rng.unitQuat();
    const Quatd b = rng.unitQuat();
    const double total = relativeAngle(a, b); // in [0, pi]: the shorter arc
    for (const double t : {0.25, 0.5, 0.75}) {
      const Quatd s = slerp(a, b, t);
      EXPECT_NEAR(length(s), 1.0, 1e-14) << "case " << i;
      EXPECT_NEAR(relativeAngle(a, s), t * total, 1e-14) << "case " << i << " t " << t;
      EXPECT_NEAR(relativeAngle(s, b), (1.0 - t) * total, 1e-14) << "case " << i << " t " << t;
    }
  }
}

TEST(Quat, slerp_halfway_has_half_the_angle_about_the_same_axis) {
  const Quatd a = Quatd::identity();
  const Quatd b = Quatd::fromAxisAngle(Vec3d{1.0, 2.0, 2.0}, 1.2);
  EXPECT_TRUE(sameRotation(slerp(a, b, 0.5), Quatd::fromAxisAngle(Vec3d{1.0, 2.0, 2.0}, 0.6), 1e-14));
  EXPECT_TRUE(sameRotation(slerp(a, b, 0.25), Quatd::fromAxisAngle(Vec3d{1.0, 2.0, 2.0}, 0.3), 1e-14));
}

TEST(Quat, slerp_takes_the_shorter_arc) {
  // +270 degrees about z is the same rotation as -90 degrees; halfway must be -45, not +135.
  const Quatd a = Quatd::identity();
  const Quatd b = Quatd::fromAxisAngle(Vec3d::unitZ(), deg(270.0));
  ASSERT_LT(dot(a, b), 0.0);
  const Quatd expected = Quatd::fromAxisAngle(Vec3d::unitZ(), deg(-45.0));
  EXPECT_TRUE(sameRotation(slerp(a, b, 0.5), expected, 1e-14));
  EXPECT_TRUE(sameRotation(slerp(a, -b, 0.5), expected, 1e-14)); // sign of b does not matter
  const double h = std::sqrt(0.5);
  EXPECT_TRUE(isNear(rotate(slerp(a, b, 0.5), Vec3d::unitX()), Vec3d{h, -h, 0.0}, 1e-14));
}

TEST(Quat, slerp_of_nearly_identical_quaternions_is_unit_and_finite) {
  // Relative angles on both sides of slerp's switch to normalized lerp (1 - cos < 64 eps, an
  // angle of ~1.7e-7), down to identical inputs.
  test::Random rng;
  for (const double gap : {1e-3, 1e-5, 1e-6, 3e-7, 1.7e-7, 1e-7, 1e-8, 1e-10, 1e-13, 1e-16, 0.0}) {
    for (int i = 0; i < 20; ++i) {
      const Quatd a = rng.unitQuat();
      const Quatd b = gap == 0.0 ? a : a * Quatd::fromAxisAngle(rng.unitVec3(), gap);
      for (const double t : {0.0, 0.3, 0.5, 1.0}) {
        const Quatd s = slerp(a, b, t);
        ASSERT_TRUE(isFinite(s)) << "gap " << gap << " t " << t;
        EXPECT_NEAR(length(s), 1.0, 1e-14) << "gap " << gap << " t " << t;
        // Stays on the short arc between them: for such small angles, within rounding of t * gap.
        EXPECT_NEAR(relativeAngle(a, s), t * gap, 1e-15 + 1e-6 * gap) << "gap " << gap << " t " << t;
      }
    }
  }
  const Quatd q = oracleQuat();
  // Identical inputs take the normalized-lerp path: q / |q|, an ulp or two from q.
  EXPECT_TRUE(isNear(slerp(q, q, 0.5), q, 1e-14));
  EXPECT_TRUE(sameRotation(slerp(q, -q, 0.5), q, 1e-14));
}

// ---------------------------------------------------------------------------------------------
// Time derivative and integration

TEST(Quat, derivative_matches_hand_value_for_identity) {
  // 1/2 [1, 0] [0, w] = [0, w / 2].
  EXPECT_EQ(derivative(Quatd::identity(), Vec3d{2.0, 4.0, 6.0}), (Quatd{0.0, 1.0, 2.0, 3.0}));
  EXPECT_EQ(derivativeWorld(Quatd::identity(), Vec3d{2.0, 4.0, 6.0}), (Quatd{0.0, 1.0, 2.0, 3.0}));
  // Body frame multiplies on the right, world frame on the left: 1/2 q [0, w] vs 1/2 [0, w] q.
  const Quatd q{1.0, 2.0, 3.0, 4.0};
  EXPECT_EQ(derivative(q, Vec3d{10.0, 12.0, 14.0}), (Quatd{-56.0, 2.0, 12.0, 4.0}));
  EXPECT_EQ(derivativeWorld(q, Vec3d{10.0, 12.0, 14.0}), (Quatd{-56.0, 8.0, 0.0, 10.0}));
}

TEST(Quat, derivative_is_tangent_to_the_unit_sphere) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Quatd q = rng.unitQuat();
    const Vec3d omega = rng.vec3();
    EXPECT_NEAR(dot(q, derivative(q, omega)), 0.0, 1e-14) << "case " << i; // d|q|^2/dt = 0
    EXPECT_NEAR(dot(q, derivativeWorld(q, omega)), 0.0, 1e-14) << "case " << i;
  }
}

TEST(Quat, world_derivative_of_rotated_rate_equals_body_derivative) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Quatd q = rng.unitQuat();
    const Vec3d omegaBody = rng.vec3();
    const Vec3d omegaWorld = rotate(q, omegaBody);
    // Rates up to ~17 rad/s: 1e-13 is ~100 ulps of the result.
    EXPECT_TRUE(isNear(derivativeWorld(q, omegaWorld), derivative(q, omegaBody), 1e-13)) << "case " << i;
  }
}

/// One classical Runge-Kutta step of q' = f(q).
template <typename F> Quatd rk4Step(const Quatd& q, double dt, F f) {
  const Quatd k1 = f(q);
  const Quatd k2 = f(q + k1 * (dt / 2.0));
  const Quatd k3 = f(q + k2 * (dt / 2.0));
  const Quatd k4 = f(q + k3 * dt);
  return q + (k1 + 2.0 * k2 + 2.0 * k3 + k4) * (dt / 6.0);
}

TEST(Quat, rk4_with_body_rate_derivative_matches_closed_form_rotation) {
  // Constant body-frame rate: q(t) = q0 fromAxisAngle(w, |w| t). RK4 on this linear ODE errs
  // by (|w| dt / 2)^5 / 5! ~ 1e-17 per step, so the 1000 steps' rounding (~1e-13) dominates.
  const Quatd q0 = Quatd::fromEuler(0.4, -0.3, 1.2);
  const Vec3d omega{0.6, -1.2, 1.5}; // |w| = 2.01 rad/s
  const double dt = 1e-3;
  const int steps = 1000;
  Quatd q = q0;
  for (int i = 0; i < steps; ++i) {
    q = rk4Step(q, dt, [&](const Quatd& s) { return derivative(s, omega); });
  }
  const double t = dt * steps;
  const Quatd expected = q0 * Quatd::fromAxisAngle(omega, length(omega) * t);
  EXPECT_TRUE(isNear(q, expected, 1e-11));
  // The frame matters: the world-frame reading of the same rate ends far away.
  EXPECT_GT(test::rotationDiff(q, Quatd::fromAxisAngle(omega, length(omega) * t) * q0), 0.1);
}

TEST(Quat, rk4_with_world_rate_derivative_matches_closed_form_rotation) {
  // Constant world-frame rate: q(t) = fromAxisAngle(w, |w| t) q0.
  const Quatd q0 = Quatd::fromEuler(-2.0, 0.9, 0.3);
  const Vec3d omega{-1.0, 0.5, 2.0};
  const double dt = 1e-3;
  const int steps = 1000;
  Quatd q = q0;
  for (int i = 0; i < steps; ++i) {
    q = rk4Step(q, dt, [&](const Quatd& s) { return derivativeWorld(s, omega); });
  }
  const double t = dt * steps;
  EXPECT_TRUE(isNear(q, Quatd::fromAxisAngle(omega, length(omega) * t) * q0, 1e-11));
}

TEST(Quat, integrate_with_constant_body_rate_matches_closed_form_within_step_error) {
  // integrate() is q <- normalize(q (1, w dt / 2)): an exact turn about the body axis w by
  // 2 atan(|w| dt / 2) per step instead of |w| dt, i.e. short by (|w| dt)^3 / 12 per step. The
  // total angle error after n steps is n times that (here 6.8e-7 rad); a quaternion component
  // moves by at most half the angle error.
  const Quatd q0 = Quatd::fromEuler(0.4, -0.3, 1.2);
  const Vec3d omega{0.6, -1.2, 1.5};
  const double rate = length(omega);
  const double dt = 1e-3;
  const int steps = 1000;
  Quatd q = q0;
  for (int i = 0; i < steps; ++i) {
    q = integrate(q, omega, dt);
  }
  const double t = dt * steps;
  const double h = rate * dt;
  const double angleError = steps * (h - 2.0 * std::atan(h / 2.0));
  EXPECT_TRUE(isNear(q, q0 * Quatd::fromAxisAngle(omega, rate * t), 0.5 * angleError + 1e-12));
  // And exactly the discrete rotation it is meant to take, up to accumulated rounding.
  EXPECT_TRUE(isNear(q, q0 * Quatd::fromAxisAngle(omega, steps * 2.0 * std::atan(h / 2.0)), 1e-12));
  EXPECT_NEAR(length(q), 1.0, 1e-14);
}

// ---------------------------------------------------------------------------------------------
// float instantiations: ~7 significant digits, so 1e-5 on O(1) values (1e-6 where only a few
// roundings are involved).

TEST(Quatf, float_quaternion_operations_match_double_oracles) {
  const Quatf q = Quatf::fromEuler(degToRad(30.0f), degToRad(20.0f), degToRad(10.0f));
  EXPECT_TRUE(isNear(q, Quatf{0.9515485246f, 0.0381345765f, 0.1893078574f, 0.2392983377f}, 1e-6f));
  EXPECT_TRUE(isNear(rotate(q, Vec3f::unitX()), Vec3f{0.8137977f, 0.4698463f, -0.3420201f}, 1e-6f));
  EXPECT_NEAR(radToDeg(angle(q)), 35.8171f, 1e-3f); // acos near 1 amplifies float rounding
  EXPECT_TRUE(isNear(axis(q), Vec3f{0.1240154f, 0.6156381f, 0.7782095f}, 1e-5f));
  const EulerAnglesf e = toEuler(q);
  EXPECT_NEAR(radToDeg(e.yaw), 30.0f, 1e-4f);
  EXPECT_NEAR(radToDeg(e.pitch), 20.0f, 1e-4f);
  EXPECT_NEAR(radToDeg(e.roll), 10.0f, 1e-4f);
  const Mat33f r = toMat33(q);
  EXPECT_TRUE(isNear(r * transpose(r), Mat33f::identity(), 1e-6f));
  EXPECT_NEAR(determinant(r), 1.0f, 1e-6f);
  EXPECT_TRUE(sameRotation(Quatf::fromMat33(r), q, 1e-6f));
  EXPECT_TRUE(isNear(q * inverse(q), Quatf::identity(), 1e-6f));
  EXPECT_TRUE(isNear(inverseRotate(q, rotate(q, Vec3f{1.0f, 2.0f, 3.0f})), Vec3f{1.0f, 2.0f, 3.0f}, 1e-5f));
  const Quatf a{1.0f, 2.0f, 3.0f, 4.0f};
  EXPECT_EQ(a * Quatf(5.0f, 6.0f, 7.0f, 8.0f), (Quatf{-60.0f, 12.0f, 30.0f, 24.0f}));
  EXPECT_EQ(Vec3f(5.0f, 6.0f, 7.0f) * a, (Quatf{-56.0f, 8.0f, 0.0f, 10.0f}));
}

TEST(Quatf, float_gimbal_slerp_and_integration_work) {
  const EulerAnglesf e = toEuler(Quatf::fromEuler(degToRad(30.0f), degToRad(90.0f), degToRad(15.0f)));
  EXPECT_NEAR(radToDeg(e.yaw), 15.0f, 1e-3f);
  EXPECT_NEAR(radToDeg(e.pitch), 90.0f, 1e-3f);
  EXPECT_NEAR(e.roll, 0.0f, 1e-6f);
  const Quatf a = Quatf::identity();
  const Quatf b = Quatf::fromAxisAngle(Vec3f::unitZ(), 1.2f);
  EXPECT_TRUE(sameRotation(slerp(a, b, 0.5f), Quatf::fromAxisAngle(Vec3f::unitZ(), 0.6f), 1e-6f));
  EXPECT_TRUE(isFinite(slerp(b, b, 0.5f)));
  const Vec3f omega{0.0f, 0.0f, 2.0f};
  Quatf q = Quatf::identity();
  for (int i = 0; i < 100; ++i) {
    q = integrate(q, omega, 1e-3f);
  }
  // 100 steps of dt = 1e-3 at 2 rad/s: angle error ~ 100 (2e-3)^3 / 12 = 7e-8, below float rounding.
  EXPECT_TRUE(sameRotation(q, Quatf::fromAxisAngle(Vec3f::unitZ(), 0.2f), 1e-5f));
  EXPECT_TRUE(isNear(derivativeWorld(q, rotate(q, omega)), derivative(q, omega), 1e-6f));
}

} // namespace
} // namespace impetus
