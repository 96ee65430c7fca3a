// Collisions (ch. 5): impulse and momentum, the coefficient of restitution, and the impulse that
// resolves an impact between two particles, spheres or rigid bodies, with Coulomb friction.
//
// This is collision *response* for one contact, the classical Newtonian model of the chapter:
// the impact is instantaneous, the bodies are rigid, positions do not change during it, and every
// non-impulsive force (gravity, drag) is negligible over its duration. Finding the contact point
// and its normal (collision detection) is geometry and belongs to the rigid worlds.
//
// Conventions shared by every function here:
// - n is the contact normal, pointing from body 2 toward body 1 (the book's convention). It may
//   have any non-zero length: it is normalized.
// - v_r = v_P1 - v_P2 is the relative velocity of the contact points; the bodies approach when
//   v_r . n < 0. Separating or resting bodies (v_r . n >= 0) get no impulse at all.
// - J >= 0 is the normal impulse: body 1 receives +J n, body 2 receives -J n.
// - An immovable body (a wall, the ground, a pinned axis) has inverse mass 0 (and inverse
//   inertia 0): that is why the vector forms take inverse masses, as game engines do.
#pragma once

#include <impetus/math/mat33.hpp>
#include <impetus/math/vec2.hpp>
#include <impetus/math/vec3.hpp>

namespace impetus {

// --- Impulse and momentum -------------------------------------------------------------------

/// Linear impulse that changes a body's velocity by `velocityChange`: J = integral F dt =
/// m (v+ - v-), N s. mass: kg, > 0; velocityChange: m/s, any finite value (signed).
[[nodiscard]] double linearImpulse(double mass, double velocityChange);

/// Average force of an impulse spread over `duration`: F_avg = J / dt, N. impulse: N s, finite;
/// duration: s, > 0.
[[nodiscard]] double averageImpactForce(double impulse, double duration);

// --- Coefficient of restitution -------------------------------------------------------------

/// The coefficient of restitution measured from the velocity components along the line of
/// action before and after an impact: e = -(v1+ - v2+) / (v1- - v2-), dimensionless.
/// All velocities m/s, finite. Throws when v1Before == v2Before (nothing collided) and when the
/// result is negative (the bodies would still be approaching, i.e. pass through each other).
/// A result above 1 is returned as measured: it means energy was added (not a passive impact).
[[nodiscard]] double coefficientOfRestitution(double v1Before, double v2Before, double v1After, double v2After);

/// The coefficient of restitution of a ball dropped on a fixed floor: e = sqrt(h_bounce / h_drop)
/// (no air drag: the impact speed is sqrt(2 g h) and g cancels). Heights in m: dropHeight > 0,
/// 0 <= bounceHeight <= dropHeight.
[[nodiscard]] double restitutionFromBounce(double dropHeight, double bounceHeight);

/// Kinetic energy dissipated by a frictionless impact: dE = 1/2 mu_red (1 - e^2) v_n^2, J (joules),
/// with the reduced mass mu_red = m1 m2 / (m1 + m2) and v_n the normal closing speed (m/s; its
/// sign does not matter). Masses in kg, > 0; one of them may be +infinity (an immovable body:
/// mu_red = the other mass). restitution in [0, 1]. The loss is independent of the tangential
/// velocities and of the frame of reference.
[[nodiscard]] double impactEnergyLoss(double mass1, double mass2, double normalClosingSpeed, double restitution);

// --- Particles and smooth spheres: impulse along the normal only --------------------------------

/// Result of a direct central impact on a line (1D).
struct Impact1DResult {
  double velocity1;         ///< body 1 after the impact, m/s
  double velocity2;         ///< body 2 after the impact, m/s
  double impulse;           ///< J >= 0, N s: body 1 gets -J along +x, body 2 gets +J
  double kineticEnergyLost; ///< 1/2 mu_red (1 - e^2)(v1 - v2)^2, J (joules), >= 0
};

/// Two particles on a line, body 1 behind body 2 (x1 < x2): they collide only when
/// v1 > v2, otherwise nothing happens. J = (1 + e)(v1 - v2) / (1/m1 + 1/m2),
/// v1+ = v1 - J/m1, v2+ = v2 + J/m2. Masses in kg, > 0, or +infinity for an immovable body
/// (not both); velocities m/s, finite; restitution in [0, 1].
[[nodiscard]] Impact1DResult resolveImpact1D(double mass1, double velocity1, double mass2, double velocity2,
                                             double restitution);

/// A particle or smooth (frictionless) sphere at the instant of impact.
struct ImpactParticle {
  double inverseMass; ///< 1/m, 1/kg, >= 0; 0 for an immovable body
  Vec3d velocity;     ///< m/s
};
/// The same in the plane.
struct ImpactParticle2D {
  double inverseMass; ///< 1/m, 1/kg, >= 0; 0 for an immovable body
  Vec2d velocity;     ///< m/s
};

/// Result of a frictionless particle impact.
struct ParticleImpactResult {
  Vec3d velocity1;          ///< m/s
  Vec3d velocity2;          ///< m/s
  double impulse;           ///< J >= 0, N s, along n on body 1 (and -n on body 2)
  double kineticEnergyLost; ///< 1/2 mu_red (1 - e^2)(v_r . n)^2, J (joules), >= 0
};
struct ParticleImpactResult2D {
  Vec2d velocity1;          ///< m/s
  Vec2d velocity2;          ///< m/s
  double impulse;           ///< J >= 0, N s, along n on body 1 (and -n on body 2)
  double kineticEnergyLost; ///< J (joules), >= 0
};

/// Frictionless impact of two particles or smooth spheres along the unit normal n (from body 2
/// toward body 1; for spheres, the line of centres): J = -(1 + e)(v_r . n) / (1/m1 + 1/m2),
/// v1+ = v1 + (J/m1) n, v2+ = v2 - (J/m2) n. Only the normal components change. No impulse
/// when v_r . n >= 0. Throws when both inverse masses are 0, n is zero or not finite,
/// restitution is outside [0, 1], or an inverse mass is negative or not finite.
[[nodiscard]] ParticleImpactResult resolveParticleImpact(const ImpactParticle& body1, const ImpactParticle& body2,
                                                         const Vec3d& normal, double restitution);
[[nodiscard]] ParticleImpactResult2D resolveParticleImpact(const ImpactParticle2D& body1, const ImpactParticle2D& body2,
                                                           const Vec2d& normal, double restitution);

// --- Rigid bodies: linear and angular impulse, with friction --------------------------------------

/// A rigid body at the instant of impact, everything in world axes.
struct ImpactBody {
  double inverseMass = 0.0;     ///< 1/m, 1/kg, >= 0; 0 for a body that cannot translate
  Mat33d inverseInertiaWorld{}; ///< I^-1 about the centre of mass in world axes (R I_body^-1 R^T),
                                ///< 1/(kg m^2): symmetric, positive semi-definite; zero for a
                                ///< body that cannot rotate
  Vec3d velocity{};             ///< of the centre of mass, m/s
  Vec3d angularVelocity{};      ///< rad/s
  Vec3d offset{};               ///< r: from the centre of mass to the contact point, m
};

/// A rigid body in the plane: the rotation axis is z, so inertia and spin are scalars.
struct ImpactBody2D {
  double inverseMass = 0.0;     ///< 1/m, 1/kg, >= 0
  double inverseInertia = 0.0;  ///< 1/I_z about the centre of mass, 1/(kg m^2), >= 0
  Vec2d velocity{};             ///< of the centre of mass, m/s
  double angularVelocity = 0.0; ///< rad/s, counter-clockwise positive
  Vec2d offset{};               ///< r: from the centre of mass to the contact point, m
};

/// Result of a rigid-body impact: the bodies' velocities after it and the impulse that acted.
struct ImpactResult {
  Vec3d velocity1{};              ///< m/s
  Vec3d angularVelocity1{};       ///< rad/s
  Vec3d velocity2{};              ///< m/s
  Vec3d angularVelocity2{};       ///< rad/s
  Vec3d impulse{};                ///< total impulse on body 1, J n - j_t t, N s (body 2 gets -impulse)
  double normalImpulse = 0.0;     ///< J >= 0, N s
  double frictionImpulse = 0.0;   ///< j_t = min(mu J, j_stick) >= 0, N s, along -t
  bool sticking = false;          ///< true when friction stopped the slip (j_t = j_stick <= mu J)
  double kineticEnergyLost = 0.0; ///< -P . (v_r- + v_r+) / 2 >= 0, J (joules)
};

struct ImpactResult2D {
  Vec2d velocity1{};              ///< m/s
  double angularVelocity1 = 0.0;  ///< rad/s
  Vec2d velocity2{};              ///< m/s
  double angularVelocity2 = 0.0;  ///< rad/s
  Vec2d impulse{};                ///< total impulse on body 1, N s (body 2 gets -impulse)
  double normalImpulse = 0.0;     ///< J >= 0, N s
  double frictionImpulse = 0.0;   ///< j_t >= 0, N s
  bool sticking = false;          ///< friction stopped the slip
  double kineticEnergyLost = 0.0; ///< J (joules), >= 0
};

/// The impulse of an impact between two rigid bodies (book ch. 5, implemented in its ch. 10),
/// with Coulomb friction capped so that the slip never reverses.
///
/// Normal impulse, with v_P = v + w x r and v_r = v_P1 - v_P2:
///   J = -(1 + e)(v_r . n) / [1/m1 + 1/m2 + n . ((I1^-1 (r1 x n)) x r1) + n . ((I2^-1 (r2 x n)) x r2)].
/// Friction: with v_r' the relative velocity after the normal impulse, the slip direction is
/// t = unit(v_r' - (v_r' . n) n) and the friction impulse -j_t t has
///   j_t = min(mu J, j_stick),  j_stick = (v_r' . t) / [1/m1 + 1/m2 + t . ((I1^-1 (r1 x t)) x r1) + (same for 2)],
/// the impulse that just stops the slip along t (the rotational terms matter: a solid ball on a
/// fixed floor has 1/m + 5/(2m), so a cap with the masses alone would be 3.5 times too large and
/// reverse the slip). Body 1 gets P = J n - j_t t: v1+ = v1 + P/m1, w1+ = w1 + I1^-1 (r1 x P);
/// body 2 gets -P.
///
/// With this choice the kinetic energy never increases: the normal impulse removes
/// J (1 - e)|v_r . n| / 2 and the friction impulse j_t (v_r' . t - j_t k_t / 2) >= j_t (v_r' . t) / 2.
/// Frictionless (mu = 0) and e = 1, energy is conserved exactly; momentum always is.
/// Limits of the model: with friction, the coupling through rotation can make the final normal
/// velocity differ from -e (v_r . n); for bodies whose inertia couples the two tangent directions
/// (3D, off-diagonal terms), sticking stops the slip along t, not the small slip across it.
///
/// Throws impetus::Error naming the field for a negative or non-finite inverse mass, an inverse
/// inertia that is not finite, symmetric and positive semi-definite, a non-finite velocity or
/// offset, a zero or non-finite normal, restitution outside [0, 1], a negative friction
/// coefficient, two immovable bodies, or a contact that neither body can move along the normal.
[[nodiscard]] ImpactResult resolveImpact(const ImpactBody& body1, const ImpactBody& body2, const Vec3d& normal,
                                         double restitution, double friction = 0.0);

/// The same in the plane, where each angular term of the denominators is (r x n)_z^2 / I.
[[nodiscard]] ImpactResult2D resolveImpact(const ImpactBody2D& body1, const ImpactBody2D& body2, const Vec2d& normal,
                                           double restitution, double friction = 0.0);

} // namespace impetus
