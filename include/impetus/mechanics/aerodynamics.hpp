// Aerodynamics of a ball (ch. 6): Reynolds number, the drag coefficient of a smooth sphere
// across Reynolds numbers (drag crisis included), drag and Magnus forces on the velocity
// relative to the air, the book's constant-coefficient Magnus model solved correctly, and a ball
// flight integrator (gravity + drag + Magnus, RK4).
//
// Frame: right-handed, y up, gravity along -y. Wind is moving air: drag and lift act on the
// velocity relative to the air, v_rel = v - wind (the book's Cannon2 treats wind as a constant
// force instead; see docs/mechanics/projectiles.md).
#pragma once

#include <impetus/core/constants.hpp>
#include <impetus/math/vec2.hpp>
#include <impetus/math/vec3.hpp>

#include <vector>

namespace impetus {

/// Dynamic viscosity of dry air at 15 degrees C (288.15 K), Pa s: Sutherland's law
/// mu = beta T^(3/2) / (T + S) with beta = 1.458e-6 kg/(m s K^1/2) and S = 110.4 K, as the
/// U.S. Standard Atmosphere 1976 and the ICAO Standard Atmosphere (Doc 7488) tabulate it at sea
/// level.
inline constexpr double airDynamicViscosity = 1.7894e-5;

/// Kinematic viscosity of the same air, nu = mu / rho with rho = 1.225 kg/m^3, m^2/s
/// (ISA sea-level table value 1.4607e-5).
inline constexpr double airKinematicViscosity = airDynamicViscosity / constants::airDensitySeaLevel;

/// Rn = rho v L / mu. speed v in m/s (>= 0), length L in m (> 0; a sphere's diameter),
/// density rho in kg/m^3 (> 0), dynamicViscosity mu in Pa s (> 0). Dimensionless.
[[nodiscard]] double reynoldsNumber(double speed, double length, double density = constants::airDensitySeaLevel,
                                    double dynamicViscosity = airDynamicViscosity);

/// Rn = v L / nu with the kinematic viscosity nu in m^2/s (> 0).
[[nodiscard]] double reynoldsNumberKinematic(double speed, double length, double kinematicViscosity);

/// The Reynolds number up to which the smooth-sphere correlation is fitted to data.
inline constexpr double sphereDragCorrelationLimit = 1.0e6;

/// Drag coefficient of a smooth sphere at Reynolds number Re (> 0), from the correlation of
/// F. A. Morrison, "An Introduction to Fluid Mechanics", Cambridge University Press (2013), fitted
/// to the standard sphere-drag data for Re up to 1e6:
///   Cd = 24/Re + 2.6 (Re/5) / (1 + (Re/5)^1.52)
///        + 0.411 (Re/263000)^-7.94 / (1 + (Re/263000)^-8) + Re^0.8 / 461000.
/// It has the Stokes limit 24/Re, Cd(1) = 24.7, the plateau 0.39-0.48 between 1e3 and 2e5, and
/// the drag crisis between 2e5 (0.41) and 4e5 (0.087). Above 1e6 the last term would grow without
/// bound, so Cd is held at its value at 1e6 (0.141), within the 0.1-0.2 of measured supercritical
/// smooth spheres. Dimpled or seamed balls (golf, baseball) reach their crisis at lower Re: use a
/// measured constant Cd for them.
[[nodiscard]] double sphereDragCoefficient(double reynolds);

/// Drag force 1/2 rho |v| v A Cd, opposite to the velocity relative to the air, N.
/// relativeVelocity in m/s (ball minus wind), airDensity kg/m^3 (>= 0), area m^2 (> 0),
/// dragCoefficient (>= 0).
[[nodiscard]] Vec3d dragForce(const Vec3d& relativeVelocity, double airDensity, double area, double dragCoefficient);

/// Spin ratio (spin parameter) S = r w / v: the equator speed of the spin over the air speed.
/// radius r in m (> 0), spinRate w in rad/s (>= 0), speed v in m/s (> 0).
[[nodiscard]] double spinRatio(double radius, double spinRate, double speed);

/// Lift coefficient of a baseball from its spin ratio S (>= 0), the fit of G. S. Sawicki,
/// M. Hubbard and W. J. Stronge, "How to hit home runs: Optimum baseball bat swing parameters for
/// maximum range trajectories", Am. J. Phys. 71 (11), 1152-1162 (2003), doi:10.1119/1.1604384:
///   C_L = 1.5 S for S <= 0.1,  C_L = 0.09 + 0.6 S for S > 0.1  (continuous at 0.15).
/// Baseball lift measurements cover roughly S = 0.1-0.6 (e.g. A. M. Nathan, Am. J. Phys. 76, 119
/// (2008)); treat larger S as an extrapolation.
[[nodiscard]] double liftCoefficientSawicki2003(double spinRatio);

/// The book's idealized Magnus coefficient for a sphere (ch. 6 sample program):
/// C = pi^2 rho r^3 w, N s/m, so that |F| = C v. airDensity kg/m^3 (>= 0), radius m (> 0),
/// spinRate rad/s (any sign: the sign is the sense of rotation). It is potential-flow
/// circulation theory, not data: for the book's own 45 m/s, 30 rev/s pitch it gives 5.0 N, 3.5 times
/// the ball's weight, where the book quotes lift up to 33 % of the weight (Ex 6.2): about 10x
/// too much. Kept as an explicit option to reproduce the book.
[[nodiscard]] double idealMagnusCoefficient(double airDensity, double radius, double spinRate);

/// How the Magnus lift coefficient is obtained.
enum class LiftModel {
  none,                ///< no Magnus force
  sawicki2003,         ///< C_L(S) of Sawicki, Hubbard & Stronge (2003), baseball
  constantCoefficient, ///< a fixed C_L (BallProperties::liftCoefficient)
  idealizedSphere,     ///< the book's F = pi^2 rho r^3 (w x v): overpredicts about 10x
};

/// Magnus force on a sphere of radius r (m) spinning at `spin` (rad/s, vector along the spin
/// axis by the right-hand rule) moving at relativeVelocity (m/s) through air of density rho:
///   F = 1/2 rho |v|^2 A C_L (w_hat x v_hat),  A = pi r^2,  C_L from the model and S = r |w| / |v|,
/// perpendicular to the velocity, so it does no work. idealizedSphere: F = pi^2 rho r^3 (w x v).
/// Zero spin or zero relative speed gives zero force. liftCoefficient is used by
/// constantCoefficient only.
[[nodiscard]] Vec3d magnusForce(const Vec3d& relativeVelocity, const Vec3d& spin, double radius, double airDensity,
                                LiftModel model, double liftCoefficient = 0.0);

// ---------------------------------------------------------------------------------------------
// The book's constant-coefficient Magnus model (ch. 6 sample program), solved correctly.

/// A ball in the x-y plane (y up) with gravity and a Magnus force F = C (z_hat x v), no drag.
/// C > 0 is backspin for a ball moving along +x (lift up), C < 0 topspin.
struct MagnusPlaneLaunch {
  Vec2d position;                              ///< m
  Vec2d velocity;                              ///< m/s
  double mass = 1.0;                           ///< kg, > 0
  double magnusCoefficient = 0.0;              ///< C, N s/m (e.g. idealMagnusCoefficient)
  double gravity = constants::standardGravity; ///< m/s^2, >= 0
};

struct MagnusPlaneState {
  double time = 0.0; ///< s
  Vec2d position;    ///< m
  Vec2d velocity;    ///< m/s
};

/// Exact solution of m dv/dt = C (z_hat x v) - m g y_hat: with Omega = C/m the velocity circles
/// at rate Omega around the drift velocity (g/Omega, 0):
///   vx = g/Omega + (vx0 - g/Omega) cos(Omega t) - vy0 sin(Omega t)
///   vy = (vx0 - g/Omega) sin(Omega t) + vy0 cos(Omega t)
/// and the position is its integral. Evaluated in a form without the g/Omega terms
/// ((1 - cos)/theta via sin^2(theta/2), a series for (theta - sin theta)/theta^2 when
/// |theta| < 1), so it is accurate for any Omega including 0 (the vacuum parabola). Valid for all
/// t >= 0 (it does not stop at the ground).
[[nodiscard]] MagnusPlaneState magnusClosedForm(const MagnusPlaneLaunch& launch, double time);

/// The book's formula, reproduced to show its two errors (spec 4.4): the x force has the wrong
/// sign (its force is C (vy, vx) - m g y_hat, not perpendicular to v, so the "lift" does work),
/// and it is not a solution of any motion equation but a whole-flight approximation that blows
/// up at t = m/|C|:
///   vx = [vx0 + (C t/m) vy0 - C g t^2/m] / [1 - (C t/m)^2],  vy = vy0 + (C t/m) vx - g t,
///   x = x0 + vx0 t + 1/2 (C/m) vy t^2,  y = y0 + vy0 t + 1/2 (C vx/m - g) t^2.
/// Throws impetus::Error naming "time" within a relative 1e-12 of the singular time.
[[nodiscard]] MagnusPlaneState bookMagnusFormula(const MagnusPlaneLaunch& launch, double time);

/// t = m/|C|, where the book's formula divides by zero (s); +inf when C = 0.
[[nodiscard]] double bookMagnusSingularTime(const MagnusPlaneLaunch& launch);

// ---------------------------------------------------------------------------------------------
// Ball flight: gravity + quadratic drag + Magnus lift, integrated with RK4.

enum class DragModel {
  none,                ///< no drag (vacuum, apart from lift)
  constantCoefficient, ///< BallProperties::dragCoefficient
  smoothSphere,        ///< sphereDragCoefficient(Re) with Re from the relative speed
};

struct BallProperties {
  double mass = 0.145;    ///< kg, > 0
  double radius = 0.0366; ///< m, > 0
  DragModel dragModel = DragModel::constantCoefficient;
  double dragCoefficient = 0.35; ///< Cd for constantCoefficient, >= 0
  LiftModel liftModel = LiftModel::sawicki2003;
  double liftCoefficient = 0.0; ///< C_L for LiftModel::constantCoefficient
};

/// A regulation baseball: 5-5.25 oz (0.142-0.149 kg) and 9-9.25 in circumference
/// (r = 36.4-37.4 mm) by the MLB Official Baseball Rules (3.01); 0.145 kg and r = 36.6 mm (the
/// book's 2.88 in diameter). Cd 0.35 is a typical mid-flight value for a batted ball (measured
/// values run from about 0.5 at low speed down to about 0.3 past the ball's drag crisis); lift
/// from Sawicki et al. (2003).
[[nodiscard]] BallProperties baseball();

/// A golf ball at the Rules of Golf limits: 45.93 g maximum, 42.67 mm minimum diameter
/// (R&A / USGA Equipment Rules, Part 4); Cd 0.25 is typical of dimpled balls past their drag
/// crisis; lift C_L = 0.2, a mid value of the 0.1-0.35 the book quotes (Ex 6.2).
[[nodiscard]] BallProperties golfBall();

struct FlightConditions {
  double airDensity = constants::airDensitySeaLevel; ///< kg/m^3, >= 0 (0: vacuum)
  double dynamicViscosity = airDynamicViscosity;     ///< Pa s, > 0 (smoothSphere drag only)
  double gravity = constants::standardGravity;       ///< m/s^2, >= 0, along -y
  Vec3d wind;                                        ///< air velocity, m/s
  Vec3d spin;                                        ///< ball spin, rad/s, constant over the flight
  double groundHeight = 0.0;                         ///< y of the ground, m
};

struct FlightSettings {
  double timeStep = 1.0e-3; ///< RK4 step, s, > 0
  double maxTime = 60.0;    ///< give up after this long, s, > 0 (at most 1e7 steps)
};

struct FlightSample {
  double time = 0.0; ///< s
  Vec3d position;    ///< m
  Vec3d velocity;    ///< m/s
};

struct BallFlight {
  std::vector<FlightSample> samples; ///< every step from launch, the last one at landing
  bool landed = false;               ///< false: still in the air at maxTime
  double flightTime = 0.0;           ///< time of landing (or maxTime), s
  Vec3d landingPoint;                ///< position at landing, m (on y = groundHeight)
  Vec3d landingVelocity;             ///< m/s
  double maxHeight = 0.0;            ///< highest y, m (the apex found between steps)
  double apexTime = 0.0;             ///< when maxHeight is reached, s
  double range = 0.0;                ///< horizontal distance along the launch's horizontal direction, m
  double lateralDeflection = 0.0;    ///< horizontal distance across it, m (+ to the right, i.e. along dir x y_hat)
};

/// dv/dt of the ball: -g y_hat + (drag + Magnus)/m, on the velocity relative to the wind.
[[nodiscard]] Vec3d ballAcceleration(const BallProperties& ball, const FlightConditions& conditions,
                                     const Vec3d& velocity);

/// Integrates the flight with rk4Step from the launch until the ball comes down through
/// y = groundHeight (the landing instant is found inside the last step by Newton iteration on
/// RK4 sub-steps, so it has the integrator's accuracy, not the step's), or until maxTime.
/// Throws impetus::Error for bad properties or conditions, or a launch below the ground.
[[nodiscard]] BallFlight simulateBallFlight(const BallProperties& ball, const FlightConditions& conditions,
                                            const Vec3d& launchPosition, const Vec3d& launchVelocity,
                                            const FlightSettings& settings = {});

} // namespace impetus
