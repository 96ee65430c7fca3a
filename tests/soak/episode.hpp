// impetus-soak's episodes (soak.cpp): a random world built from (seed, episode) alone, inside or
// outside the documented envelope, with what the checks need to know about it.
#pragma once

#include <impetus/core/task_runner.hpp>
#include <impetus/rigid2d/world.hpp>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace soak {

using namespace impetus;
using namespace impetus::rigid2d;

/// splitmix64: the same numbers on every platform (std:: distributions differ between
/// standard libraries, and a soak failure must reproduce anywhere).
class Random {
public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [lo, hi).
  float uniform(float lo, float hi) {
    const double u = static_cast<double>(next() >> 11) * 0x1.0p-53;
    return lo + static_cast<float>(u) * (hi - lo);
  }
  /// 10^uniform(lo, hi): sizes and masses spread over orders of magnitude.
  float logUniform(float lo, float hi) { return std::pow(10.0f, uniform(lo, hi)); }
  bool chance(float p) { return uniform(0.0f, 1.0f) < p; }
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }

private:
  std::uint64_t state_;
};

constexpr float arenaHalfWidth = 60.0f; ///< m, inside the walls
constexpr float wallThickness = 5.0f;   ///< m
constexpr float timeStep = 1.0f / 60.0f;

/// The documented envelope: body half-sizes (m, log10 range), densities (kg/m^2: 0.1 to 10 times
/// water's 1000 kg/m^3 over a metre's depth) and the largest ratio across a joint of the two
/// bodies' masses and of their effective masses at its lever arms (m k^2 / (k^2 + r^2); the plain mass ratio at r = 0).
constexpr float insideMinLogHalfSize = -1.3f; // 5 cm: 0.1 m across
constexpr float insideMaxLogHalfSize = 0.7f;  // 5 m: 10 m across
constexpr float insideMinLogDensity = 2.0f;
constexpr float insideMaxLogDensity = 4.0f;
constexpr float insideMaxJointMassRatio = 10.0f;

struct EpisodeStats {
  std::int64_t steps = 0;
  std::size_t bodies = 0;
  std::size_t joints = 0;
  double worstEnergyGrowth = 0.0; ///< of closed episodes, as a fraction of the energy scale
};

struct Episode {
  World world;
  std::vector<BodyId> bodies;    ///< live dynamic and kinematic bodies
  std::vector<float> extents;    ///< each body's bounding radius about its origin, m
  std::vector<JointId> joints;   ///< live joints
  std::vector<BodyId> destroyed; ///< ids that must stay invalid
  std::vector<JointId> destroyedJoints;
  /// Bodies a kinematic or much heavier body drove into a wall: exempt from the arena bound for
  /// the rest of the episode (drivenIntoWall).
  std::vector<BodyId> drivenIntoWalls;
  bool closed = false;
  bool inside = true; ///< built inside the documented envelope (energy checked)
  double energy0 = 0.0;
  double energyScale = 0.0;
};

/// The episode `index` of the run with `seed`: a walled arena of 20 to 99 random bodies, some
/// joined (joints, prismatic: which kinds), inside or outside the envelope.
std::unique_ptr<Episode> buildEpisode(std::uint64_t seed, int index, TaskRunner* runner, bool joints, bool prismatic,
                                      bool inside);
/// One random body: a circle, capsule, box or polygon; inside the envelope 0.1 to 10 m across at a
/// density of 100 to 10,000 kg/m^2, outside it 1 cm to 10 m across whose density makes its mass
/// 1 to 100 kg. Adds the body to e.bodies (and its bounding radius to e.extents).
void addBody(Episode& e, Random& rng, const Vec2f& at, bool closed);
/// Kinetic plus potential energy (gravity (0, -10), zero at the arena floor), J.
double mechanicalEnergy(const Episode& e);

} // namespace soak
