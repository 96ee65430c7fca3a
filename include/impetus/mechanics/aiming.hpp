// Aiming in vacuum (ch. 2, 6): the launch angles that send a projectile of a given speed through
// a given point, and the least speed that can reach it. Flat ground, constant g, no air.
//
// For a target at horizontal distance x and height y above the launch point, speed v, the
// angles above the horizontal satisfy
//   tan(theta) = (v^2 +- sqrt(v^4 - g (g x^2 + 2 y v^2))) / (g x),
// a low (flat, faster) and a high (lobbed) solution that merge when the root is zero; the
// target is out of reach when it is negative. The least speed that reaches the target is
//   v_min^2 = g (y + sqrt(x^2 + y^2)), at tan(theta) = (y + sqrt(x^2 + y^2)) / x.
#pragma once

#include <impetus/math/vec3.hpp>

#include <optional>

namespace impetus {

/// One way to hit the target.
struct LaunchSolution {
  double angle = 0.0;        ///< above the horizontal, rad, in [-pi/2, pi/2]
  double timeOfFlight = 0.0; ///< s, to reach the target
};

struct AimSolutions {
  LaunchSolution low;  ///< the flatter, quicker trajectory
  LaunchSolution high; ///< the lobbed trajectory (equal to low at the edge of the range)
};

/// Launch angles to pass through (distance, height) relative to the launch point; none when the
/// target is out of reach at this speed. distance >= 0 (m), height any (m), speed > 0 (m/s),
/// gravity > 0 (m/s^2). At distance 0 the only solutions are straight up (if the height can be
/// reached) or straight down (below). Throws impetus::Error for invalid input.
[[nodiscard]] std::optional<AimSolutions> launchAngles(double distance, double height, double speed,
                                                       double gravity = 9.81);

/// The least launch speed that reaches (distance, height), m/s, and the angle that needs it.
struct MinimumSpeed {
  double speed = 0.0; ///< m/s
  double angle = 0.0; ///< rad above the horizontal
};
[[nodiscard]] MinimumSpeed minimumLaunchSpeed(double distance, double height, double gravity = 9.81);

/// Aiming in 3D (+y up): unit launch directions from `from` through `to` at `speed`; none when
/// out of reach.
struct Aim3 {
  Vec3d lowDirection;
  Vec3d highDirection;
  double lowTime = 0.0;  ///< s
  double highTime = 0.0; ///< s
};
[[nodiscard]] std::optional<Aim3> aimAt(const Vec3d& from, const Vec3d& to, double speed, double gravity = 9.81);

} // namespace impetus
