// Stereo 3D (ch. 24) against references the library did not produce: a hand-derived off-axis
// case with round numbers (every matrix entry and projected point worked out below), the spec's
// 60-degree oracle, the parallax formula P = e (1 - C/Z) checked through the full matrices, and
// the toe-in method's vertical parallax (which the off-axis pair must not have).
#include <impetus/display/stereo.hpp>
#include <impetus/display/stereo_frustum.hpp>
#include <impetus/math/scalar.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace impetus::display {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

Vec3d project(const EyeMatrices& m, const Vec3d& p) {
  return perspectiveDivide(m.projection * transformPoint(m.view, p));
}

// ---- Hand-derived case --------------------------------------------------------------------------
// 90-degree vertical field, square aspect, near plane 1, convergence 4, interaxial 0.5, far 100,
// mono camera at the origin looking down -z:
//   t = n tan 45 = 1, w = 1, s = (e/2) n / C = 0.25 / 4 = 0.0625
//   left eye:  at (-0.25, 0, 0), frustum [-0.9375, 1.0625] x [-1, 1]
//   right eye: at (+0.25, 0, 0), frustum [-1.0625, 0.9375] x [-1, 1]
//   glFrustum, left eye: m00 = 2n/(r-l) = 1, m02 = (r+l)/(r-l) = 0.0625, m11 = 1, m12 = 0,
//   m22 = -(f+n)/(f-n) = -101/99, m23 = -2fn/(f-n) = -200/99, m32 = -1.
// A point (x, y, -Z) is at (x + 0.25, y, -Z) in the left eye's space, so its left NDC x is
//   (x + 0.25 - 0.0625 Z) / Z   and the right's (x - 0.25 + 0.0625 Z) / Z.

StereoCamera handCamera() {
  StereoCamera c;
  c.interaxial = 0.5;
  c.convergence = 4.0;
  c.nearPlane = 1.0;
  c.farPlane = 100.0;
  c.verticalFov = pi<double> / 2.0;
  c.aspect = 1.0;
  return c;
}

TEST(StereoFrustum, hand_derived_off_axis_frustums_and_matrices) {
  const StereoCamera c = handCamera();
  const Frustum l = offAxisFrustum(c, Eye::left);
  const Frustum r = offAxisFrustum(c, Eye::right);
  EXPECT_DOUBLE_EQ(l.left, -0.9375);
  EXPECT_DOUBLE_EQ(l.right, 1.0625);
  EXPECT_DOUBLE_EQ(r.left, -1.0625);
  EXPECT_DOUBLE_EQ(r.right, 0.9375);
  EXPECT_NEAR(l.top, 1.0, 1e-15);
  EXPECT_NEAR(l.bottom, -1.0, 1e-15);
  const Matrix4 p = frustumMatrix(l);
  EXPECT_DOUBLE_EQ(p(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(p(0, 2), 0.0625);
  EXPECT_NEAR(p(1, 1), 1.0, 1e-15);
  EXPECT_NEAR(p(1, 2), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(p(2, 2), -101.0 / 99.0);
  EXPECT_DOUBLE_EQ(p(2, 3), -200.0 / 99.0);
  EXPECT_DOUBLE_EQ(p(3, 2), -1.0);
  EXPECT_DOUBLE_EQ(p(3, 3), 0.0);
  // Column-major for OpenGL: element (0, 2) is the 9th number.
  EXPECT_DOUBLE_EQ(p.data()[8], 0.0625);
  // The left eye's view matrix is a translation by +0.25 in x.
  const Matrix4 v = offAxisView({}, c, Eye::left);
  EXPECT_DOUBLE_EQ(v(0, 3), 0.25);
  EXPECT_DOUBLE_EQ(v(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(v(2, 2), 1.0);
  EXPECT_NEAR(toeInAngle(c), std::atan(0.0625), 1e-15);
}

TEST(StereoFrustum, hand_derived_projections_give_the_expected_parallax) {
  const StereoCamera c = handCamera();
  const EyeMatrices left = offAxisEye({}, c, Eye::left);
  const EyeMatrices right = offAxisEye({}, c, Eye::right);
  // On the convergence plane (Z = 4): the same NDC in both eyes, zero parallax.
  const Vec3d onScreen{0.8, -0.5, -4.0};
  EXPECT_NEAR(project(left, onScreen).x, 0.8 / 4.0, 1e-15);
  EXPECT_NEAR(project(right, onScreen).x, 0.8 / 4.0, 1e-15);
  // At Z = 8: left (0.25 - 0.5)/8 = -0.03125, right +0.03125; the NDC gap 0.0625 times the half
  // width of the convergence plane (4) is 0.25 = e (1 - C/Z) = 0.5 (1 - 4/8).
  const Vec3d behind{0.0, 0.0, -8.0};
  EXPECT_NEAR(project(left, behind).x, -0.03125, 1e-15);
  EXPECT_NEAR(project(right, behind).x, 0.03125, 1e-15);
  // At Z = 2 (in front): left (0.25 - 0.125)/2 = 0.0625, right -0.0625: crossed, P = -0.5.
  const Vec3d front{0.0, 0.0, -2.0};
  EXPECT_NEAR(project(left, front).x, 0.0625, 1e-15);
  EXPECT_NEAR(project(right, front).x, -0.0625, 1e-15);
  EXPECT_DOUBLE_EQ(screenParallax(0.5, 4.0, 8.0), 0.25);
  EXPECT_DOUBLE_EQ(screenParallax(0.5, 4.0, 2.0), -0.5);
  // The near plane's corners map to the NDC cube's: (-1, -1, -1) and (1, 1, -1); the far plane to z = 1.
  const Frustum l = offAxisFrustum(c, Eye::left);
  const Vec3d corner = perspectiveDivide(frustumMatrix(l) * Vec4d{l.left, l.bottom, -1.0, 1.0});
  EXPECT_NEAR(corner.x, -1.0, 1e-15);
  EXPECT_NEAR(corner.y, -1.0, 1e-15);
  EXPECT_NEAR(corner.z, -1.0, 1e-15);
  EXPECT_NEAR(perspectiveDivide(frustumMatrix(l) * Vec4d{0.0, 0.0, -100.0, 1.0}).z, 1.0, 1e-14);
}

TEST(StereoFrustum, spec_sixty_degree_oracle) {
  // Spec ch. 24: fov 60, aspect 16/9, n = 0.1, C = 10, e = 0.065: t = 0.057735, w = 0.102640,
  // s = 3.25e-4; left [-0.102315, 0.102965], right [-0.102965, 0.102315].
  StereoCamera c;
  c.verticalFov = degToRad(60.0);
  c.aspect = 16.0 / 9.0;
  c.nearPlane = 0.1;
  c.convergence = 10.0;
  c.interaxial = 0.065;
  const Frustum m = monoFrustum(c);
  EXPECT_NEAR(m.top, 0.057735, 5e-7);
  EXPECT_NEAR(m.right, 0.102640, 5e-7);
  const Frustum l = offAxisFrustum(c, Eye::left);
  const Frustum r = offAxisFrustum(c, Eye::right);
  EXPECT_NEAR(l.left, -0.102315, 5e-7);
  EXPECT_NEAR(l.right, 0.102965, 5e-7);
  EXPECT_NEAR(r.left, -0.102965, 5e-7);
  EXPECT_NEAR(r.right, 0.102315, 5e-7);
  EXPECT_NEAR(l.right - m.right, 3.25e-4, 1e-12);
}

TEST(StereoFrustum, parallax_through_the_matrices_is_e_times_one_minus_c_over_z_for_any_camera) {
  // A camera somewhere, looking somewhere: the screen parallax measured through the full matrices
  // (NDC gap x half-width of the convergence plane) equals the closed form at every depth.
  StereoCamera c;
  c.interaxial = 0.3;
  c.convergence = 12.0;
  c.verticalFov = degToRad(50.0);
  c.aspect = 1.6;
  const CameraPose pose{{3.0, 1.7, -2.0}, {1.0, -0.2, -1.0}, {0.0, 1.0, 0.0}};
  const EyeMatrices left = offAxisEye(pose, c, Eye::left);
  const EyeMatrices right = offAxisEye(pose, c, Eye::right);
  const Vec3d f = normalize(pose.forward);
  const double halfWidth = 0.5 * convergencePlaneWidth(c.convergence, horizontalFov(c.verticalFov, c.aspect));
  for (const double z : {3.0, 6.0, 12.0, 40.0, 500.0}) {
    const Vec3d p = pose.position + f * z;
    const double gap = project(right, p).x - project(left, p).x;
    EXPECT_NEAR(gap * halfWidth, screenParallax(c.interaxial, c.convergence, z), 1e-12) << z;
    EXPECT_NEAR(project(right, p).y, project(left, p).y, 1e-14); // no vertical parallax
  }
}

TEST(StereoFrustum, toe_in_has_vertical_parallax_off_axis_does_not) {
  const StereoCamera c = handCamera();
  const Vec3d corner{2.0, 1.5, -6.0}; // up and to the right of the view centre
  const EyeMatrices offL = offAxisEye({}, c, Eye::left), offR = offAxisEye({}, c, Eye::right);
  const EyeMatrices toeL = toeInEye({}, c, Eye::left), toeR = toeInEye({}, c, Eye::right);
  EXPECT_NEAR(project(offL, corner).y, project(offR, corner).y, 1e-15);
  // Toe-in: the eyes' image planes are turned by +-3.58 degrees; the point's y differs by ~1 %.
  const double dy = project(toeL, corner).y - project(toeR, corner).y;
  EXPECT_GT(std::abs(dy), 1e-3);
  // Both methods agree at the convergence point itself (zero parallax, both eyes at the centre).
  const Vec3d target{0.0, 0.0, -4.0};
  EXPECT_NEAR(project(toeL, target).x, 0.0, 1e-15);
  EXPECT_NEAR(project(toeR, target).x, 0.0, 1e-15);
}

TEST(StereoFrustum, look_at_is_glu_look_at) {
  // The default camera (origin, -z, y up) has the identity view.
  const Matrix4 v = lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0});
  for (int r = 0; r < 4; ++r) {
    for (int k = 0; k < 4; ++k) {
      EXPECT_NEAR(v(r, k), r == k ? 1.0 : 0.0, 1e-15);
    }
  }
  // Looking down +x from (1, 2, 3): the target ends on the -z axis, 5 units away.
  const Vec4d p = transformPoint(lookAt({1, 2, 3}, {6, 2, 3}, {0, 1, 0}), {6.0, 2.0, 3.0});
  EXPECT_NEAR(p.x, 0.0, 1e-15);
  EXPECT_NEAR(p.y, 0.0, 1e-15);
  EXPECT_NEAR(p.z, -5.0, 1e-15);
  expectErrorField([] { (void)lookAt({0, 0, 0}, {0, 0, 0}, {0, 1, 0}); }, "target");
  expectErrorField([] { (void)lookAt({0, 0, 0}, {0, 1, 0}, {0, 1, 0}); }, "up");
}

TEST(StereoFrustum, bad_cameras_are_refused) {
  StereoCamera c;
  c.convergence = 0.05; // inside the near plane
  expectErrorField([&] { (void)offAxisFrustum(c, Eye::left); }, "convergence");
  c = {};
  c.farPlane = 0.1;
  expectErrorField([&] { (void)monoFrustum(c); }, "farPlane");
  c = {};
  c.verticalFov = pi<double>;
  expectErrorField([&] { (void)monoFrustum(c); }, "verticalFov");
  c = {};
  c.interaxial = -0.1;
  expectErrorField([&] { (void)offAxisFrustum(c, Eye::right); }, "interaxial");
  c = {};
  c.aspect = nan;
  expectErrorField([&] { (void)monoFrustum(c); }, "aspect");
  expectErrorField([] { (void)frustumMatrix({1.0, -1.0, -1.0, 1.0, 0.1, 10.0}); }, "right");
}

// ---- Parallax, separation and the budget ----------------------------------------------------------

TEST(Stereo, separation_and_interaxial_convert_through_the_convergence_plane_width) {
  // Spec: 6.5 cm eyes on a 53.1 cm screen: separation 0.1224.
  EXPECT_NEAR(0.065 / 0.531, 0.1224, 5e-5);
  // 90-degree horizontal field at C = 4: W = 8, so separation 0.0625 is e = 0.5.
  EXPECT_NEAR(interaxialFromSeparation(0.0625, 4.0, pi<double> / 2.0), 0.5, 1e-15);
  EXPECT_NEAR(separationFromInteraxial(0.5, 4.0, pi<double> / 2.0), 0.0625, 1e-15);
  EXPECT_NEAR(horizontalFov(pi<double> / 2.0, 1.0), pi<double> / 2.0, 1e-15);
  EXPECT_NEAR(horizontalFov(degToRad(60.0), 16.0 / 9.0), 2.0 * std::atan(16.0 / 9.0 * std::tan(degToRad(30.0))), 1e-15);
  // The budget's ratios P/e (spec): C/2 -> -1, C -> 0, 2C -> 0.5, 10C -> 0.9, 100C -> 0.99.
  EXPECT_DOUBLE_EQ(screenParallax(1.0, 10.0, 5.0), -1.0);
  EXPECT_DOUBLE_EQ(screenParallax(1.0, 10.0, 10.0), 0.0);
  EXPECT_DOUBLE_EQ(screenParallax(1.0, 10.0, 20.0), 0.5);
  EXPECT_DOUBLE_EQ(screenParallax(1.0, 10.0, 100.0), 0.9);
  EXPECT_DOUBLE_EQ(screenParallax(1.0, 10.0, 1000.0), 0.99);
  EXPECT_EQ(depthZone(4.0, 10.0), DepthZone::tooNear);
  EXPECT_EQ(depthZone(5.0, 10.0), DepthZone::outOfScreen);
  EXPECT_EQ(depthZone(10.0, 10.0), DepthZone::action);
  EXPECT_EQ(depthZone(100.0, 10.0), DepthZone::action);
  EXPECT_EQ(depthZone(1000.0, 10.0), DepthZone::background);
  EXPECT_EQ(depthZone(1001.0, 10.0), DepthZone::tooFar);
  expectErrorField([] { (void)screenParallax(0.065, 10.0, 0.0); }, "depth");
  expectErrorField([] { (void)depthZone(1.0, -1.0); }, "convergence");
}

TEST(Stereo, perceived_distance_from_screen_parallax) {
  // Seen from 0.6 m with 65 mm eyes: zero parallax on the screen, half the eye separation at
  // twice the distance, the full separation at infinity, crossed parallax of one separation at
  // half the distance.
  EXPECT_DOUBLE_EQ(*perceivedDistance(0.0, 0.6), 0.6);
  EXPECT_DOUBLE_EQ(*perceivedDistance(0.0325, 0.6), 1.2);
  EXPECT_DOUBLE_EQ(*perceivedDistance(-0.065, 0.6), 0.3);
  EXPECT_FALSE(perceivedDistance(0.065, 0.6).has_value());
  EXPECT_FALSE(perceivedDistance(0.1, 0.6).has_value()); // divergent
  expectErrorField([] { (void)perceivedDistance(0.0, 0.0); }, "viewingDistance");
}

} // namespace
} // namespace impetus::display
