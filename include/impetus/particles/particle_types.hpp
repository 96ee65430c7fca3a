// Definitions for the particle world (ch. 8, 13): particles, obstacles, springs, distance
// constraints, attractors and emitters. Plain structs with SI defaults; the world validates them
// when they are added and throws impetus::Error naming the bad field.
#pragma once

#include <impetus/core/id_pool.hpp>
#include <impetus/math/quat.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/vec3.hpp>

#include <cstdint>
#include <limits>

namespace impetus {

using ParticleId = Id<struct ParticleTag>;
using ObstacleId = Id<struct ObstacleTag>;
using SpringId = Id<struct SpringTag>;
using ConstraintId = Id<struct ConstraintTag>;
using EmitterId = Id<struct EmitterTag>;

inline constexpr float infiniteLifetime = std::numeric_limits<float>::infinity();

/// How the world advances particles between collision and constraint passes.
enum class ParticleIntegrator {
  semiImplicitEuler, ///< v += a h; x += v h. First order, symplectic: the default, as in games
  explicitEuler,     ///< x += v h; v += a h. First order; its energy grows (the book's ch. 7 warning)
  velocityVerlet,    ///< second order, symplectic for position-only forces
  rk4,               ///< classic fourth order on the whole state; four force evaluations per step
};

struct ParticleDef {
  Vec3f position;
  Vec3f velocity;
  float mass = 1.0f;                 ///< kg, > 0 (use pinned for an immovable particle)
  float radius = 0.1f;               ///< collision radius, m, > 0 (also the drag's frontal area pi r^2)
  float lifetime = infiniteLifetime; ///< s; the particle is destroyed when its age reaches it
  bool pinned = false;               ///< held in place (infinite mass): ends of ropes, cloth corners
  std::uint32_t userData = 0;
};

/// Surface response of an obstacle: restitution e (0 = no bounce, 1 = elastic) and Coulomb
/// friction mu.
struct SurfaceMaterial {
  float restitution = 0.6f; ///< the book's ch. 8 value
  float friction = 0.4f;
};

struct PlaneObstacle {
  Vec3f normal{0.0f, 1.0f, 0.0f}; ///< points into the free side; normalized when added
  float offset = 0.0f;            ///< the plane is dot(normal, x) = offset, m
};
struct SphereObstacle {
  Vec3f center;
  float radius = 1.0f;
};
struct BoxObstacle {
  Vec3f center;
  Vec3f halfExtents{0.5f, 0.5f, 0.5f};
  Quatf rotation = Quatf::identity();
};
struct CapsuleObstacle {
  Vec3f pointA;
  Vec3f pointB;
  float radius = 0.5f;
};

/// A spring-damper between two particles (ch. 3, 13):
/// F1 = (k (|d| - r) + c (v2 - v1).u) u, u = d/|d|, d = x2 - x1, and F2 = -F1, computed once per
/// pair. `b` may be null: the spring then ties `a` to the fixed point `anchor`.
struct SpringDef {
  ParticleId a;
  ParticleId b;
  Vec3f anchor;              ///< world point, used when b is null
  float stiffness = 1000.0f; ///< k, N/m (the book's rope)
  float damping = 100.0f;    ///< c, N s/m
  float restLength = -1.0f;  ///< r, m; negative: the distance when the spring is created
};

/// A distance constraint solved by XPBD (extended position-based dynamics): |x2 - x1| = length
/// with compliance alpha (m/N, the inverse of a stiffness; 0 = rigid). `b` may be null: the
/// constraint then ties `a` to `anchor`. A rope segment (`maxOnly`) only resists stretching.
struct DistanceConstraintDef {
  ParticleId a;
  ParticleId b;
  Vec3f anchor;
  float length = -1.0f;    ///< m; negative: the distance when the constraint is created
  float compliance = 0.0f; ///< m/N, >= 0
  bool maxOnly = false;    ///< slack allowed: acts only when stretched (rope)
};

/// A point attractor (or repeller, strength < 0): a = mu (p - x) / (|p - x|^2 + eps^2)^(3/2),
/// gravity-like with a softening length eps that keeps it finite at the centre.
struct Attractor {
  Vec3f position;
  float strength = 10.0f; ///< mu, m^3/s^2 (G M for a real mass)
  float softening = 0.1f; ///< eps, m, > 0
};

/// Spawns particles from a point: `burst` at once, then `rate` per second for `duration`.
/// Each gets a speed in [minSpeed, maxSpeed] along a direction within `coneAngle` of
/// `direction` (pi: all around), and a life in [minLifetime, maxLifetime].
struct EmitterDef {
  Vec3f position;
  Vec3f direction{0.0f, 1.0f, 0.0f};
  float coneAngle = pi<float>;       ///< half-angle, rad
  float minSpeed = 1.0f;             ///< m/s
  float maxSpeed = 2.0f;             ///< m/s
  float rate = 0.0f;                 ///< particles per second after the burst
  int burst = 0;                     ///< particles spawned at once
  float duration = infiniteLifetime; ///< s of continuous emission
  float minLifetime = 1.0f;          ///< s
  float maxLifetime = 1.0f;          ///< s
  float mass = 0.01f;                ///< kg
  float radius = 0.02f;              ///< m
  bool planar = false;               ///< directions in the x-y plane only (2D effects)
  std::uint32_t seed = 1;            ///< the same seed gives the same particles
};

} // namespace impetus
