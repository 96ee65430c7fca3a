// Soft constraints, shared by every world's contacts and joints (the solver layer: no dimension
// in it): one function turns a stiffness (hertz) and a damping ratio into the coefficients the
// soft step solves with, so the same hertz means the same spring everywhere.
#pragma once

#include <impetus/math/scalar.hpp>

#include <limits>

namespace impetus::solver {

/// Soft constraint coefficients for a spring of `hertz` and damping ratio `zeta` over a
/// substep h (Erin Catto, "Solver2D" soft step): the bias rate (1/s) that turns a position
/// error into a velocity target, and the mass and impulse scales that make the constraint a
/// spring-damper solved implicitly instead of rigid. Zero hertz: rigid (no bias, full mass).
struct Softness {
  float biasRate = 0.0f;
  float massScale = 1.0f;
  float impulseScale = 0.0f;
  /// The largest bias speed, in the row's units per second (m/s, or rad/s for an angle row):
  /// how fast an error may be taken back (a joint's maxJointPushSpeed). No bound by default.
  float maxBias = std::numeric_limits<float>::infinity();
};

[[nodiscard]] inline Softness makeSoft(float hertz, float zeta, float h) {
  if (hertz == 0.0f) {
    return {};
  }
  const float omega = 2.0f * pi<float> * hertz;
  const float a1 = 2.0f * zeta + h * omega;
  const float a2 = h * omega * a1;
  const float a3 = 1.0f / (1.0f + a2);
  return {omega / a1, a2 * a3, a3, std::numeric_limits<float>::infinity()};
}

} // namespace impetus::solver
