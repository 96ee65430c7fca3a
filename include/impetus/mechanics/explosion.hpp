// The book's kinematic particle explosion (ch. 2): particles fly out of a point on closed-form
// trajectories x = v cos(theta) t, y = v sin(theta) t + g t^2 / 2 and fade out over their life.
//
// Differences from the book's program:
// - positions are evaluated at the time asked for, not advanced by a fixed 10 ms per frame, so
//   the effect runs at the same speed at any frame rate;
// - y points up (the book's screen space had y down and negated the angle);
// - the random numbers come from a seeded generator owned by the caller, so an explosion is
//   reproducible (replays, tests).
// On the particle world (ch. 8) the same effect runs with forces; this is the cheap version.
#pragma once

#include <impetus/math/vec2.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace impetus {

struct ExplosionSettings {
  Vec2d origin;                    ///< m
  double speed = 10.0;             ///< "strength": particles leave at a speed in [speed/2, speed], m/s
  double life = 2.0;               ///< "duration": particles live [0.8, 1.0] x life, s
  double gravity = -9.81;          ///< vertical acceleration (negative pulls down), m/s^2
  std::optional<double> direction; ///< mean direction, rad from +x counter-clockwise; none = all around
  double spread = 0.174532925199;  ///< half-width of the cone around `direction`, rad (book: 10 degrees)
  int count = 50;                  ///< number of particles (the book's _MAXPARTICLES)
  std::uint32_t seed = 1;          ///< random seed: the same seed gives the same explosion
};

struct ExplosionParticle {
  Vec2d velocity; ///< initial velocity, m/s
  double life;    ///< s
};

/// What a particle looks like at time t.
struct ParticleSnapshot {
  Vec2d position;    ///< m
  double fade = 0.0; ///< brightness (life - t) / life in [0, 1]; 0 once dead
  bool alive = false;
};

class KinematicExplosion {
public:
  /// Spawns the particles. Throws impetus::Error for a negative speed or life, a count outside
  /// [1, 100000], or non-finite values.
  explicit KinematicExplosion(const ExplosionSettings& settings);

  [[nodiscard]] ParticleSnapshot particleAt(std::size_t index, double time) const;
  [[nodiscard]] const std::vector<ExplosionParticle>& particles() const noexcept { return particles_; }
  [[nodiscard]] const Vec2d& origin() const noexcept { return origin_; }
  /// Number of particles still alive at `time`.
  [[nodiscard]] std::size_t aliveCount(double time) const noexcept;
  /// When the last particle dies, s: the effect is over.
  [[nodiscard]] double endTime() const noexcept;

private:
  Vec2d origin_;
  double gravity_;
  std::vector<ExplosionParticle> particles_;
};

} // namespace impetus
