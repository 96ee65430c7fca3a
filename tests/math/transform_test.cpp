// Rot2, Transform2 and Transform3: hand-computed values, and the composition and inverse identities
// over seeded random rotations and translations.
#include "math_test_util.hpp"

#include <impetus/math/math.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace impetus {
namespace {

using test::isNear;
using test::sameRotation;

constexpr double kPi = pi<double>;

Rot2d randomRot2(test::Random& rng) { return Rot2d::fromAngle(rng.uniform(-kPi, kPi)); }
Transform2d randomTransform2(test::Random& rng) { return {rng.vec2(), randomRot2(rng)}; }
Transform3d randomTransform3(test::Random& rng) { return {rng.vec3(), rng.unitQuat()}; }

// Points and translations are in [-10, 10] and composed transforms move them up to ~40 away from
// the origin, so 1e-13 is ~20 ulps of the largest coordinates: a few roundings per rotation.
constexpr double kPointTol = 1e-13;

// ---------------------------------------------------------------------------------------------
// Rot2

TEST(Rot2, default_and_identity_are_the_zero_rotation) {
  EXPECT_EQ(Rot2d{}, Rot2d::identity());
  EXPECT_EQ(Rot2d::identity().c, 1.0);
  EXPECT_EQ(Rot2d::identity().s, 0.0);
  EXPECT_EQ(Rot2d::identity().angle(), 0.0);
  EXPECT_EQ(rotate(Rot2d::identity(), Vec2d(3.0, -4.0)), (Vec2d{3.0, -4.0}));
}

TEST(Rot2, quarter_turn_rotates_x_to_y_counter_clockwise) {
  const Rot2d r = Rot2d::fromAngle(kPi / 2.0);
  EXPECT_TRUE(isNear(rotate(r, Vec2d{1.0, 0.0}), Vec2d{0.0, 1.0}, 1e-14));
  EXPECT_TRUE(isNear(rotate(r, Vec2d{0.0, 1.0}), Vec2d{-1.0, 0.0}, 1e-14));
  EXPECT_TRUE(isNear(inverseRotate(r, Vec2d{0.0, 1.0}), Vec2d{1.0, 0.0}, 1e-14));
}

TEST(Rot2, from_angle_then_angle_round_trips_over_minus_pi_to_pi) {
  // atan2(sin a, cos a) = a to within an ulp or two of a (|a| <= pi), well inside 1e-14.
  for (const double a : {kPi, kPi - 1e-9, kPi / 2.0, 1.0, 1e-300, 0.0, -1e-9, -kPi / 2.0, -3.0, -kPi + 1e-9}) {
    EXPECT_NEAR(Rot2d::fromAngle(a).angle(), a, 1e-14) << "angle " << a;
  }
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const double a = rng.uniform(-kPi, kPi);
    EXPECT_NEAR(Rot2d::fromAngle(a).angle(), a, 1e-14) << "case " << i;
  }
}

TEST(Rot2, angle_wraps_into_minus_pi_to_pi) {
  EXPECT_NEAR(Rot2d::fromAngle(1.5 * kPi).angle(), -0.5 * kPi, 1e-14);
  EXPECT_NEAR(Rot2d::fromAngle(-1.5 * kPi).angle(), 0.5 * kPi, 1e-14);
  EXPECT_NEAR(Rot2d::fromAngle(2.0 * kPi + 0.25).angle(), 0.25, 1e-14);
}

TEST(Rot2, rotate_and_inverse_rotate_undo_each_other) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Rot2d r = randomRot2(rng);
    const Vec2d v = rng.vec2();
    EXPECT_TRUE(isNear(inverseRotate(r, rotate(r, v)), v, kPointTol)) << "case " << i;
    EXPECT_TRUE(isNear(rotate(r, inverseRotate(r, v)), v, kPointTol)) << "case " << i;
    EXPECT_NEAR(length(rotate(r, v)), length(v), kPointTol) << "case " << i;
  }
}

TEST(Rot2, rotate_agrees_with_rotation_matrices) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const double a = rng.uniform(-kPi, kPi);
    const Rot2d r = Rot2d::fromAngle(a);
    const Vec2d v = rng.vec2();
    EXPECT_TRUE(isNear(r.toMat22(), rotation22(a), 0.0)) << "case " << i; // same cos and sin
    EXPECT_TRUE(isNear(rotate(r, v), r.toMat22() * v, kPointTol)) << "case " << i;
    EXPECT_TRUE(isNear(inverseRotate(r, v), transpose(r.toMat22()) * v, kPointTol)) << "case " << i;
    // The plane rotation is the 3D rotation about z.
    const Vec3d v3 = rotationZ(a) * Vec3d{v.x, v.y, 0.0};
    EXPECT_TRUE(isNear(rotate(r, v), Vec2d{v3.x, v3.y}, kPointTol)) << "case " << i;
  }
}

TEST(Rot2, mul_adds_angles_and_inv_mul_subtracts_them) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const double a = rng.uniform(-kPi, kPi);
    const double b = rng.uniform(-kPi, kPi);
    const Rot2d ra = Rot2d::fromAngle(a);
    const Rot2d rb = Rot2d::fromAngle(b);
    EXPECT_NEAR(test::angleDiff(mul(ra, rb).angle(), a + b), 0.0, 1e-14) << "case " << i;
    EXPECT_NEAR(test::angleDiff(invMul(ra, rb).angle(), b - a), 0.0, 1e-14) << "case " << i;
    const Vec2d v = rng.vec2();
    EXPECT_TRUE(isNear(rotate(mul(ra, rb), v), rotate(ra, rotate(rb, v)), kPointTol)) << "case " << i;
    EXPECT_TRUE(isNear(rotate(invMul(ra, rb), v), inverseRotate(ra, rotate(rb, v)), kPointTol)) << "case " << i;
    EXPECT_TRUE(isNear(invMul(ra, ra), Rot2d::identity(), 1e-14)) << "case " << i;
  }
}

TEST(Rot2, normalize_rescales_drifted_rotation_and_maps_zero_to_identity) {
  EXPECT_TRUE(isNear(normalize(Rot2d{1.2, 1.6}), Rot2d{0.6, 0.8}, 1e-14));
  EXPECT_EQ(normalize(Rot2d{0.0, 0.0}), Rot2d::identity());
  const Rot2d r = normalize(Rot2d{-3.0, 4.0});
  EXPECT_NEAR(std::hypot(r.c, r.s), 1.0, 1e-14);
  EXPECT_NEAR(r.angle(), std::atan2(4.0, -3.0), 1e-14);
}

// ---------------------------------------------------------------------------------------------
// Transform2

TEST(Transform2, transform_point_matches_hand_value) {
  const Transform2d t{{1.0, 2.0}, Rot2d::fromAngle(kPi / 2.0)};
  // (1, 0) turns to (0, 1), then moves by (1, 2).
  EXPECT_TRUE(isNear(transformPoint(t, Vec2d{1.0, 0.0}), Vec2d{1.0, 3.0}, 1e-14));
  EXPECT_TRUE(isNear(inverseTransformPoint(t, Vec2d{1.0, 3.0}), Vec2d{1.0, 0.0}, 1e-14));
  EXPECT_EQ(transformPoint(Transform2d::identity(), Vec2d(5.0, -6.0)), (Vec2d{5.0, -6.0}));
  EXPECT_EQ(Transform2d{}, Transform2d::identity());
}

TEST(Transform2, mul_composes_transforms_right_to_left) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Transform2d a = randomTransform2(rng);
    const Transform2d b = randomTransform2(rng);
    const Vec2d v = rng.vec2();
    EXPECT_TRUE(isNear(transformPoint(mul(a, b), v), transformPoint(a, transformPoint(b, v)), kPointTol))
        << "case " << i;
  }
}

TEST(Transform2, inverse_undoes_transform) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Transform2d t = randomTransform2(rng);
    const Vec2d v = rng.vec2();
    EXPECT_TRUE(isNear(transformPoint(inverse(t), transformPoint(t, v)), v, kPointTol)) << "case " << i;
    EXPECT_TRUE(isNear(transformPoint(t, transformPoint(inverse(t), v)), v, kPointTol)) << "case " << i;
    EXPECT_TRUE(isNear(inverseTransformPoint(t, v), transformPoint(inverse(t), v), kPointTol)) << "case " << i;
    const Transform2d shouldBeIdentity = mul(t, inverse(t));
    EXPECT_TRUE(isNear(shouldBeIdentity.p, Vec2d::zero(), kPointTol)) << "case " << i;
    EXPECT_TRUE(isNear(shouldBeIdentity.q, Rot2d::identity(), 1e-14)) << "case " << i;
  }
}

TEST(Transform2, inv_mul_equals_mul_by_inverse) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Transform2d a = randomTransform2(rng);
    const Transform2d b = randomTransform2(rng);
    const Vec2d v = rng.vec2();
    EXPECT_TRUE(isNear(transformPoint(invMul(a, b), v), transformPoint(mul(inverse(a), b), v), kPointTol))
        << "case " << i;
    EXPECT_TRUE(isNear(transformPoint(invMul(a, b), v), inverseTransformPoint(a, transformPoint(b, v)), kPointTol))
        << "case " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Transform3

TEST(Transform3, transform_point_matches_hand_value) {
  const Transform3d t{{1.0, 2.0, 3.0}, Quatd::fromAxisAngle(Vec3d::unitZ(), kPi / 2.0)};
  // (1, 0, 0) turns to (0, 1, 0), then moves by (1, 2, 3).
  EXPECT_TRUE(isNear(transformPoint(t, Vec3d{1.0, 0.0, 0.0}), Vec3d{1.0, 3.0, 3.0}, 1e-14));
  EXPECT_TRUE(isNear(inverseTransformPoint(t, Vec3d{1.0, 3.0, 3.0}), Vec3d{1.0, 0.0, 0.0}, 1e-14));
  EXPECT_EQ(transformPoint(Transform3d::identity(), Vec3d(5.0, -6.0, 7.0)), (Vec3d{5.0, -6.0, 7.0}));
  EXPECT_EQ(Transform3d{}, Transform3d::identity());
}

TEST(Transform3, mul_composes_transforms_right_to_left) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Transform3d a = randomTransform3(rng);
    const Transform3d b = randomTransform3(rng);
    const Vec3d v = rng.vec3();
    EXPECT_TRUE(isNear(transformPoint(mul(a, b), v), transformPoint(a, transformPoint(b, v)), kPointTol))
        << "case " << i;
  }
}

TEST(Transform3, inverse_undoes_transform) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Transform3d t = randomTransform3(rng);
    const Vec3d v = rng.vec3();
    EXPECT_TRUE(isNear(transformPoint(inverse(t), transformPoint(t, v)), v, kPointTol)) << "case " << i;
    EXPECT_TRUE(isNear(transformPoint(t, transformPoint(inverse(t), v)), v, kPointTol)) << "case " << i;
    EXPECT_TRUE(isNear(inverseTransformPoint(t, v), transformPoint(inverse(t), v), kPointTol)) << "case " << i;
    const Transform3d shouldBeIdentity = mul(t, inverse(t));
    EXPECT_TRUE(isNear(shouldBeIdentity.p, Vec3d::zero(), kPointTol)) << "case " << i;
    EXPECT_TRUE(sameRotation(shouldBeIdentity.q, Quatd::identity(), 1e-14)) << "case " << i;
  }
}

TEST(Transform3, inv_mul_equals_mul_by_inverse) {
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const Transform3d a = randomTransform3(rng);
    const Transform3d b = randomTransform3(rng);
    const Vec3d v = rng.vec3();
    EXPECT_TRUE(isNear(transformPoint(invMul(a, b), v), transformPoint(mul(inverse(a), b), v), kPointTol))
        << "case " << i;
    EXPECT_TRUE(isNear(transformPoint(invMul(a, b), v), inverseTransformPoint(a, transformPoint(b, v)), kPointTol))
        << "case " << i;
  }
}

TEST(Transform3, planar_transform3_agrees_with_transform2) {
  // A Transform3 that turns about z and moves in the xy plane acts like the Transform2.
  test::Random rng;
  for (int i = 0; i < test::kCases; ++i) {
    const double a = rng.uniform(-kPi, kPi);
    const Vec2d p = rng.vec2();
    const Vec2d v = rng.vec2();
    const Transform2d t2{p, Rot2d::fromAngle(a)};
    const Transform3d t3{{p.x, p.y, 0.0}, Quatd::fromAxisAngle(Vec3d::unitZ(), a)};
    const Vec3d r3 = transformPoint(t3, Vec3d{v.x, v.y, 0.0});
    EXPECT_TRUE(isNear(transformPoint(t2, v), Vec2d{r3.x, r3.y}, kPointTol)) << "case " << i;
    EXPECT_NEAR(r3.z, 0.0, kPointTol) << "case " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// float instantiations: ~7 significant digits; points up to ~10, so 1e-5.

TEST(Transform2f, float_transforms_compose_and_invert) {
  const Transform2f a{{1.0f, 2.0f}, Rot2f::fromAngle(0.5f)};
  const Transform2f b{{-3.0f, 0.5f}, Rot2f::fromAngle(-2.0f)};
  const Vec2f v{4.0f, -1.0f};
  EXPECT_TRUE(isNear(transformPoint(mul(a, b), v), transformPoint(a, transformPoint(b, v)), 1e-5f));
  EXPECT_TRUE(isNear(transformPoint(inverse(a), transformPoint(a, v)), v, 1e-5f));
  EXPECT_TRUE(isNear(transformPoint(invMul(a, b), v), inverseTransformPoint(a, transformPoint(b, v)), 1e-5f));
  EXPECT_NEAR(Rot2f::fromAngle(2.5f).angle(), 2.5f, 1e-6f);
  EXPECT_TRUE(isNear(normalize(Rot2f{1.2f, 1.6f}), Rot2f{0.6f, 0.8f}, 1e-6f));
}

TEST(Transform3f, float_transforms_compose_and_invert) {
  const Transform3f a{{1.0f, 2.0f, 3.0f}, Quatf::fromEuler(0.3f, -0.2f, 1.0f)};
  const Transform3f b{{-3.0f, 0.5f, 2.0f}, Quatf::fromAxisAngle(Vec3f{1.0f, 1.0f, 0.0f}, 2.0f)};
  const Vec3f v{4.0f, -1.0f, 0.5f};
  EXPECT_TRUE(isNear(transformPoint(mul(a, b), v), transformPoint(a, transformPoint(b, v)), 1e-5f));
  EXPECT_TRUE(isNear(transformPoint(inverse(a), transformPoint(a, v)), v, 1e-5f));
  EXPECT_TRUE(isNear(transformPoint(invMul(a, b), v), inverseTransformPoint(a, transformPoint(b, v)), 1e-5f));
}

} // namespace
} // namespace impetus
