// A rope (ch. 13): a line of particles joined end to end, built in a ParticleWorld through its
// public API.
//
// Two models:
// - RopeModel::xpbd (default): each segment is a distance constraint solved by XPBD with a
//   compliance (m/N; 0 = inextensible) that acts only when stretched, so the rope can go slack.
//   It is stable at a 1/60 s frame whatever the mass and stiffness; its error is residual
//   stretch, which the world's substeps reduce as h^2 (one constraint pass per substep): a
//   10-segment rope swinging at 60 Hz stretches 2.1 % at 4 substeps, 0.9 % at 8, 0.25 % at 16.
// - RopeModel::bookSprings: the book's chain of spring-dampers (k = 1000 N/m, d = 100 N s/m).
//   A penalty force: it stretches under load (segment j of an N-segment rope hanging from its
//   start carries (N - j) m g and stretches by that over k), and semi-implicit Euler is stable
//   only while the substep h is short for the chain's fastest mode, which has stiffness 4 k / m
//   and damping 4 d / m: h < sqrt(m / k) and h < m / (2 d). With the book's 1 kg particles and
//   d = 100 N s/m that is 5 ms (the default world's substep is 1/240 s = 4.2 ms).
//
// The mass is spread evenly over the segments + 1 particles; a pinned end keeps its share but
// never moves (the book's locked particle 0).
#pragma once

#include <impetus/particles/particle_world.hpp>

#include <vector>

namespace impetus {

enum class RopeModel {
  xpbd,        ///< distance constraints with compliance, slack allowed (default)
  bookSprings, ///< the book's spring-dampers between neighbours
};

struct RopeDef {
  Vec3f start;                       ///< first particle, m
  Vec3f end{1.0f, 0.0f, 0.0f};       ///< last particle, m; != start. The rope starts straight
  int segments = 9;                  ///< >= 1; the rope has segments + 1 particles (book: 9 and 10)
  float totalMass = 10.0f;           ///< kg, > 0, shared evenly (the book: 10 particles of 1 kg)
  float particleRadius = 0.05f;      ///< m, > 0: collision radius and drag area pi r^2
  RopeModel model = RopeModel::xpbd; ///< how the segments hold together
  float compliance = 0.0f;           ///< xpbd: m/N, >= 0 (1/k for a spring-like rope; 0 = rigid)
  float stiffness = 1000.0f;         ///< bookSprings: k, N/m, > 0 (the book's value)
  float damping = 100.0f;            ///< bookSprings: d, N s/m, >= 0 (the book's value)
  bool pinStart = true;              ///< hold the first particle in place (the book's locked particle)
  bool pinEnd = false;               ///< hold the last particle in place (a rope bridge, a vine)

  /// A def from `start` along `direction` (need not be unit length) for `length` metres.
  [[nodiscard]] static RopeDef along(const Vec3f& start, const Vec3f& direction, float length);
};

/// What createRope made: the particles from start to end, and the segments joining particle i
/// to i + 1 (constraints for xpbd, springs for bookSprings; the other list is empty).
struct Rope {
  std::vector<ParticleId> particles;
  std::vector<ConstraintId> constraints;
  std::vector<SpringId> springs;
  float restLength = 0.0f; ///< total unstretched length, m
};

/// Creates the rope's particles and connections in `world`. Throws impetus::Error naming the
/// field of `def` that is invalid (the world is unchanged then).
[[nodiscard]] Rope createRope(ParticleWorld& world, const RopeDef& def);

/// The rope's current length: the sum of its segments' lengths, m.
[[nodiscard]] float ropeLength(const ParticleWorld& world, const Rope& rope);

} // namespace impetus
