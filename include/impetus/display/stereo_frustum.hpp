// Stereo frustums (ch. 24): off-axis (asymmetric) and toe-in projections per eye, with the
// projection and view matrices ready for OpenGL.
//
// Off-axis (the correct method): both cameras look straight ahead, parallel to the mono camera,
// shifted by -e/2 (left) and +e/2 (right) along its right vector; each frustum is sheared so that
// the two frustums share one rectangle on the convergence plane (the screen). With the near
// plane n, vertical field of view fov and aspect a (glFrustum's left/right/bottom/top on the
// near plane):
//   t = n tan(fov / 2),  w = a t,  s = (e / 2) n / C
//   left eye   [left, right] = [-w + s, w + s]      right eye  [-w - s, w - s]      bottom = -t, top = t
// (the eye moved left sees the screen rectangle to its right: by similar triangles its centre
// is e/2 to the right at distance C, e/2 n / C on the near plane).
// Toe-in (for comparison only): the cameras keep the symmetric mono frustum and are turned
// inwards by atan((e/2)/C) to look at the convergence point. Their image planes are then not
// parallel: points off the centre get vertical parallax (keystone), which the eyes cannot fuse
// comfortably. The off-axis pair has none.
//
// Matrices follow OpenGL: right-handed eye space looking down -z, `frustumMatrix` is glFrustum's,
// `lookAt` is gluLookAt's (matrix4.hpp: column-major).
#pragma once

#include <impetus/display/matrix4.hpp>
#include <impetus/math/vec3.hpp>

namespace impetus::display {

enum class Eye { left, right };

struct StereoCamera {
  double interaxial = 0.065;            ///< e, world units (m) between the two cameras (>= 0)
  double convergence = 10.0;            ///< C, distance of the zero-parallax plane (> near)
  double nearPlane = 0.1;               ///< n (> 0)
  double farPlane = 1000.0;             ///< f (> n)
  double verticalFov = 1.0471975511966; ///< rad (60 degrees), in (0, pi)
  double aspect = 16.0 / 9.0;           ///< width / height (> 0)
};

/// glFrustum's arguments: the near plane's rectangle and the clip distances.
struct Frustum {
  double left = 0.0, right = 0.0, bottom = 0.0, top = 0.0;
  double nearPlane = 0.0, farPlane = 0.0;
};

/// Throws impetus::Error naming the field for a bad camera (e.g. "convergence" at or before the
/// near plane, "farPlane" at or before it).
void validate(const StereoCamera& camera);

/// The mono camera's symmetric frustum (also each toe-in eye's).
[[nodiscard]] Frustum monoFrustum(const StereoCamera& camera);
/// The eye's asymmetric frustum.
[[nodiscard]] Frustum offAxisFrustum(const StereoCamera& camera, Eye eye);

/// The eye's offset along the mono camera's right vector: -e/2 (left) or +e/2 (right).
[[nodiscard]] double eyeOffset(const StereoCamera& camera, Eye eye);
/// atan((e/2) / C): how far each toe-in camera turns inwards, rad.
[[nodiscard]] double toeInAngle(const StereoCamera& camera);

/// glFrustum(l, r, b, t, n, f).
[[nodiscard]] Matrix4 frustumMatrix(const Frustum& frustum);

/// gluLookAt: the view matrix of a camera at `eye` looking at `target` with `up` (not parallel to
/// the view direction). Throws impetus::Error naming "target" or "up" when degenerate.
[[nodiscard]] Matrix4 lookAt(const Vec3d& eye, const Vec3d& target, const Vec3d& up);

/// The mono camera: where it is, where it looks, which way is up.
struct CameraPose {
  Vec3d position{0.0, 0.0, 0.0};
  Vec3d forward{0.0, 0.0, -1.0}; ///< need not be unit
  Vec3d up{0.0, 1.0, 0.0};
};

/// The eye's position: the mono camera's moved by eyeOffset along its right vector.
[[nodiscard]] Vec3d eyePosition(const CameraPose& pose, const StereoCamera& camera, Eye eye);

/// Off-axis: the eye's view matrix (parallel to the mono camera). Use with offAxisFrustum.
[[nodiscard]] Matrix4 offAxisView(const CameraPose& pose, const StereoCamera& camera, Eye eye);
/// Toe-in: the eye looks at the convergence point straight ahead of the mono camera. Use with
/// monoFrustum.
[[nodiscard]] Matrix4 toeInView(const CameraPose& pose, const StereoCamera& camera, Eye eye);

/// Both of an eye's matrices.
struct EyeMatrices {
  Matrix4 projection;
  Matrix4 view;
};

[[nodiscard]] EyeMatrices offAxisEye(const CameraPose& pose, const StereoCamera& camera, Eye eye);
[[nodiscard]] EyeMatrices toeInEye(const CameraPose& pose, const StereoCamera& camera, Eye eye);

} // namespace impetus::display
