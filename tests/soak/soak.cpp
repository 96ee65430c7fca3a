// impetus-soak: random 2D worlds stepped for a long time, with the engine's invariants checked
// after every step. What a game throws at an engine over hours, compressed: shapes from 1 cm to
// 10 m across, masses 1 to 100 kg side by side, bodies thrown at up to 200 m/s, joints of every kind,
// bodies destroyed and created while others sleep, rest and collide.
//
//   impetus-soak [--seconds S] [--seed N] [--episode-seconds T] [--threads K] [--joints on|off] [--prismatic on|off]
//                [--envelope inside|outside]
//                [--episodes N]        (exactly N episodes, whatever the time: what CI runs)
//                [--first-episode N]   (start at episode N: a failure's reproduction)
//
// Two tiers (docs/reliability.md, "The envelope"). Inside the documented envelope (bodies 0.1 to
// 10 m across, densities 0.1 to 10 times water's, at most 10:1 in mass and in effective mass
// at a joint's lever arms: m k^2 / (k^2 + r^2), k the radius of gyration and r the arm) the engine
// promises stable, energy-bounded behaviour; outside it (1 cm to 10 m, 1 to 100 kg whatever the
// size, any mass ratio) only that the world stays finite, in the arena, with every id valid.
// Each episode builds a world from (seed, episode) alone, so any failure is reproduced by its
// seed and episode number. Checked after every step:
//   - every body's position, rotation and velocities are finite;
//   - no body leaves the walled arena (walls 5 m thick; fast bodies are bullets or rely on the
//     continuous collision against static shapes), except one that a kinematic body or a body
//     more than 10 times heavier drove into a wall (through joints and contacts): the wall's
//     push cannot stop such a driver through the light body within a step, and, freed inside a
//     wall, the body is pushed out of the nearer face;
//   - every id the episode holds is valid and every id it destroyed is not; destroying a body
//     also destroys its joints;
//   - inside the envelope, in closed episodes (no motors, springs, kinematic bodies, restitution
//     or API changes), the mechanical energy never grows beyond E0 + 1% of the system's energy
//     scale (soft contacts and joints only dissipate; what they may add is the small push-out of
//     overlap). Outside it the worst growth is reported, not checked.
// Exit status 0 when every check held, 1 (with the seed, episode, step and what failed) if not,
// 2 for bad arguments.
#include "episode.hpp"

#include <impetus/core/task_runner.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/world.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fenv.h>
#include <memory>
#include <optional>
#include <string>
#include <vector>
namespace {

using namespace impetus;
using namespace impetus::rigid2d;
using soak::addBody;
using soak::arenaHalfWidth;
using soak::buildEpisode;
using soak::Episode;
using soak::EpisodeStats;
using soak::mechanicalEnergy;
using soak::Random;
using soak::timeStep;
using soak::wallThickness;

struct Failure {
  std::string what;
};

/// What the game does between steps (open episodes): destroys a body now and then, throws a new
/// one in, and teleports one.
void meddle(Episode& e, Random& rng) {
  if (rng.chance(0.02f) && e.bodies.size() > 5) {
    const auto i = static_cast<std::size_t>(rng.below(static_cast<int>(e.bodies.size())));
    const BodyId victim = e.bodies[i];
    e.world.destroyBody(victim);
    e.destroyed.push_back(victim);
    e.bodies.erase(e.bodies.begin() + static_cast<std::ptrdiff_t>(i));
    e.extents.erase(e.extents.begin() + static_cast<std::ptrdiff_t>(i));
    // Its joints went with it.
    for (std::size_t j = 0; j < e.joints.size();) {
      if (!e.world.isValid(e.joints[j])) {
        e.destroyedJoints.push_back(e.joints[j]);
        e.joints.erase(e.joints.begin() + static_cast<std::ptrdiff_t>(j));
      } else {
        ++j;
      }
    }
  }
  if (rng.chance(0.02f)) {
    addBody(e, rng, {rng.uniform(-50.0f, 50.0f), 50.0f}, false);
  }
  if (rng.chance(0.01f) && !e.bodies.empty()) {
    const BodyId b = e.bodies[static_cast<std::size_t>(rng.below(static_cast<int>(e.bodies.size())))];
    e.world.setTransform(b, {rng.uniform(-40.0f, 40.0f), rng.uniform(-40.0f, 40.0f)}, rng.uniform(-3.0f, 3.0f));
  }
}

/// The envelope's mass ratio: a body this many times heavier than one it presses into a wall
/// can drive it in (drivenIntoWall).
constexpr float maxDrivingMassRatio = soak::insideMaxJointMassRatio;

bool finite(const Vec2f& v) { return std::isfinite(v.x) && std::isfinite(v.y); }

/// Whether a heavier body drives the body into a wall: a chain of joints and touching contacts
/// through dynamic bodies links it to a kinematic body or to one more than maxDrivingMassRatio
/// times heavier. A kinematic body goes where it is sent, walls or not, with infinite mass, and
/// what it drives goes with it (a body on a paddle's slider pressed into a wall, or squeezed
/// between the paddle and a wall: no solver can hold both an infinitely heavy driver and a wall).
/// A much heavier dynamic body does the same in degree: the wall's push reaches it only through
/// the light body it presses, a mass ratio's worth of iterations later, which one solve and one
/// relax pass a substep cannot give: a light plank pressed by a block seventy times heavier goes
/// into the wall. Such a body can reach anywhere its driver pushes it, so the arena bound
/// does not hold it; nor once freed, if it was left in a wall (it is pushed out of the nearer
/// face). docs/reliability.md ("Soak") lists the episodes that showed it.
bool drivenIntoWall(const Episode& e, BodyId b) {
  std::vector<ContactData> contacts;
  e.world.contacts(contacts);
  // Breadth first through joints and touching contacts, from b, across dynamic bodies only (a
  // static wall drives nothing, and through it everything would be linked).
  std::vector<BodyId> reached{b};
  const float heavier = maxDrivingMassRatio * e.world.mass(b);
  const auto reach = [&](BodyId from, BodyId a, BodyId c) {
    const BodyId other = a == from ? c : (c == from ? a : from);
    if (other != from && std::find(reached.begin(), reached.end(), other) == reached.end()) {
      reached.push_back(other);
    }
  };
  for (std::size_t next = 0; next < reached.size(); ++next) {
    const BodyId at = reached[next];
    const BodyType type = e.world.bodyType(at);
    if (type == BodyType::kinematicBody || (type == BodyType::dynamicBody && e.world.mass(at) > heavier)) {
      return true;
    }
    if (type == BodyType::staticBody) {
      continue;
    }
    for (const JointId j : e.joints) {
      if (e.world.isValid(j)) {
        reach(at, e.world.jointBodyA(j), e.world.jointBodyB(j));
      }
    }
    for (const ContactData& c : contacts) {
      reach(at, e.world.shapeBody(c.shapeA), e.world.shapeBody(c.shapeB));
    }
  }
  return false;
}

/// The invariants; the first one broken, or none.
std::optional<Failure> check(Episode& e, EpisodeStats& stats) {
  for (const BodyId b : e.bodies) {
    if (!e.world.isValid(b)) {
      return Failure{"a live body's id is invalid (index " + std::to_string(b.index) + ")"};
    }
    const Transform2f xf = e.world.transform(b);
    if (!finite(xf.p) || !std::isfinite(xf.q.c) || !std::isfinite(xf.q.s) || !finite(e.world.linearVelocity(b)) ||
        !std::isfinite(e.world.angularVelocity(b))) {
      return Failure{"body " + std::to_string(b.index) + " is not finite"};
    }
    const Vec2f c = e.world.worldCenterOfMass(b);
    const auto marked = [&] {
      return std::find(e.drivenIntoWalls.begin(), e.drivenIntoWalls.end(), b) != e.drivenIntoWalls.end();
    };
    if ((std::abs(c.x) > arenaHalfWidth || std::abs(c.y) > arenaHalfWidth) && !marked() && drivenIntoWall(e, b)) {
      e.drivenIntoWalls.push_back(b);
    }
    // A centre can reach at most a shape's size past the inner wall face; 10 m shapes exist.
    const float bound = arenaHalfWidth + wallThickness;
    if ((std::abs(c.x) > bound || std::abs(c.y) > bound) && !marked()) {
      return Failure{"body " + std::to_string(b.index) + " left the arena at (" + std::to_string(c.x) + ", " +
                     std::to_string(c.y) + "), speed " + std::to_string(length(e.world.linearVelocity(b))) + " m/s"};
    }
  }
  for (const BodyId b : e.destroyed) {
    if (e.world.isValid(b)) {
      return Failure{"a destroyed body's id is valid again"};
    }
  }
  for (const JointId j : e.joints) {
    if (!e.world.isValid(j)) {
      return Failure{"a live joint's id is invalid"};
    }
  }
  for (const JointId j : e.destroyedJoints) {
    if (e.world.isValid(j)) {
      return Failure{"a destroyed joint's id is valid again"};
    }
  }
  if (e.closed) {
    const double growth = (mechanicalEnergy(e) - e.energy0) / e.energyScale;
    stats.worstEnergyGrowth = std::max(stats.worstEnergyGrowth, growth);
    if (e.inside && growth > 0.01) {
      return Failure{"a closed system gained " + std::to_string(100.0 * growth) + "% of its energy scale"};
    }
  }
  return std::nullopt;
}

/// Debugging aid (IMPETUS_SOAK_TRACE set): each step, the fastest body and the energy.
void trace(const Episode& e, std::int64_t step) {
  float fastest = 0.0f;
  float fastestSpin = 0.0f;
  std::uint32_t which = 0;
  for (const BodyId b : e.bodies) {
    const float v = length(e.world.linearVelocity(b));
    fastestSpin = std::max(fastestSpin, std::abs(e.world.angularVelocity(b)));
    if (v > fastest) {
      fastest = v;
      which = b.index;
    }
  }
  std::fprintf(stderr, "step %lld: energy %.6g J, fastest body %u at %.3g m/s, fastest spin %.3g rad/s\n",
               static_cast<long long>(step), mechanicalEnergy(e), which, static_cast<double>(fastest),
               static_cast<double>(fastestSpin));
}

int usage(const std::string& why) {
  std::fprintf(stderr,
               "impetus-soak: %s\nusage: impetus-soak [--seconds S] [--seed N] [--episode-seconds T] "
               "[--threads K] [--joints on|off] [--prismatic on|off] [--envelope inside|outside] [--episodes N] "
               "[--first-episode N]\n",
               why.c_str());
  return 2;
}

} // namespace

int main(int argc, char** argv) {
  double wallSeconds = 10.0;
  std::uint64_t seed = 1;
  double episodeSeconds = 60.0;
  int threads = 1;
  bool joints = true;
  bool prismatic = true;
  bool inside = true;
  long long firstEpisode = 0;
  long long episodeCount = 0; // 0: as many as fit in --seconds
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) {
      return usage("missing value after " + arg);
    }
    const std::string value = argv[++i];
    char* end = nullptr;
    if (arg == "--seconds") {
      wallSeconds = std::strtod(value.c_str(), &end);
    } else if (arg == "--seed") {
      seed = std::strtoull(value.c_str(), &end, 10);
    } else if (arg == "--episode-seconds") {
      episodeSeconds = std::strtod(value.c_str(), &end);
    } else if (arg == "--episodes") {
      episodeCount = std::strtoll(value.c_str(), &end, 10);
    } else if (arg == "--first-episode") {
      firstEpisode = std::strtoll(value.c_str(), &end, 10);
    } else if (arg == "--joints") {
      joints = value != "0" && value != "off";
      end = argv[i] + value.size();
    } else if (arg == "--prismatic") {
      prismatic = value != "0" && value != "off";
      end = argv[i] + value.size();
    } else if (arg == "--envelope") {
      if (value != "inside" && value != "outside") {
        return usage("--envelope = " + value + ": inside or outside");
      }
      inside = value == "inside";
      end = argv[i] + value.size();
    } else if (arg == "--threads") {
      threads = static_cast<int>(std::strtol(value.c_str(), &end, 10));
    } else {
      return usage("unknown option " + arg);
    }
    if (end == value.c_str() || *end != '\0') {
      std::string why = arg;
      why += " = " + value + ": not a number";
      return usage(why);
    }
  }
  if (!(wallSeconds > 0.0) || !(episodeSeconds > 0.0) || threads < 1 || threads > 64 || firstEpisode < 0 ||
      firstEpisode > 1000000000 || episodeCount < 0 || episodeCount > 1000000000) {
    return usage("--seconds and --episode-seconds must be positive, --threads 1 to 64");
  }
  if (std::getenv("IMPETUS_SOAK_TRAP") != nullptr) {
    feenableexcept(FE_INVALID); // debugging aid: stop at the first NaN
  }
  std::unique_ptr<ThreadPool> pool = threads > 1 ? std::make_unique<ThreadPool>(threads) : nullptr;
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  EpisodeStats total;
  int episodes = static_cast<int>(firstEpisode); // each episode is built from (seed, index) alone
  int closedEpisodes = 0;
  const auto stepsPerEpisode = static_cast<std::int64_t>(episodeSeconds / timeStep);
  const long long lastEpisode = firstEpisode + episodeCount;
  while (episodeCount > 0 ? episodes < lastEpisode : elapsed() < wallSeconds) {
    const int index = episodes++;
    try {
      std::unique_ptr<Episode> e = buildEpisode(seed, index, pool.get(), joints, prismatic, inside);
      closedEpisodes += e->closed ? 1 : 0;
      Random rng(seed ^ (0xabcdef12345ULL + static_cast<std::uint64_t>(index)));
      for (std::int64_t step = 0; step < stepsPerEpisode; ++step) {
        if (!e->closed) {
          meddle(*e, rng);
        }
        try {
          e->world.step(timeStep);
        } catch (const Error& error) {
          std::fprintf(stderr, "impetus-soak: FAILED seed %llu episode %d (%s) step %lld: impetus::Error %s\n",
                       static_cast<unsigned long long>(seed), index, e->closed ? "closed" : "open",
                       static_cast<long long>(step), error.what());
          return 1;
        }
        if (std::getenv("IMPETUS_SOAK_TRACE") != nullptr) {
          trace(*e, step);
        }
        ++total.steps;
        if (const std::optional<Failure> f = check(*e, total)) {
          std::fprintf(stderr, "impetus-soak: FAILED seed %llu episode %d (%s) step %lld: %s\n",
                       static_cast<unsigned long long>(seed), index, e->closed ? "closed" : "open",
                       static_cast<long long>(step), f->what.c_str());
          return 1;
        }
      }
      total.bodies += e->bodies.size();
      total.joints += e->joints.size();
    } catch (const Error& error) {
      std::fprintf(stderr, "impetus-soak: FAILED seed %llu episode %d: impetus::Error %s\n",
                   static_cast<unsigned long long>(seed), index, error.what());
      return 1;
    }
  }
  std::printf("impetus-soak: seed %llu, %s the envelope, %d episodes (%d closed) of %.0f s simulated, %lld steps, "
              "%zu bodies and %zu joints at the ends, %.0f s wall; every invariant held. Worst energy growth of a "
              "closed system: %.4f%% of its energy scale (%s).\n",
              static_cast<unsigned long long>(seed), inside ? "inside" : "outside",
              episodes - static_cast<int>(firstEpisode), closedEpisodes, episodeSeconds,
              static_cast<long long>(total.steps), total.bodies, total.joints, elapsed(),
              100.0 * total.worstEnergyGrowth, inside ? "bound 1%" : "not bounded outside the envelope");
  return 0;
}
