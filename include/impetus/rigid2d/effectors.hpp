// Force effectors for the 2D world (the book's ch. 14 "force effector" component): objects that
// apply forces at points, once per step, through the World's public API. Call apply(world, dt)
// for each effector (or a ForceEffectorSet) right before world.step(dt):
//
//   GravityField      an extra uniform acceleration, optionally only inside a box
//   PointAttractor    an inverse-square pull toward a point, with softening
//   WindDrag          quadratic (and linear) drag on one body relative to the air, at a centre of
//                     pressure: an offset centre of pressure gives torque (weathervaning)
//   Thruster          a force along a body-local direction at a body-local point
//   SpringDamper      a spring and dashpot between two bodies' anchors (or a body and a world
//                     point), computed once and applied equal and opposite
//   Explosion         a one-shot radial impulse with linear falloff, occluded by nothing
//   Buoyancy          2D buoyancy in a water region: displaced area, drag, angular drag
//
// Units. The 2D world is a slab of unit depth: shape densities are areal (kg/m^2), so a mass in
// kg is an areal density times an area in m^2. Forces are N, torques N m, impulses N s.
//
// Timing. The world holds an applied force constant through the step's substeps, so the forces
// an effector computes are evaluated once per step. Forces that depend on position (springs,
// attraction, buoyancy) are evaluated at the state predicted a fraction beta = (k - 1) / (2 k)
// of the step ahead (k the world's substeps; 1 for the book's solver): with that choice the
// step is area-preserving for a linear spring (an undamped oscillator keeps its amplitude, and
// an orbit its radius, instead of gaining energy every step). Why: k substeps of h = dt / k
// with a constant a give v' = v + a dt, x' = x + v dt + c a dt^2 with c = (k + 1) / (2 k); for
// a = -w^2 (x + beta dt v) the step's matrix has determinant 1 + (1 - c - beta) (w dt)^2, which
// is 1 for beta = 1 - c. Held at beta = 0 instead, a 1 Hz spring stepped at 60 Hz grows from
// 0.3 m to 1.03 m amplitude in 10 s, and an orbit spirals out 15% in one turn.
//
// Sleeping. A force wakes its body, so a body an effector keeps pushing never falls asleep. The
// fields (GravityField, PointAttractor, Buoyancy) skip bodies that are already asleep: wake a
// body (World::setAwake) for a new field to act on it.
//
// Every settings struct is validated when the effector is built: a NaN, an infinity where a
// finite value is needed, or a negative coefficient throws impetus::Error naming the field.
// Body ids are checked when apply() runs (impetus::Error naming "body", "bodyA" or "bodyB").
#pragma once

#include <impetus/math/transform2.hpp>
#include <impetus/rigid2d/aabb.hpp>
#include <impetus/rigid2d/types.hpp>
#include <impetus/rigid2d/world.hpp>

#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace impetus::rigid2d {

/// Something that applies forces (or impulses) to bodies of a World, once per step.
class ForceEffector {
public:
  virtual ~ForceEffector() = default;
  /// Applies its forces for the coming step of dt seconds (forces act during the step; one-shot
  /// impulses act now). Call it before World::step(dt). Throws impetus::Error naming `dt` unless
  /// 0 < dt <= 1.
  virtual void apply(World& world, float dt) = 0;
};

/// The effectors of a world, applied in the order they were added.
class ForceEffectorSet {
public:
  /// Adds an effector and returns it (owned by the set).
  template <class E> E& add(E effector) {
    auto owned = std::make_unique<E>(std::move(effector));
    E& ref = *owned;
    effectors_.push_back(std::move(owned));
    return ref;
  }
  /// Removes an effector added to this set (by address); false when it is not here.
  bool remove(const ForceEffector& effector);
  [[nodiscard]] std::size_t size() const noexcept { return effectors_.size(); }
  /// Applies every effector for the coming step.
  void apply(World& world, float dt);

private:
  std::vector<std::unique_ptr<ForceEffector>> effectors_;
};

/// The fraction beta of the coming step at which position-dependent forces are evaluated:
/// (k - 1) / (2 k) for the soft step with k substeps, 0 for the book's solver (one
/// semi-implicit Euler step). A force F(x + beta dt v) held through the step makes the world's
/// step area-preserving for a linear spring (see the header's note). For custom effectors.
[[nodiscard]] float predictionFraction(const World& world) noexcept;

// ---------------------------------------------------------------------------------------------
// Fields.

struct GravityFieldSettings {
  Vec2f acceleration{0.0f, -10.0f}; ///< m/s^2, added to the world's gravity
  /// When set, only bodies whose centre of mass is inside the box (world, m) feel the field.
  std::optional<AABB> region;
};

/// An extra uniform acceleration on every awake dynamic body: F = m a at the centre of mass.
class GravityField final : public ForceEffector {
public:
  explicit GravityField(const GravityFieldSettings& settings);
  void apply(World& world, float dt) override;
  [[nodiscard]] const GravityFieldSettings& settings() const noexcept { return settings_; }
  void setAcceleration(const Vec2f& acceleration);

private:
  GravityFieldSettings settings_;
  std::vector<BodyId> bodies_;
};

struct PointAttractorSettings {
  Vec2f center;           ///< m, world
  float mu = 1.0f;        ///< m^3/s^2, the gravitational parameter G M (negative repels)
  float softening = 0.0f; ///< m, eps >= 0: the acceleration is mu / (r^2 + eps^2)
  /// m, > 0: bodies farther than this feel nothing. Unset: no limit.
  std::optional<float> maxRadius;
};

/// Pulls every awake dynamic body's centre of mass toward `center` with an acceleration of
/// mu / (r^2 + eps^2) (r the distance, m): F = m mu / (r^2 + eps^2) toward the centre. A body
/// exactly at the centre feels nothing.
class PointAttractor final : public ForceEffector {
public:
  explicit PointAttractor(const PointAttractorSettings& settings);
  void apply(World& world, float dt) override;
  [[nodiscard]] const PointAttractorSettings& settings() const noexcept { return settings_; }

private:
  PointAttractorSettings settings_;
  std::vector<BodyId> bodies_;
};

// ---------------------------------------------------------------------------------------------
// Per-body effectors.

struct WindDragSettings {
  BodyId body;
  Vec2f airVelocity;         ///< m/s, world
  float airDensity = 1.225f; ///< rho, kg/m^3 (sea-level air)
  /// Cd A, m^2: drag coefficient times the projected (frontal) area. The 2D body is a slab of
  /// unit depth, so for a body of width w across the flow A = w * 1 m (e.g. a 1 m plate
  /// broadside: Cd ~ 2, CdA ~ 2 m^2; a 1 m cylinder: Cd ~ 1.2). >= 0.
  float dragArea = 1.0f;
  /// c_lin, N s/m >= 0: an optional linear (viscous) term -c_lin v_rel.
  float linearDrag = 0.0f;
  Vec2f localCenterOfPressure; ///< m, body frame: where the drag acts
};

/// Aerodynamic drag on one body relative to moving air (the ch. 9 hovercraft model with the
/// book's separate wind force fixed: drag acts on the velocity relative to the air):
///   v_rel = v_cp - v_air (v_cp the velocity of the centre of pressure),
///   F = -1/2 rho CdA |v_rel| v_rel - c_lin v_rel, applied at the centre of pressure,
/// so a centre of pressure aft of the centre of mass turns the body to trail the wind. The
/// force is limited so that one step never more than stops the relative motion of that point
/// (an explicit step of a stiff drag would otherwise overshoot and oscillate).
class WindDrag final : public ForceEffector {
public:
  explicit WindDrag(const WindDragSettings& settings);
  void apply(World& world, float dt) override;
  [[nodiscard]] const WindDragSettings& settings() const noexcept { return settings_; }
  void setAirVelocity(const Vec2f& airVelocity);
  /// The force (N, world) applied by the last apply().
  [[nodiscard]] Vec2f lastForce() const noexcept { return lastForce_; }

private:
  WindDragSettings settings_;
  Vec2f lastForce_;
};

struct ThrusterSettings {
  BodyId body;
  Vec2f localPoint;                 ///< m, body frame: where the thrust acts
  Vec2f localDirection{1.0f, 0.0f}; ///< body frame, non-zero (normalized on construction)
  float thrust = 0.0f;              ///< N, finite (negative: reverse thrust)
};

/// A jet fixed to a body: a force of `thrust` N along the body-local direction at the
/// body-local point. Through the centre of mass it only accelerates the body (a = F / m); off
/// the centre it also turns it (alpha = (r x F) / I).
class Thruster final : public ForceEffector {
public:
  explicit Thruster(const ThrusterSettings& settings);
  void apply(World& world, float dt) override;
  [[nodiscard]] const ThrusterSettings& settings() const noexcept { return settings_; }
  /// N, finite.
  void setThrust(float thrust);
  [[nodiscard]] float thrust() const noexcept { return settings_.thrust; }

private:
  ThrusterSettings settings_;
};

struct SpringDamperSettings {
  BodyId bodyA;
  Vec2f localAnchorA; ///< m, body A's frame
  /// The other end: a body, or (null id) a fixed world point.
  BodyId bodyB;
  Vec2f localAnchorB;      ///< m, body B's frame, or a world point when bodyB is null
  float stiffness = 0.0f;  ///< k, N/m >= 0
  float damping = 0.0f;    ///< c, N s/m >= 0
  float restLength = 0.0f; ///< L0, m >= 0
};

/// A spring and dashpot along the line between two anchors: the tension
///   T = k (L - L0) + c dL/dt
/// (L the anchors' distance, dL/dt its rate) pulls the anchors together when positive. It is
/// computed once per step and applied equal and opposite (+T u on A, -T u on B, u the unit
/// vector from A to B), so the pair's momentum is conserved. Anchors closer than 1e-6 m have no
/// direction and feel nothing.
class SpringDamper final : public ForceEffector {
public:
  explicit SpringDamper(const SpringDamperSettings& settings);
  void apply(World& world, float dt) override;
  [[nodiscard]] const SpringDamperSettings& settings() const noexcept { return settings_; }
  /// The tension (N, > 0 pulling) applied by the last apply().
  [[nodiscard]] float lastTension() const noexcept { return lastTension_; }

private:
  SpringDamperSettings settings_;
  float lastTension_ = 0.0f;
};

struct ExplosionSettings {
  Vec2f center;         ///< m, world
  float radius = 1.0f;  ///< R, m > 0
  float impulse = 1.0f; ///< J0, N s >= 0: the impulse at the centre
};

/// A radial blast, once: every dynamic body whose centre of mass lies within R of the centre
/// (at distance 0 < r < R) receives an impulse J0 (1 - r / R) away from the centre, at its
/// centre of mass (no spin). Linear falloff: J0 at the centre, 0 at the edge. Nothing occludes
/// it. The first apply() fires it (waking the bodies it hits); later calls do nothing until
/// rearm().
class Explosion final : public ForceEffector {
public:
  explicit Explosion(const ExplosionSettings& settings);
  void apply(World& world, float dt) override;
  [[nodiscard]] const ExplosionSettings& settings() const noexcept { return settings_; }
  [[nodiscard]] bool fired() const noexcept { return fired_; }
  void rearm() noexcept { fired_ = false; }
  /// The impulse (N s) a body with its centre of mass at `point` receives.
  [[nodiscard]] Vec2f impulseAt(const Vec2f& point) const noexcept;

private:
  ExplosionSettings settings_;
  bool fired_ = false;
  std::vector<BodyId> bodies_;
};

// ---------------------------------------------------------------------------------------------
// Buoyancy.

/// The part of a shape below a horizontal water line.
struct SubmergedArea {
  float area = 0.0f; ///< m^2
  Vec2f centroid;    ///< m, world (meaningful when area > 0)
};

/// The area of a shape (placed by `xf`) below y = surfaceY, and its centroid, optionally only
/// between x = xMin and x = xMax (world, m).
/// - Polygons (radius 0): exact (clipped by the half-planes).
/// - Circles: exact (the circular-segment formula), unless an x bound cuts the circle.
/// - Capsules, rounded polygons, and circles cut by an x bound: the outline with its arcs
///   replaced by chords of at most pi/32 rad, clipped exactly. The chords lose at most
///   pi r^2 (1 - sin(a) / a) < 0.17% of pi r^2 (a = pi/32) of the area.
/// - Segments and chain segments enclose no area: zero.
[[nodiscard]] SubmergedArea submergedArea(const ShapeGeometry& shape, const Transform2f& xf, float surfaceY,
                                          float xMin = -std::numeric_limits<float>::infinity(),
                                          float xMax = std::numeric_limits<float>::infinity());

struct BuoyancySettings {
  float surfaceHeight = 0.0f; ///< m: the water lies below y = surfaceHeight
  /// m: the water's x extent (xMin <= xMax; infinite by default).
  float xMin = -std::numeric_limits<float>::infinity();
  float xMax = std::numeric_limits<float>::infinity();
  /// rho, kg/m^2 > 0: the fluid's areal density, as the shapes' (water: 1000 kg/m^3 over the
  /// unit depth = 1000 kg/m^2). A body whose density is below it floats.
  float fluidDensity = 1000.0f;
  Vec2f gravity{0.0f, -10.0f}; ///< m/s^2: the buoyant force is -rho A g (use the world's)
  Vec2f fluidVelocity;         ///< m/s: a current
  /// c_lin, 1/s >= 0: drag force -c_lin rho A_sub (v - v_fluid) per shape, v the velocity of
  /// its submerged centroid. Scaled by the displaced mass rho A_sub, so c_lin is the rate at
  /// which a fully submerged, neutrally buoyant body loses its speed through the water
  /// whatever the fluid's density (a rate of 2 halves it in 0.35 s).
  float linearDrag = 2.0f;
  /// c_ang, 1/s >= 0: drag torque -c_ang rho A_sub^2 w (displaced mass times area: an inertia,
  /// kg m^2), so that it too is independent of scale and density (a fully submerged, neutrally
  /// buoyant square of inertia m A / 6 loses its spin at the rate 6 c_ang, plus the linear drag's
  /// share).
  float angularDrag = 1.0f;
};

/// Archimedes in 2D: for each awake dynamic body, for each of its shapes, the submerged area
/// A_sub and its centroid c; the buoyant force rho A_sub (-g) acts at c (so a tilted hull rights
/// itself when its metacentre is above its centre of mass), and linear drag opposes the motion
/// through the water there; angular drag opposes the spin. The drag force and torque are limited so one step never more
/// than stops the body relative to the water. Sensor shapes are skipped.
class Buoyancy final : public ForceEffector {
public:
  explicit Buoyancy(const BuoyancySettings& settings);
  void apply(World& world, float dt) override;
  [[nodiscard]] const BuoyancySettings& settings() const noexcept { return settings_; }
  /// m, finite. Bodies asleep below the new level are not woken: see the header's note.
  void setSurfaceHeight(float surfaceHeight);
  void setFluidVelocity(const Vec2f& velocity);

private:
  BuoyancySettings settings_;
  std::vector<BodyId> bodies_;
  std::vector<ShapeId> shapes_;
};

} // namespace impetus::rigid2d
