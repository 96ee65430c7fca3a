// The book's cannon (ch. 2) and Cannon2 (ch. 4): a shell fired from a barrel of length L at
// angles alpha (from the vertical +y, 0 = straight up, pi/2 = level) and gamma (in the x-z
// plane from +x toward +z), flying in vacuum or with linear drag and wind, at a target box.
//
// Frames: +y up, x and z horizontal. Everything SI: m, s, kg, rad.
//
// What changed from the book, and why:
// - the shot is tested against the target by the segment between two samples, not the point at
//   each sample, so a fast shell cannot pass through the target between steps (the book's test
//   can, as it admits); the ground impact is found by root-finding, not at the first sample below
//   ground;
// - Cannon2's wind is, by default, moving air that the drag acts against (F = -C (v - w)); the
//   book's separate wind force F = -Cw vw (cos gw, 0, sin gw) with its own coefficient is kept as
//   WindModel::bookConstantForce. With linear drag the two are the same physics exactly when
//   Cw = C (moving air adds the constant force C w); with any other Cw the book's shell drifts at
//   Cw/C times the wind speed, which no air does. Only the moving-air form carries over to
//   quadratic drag (ch. 6's ball flight), where wind is not a constant force at all;
// - C = 0 (no drag) is the vacuum limit, computed without the book's division by zero;
// - pi is pi, not 3.14.
#pragma once

#include <impetus/math/vec3.hpp>

#include <vector>

namespace impetus {

/// The gun: muzzle speed, barrel angles and geometry.
struct CannonSetup {
  double muzzleSpeed = 50.0;  ///< m/s, > 0
  double altitude = 0.785398; ///< alpha: angle of the barrel from the vertical (+y), rad, in [0, pi]
  double azimuth = 0.0;       ///< gamma: angle in the x-z plane from +x toward +z, rad
  double barrelLength = 2.0;  ///< L, m, >= 0
  double baseHeight = 0.0;    ///< Yb: height of the barrel's pivot above the ground, m
};

/// Direction cosines of the barrel (cos X, cos Y, cos Z) = (sin a cos g, cos a, sin a sin g).
[[nodiscard]] Vec3d barrelDirection(double altitude, double azimuth);

/// Where the shell leaves the barrel: (L sin a cos g, Yb + L cos a, L sin a sin g), m.
[[nodiscard]] Vec3d muzzlePosition(const CannonSetup& cannon);

/// Vm times the direction cosines, m/s.
[[nodiscard]] Vec3d muzzleVelocity(const CannonSetup& cannon);

/// How wind acts on the shell (Cannon2).
enum class WindModel {
  /// Linear drag against the air, which moves with the wind: F = -C (v - w). Physical default.
  movingAir,
  /// The book's constant force F = -Cw vw (cos gw, 0, sin gw), independent of the shell's
  /// velocity. Kept to reproduce the book's program.
  bookConstantForce,
};

/// Air and wind for Cannon2. With dragCoefficient = 0 and no wind, the vacuum model.
struct Atmosphere {
  double gravity = 9.81;        ///< m/s^2 (the book uses 9.81 in ch. 2)
  double dragCoefficient = 0.0; ///< C, linear drag F = -C v, kg/s (N s/m), >= 0
  double windSpeed = 0.0;       ///< vw, m/s, >= 0
  double windDirection = 0.0;   ///< gw: where the wind comes from, in the x-z plane from +x toward
                                ///< +z, rad (gw = 0 blows toward -x, as in the book)
  double windCoefficient = 0.0; ///< Cw, kg/s: only for WindModel::bookConstantForce
  WindModel windModel = WindModel::movingAir;
};

/// A shell's state at time t after firing.
struct ShellState {
  double time = 0.0; ///< s
  Vec3d position;    ///< m
  Vec3d velocity;    ///< m/s
};

/// The closed-form flight of a shell of `mass` kg: per axis m dv/dt = -C v + F with constant F,
/// so v(t) = v_inf + (v1 - v_inf) e^(-kt) and s(t) = s1 + v_inf t + (v1 - v_inf)(1 - e^(-kt))/k,
/// k = C/m, v_inf = F/C (the book's Cannon2 equations), evaluated without cancellation as k -> 0
/// where they become s1 + v1 t + F t^2/(2m). Exact for any t >= 0.
class ShellFlight {
public:
  /// Throws impetus::Error for a non-positive mass, negative coefficients or speeds, or
  /// non-finite input.
  ShellFlight(const CannonSetup& cannon, double mass, const Atmosphere& air);

  [[nodiscard]] ShellState at(double time) const;
  /// The constant force on the shell apart from the drag -C v, N.
  [[nodiscard]] const Vec3d& constantForce() const noexcept { return force_; }
  /// Terminal velocity F/C (infinite components when C = 0), m/s.
  [[nodiscard]] Vec3d terminalVelocity() const noexcept;

private:
  Vec3d start_;
  Vec3d launch_;
  Vec3d force_;
  double mass_;
  double decayRate_; // k = C/m, 1/s
};

/// An axis-aligned target: centre and full extents (Length along x, Height along y, Width along
/// z, as in the book's dialog).
struct TargetBox {
  Vec3d center;
  Vec3d size; ///< m, each >= 0
};

enum class ShotOutcome { hit, ground, timeout };

struct ShotResult {
  ShotOutcome outcome = ShotOutcome::timeout;
  double time = 0.0;                  ///< s: when the shell entered the target or reached the ground
  Vec3d position;                     ///< where, m
  Vec3d velocity;                     ///< with which velocity, m/s
  std::vector<ShellState> trajectory; ///< samples every time step, ending at the outcome
};

/// Flies a shell until it enters the target (inclusive box), reaches the ground (y = 0) or
/// `maxTime` passes. Samples every `timeStep` s; between two samples the chord is tested against
/// the box (no tunnelling) and the ground crossing is refined by bisection to 1e-9 s.
/// Throws impetus::Error for a non-positive time step or a negative target size.
[[nodiscard]] ShotResult fireAtTarget(const ShellFlight& flight, const TargetBox& target, double timeStep = 0.01,
                                      double maxTime = 3600.0);

/// The book's 2D rifle shot (ch. 2): fired level at `muzzleSpeed` at a target `distance` away;
/// time to the target n / vm and the drop 1/2 g t^2 in vacuum.
struct RifleShot {
  double time = 0.0; ///< s
  double drop = 0.0; ///< m, below the line of the barrel
};
[[nodiscard]] RifleShot rifleShot(double distance, double muzzleSpeed, double gravity = 9.81);

} // namespace impetus
