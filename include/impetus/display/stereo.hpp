// Stereo 3D (ch. 24): interaxial distance, convergence, parallax and its budget.
//
// A stereo renderer draws the scene twice, from two cameras a distance e apart (the interaxial
// distance, in world units) along the mono camera's right vector. The convergence distance C is
// where the two views coincide: a point there has zero parallax and appears at the screen's
// depth. For a point at view depth Z the horizontal offset between its left and right images,
// measured on the convergence plane, is the screen parallax
//   P = e (1 - C / Z)                    (similar triangles through the two eyes)
// positive behind the screen (the left image further left: uncrossed), negative in front of it
// (crossed), and tending to e at infinity. NVIDIA's "separation" is e over the width of the
// convergence plane, W = 2 C tan(hfov / 2): the parallax of infinity as a fraction of the screen
// width, so P / W = separation (1 - C / Z) (NVIDIA's parallax = separation (1 - convergence / W)).
//
// On a real screen of width S viewed from a distance D by eyes i apart (6.5 cm for adults, 3-6.5
// cm over children and adults) the physical parallax is p = (P / W) S and the point is seen at
//   Z_seen = D i / (i - p)
// (p = i: at infinity; p > i would make the eyes diverge). The book's parallax budget: keep the
// action between C and 10 C and the whole scene between C/2 and 100 C, where P/W is -1 to 0.99
// of the separation.
#pragma once

#include <optional>

namespace impetus::display {

/// P = e (1 - C / Z), world units on the convergence plane. e >= 0, C > 0, Z > 0 (fields
/// "interaxial", "convergence", "depth").
[[nodiscard]] double screenParallax(double interaxial, double convergence, double depth);

/// hfov = 2 atan(aspect tan(vfov / 2)), rad. 0 < vfov < pi, aspect > 0.
[[nodiscard]] double horizontalFov(double verticalFov, double aspect);

/// W = 2 C tan(hfov / 2): the width of the convergence plane seen by the mono camera.
[[nodiscard]] double convergencePlaneWidth(double convergence, double horizontalFov);

/// e = separation W (separation = parallax of infinity / screen width, >= 0).
[[nodiscard]] double interaxialFromSeparation(double separation, double convergence, double horizontalFov);
/// separation = e / W.
[[nodiscard]] double separationFromInteraxial(double interaxial, double convergence, double horizontalFov);

/// Where a viewer sees a point with physical screen parallax p (m, + behind the screen): D i /
/// (i - p), m from the eyes; none when p >= i (at or beyond infinity: the eyes would diverge).
/// viewingDistance D > 0, eyeSeparation i > 0.
[[nodiscard]] std::optional<double> perceivedDistance(double screenParallaxMetres, double viewingDistance,
                                                      double eyeSeparation = 0.065);

/// The book's parallax budget for a depth Z and convergence C.
enum class DepthZone {
  tooNear,     ///< Z < C/2: more crossed parallax than eyes fuse comfortably
  outOfScreen, ///< C/2 <= Z < C: in front of the screen; use sparingly, never cut by the edges
  action,      ///< C <= Z <= 10 C: where the important action belongs
  background,  ///< 10 C < Z <= 100 C
  tooFar,      ///< Z > 100 C
};

[[nodiscard]] DepthZone depthZone(double depth, double convergence);
[[nodiscard]] const char* toString(DepthZone zone) noexcept;

} // namespace impetus::display
