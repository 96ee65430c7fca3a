// The particle world (ch. 8, 13): point masses with a collision radius under gravity, drag
// relative to the wind, attractors, user forces and springs; colliding with static obstacles
// and, optionally, with each other; tied by distance constraints (ropes, cloth); spawned by
// emitters. Single precision, SI units, +y up.
//
// One step of dt is split into `substeps` of h = dt / substeps. Each substep:
//   1. forces -> accelerations (gravity, drag, attractors, springs, user forces), and the
//      integrator advances velocities and positions (semi-implicit Euler by default);
//   2. distance constraints are projected (XPBD: one iteration per substep is enough, since many
//      small substeps converge better than many iterations);
//   3. particles are pushed out of obstacles and their velocities reflected with restitution and
//      Coulomb friction (the tangential distance friction prevented during the substep is taken
//      back as well, so static friction holds on a slope); a contact approaching slower than
//      `restThreshold` does not bounce, so a particle that has come to rest stays at rest (the
//      book's particles micro-bounce forever);
//   4. particle-particle contacts (if enabled) from a spatial hash grid, resolved pairwise with
//      equal and opposite impulses (momentum is conserved to rounding).
// Emitters spawn once per step, before the substeps; particles age and those past their
// lifetime are destroyed once per step, after them (so between steps age() is the time a
// particle has been simulated for, and is below its lifetime).
// Everything runs in a fixed order: the same inputs give bit-identical results.
#pragma once

#include <impetus/particles/particle_types.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace impetus {

struct ParticleWorldSettings {
  Vec3f gravity{0.0f, -9.81f, 0.0f}; ///< m/s^2
  ParticleIntegrator integrator = ParticleIntegrator::semiImplicitEuler;
  int substeps = 4; ///< per step, >= 1
  /// XPBD passes over the distance constraints per substep, >= 1. More substeps converge
  /// better than more iterations (a 10-segment rope stays within 1% of its length at 1/60 s
  /// with 8 substeps); iterations are the cheaper knob when forces are expensive.
  int constraintIterations = 1;

  // Drag, relative to the air: v_rel = v - wind.
  Vec3f wind;                   ///< uniform air velocity, m/s
  float linearDrag = 0.0f;      ///< k: F = -k v_rel, kg/s (the same for every particle)
  float dragCoefficient = 0.0f; ///< Cd: F = -1/2 rho Cd (pi r^2) |v_rel| v_rel (0 = off)
  float airDensity = 1.225f;    ///< rho, kg/m^3
  /// Optional wind field, m/s, at a position and time; replaces `wind` when set.
  std::function<Vec3f(const Vec3f& position, float time)> windField;

  // Contacts.
  float restThreshold = 0.5f;       ///< approach speed (m/s) below which contacts do not bounce
  bool particleCollisions = false;  ///< particles collide with each other
  float particleRestitution = 0.5f; ///< e between particles
};

class ParticleWorld {
public:
  explicit ParticleWorld(const ParticleWorldSettings& settings = {});
  ~ParticleWorld();
  ParticleWorld(ParticleWorld&&) noexcept;
  ParticleWorld& operator=(ParticleWorld&&) noexcept;
  ParticleWorld(const ParticleWorld&) = delete;
  ParticleWorld& operator=(const ParticleWorld&) = delete;

  /// Advances by dt seconds (0 < dt <= 1). Never throws for valid state.
  void step(float dt);

  // Particles.
  ParticleId createParticle(const ParticleDef& def);
  /// Removes the particle and every spring and constraint attached to it.
  void destroyParticle(ParticleId id);
  [[nodiscard]] bool isValid(ParticleId id) const noexcept;
  [[nodiscard]] std::size_t particleCount() const noexcept;
  [[nodiscard]] Vec3f position(ParticleId id) const;
  [[nodiscard]] Vec3f velocity(ParticleId id) const;
  [[nodiscard]] float mass(ParticleId id) const;
  [[nodiscard]] float radius(ParticleId id) const;
  /// Seconds since the particle was created.
  [[nodiscard]] float age(ParticleId id) const;
  /// Seconds it lives in all (infiniteLifetime for permanent particles).
  [[nodiscard]] float lifetime(ParticleId id) const;
  void setPosition(ParticleId id, const Vec3f& position);
  void setVelocity(ParticleId id, const Vec3f& velocity);
  void setPinned(ParticleId id, bool pinned);
  /// A force (N) acting for the whole of the next step.
  void applyForce(ParticleId id, const Vec3f& force);
  /// An instant change of momentum (N s).
  void applyImpulse(ParticleId id, const Vec3f& impulse);

  /// Dense views for rendering and analysis, in the world's internal order (which changes when
  /// particles are destroyed); ids()[i] names positions()[i].
  [[nodiscard]] std::span<const Vec3f> positions() const noexcept;
  [[nodiscard]] std::span<const Vec3f> velocities() const noexcept;
  [[nodiscard]] std::span<const ParticleId> ids() const noexcept;
  /// A hash of the exact state of every particle, in the dense order: id, position, velocity
  /// (StateHash: FNV-1a over the bits). Equal hashes: identical states.
  [[nodiscard]] std::uint64_t stateHash() const;

  // Obstacles (static).
  ObstacleId addObstacle(const PlaneObstacle& plane, const SurfaceMaterial& material = {});
  ObstacleId addObstacle(const SphereObstacle& sphere, const SurfaceMaterial& material = {});
  ObstacleId addObstacle(const BoxObstacle& box, const SurfaceMaterial& material = {});
  ObstacleId addObstacle(const CapsuleObstacle& capsule, const SurfaceMaterial& material = {});
  void removeObstacle(ObstacleId id);
  [[nodiscard]] std::size_t obstacleCount() const noexcept;

  // Connections.
  SpringId addSpring(const SpringDef& def);
  void removeSpring(SpringId id);
  ConstraintId addDistanceConstraint(const DistanceConstraintDef& def);
  void removeDistanceConstraint(ConstraintId id);
  [[nodiscard]] std::size_t springCount() const noexcept;
  [[nodiscard]] std::size_t constraintCount() const noexcept;

  // Effectors and emitters.
  void addAttractor(const Attractor& attractor);
  EmitterId addEmitter(const EmitterDef& def);
  void removeEmitter(EmitterId id);

  // Energies (J): kinetic, gravitational potential (-m g . x) and elastic (springs).
  [[nodiscard]] double kineticEnergy() const noexcept;
  [[nodiscard]] double potentialEnergy() const noexcept;
  [[nodiscard]] double springEnergy() const noexcept;
  /// Total linear momentum of the movable particles, kg m/s.
  [[nodiscard]] Vec3d momentum() const noexcept;

  [[nodiscard]] const ParticleWorldSettings& settings() const noexcept;
  /// Throws impetus::Error for invalid settings (the world is unchanged then).
  void setSettings(const ParticleWorldSettings& settings);
  [[nodiscard]] float time() const noexcept;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace impetus
