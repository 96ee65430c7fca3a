// An hourglass on a phone (ch. 8's suggestion, with ch. 21's accelerometer): sand grains as
// particles in a glass of two bulbs joined by a neck, under the gravity the accelerometer
// reads. Turn the device over and the sand flows the other way; tilt it and the flow slows.
//
// The glass lies in the screen's plane, in the device's frame (x right, y towards the top edge,
// metres, the neck's centre at the origin). Each bulb is a box of width W and height H (from the
// neck to its end) whose end by the neck is a funnel: straight walls at `funnelAngle` from the
// neck's line down to the neck, a slot of width D. The walls are box obstacles of the particle
// world, laid outside the outline so that its inside is exactly the glass.
//
// The grains are discs (particles at z = 0 that stay there: every force and contact normal
// lies in the plane) of diameters spread evenly around d, all of the mass of a mean grain
// (rho pi d^3 / 6), colliding with each other plastically (restitution 0) and with the glass
// with Coulomb friction. The in-plane part of gravity, g (a_x, a_y) from a reading in the
// gravity-direction convention, drives them; the part across the screen (a_z) presses them on
// the glass and is left out (the screen is frictionless).
//
// A granular flow through an orifice does not depend on the height of the sand above it, unlike
// a liquid's (Torricelli: v = sqrt(2 g h)): the grains above the neck are held by arches and by
// friction on the walls (Janssen), and only those that fall free from a region about one neck
// width above the orifice leave it. Dimensional analysis then gives Beverloo's law, in 3D
// W = C rho_b sqrt(g) (D - k d)^(5/2) (kg/s), and through a slot in 2D
//   Q = C (phi / a) sqrt(g) (D - k d)^(3/2)   grains/s,   a = pi d^2 / 4 (a grain's area)
// with phi the packing fraction (about 0.8 for discs), k ~ 1.5 (the grains' centres cannot
// pass within a radius of the edges) and C of order 1. beverlooRate2d evaluates it; the model's
// own C and k, measured, are in docs/digital-physics.md.
#pragma once

#include <impetus/math/vec2.hpp>
#include <impetus/math/vec3.hpp>
#include <impetus/particles/particle_world.hpp>
#include <impetus/sensors/tilt.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace impetus::sensors {

struct HourglassSettings {
  double bulbWidth = 0.05;                 ///< W, m: each bulb's inner width
  double bulbHeight = 0.06;                ///< H, m: from the neck to a bulb's end (> its funnel)
  double neckWidth = 0.008;                ///< D, m: the slot between the bulbs (> the largest grain)
  double funnelAngle = 1.0471975511965976; ///< rad from the neck's line, in [pi/4, pi/2): 60 deg
  int grainCount = 300;                    ///< N, >= 1 (must fit in one bulb)
  double grainDiameter = 0.002;            ///< d, m: the mean
  double sizeSpread = 0.1;                 ///< diameters even in d (1 -+ spread), [0, 0.5): no crystals
  double grainDensity = 2650.0;            ///< rho, kg/m^3 (quartz)
  double gravity = 9.80665;                ///< m/s^2 per g of reading
  double wallFriction = 0.5;               ///< mu between grain and glass
  double wallRestitution = 0.1;            ///< e between grain and glass, [0, 1]
  double damping = 0.0;                    ///< 1/s: linear drag on each grain (air), >= 0
  int substeps = 16;                       ///< particle-world substeps per step, >= 1
  double settleTime = 1.0;                 ///< s the sand settles on a stopper in the neck first, >= 0
  std::uint32_t seed = 1;                  ///< grain sizes: the same seed, the same sand
  AccelConvention convention = AccelConvention::gravityDirection; ///< of the readings (iOS's)
};

/// The bulbs in the device's frame: top is +y, whichever way up the device is held.
enum class Bulb { top, bottom };

class Hourglass {
public:
  /// The sand starts in `filled`, in loose rows from the neck's end of the bulb outward (it
  /// settles as soon as gravity acts). Throws impetus::Error naming the setting: sizes finite
  /// and positive, the funnel shorter than the bulb, the neck wider than the largest grain,
  /// funnelAngle in (0, pi/2), sizeSpread in [0, 0.5), wallRestitution in [0, 1], damping and
  /// wallFriction >= 0, substeps >= 1, and grainCount >= 1 and no more than one bulb holds.
  explicit Hourglass(const HourglassSettings& settings, Bulb filled = Bulb::top);

  /// Advances by dt s (0 < dt <= 1) under an accelerometer reading (g, in settings.convention),
  /// held over the step. Throws impetus::Error naming "reading" or "dt".
  void step(const Vec3d& readingG, double dt);
  /// Advances by dt s with the device held upright in the screen's plane and turned by `tilt`
  /// rad counter-clockwise seen from the front (tiltAngle's convention: 0 upright, pi upside
  /// down): gravity g (sin tilt, -cos tilt) in the device's frame.
  void stepAtTilt(double tilt, double dt);
  /// Advances by dt s under an in-plane gravity (m/s^2, the device's frame).
  void stepWithGravity(const Vec2d& gravity, double dt);

  /// Grains whose centre is in the bulb (y > 0: top; y <= 0: bottom).
  [[nodiscard]] int grainsIn(Bulb bulb) const noexcept;
  [[nodiscard]] int grainCount() const noexcept { return static_cast<int>(radii_.size()); }
  /// Grain centres (z = 0) and radii, in the same order.
  [[nodiscard]] std::span<const Vec3f> positions() const noexcept { return world_.positions(); }
  [[nodiscard]] std::span<const Vec3f> velocities() const noexcept { return world_.velocities(); }
  [[nodiscard]] std::span<const float> radii() const noexcept { return radii_; }
  /// The glass's inner outline, counter-clockwise from the bottom bulb's right end corner
  /// (10 points, m).
  [[nodiscard]] const std::vector<Vec2d>& outline() const noexcept { return outline_; }
  /// The funnel's height above (or below) the neck: (W - D) tan(funnelAngle) / 2, m.
  [[nodiscard]] double funnelHeight() const noexcept;
  /// The in-plane gravity of the last step, m/s^2.
  [[nodiscard]] const Vec2d& gravity() const noexcept { return gravity_; }
  [[nodiscard]] double time() const noexcept { return time_; }
  [[nodiscard]] const HourglassSettings& settings() const noexcept { return settings_; }
  [[nodiscard]] const ParticleWorld& world() const noexcept { return world_; }
  /// The grains' state hash (ParticleWorld::stateHash): equal hashes, identical sand.
  [[nodiscard]] std::uint64_t stateHash() const { return world_.stateHash(); }

private:
  HourglassSettings settings_;
  ParticleWorld world_;
  std::vector<float> radii_;
  std::vector<Vec2d> outline_;
  Vec2d gravity_;
  double time_ = 0.0;
};

/// The in-plane gravity (m/s^2, device frame) of a reading in g: g (a_x, a_y) in the
/// gravity-direction convention. Throws impetus::Error naming "reading".
[[nodiscard]] Vec2d deviceGravity(const Vec3d& readingG, AccelConvention convention, double gravity);

/// Beverloo's law for a 2D slot: grains per second Q = C (phi / (pi d^2 / 4)) sqrt(g) (D - k d)^(3/2),
/// 0 when D <= k d (the slot jams). Throws impetus::Error naming the argument (D, d, g, phi, C
/// finite and positive, k >= 0).
[[nodiscard]] double beverlooRate2d(double neckWidth, double grainDiameter, double gravity, double coefficient,
                                    double edgeFactor, double packing = 0.82);

} // namespace impetus::sensors
