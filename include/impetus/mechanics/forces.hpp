// Forces (ch. 3): gravitation, weight, drag, pressure, buoyancy, spring-damper, torque.
//
// SI units: N, kg, m, s, Pa = N/m^2, kg/m^3. Vector forces are in world axes. Every function
// validates its input and throws impetus::Error naming the offending parameter (negative mass
// or density, zero area, non-finite values...). Friction is in friction.hpp.
#pragma once

#include <impetus/core/constants.hpp>
#include <impetus/math/vec2.hpp>
#include <impetus/math/vec3.hpp>

#include <span>

namespace impetus {

// ---- Gravitation and weight -------------------------------------------------------------------

/// Newton's law of gravitation, F = G m1 m2 / r^2, N: the attraction between two point masses
/// (or spherically symmetric bodies) whose centres are `distance` m > 0 apart. Masses in kg
/// (>= 0); G in m^3 kg^-1 s^-2 (CODATA 2018 by default; the book used 6.673e-11).
[[nodiscard]] double gravitationalForce(double mass1, double mass2, double distance,
                                        double gravitationalConstant = constants::gravitationalConstant);

/// The same as a vector: the force on body 1 at position1, pulled toward body 2 at position2,
/// F1 = G m1 m2 (p2 - p1) / |p2 - p1|^3; the force on body 2 is -F1. Throws (naming position2)
/// when the centres coincide.
[[nodiscard]] Vec3d gravitationalForce(double mass1, const Vec3d& position1, double mass2, const Vec3d& position2,
                                       double gravitationalConstant = constants::gravitationalConstant);

/// W = m g, N. mass >= 0 kg; gravity >= 0 m/s^2 (standard gravity 9.80665 by default; the book
/// uses 9.8 and 9.81).
[[nodiscard]] double weight(double mass, double gravity = constants::standardGravity);

/// g(h) = G M / (R + h)^2, m/s^2: the gravitational acceleration at `altitude` h m above the
/// surface of a spherically symmetric body of mass M kg (> 0) and radius R m (> 0). Valid for
/// h >= 0; a small negative h (a valley) is accepted, but R + h must stay positive. It is pure
/// gravitation: the Earth's rotation lowers the measured g by up to 0.034 m/s^2 at the equator.
[[nodiscard]] double gravityAtAltitude(double altitude, double bodyMass, double bodyRadius,
                                       double gravitationalConstant = constants::gravitationalConstant);

// ---- Fluid drag --------------------------------------------------------------------------------
//
// Drag acts on the velocity relative to the fluid, v_rel = v - fluidVelocity: a body at rest in
// a wind is pushed downwind, and a body drifting with a current feels none. (The book's Cannon2
// applies wind as a separate constant force; this is the physical form.)

/// Idealized laminar drag F = -C v_rel, N, with dragConstant C >= 0 in N s/m.
[[nodiscard]] Vec3d linearDragForce(const Vec3d& velocity, double dragConstant, const Vec3d& fluidVelocity = {});

/// Idealized turbulent drag F = -C |v_rel| v_rel, N, with dragConstant C >= 0 in kg/m (= N s^2/m^2).
[[nodiscard]] Vec3d quadraticDragForce(const Vec3d& velocity, double dragConstant, const Vec3d& fluidVelocity = {});

/// C = 1/2 rho A C_d, kg/m: the constant of quadraticDragForce for a fluid of density rho
/// (kg/m^3, >= 0), a reference (frontal) area A (m^2, > 0) and a drag coefficient C_d (>= 0).
[[nodiscard]] double quadraticDragConstant(double density, double area, double dragCoefficient);

/// F = -1/2 rho A C_d |v_rel| v_rel, N (the quadratic drag of a body in a fluid).
[[nodiscard]] Vec3d fluidDragForce(const Vec3d& velocity, double density, double area, double dragCoefficient,
                                   const Vec3d& fluidVelocity = {});

// ---- Pressure and buoyancy ---------------------------------------------------------------------

/// F = P A, N: the force of a uniform pressure P (Pa, any sign: gauge pressure may be negative)
/// on a flat area A (m^2, > 0), normal to it.
[[nodiscard]] double pressureForce(double pressure, double area);

/// P = P0 + rho g h, Pa: the pressure at `depth` h m (>= 0) below the surface of a fluid at rest
/// of density rho (kg/m^3, >= 0), with surfacePressure P0 (Pa; 0 gives the gauge pressure,
/// constants::standardAtmosphere the absolute pressure under air at sea level).
[[nodiscard]] double hydrostaticPressure(double density, double depth, double gravity = constants::standardGravity,
                                         double surfacePressure = 0.0);

/// Archimedes: F_B = rho g V, N, upward, for a displaced volume V (m^3, >= 0) of a fluid of
/// density rho (kg/m^3, >= 0). rho g is the fluid's specific weight, N/m^3.
[[nodiscard]] double buoyantForce(double fluidDensity, double displacedVolume,
                                  double gravity = constants::standardGravity);

/// What a uniform body released in a fluid does.
enum class Flotation {
  floats,  ///< body lighter than the fluid: it rises and floats partly submerged
  neutral, ///< same density: it stays wherever it is put
  sinks,   ///< body denser than the fluid
};

/// A uniform body of volume V immersed in a fluid.
struct ImmersedBody {
  double weight;            ///< m g = rho_body g V, N
  double buoyantForce;      ///< rho_fluid g V when fully submerged, N
  double netForce;          ///< buoyantForce - weight, N, upward positive, fully submerged
  double submergedFraction; ///< at equilibrium: rho_body / rho_fluid when it floats, else 1
  Flotation flotation;
};

/// Densities in kg/m^3 (bodyDensity >= 0, fluidDensity > 0), volume in m^3 (>= 0). A floating
/// body sinks until the fluid it displaces weighs as much as it does: rho_f g (f V) = rho_b g V,
/// so f = rho_b / rho_f.
[[nodiscard]] ImmersedBody immersedBody(double bodyDensity, double fluidDensity, double volume,
                                        double gravity = constants::standardGravity);

// ---- Spring-damper -----------------------------------------------------------------------------

/// A linear spring with a parallel linear damper between two points.
struct SpringDamper {
  double stiffness;  ///< k_s >= 0, N/m
  double damping;    ///< k_d >= 0, N s/m
  double restLength; ///< r >= 0, m
};

/// The force on point 1 (the force on point 2 is its negative: apply both):
///   L = p1 - p2,  F1 = -[k_s (|L| - r) + k_d ((v1 - v2) . L) / |L|] L / |L|   (N).
/// A stretched spring pulls the points together, a compressed one pushes them apart; the damper
/// opposes the rate of change of the length, so its power F1 . (v1 - v2) is never positive.
/// Coincident points (|L| = 0, the direction is undefined): the direction is taken as zero, as
/// normalize() and Box2D's distance joint do, so the force is zero, never NaN. For a zero rest
/// length this is the exact limit (the spring term k_s L -> 0); a spring with r > 0 does not
/// push coincident points apart.
[[nodiscard]] Vec3d springDamperForce(const SpringDamper& spring, const Vec3d& position1, const Vec3d& velocity1,
                                      const Vec3d& position2, const Vec3d& velocity2);

/// The same in the plane.
[[nodiscard]] Vec2d springDamperForce(const SpringDamper& spring, const Vec2d& position1, const Vec2d& velocity1,
                                      const Vec2d& position2, const Vec2d& velocity2);

// ---- Torque and resultants ---------------------------------------------------------------------

/// M = r x F, N m: the moment of `force` (N) applied at `arm` r (m) from the axis or point the
/// moment is taken about. Its magnitude is F d, with d the perpendicular distance from the point
/// to the line of action; a force through the point makes none.
[[nodiscard]] Vec3d torque(const Vec3d& arm, const Vec3d& force);

/// In the plane: M_z = r_x F_y - r_y F_x, N m (counter-clockwise positive).
[[nodiscard]] double torque(const Vec2d& arm, const Vec2d& force);

/// A force and the point where it acts, in world axes.
struct AppliedForce {
  Vec3d force; ///< N
  Vec3d point; ///< m
};

/// The sum of a set of forces and the sum of their moments about one point.
struct ForceResultant {
  Vec3d force;  ///< sum F_i, N
  Vec3d torque; ///< sum (p_i - about) x F_i, N m
};

/// Forces add as vectors wherever they act; their moments add about a common point `about`.
[[nodiscard]] ForceResultant resultant(std::span<const AppliedForce> forces, const Vec3d& about);

/// A force and its point of application in the plane.
struct AppliedForce2 {
  Vec2d force; ///< N
  Vec2d point; ///< m
};

/// The plane resultant: the force and the moment about z.
struct ForceResultant2 {
  Vec2d force;   ///< N
  double torque; ///< N m, counter-clockwise positive
};

[[nodiscard]] ForceResultant2 resultant(std::span<const AppliedForce2> forces, const Vec2d& about);

} // namespace impetus
