// Kinetics (ch. 4): ship with thrust and linear resistance, box tipping versus sliding.
//
// Forces known, motion wanted: the book's six steps (mass properties; every force and moment,
// reactions included; their sums; the accelerations from F = m a and M = I alpha; integrate once
// for the velocities, twice for the displacements), here solved in closed form. SI units. Every
// function validates its input and throws impetus::Error naming the offending parameter.
#pragma once

#include <impetus/core/constants.hpp>

#include <optional>

namespace impetus {

// ---- Ship with thrust and linear resistance (ch. 4, Ex 4.1) ----------------------------------
//
// A ship moving in a straight line, buoyancy balancing its weight: m dv/dt = T - C v. With
// k = C / m (1/s) and v_inf = T / C:
//   v(t) = v_inf + (v0 - v_inf) e^{-k t},
//   s(t) = v_inf t + (v0 - v_inf) (1 - e^{-k t}) / k,
//   a(t) = (T - C v(t)) / m = (T / m - k v0) e^{-k t}.
// From rest this is the book's v = (T/C)(1 - e^{-Ct/m}), s = (T/C) t - (T m / C^2)(1 - e^{-Ct/m}),
// a = (T/m) e^{-Ct/m}. C -> 0 gives uniform acceleration exactly (expm1 and a series, no 0/0).

/// The ship's motion at one time.
struct ShipState {
  double speed;        ///< v, m/s
  double distance;     ///< s from the start, m
  double acceleration; ///< a, m/s^2
};

/// thrust T in N (any sign: negative is astern); mass m > 0 kg; resistanceCoefficient C >= 0 in
/// N s/m (kg/s); time t >= 0 s; initialSpeed v0 in m/s.
[[nodiscard]] ShipState shipMotion(double thrust, double mass, double resistanceCoefficient, double time,
                                   double initialSpeed = 0.0);

/// v_inf = T / C, m/s: the speed at which resistance balances thrust. resistanceCoefficient > 0.
[[nodiscard]] double shipTerminalSpeed(double thrust, double resistanceCoefficient);

/// tau = m / C, s: the time in which the gap to the terminal speed shrinks by e.
[[nodiscard]] double shipTimeConstant(double mass, double resistanceCoefficient);

// ---- Box pushed on a floor: tipping versus sliding (ch. 4, Fig 4-6) ---------------------------
//
// A uniform box of width w (along the push) and height h, centre of gravity at its centre, on
// level ground; a horizontal push F on its trailing face at height h_p. The floor holds it at
// its leading edge (reaction R1) and trailing edge (R2), with friction F_f along the floor
// opposing the push. While the box stays flat (alpha = 0):
//   R1 + R2 = m g,   F - F_f = m a,   moments about the centre of gravity = 0:
//   F (h_p - h/2) + F_f h/2 = (w/2)(R1 - R2).
// Held by static friction (F_f = F, a = 0):  R2 = m g / 2 - F h_p / w.
// Sliding (F_f = mu_k m g, a = (F - mu_k m g) / m):
//   R2 = m g / 2 - [F (h_p - h/2) + mu_k m g h/2] / w.
// It starts to tip about the leading edge when R2 reaches 0:
//   held:    F_tip = m g w / (2 h_p), which needs F_tip <= mu_s m g, i.e. h_p >= w / (2 mu_s);
//   sliding: F_tip = m g (w - mu_k h) / (2 h_p - h), for h_p > h/2.
// With mu_s = mu_k the two agree when F_tip = mu m g (the spec's check).

/// The box and the push.
struct PushedBox {
  double mass;                                 ///< m > 0, kg
  double width;                                ///< w > 0, along the push, m
  double height;                               ///< h > 0, m
  double pushHeight;                           ///< h_p in (0, h], m
  double staticCoefficient;                    ///< mu_s >= 0
  double kineticCoefficient;                   ///< 0 <= mu_k <= mu_s
  double gravity = constants::standardGravity; ///< g >= 0, m/s^2
};

/// The floor's reactions on a box that stays flat.
struct BoxSupportReactions {
  double leadingReaction;  ///< R1, at the leading bottom edge, N (up)
  double trailingReaction; ///< R2, at the trailing bottom edge (the pushed side), N (up)
  double frictionForce;    ///< F_f, along the floor against the push, N
  double acceleration;     ///< a, m/s^2, in the direction of the push
};

/// The reactions at a push F >= 0 N, with the box held by static friction (sliding = false: the
/// friction the equilibrium needs, F_f = F, whether or not mu_s can supply it) or sliding in the
/// direction of the push (sliding = true: F_f = mu_k m g). A negative reaction means the box
/// cannot stay flat: trailingReaction < 0 tips it forward about its leading edge,
/// leadingReaction < 0 backward about its trailing edge (a hard, low push on a tall sliding box).
[[nodiscard]] BoxSupportReactions boxSupportReactions(const PushedBox& box, double pushForce, bool sliding);

/// What a box at rest does under a push.
enum class BoxMotion {
  rests,        ///< held by static friction
  slides,       ///< slides and stays flat
  tipsForward,  ///< rotates about its leading bottom edge
  tipsBackward, ///< sliding, rotates about its trailing bottom edge
};

/// The motion at the onset of a push F >= 0 N on a box at rest, and the reactions of the
/// regime it starts in (held when F <= mu_s m g, else sliding).
struct BoxResponse {
  BoxMotion motion;
  BoxSupportReactions reactions;
};

[[nodiscard]] BoxResponse pushBoxAtRest(const PushedBox& box, double pushForce);

/// The thresholds of a push increased slowly from zero.
struct BoxTipping {
  double slidingForce;       ///< mu_s m g, N: the push at which the box starts to slide
  double tippingForceAtRest; ///< m g w / (2 h_p), N: the push at which a held box tips
  double criticalPushHeight; ///< w / (2 mu_s), m: at or above it the box tips before it slides (+inf for mu_s = 0)
  bool tipsFirst;            ///< tippingForceAtRest <= slidingForce
  /// m g (w - mu_k h) / (2 h_p - h), N (at least 0): the push at which a *sliding* box tips
  /// forward; none when h_p <= h/2 (pushing at or below the centre a stronger push never tips
  /// it forward).
  std::optional<double> tippingForceWhileSliding;
  /// m g (w + mu_k h) / (h - 2 h_p), N: the push at which a sliding box tips backward about its
  /// trailing edge; none when h_p >= h/2.
  std::optional<double> backwardTippingForceWhileSliding;
};

[[nodiscard]] BoxTipping boxTipping(const PushedBox& box);

} // namespace impetus
