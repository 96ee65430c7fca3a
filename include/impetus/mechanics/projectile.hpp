// Projectiles (ch. 6): vacuum trajectories with a launch height (the book's tables 6-1 to 6-4)
// and terminal velocity under linear and quadratic drag.
//
// Frame: x horizontal along the shot, y up, origin on the ground below the launch point. Flat
// Earth, constant gravity, no air: the path is a parabola. The book's tables are special cases:
//   6-1 target at the launch height, 6-2 target higher by b, 6-3 target lower by b,
//   6-4 dropped from a vehicle flying level (angle 0, launch height h, target at 0).
// All of them are vacuumFlight(launch, targetHeight); the tests check each against the table's
// own formula. (The book's table 6-2 labels its first row "t" for x(t), and table 6-4 gives
// "h = g t^2/2" for h = g T^2/2: typos, see docs/mechanics/projectiles.md.)
#pragma once

#include <impetus/core/constants.hpp>
#include <impetus/math/vec2.hpp>

namespace impetus {

/// A launch in a vertical plane.
struct VacuumLaunch {
  double speed = 0.0;                          ///< v0, m/s, >= 0
  double angle = 0.0;                          ///< phi above the horizontal, rad, in [-pi/2, pi/2]
  double launchHeight = 0.0;                   ///< y of the launch point, m (any finite value)
  double gravity = constants::standardGravity; ///< g, m/s^2, > 0 (the book uses 9.8)
};

/// Position and velocity at one instant.
struct ProjectilePoint {
  double time = 0.0;  ///< s since launch
  Vec2d position;     ///< (x, y), m
  Vec2d velocity;     ///< (vx, vy), m/s
  double speed = 0.0; ///< |v| = sqrt(v0^2 - 2 g t v0 sin(phi) + g^2 t^2), m/s
};

/// A vacuum flight from the launch point to a target height.
struct VacuumFlight {
  double timeOfFlight = 0.0; ///< T: the (last) time y(T) = target height, s
  double range = 0.0;        ///< R = v0 cos(phi) T, horizontal distance, m
  double apexTime = 0.0;     ///< v0 sin(phi)/g, or 0 when launched level or downward, s
  double apexHeight = 0.0;   ///< highest y reached, m (absolute: launch height included)
  double impactSpeed = 0.0;  ///< sqrt(v0^2 + 2 g (launchHeight - targetHeight)), m/s
  double impactAngle = 0.0;  ///< direction of the velocity at impact below the horizontal, rad (>= 0 when descending)
};

/// x(t) = v0 cos(phi) t, y(t) = h0 + v0 sin(phi) t - g t^2/2, vx = v0 cos(phi),
/// vy = v0 sin(phi) - g t. Valid for any t >= 0 (the parabola continues below the ground: the
/// caller decides where the flight ends). Throws impetus::Error for bad launch values or
/// negative/non-finite time.
[[nodiscard]] ProjectilePoint vacuumPointAt(const VacuumLaunch& launch, double time);

/// Flight to the height `targetHeight` (m, same frame as launchHeight), descending branch:
///   T = (v0 sin(phi) + sqrt(v0^2 sin^2(phi) - 2 g (targetHeight - launchHeight))) / g,
/// which is the book's T = v0 sin(phi)/g + sqrt(2 (h - b)/g) (table 6-2, b above) and
/// T = v0 sin(phi)/g + sqrt(2 h/g) (table 6-3, b below, h measured above the target). With the
/// target at the launch height, T = 2 v0 sin(phi)/g and R = v0^2 sin(2 phi)/g (table 6-1).
/// Throws impetus::Error naming "targetHeight" ("target never reached") when the apex is below
/// the target (no real root) or the target was only at or above the launch before launch
/// (launched downward at a higher target). A target at the launch height when launched level or
/// downward is reached at T = 0 (range 0).
[[nodiscard]] VacuumFlight vacuumFlight(const VacuumLaunch& launch, double targetHeight = 0.0);

/// Table 6-4: an object released from a vehicle flying level at `speed` (m/s, >= 0) at `height`
/// (m, >= 0) above the ground: T = sqrt(2 h/g), R = v0 T, impact speed sqrt(v0^2 + g^2 T^2).
/// With speed 0 it is plain free fall.
[[nodiscard]] VacuumFlight vehicleDrop(double speed, double height, double gravity = constants::standardGravity);

/// The launch angle (rad) that maximizes the range to a target at height `targetHeight`
/// relative to a launch at `launchHeight` with speed v0 (m/s, > 0):
///   phi* = atan(v0 / sqrt(v0^2 + 2 g (launchHeight - targetHeight))),
/// which is 45 degrees for a target at the launch height. Requires the target to be reachable at
/// all (v0^2 + 2 g (launchHeight - targetHeight) > 0), else throws naming "targetHeight".
[[nodiscard]] double maximumRangeAngle(double speed, double launchHeight = 0.0, double targetHeight = 0.0,
                                       double gravity = constants::standardGravity);

/// Terminal velocity under quadratic drag F = 1/2 rho v^2 A Cd balancing the weight W = m g:
///   v_t = sqrt(2 W / (Cd rho A)),  m/s.
/// weight W in N (> 0), dragCoefficient Cd (> 0), fluidDensity rho in kg/m^3 (> 0),
/// area A (projected frontal area) in m^2 (> 0). Valid while Cd is roughly constant over the
/// fall (see sphereDragCoefficient for how it changes with the Reynolds number).
[[nodiscard]] double terminalVelocityQuadratic(double weight, double dragCoefficient, double fluidDensity, double area);

/// Terminal velocity under linear drag F = C v (the book's Cannon2 model): v_t = W / C, m/s.
/// weight W in N (> 0), linearDragCoefficient C in N s/m (> 0).
[[nodiscard]] double terminalVelocityLinear(double weight, double linearDragCoefficient);

} // namespace impetus
