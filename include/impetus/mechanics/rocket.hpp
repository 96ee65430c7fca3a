// Variable mass (ch. 6): the rocket equation, thrust, and the vertical flight of a rocket with
// a constant burn rate under constant gravity (no air resistance, no nozzle pressure thrust:
// the book's assumptions), through burn-out and the ballistic coast to the peak.
//
// Newton's second law for a body that expels mass at velocity u relative to itself:
//   m dv/dt = F_ext + u mdot,   thrust = mdot u,   m(t) = m0 - mdot t.
// (When the mass gained or lost has zero absolute velocity, as fuel burnt by a ship, it is
// F = d(m v)/dt instead: see the spec, ch. 6 item 9.)
#pragma once

#include <impetus/core/constants.hpp>

namespace impetus {

/// The ideal rocket equation (Tsiolkovsky): delta-v = u ln(m0/m1), m/s, with no external force.
/// exhaustVelocity u in m/s (> 0), initialMass m0 and finalMass m1 in kg (0 < m1 <= m0).
[[nodiscard]] double rocketDeltaV(double exhaustVelocity, double initialMass, double finalMass);

/// Thrust = mdot u, N. burnRate mdot in kg/s (>= 0), exhaustVelocity u in m/s (>= 0).
[[nodiscard]] double rocketThrust(double burnRate, double exhaustVelocity);

/// A rocket flying straight up (altitude y and velocity positive upward).
struct VerticalRocket {
  double initialMass = 0.0;                    ///< m0, total mass at ignition, kg, > 0
  double propellantMass = 0.0;                 ///< kg, > 0 and < initialMass (the rest is structure and payload)
  double burnRate = 0.0;                       ///< mdot, kg/s, > 0 (constant)
  double exhaustVelocity = 0.0;                ///< u, relative to the rocket, m/s, > 0
  double gravity = constants::standardGravity; ///< m/s^2, > 0
  /// m/s. 0 means the rocket starts at rest on a launch pad: it stays there until its thrust
  /// exceeds its weight (at ignition, or later once enough propellant has burnt).
  double initialVelocity = 0.0;
  double initialAltitude = 0.0; ///< m
};

/// The rocket at one instant.
struct RocketState {
  double time = 0.0;         ///< s since ignition
  double mass = 0.0;         ///< kg
  double velocity = 0.0;     ///< m/s, + up
  double altitude = 0.0;     ///< m
  double acceleration = 0.0; ///< m/s^2, + up (0 while held on the pad)
  bool burning = false;      ///< before burn-out
};

struct RocketFlight {
  double thrust = 0.0;                ///< mdot u, N
  double liftoffThrustToWeight = 0.0; ///< thrust / (m0 g) at ignition
  /// Whether the rocket leaves the pad (always true when it starts moving). False when its
  /// thrust never exceeds its weight before burn-out: it then stays on the pad.
  bool liftsOff = false;
  double liftoffTime = 0.0;     ///< when the thrust first exceeds the weight, s (0 if at ignition)
  double burnoutTime = 0.0;     ///< t_b = propellantMass / burnRate, s
  double burnoutMass = 0.0;     ///< m0 - propellant, kg
  double burnoutVelocity = 0.0; ///< m/s
  double burnoutAltitude = 0.0; ///< m
  double peakAltitude = 0.0;    ///< highest altitude, m (coast: y_b + v_b^2/(2 g))
  double peakTime = 0.0;        ///< s (coast: t_b + v_b/g)
  double idealDeltaV = 0.0;     ///< u ln(m0/m_b): the speed gained with no gravity, m/s
};

/// Burn (from lift-off, with m(t) = m0 - mdot t and tau = t - t_liftoff):
///   v(t) = v0 + u ln(m(t_l)/m(t)) - g tau,
///   y(t) = y0 + v0 tau + u tau - (u m(t)/mdot) ln(m(t_l)/m(t)) - g tau^2/2,
/// (the spec's ch. 6 item 9 with t_l = 0), then a ballistic coast with -g. The model has no
/// ground after lift-off: the coast continues below the launch altitude. Throws impetus::Error
/// for bad input.
[[nodiscard]] RocketFlight verticalRocketFlight(const VerticalRocket& rocket);

/// The state at `time` (s since ignition, >= 0), burn or coast.
[[nodiscard]] RocketState verticalRocketStateAt(const VerticalRocket& rocket, double time);

} // namespace impetus
