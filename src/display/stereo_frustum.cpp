#include <impetus/display/stereo_frustum.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>

#include <cmath>

namespace impetus::display {
namespace {

/// The mono camera's unit right vector, forward x up.
Vec3d rightVector(const CameraPose& pose) {
  requireFinite(pose.position, "position");
  requireFinite(pose.forward, "forward");
  requireFinite(pose.up, "up");
  if (lengthSquared(pose.forward) == 0.0) {
    throwInvalid("forward", 0.0, "must not be zero (the camera looks nowhere)");
  }
  const Vec3d r = normalize(cross(pose.forward, pose.up));
  if (lengthSquared(r) == 0.0) {
    throwInvalid("up", 0.0, "must not be parallel to forward (or zero)");
  }
  return r;
}

} // namespace

void validate(const StereoCamera& c) {
  requireNonNegative(c.interaxial, "interaxial");
  requirePositive(c.nearPlane, "nearPlane");
  requireFinite(c.farPlane, "farPlane");
  if (!(c.farPlane > c.nearPlane)) {
    throwInvalid("farPlane", c.farPlane, "must be beyond nearPlane");
  }
  requireFinite(c.convergence, "convergence");
  if (!(c.convergence > c.nearPlane)) {
    throwInvalid("convergence", c.convergence, "must be beyond nearPlane");
  }
  requireFinite(c.verticalFov, "verticalFov");
  if (!(c.verticalFov > 0.0 && c.verticalFov < pi<double>)) {
    throwInvalid("verticalFov", c.verticalFov, "must be between 0 and pi rad");
  }
  requirePositive(c.aspect, "aspect");
}

Frustum monoFrustum(const StereoCamera& c) {
  validate(c);
  const double t = c.nearPlane * std::tan(0.5 * c.verticalFov);
  const double w = c.aspect * t;
  return {-w, w, -t, t, c.nearPlane, c.farPlane};
}

Frustum offAxisFrustum(const StereoCamera& c, Eye eye) {
  Frustum f = monoFrustum(c);
  // The screen rectangle's centre, seen from the eye, is -offset away at distance C: on the near
  // plane that is -offset n / C. s = (e/2) n / C.
  const double shift = -eyeOffset(c, eye) * c.nearPlane / c.convergence;
  f.left += shift;
  f.right += shift;
  return f;
}

double eyeOffset(const StereoCamera& c, Eye eye) {
  requireNonNegative(c.interaxial, "interaxial");
  return eye == Eye::left ? -0.5 * c.interaxial : 0.5 * c.interaxial;
}

double toeInAngle(const StereoCamera& c) {
  validate(c);
  return std::atan(0.5 * c.interaxial / c.convergence);
}

Matrix4 frustumMatrix(const Frustum& f) {
  requirePositive(f.nearPlane, "nearPlane");
  requireFinite(f.farPlane, "farPlane");
  if (!(f.farPlane > f.nearPlane)) {
    throwInvalid("farPlane", f.farPlane, "must be beyond nearPlane");
  }
  requireFinite(f.left, "left");
  requireFinite(f.right, "right");
  requireFinite(f.bottom, "bottom");
  requireFinite(f.top, "top");
  if (!(f.right > f.left)) {
    throwInvalid("right", f.right, "must exceed left");
  }
  if (!(f.top > f.bottom)) {
    throwInvalid("top", f.top, "must exceed bottom");
  }
  const double n = f.nearPlane;
  const double fa = f.farPlane;
  Matrix4 m;
  m(0, 0) = 2.0 * n / (f.right - f.left);
  m(0, 2) = (f.right + f.left) / (f.right - f.left);
  m(1, 1) = 2.0 * n / (f.top - f.bottom);
  m(1, 2) = (f.top + f.bottom) / (f.top - f.bottom);
  m(2, 2) = -(fa + n) / (fa - n);
  m(2, 3) = -2.0 * fa * n / (fa - n);
  m(3, 2) = -1.0;
  return m;
}

Matrix4 lookAt(const Vec3d& eye, const Vec3d& target, const Vec3d& up) {
  requireFinite(eye, "eye");
  requireFinite(target, "target");
  requireFinite(up, "up");
  const Vec3d f = normalize(target - eye);
  if (lengthSquared(f) == 0.0) {
    throwInvalid("target", 0.0, "must differ from the eye position");
  }
  const Vec3d s = normalize(cross(f, up));
  if (lengthSquared(s) == 0.0) {
    throwInvalid("up", 0.0, "must not be parallel to the view direction (or zero)");
  }
  const Vec3d u = cross(s, f);
  Matrix4 m = Matrix4::identity();
  m(0, 0) = s.x;
  m(0, 1) = s.y;
  m(0, 2) = s.z;
  m(1, 0) = u.x;
  m(1, 1) = u.y;
  m(1, 2) = u.z;
  m(2, 0) = -f.x;
  m(2, 1) = -f.y;
  m(2, 2) = -f.z;
  m(0, 3) = -dot(s, eye);
  m(1, 3) = -dot(u, eye);
  m(2, 3) = dot(f, eye);
  return m;
}

Vec3d eyePosition(const CameraPose& pose, const StereoCamera& camera, Eye eye) {
  return pose.position + rightVector(pose) * eyeOffset(camera, eye);
}

Matrix4 offAxisView(const CameraPose& pose, const StereoCamera& camera, Eye eye) {
  validate(camera);
  const Vec3d p = eyePosition(pose, camera, eye);
  return lookAt(p, p + pose.forward, pose.up);
}

Matrix4 toeInView(const CameraPose& pose, const StereoCamera& camera, Eye eye) {
  validate(camera);
  const Vec3d p = eyePosition(pose, camera, eye);
  const Vec3d target = pose.position + normalize(pose.forward) * camera.convergence;
  return lookAt(p, target, pose.up);
}

EyeMatrices offAxisEye(const CameraPose& pose, const StereoCamera& camera, Eye eye) {
  return {frustumMatrix(offAxisFrustum(camera, eye)), offAxisView(pose, camera, eye)};
}

EyeMatrices toeInEye(const CameraPose& pose, const StereoCamera& camera, Eye eye) {
  return {frustumMatrix(monoFrustum(camera)), toeInView(pose, camera, eye)};
}

} // namespace impetus::display
