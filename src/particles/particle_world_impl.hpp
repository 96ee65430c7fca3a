// Internal state of ParticleWorld, shared by its translation units. Hot per-particle data is
// kept in dense parallel arrays (structure of arrays) indexed 0..n-1; ids map to dense indices
// through the id pool's slots, and destroying a particle moves the last one into its place.
#pragma once

#include <impetus/core/id_pool.hpp>
#include <impetus/particles/particle_world.hpp>

#include <random>
#include <variant>
#include <vector>

namespace impetus::detail {

struct ObstacleShape {
  std::variant<PlaneObstacle, SphereObstacle, BoxObstacle, CapsuleObstacle> shape;
  SurfaceMaterial material;
  ObstacleId id;
};

struct Spring {
  ParticleId a;
  ParticleId b;
  Vec3f anchor;
  float stiffness;
  float damping;
  float restLength;
  SpringId id;
};

struct DistanceConstraint {
  ParticleId a;
  ParticleId b;
  Vec3f anchor;
  float length;
  float compliance;
  bool maxOnly;
  ConstraintId id;
};

struct Emitter {
  EmitterDef def;
  EmitterId id;
  std::mt19937 rng;
  float elapsed = 0.0f;
  float carry = 0.0f; ///< fractional particles owed to `rate`
  bool burstDone = false;
};

/// Particles (dense, parallel arrays).
struct ParticleStore {
  std::vector<Vec3f> position;
  std::vector<Vec3f> velocity;
  std::vector<Vec3f> userForce; ///< N, cleared after each step
  std::vector<float> mass;
  std::vector<float> inverseMass; ///< 0 when pinned
  std::vector<float> radius;
  std::vector<float> age;
  std::vector<float> lifetime;
  std::vector<std::uint32_t> userData;
  std::vector<ParticleId> id;

  [[nodiscard]] std::size_t size() const noexcept { return position.size(); }
};

/// Scratch arrays reused from step to step (no allocation in the steady state).
struct Scratch {
  std::vector<Vec3f> acceleration;
  std::vector<Vec3f> x0, v0, k1x, k1v, k2x, k2v, k3x, k3v, k4x, k4v;
  std::vector<Vec3f> beforeConstraints;
  std::vector<float> lambda;
  // Spatial hash for particle-particle contacts.
  std::vector<std::uint32_t> cellStart;
  std::vector<std::uint32_t> cellOfParticle;
  std::vector<std::uint32_t> sorted;
  std::vector<std::uint32_t> cursor;
};

struct ParticleWorldState {
  ParticleWorldSettings settings;
  float time = 0.0f;

  IdPool particleIds;
  std::vector<std::uint32_t> slotToDense; ///< by id slot index
  ParticleStore particles;

  IdPool obstacleIds;
  std::vector<ObstacleShape> obstacles;
  IdPool springIds;
  std::vector<Spring> springs;
  IdPool constraintIds;
  std::vector<DistanceConstraint> constraints;
  std::vector<Attractor> attractors;
  IdPool emitterIds;
  std::vector<Emitter> emitters;

  Scratch scratch;

  /// Dense index of a live particle; throws impetus::Error for a stale or null id.
  [[nodiscard]] std::uint32_t dense(ParticleId id) const;
};

// particle_dynamics.cpp
/// a = F/m for every particle at state (x, v): gravity, drag, attractors, springs, user forces.
/// Drag is limited to what stops a particle relative to the air within the (stage) step `h`:
/// an explicit step of a stronger drag would reverse the velocity and grow it step after step.
void computeAccelerations(const ParticleWorldState& w, std::span<const Vec3f> x, std::span<const Vec3f> v,
                          std::span<Vec3f> a, float h);
/// Advances velocities and positions by h with the world's integrator.
void integrate(ParticleWorldState& w, float h);
/// One XPBD pass over the distance constraints, then v += (x_after - x_before) / h.
void solveConstraints(ParticleWorldState& w, float h);

// particle_contacts.cpp
/// Pushes particles out of the obstacles and applies restitution and friction; h is the substep.
void collideObstacles(ParticleWorldState& w, float h);
void collideParticles(ParticleWorldState& w);

} // namespace impetus::detail
