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
// 10 m across, densities 0.1 to 10 times water's, at most 10:1 in mass across a joint) the engine
// promises stable, energy-bounded behaviour; outside it (1 cm to 10 m, 1 to 100 kg whatever the
// size, any mass ratio) only that the world stays finite, in the arena, with every id valid.
// Each episode builds a world from (seed, episode) alone, so any failure is reproduced by its
// seed and episode number. Checked after every step:
//   - every body's position, rotation and velocities are finite;
//   - no body leaves the walled arena (walls 5 m thick; fast bodies are bullets or rely on the
//     continuous collision against static shapes), except one that a kinematic body drove into
//     a wall (through joints and contacts): its infinitely heavy driver can take it anywhere,
//     and, freed inside a wall, it is pushed out of the nearer face;
//   - every id the episode holds is valid and every id it destroyed is not; destroying a body
//     also destroys its joints;
//   - inside the envelope, in closed episodes (no motors, springs, kinematic bodies, restitution
//     or API changes), the mechanical energy never grows beyond E0 + 1% of the system's energy
//     scale (soft contacts and joints only dissipate; what they may add is the small push-out of
//     overlap). Outside it the worst growth is reported, not checked.
// Exit status 0 when every check held, 1 (with the seed, episode, step and what failed) if not,
// 2 for bad arguments.
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
/// water's 1000 kg/m^3 over a metre's depth) and the largest mass ratio across a joint.
constexpr float insideMinLogHalfSize = -1.3f; // 5 cm: 0.1 m across
constexpr float insideMaxLogHalfSize = 0.7f;  // 5 m: 10 m across
constexpr float insideMinLogDensity = 2.0f;
constexpr float insideMaxLogDensity = 4.0f;
constexpr float insideMaxJointMassRatio = 10.0f;

struct Failure {
  std::string what;
};

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
  /// Bodies a kinematic body drove into a wall: exempt from the arena bound for the rest of the
  /// episode (drivenByKinematic).
  std::vector<BodyId> drivenIntoWalls;
  bool closed = false;
  bool inside = true; ///< built inside the documented envelope (energy checked)
  double energy0 = 0.0;
  double energyScale = 0.0;
};

WorldDef worldDef(TaskRunner* runner) {
  WorldDef def;
  def.taskRunner = runner;
  return def;
}

/// One random body: a circle, capsule, box or polygon; inside the envelope 0.1 to 10 m across at a
/// density of 100 to 10,000 kg/m^2, outside it 1 cm to 10 m across whose density makes its mass
/// 1 to 100 kg. Adds the body to e.bodies (and its bounding radius to e.extents).
void addBody(Episode& e, Random& rng, const Vec2f& at, bool closed) {
  BodyDef def;
  def.type = (!closed && rng.chance(0.05f)) ? BodyType::kinematicBody : BodyType::dynamicBody;
  def.position = at;
  def.angle = rng.uniform(-3.14f, 3.14f);
  const float speed = rng.chance(0.1f) ? rng.uniform(50.0f, 200.0f) : rng.uniform(0.0f, 10.0f);
  const float heading = rng.uniform(-3.14f, 3.14f);
  def.linearVelocity = {speed * std::cos(heading), speed * std::sin(heading)};
  def.angularVelocity = def.type == BodyType::kinematicBody ? rng.uniform(-2.0f, 2.0f) : rng.uniform(-5.0f, 5.0f);
  def.bullet = speed > 50.0f && rng.chance(0.5f);
  if (def.type == BodyType::kinematicBody) {
    def.linearVelocity = {}; // a spinning paddle: kinematic bodies go where they are sent, walls or not
  }
  const BodyId body = e.world.createBody(def);
  float size = e.inside ? rng.logUniform(insideMinLogHalfSize, insideMaxLogHalfSize)
                        : rng.logUniform(-2.3f, 0.7f); // half-size: 1 cm to 10 m across
  const float density = rng.logUniform(insideMinLogDensity, insideMaxLogDensity);
  const float outsideMass = rng.logUniform(0.0f, 2.0f); // 1 to 100 kg
  // Inside the envelope the density is drawn; outside, the mass (whatever the size).
  const auto densityFor = [&](float area) { return e.inside ? density : outsideMass / area; };
  ShapeDef shape;
  shape.friction = rng.uniform(0.0f, 1.0f);
  shape.restitution = closed ? 0.0f : (rng.chance(0.3f) ? rng.uniform(0.0f, 1.0f) : 0.0f);
  shape.rollingResistance = closed ? 0.0f : (rng.chance(0.2f) ? rng.uniform(0.0f, 0.2f) : 0.0f);
  float area = 0.0f;
  float extent = size;
  switch (rng.below(4)) {
  case 0:
    area = pi<float> * size * size;
    shape.density = densityFor(area);
    e.world.createShape(body, shape, Circle{{}, size});
    break;
  case 1: {
    const float radius = 0.3f * size;
    area = pi<float> * radius * radius + 1.4f * size * 2.0f * radius;
    shape.density = densityFor(area);
    e.world.createShape(body, shape, Capsule{{-0.7f * size, 0.0f}, {0.7f * size, 0.0f}, radius});
    break;
  }
  case 2: {
    // Boxes and polygons no smaller than 5 cm: below a few linear slops (5 mm) a hull has no
    // distinct corners left.
    size = std::max(size, 0.05f);
    const float aspect = std::max(rng.logUniform(-1.0f, 0.0f), 0.02f / size);
    area = 4.0f * size * size * aspect;
    extent = size * std::sqrt(1.0f + aspect * aspect);
    shape.density = densityFor(area);
    e.world.createShape(body, shape, makeBox(size, size * aspect));
    break;
  }
  default: {
    size = std::max(size, 0.05f);
    std::array<Vec2f, 8> points;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const float a = 6.2832f * static_cast<float>(i) / 8.0f + rng.uniform(-0.3f, 0.3f);
      const float r = size * rng.uniform(0.5f, 1.0f);
      points[i] = {r * std::cos(a), r * std::sin(a)};
    }
    const Polygon polygon = makePolygon(points, rng.chance(0.3f) ? 0.1f * size : 0.0f);
    area = 2.0f * size * size; // a rough area: the density only sets the mass scale
    extent = 1.1f * size;
    shape.density = densityFor(area);
    e.world.createShape(body, shape, polygon);
    break;
  }
  }
  e.bodies.push_back(body);
  e.extents.push_back(extent);
}

/// A random joint between body A and body B placed against its right side (closed episodes: no
/// motors or springs); the pin is where their bounding circles touch, `extentA` right of A.
void addJoint(Episode& e, Random& rng, BodyId a, BodyId b, float extentA, bool closed, bool prismatic) {
  const Vec2f pa = e.world.worldCenterOfMass(a);
  const Vec2f pb = e.world.worldCenterOfMass(b);
  const Vec2f mid = e.world.position(a) + Vec2f{extentA, 0.0f};
  const auto local = [&](BodyId body, const Vec2f& p) {
    const Transform2f xf = e.world.transform(body);
    return inverseTransformPoint(xf, p);
  };
  // Joints start at rest: reference angles are the bodies' relative angle when joined.
  const float relativeAngle = e.world.angle(b) - e.world.angle(a);
  JointId id;
  int kind = rng.below(closed ? 3 : 6);
  if (kind == 2 && !prismatic) {
    kind = rng.below(2); // a revolute or distance joint instead
  }
  switch (kind) {
  case 0: {
    RevoluteJointDef d;
    d.referenceAngle = relativeAngle;
    d.bodyA = a;
    d.bodyB = b;
    d.localAnchorA = local(a, mid);
    d.localAnchorB = local(b, mid);
    d.enableLimit = rng.chance(0.5f);
    d.lowerAngle = -1.0f;
    d.upperAngle = 1.0f;
    if (!closed && rng.chance(0.3f)) {
      d.enableMotor = true;
      d.motorSpeed = rng.uniform(-5.0f, 5.0f);
      d.maxMotorTorque = rng.logUniform(0.0f, 3.0f);
    }
    id = e.world.createJoint(d);
    break;
  }
  case 1: {
    DistanceJointDef d;
    d.bodyA = a;
    d.bodyB = b;
    d.length = std::max(0.05f, length(pb - pa));
    if (!closed && rng.chance(0.5f)) {
      d.enableSpring = true;
      d.hertz = rng.uniform(0.5f, 5.0f);
      d.dampingRatio = rng.uniform(0.0f, 1.0f);
    }
    id = e.world.createJoint(d);
    break;
  }
  case 2: {
    PrismaticJointDef d;
    d.referenceAngle = relativeAngle;
    d.bodyA = a;
    d.bodyB = b;
    d.localAnchorA = local(a, mid);
    d.localAnchorB = local(b, mid);
    d.enableLimit = true;
    d.lowerTranslation = -1.0f;
    d.upperTranslation = 1.0f;
    id = e.world.createJoint(d);
    break;
  }
  case 3: {
    WeldJointDef d;
    d.referenceAngle = relativeAngle;
    d.bodyA = a;
    d.bodyB = b;
    d.localAnchorA = local(a, mid);
    d.localAnchorB = local(b, mid);
    d.linearHertz = rng.chance(0.5f) ? rng.uniform(1.0f, 10.0f) : 0.0f;
    id = e.world.createJoint(d);
    break;
  }
  case 4: {
    WheelJointDef d;
    d.bodyA = a;
    d.bodyB = b;
    d.localAnchorA = local(a, pb);
    d.enableMotor = rng.chance(0.5f);
    d.motorSpeed = rng.uniform(-10.0f, 10.0f);
    d.maxMotorTorque = rng.logUniform(0.0f, 3.0f);
    id = e.world.createJoint(d);
    break;
  }
  default: {
    MotorJointDef d;
    d.bodyA = a;
    d.bodyB = b;
    d.linearOffset = local(a, e.world.position(b));
    d.angularOffset = relativeAngle;
    d.maxForce = rng.logUniform(0.0f, 3.0f);
    d.maxTorque = rng.logUniform(0.0f, 3.0f);
    id = e.world.createJoint(d);
    break;
  }
  }
  e.joints.push_back(id);
}

/// Kinetic plus potential energy (gravity (0, -10), zero at the arena floor), J.
double mechanicalEnergy(const Episode& e) {
  double total = 0.0;
  for (const BodyId b : e.bodies) {
    const double m = e.world.mass(b);
    const Vec2f v = e.world.linearVelocity(b);
    const double w = e.world.angularVelocity(b);
    const double y = e.world.worldCenterOfMass(b).y + arenaHalfWidth;
    total += 0.5 * m * (static_cast<double>(v.x) * v.x + static_cast<double>(v.y) * v.y) +
             0.5 * e.world.rotationalInertia(b) * w * w + m * 10.0 * y;
  }
  return total;
}

std::unique_ptr<Episode> buildEpisode(std::uint64_t seed, int index, TaskRunner* runner, bool joints, bool prismatic,
                                      bool inside) {
  Random rng(seed * 0x100000001b3ULL + static_cast<std::uint64_t>(index));
  auto e = std::make_unique<Episode>(Episode{World(worldDef(runner)), {}, {}, {}, {}, {}, {}, false, inside, 0.0, 0.0});
  e->closed = rng.chance(0.3f);
  // The arena: four thick walls.
  const BodyId arena = e->world.createBody({});
  const float h = arenaHalfWidth + wallThickness / 2.0f;
  const float span = arenaHalfWidth + wallThickness;
  e->world.createShape(arena, {}, makeOffsetBox(span, wallThickness / 2.0f, {0.0f, -h}, 0.0f));
  e->world.createShape(arena, {}, makeOffsetBox(span, wallThickness / 2.0f, {0.0f, h}, 0.0f));
  e->world.createShape(arena, {}, makeOffsetBox(wallThickness / 2.0f, span, {-h, 0.0f}, 0.0f));
  e->world.createShape(arena, {}, makeOffsetBox(wallThickness / 2.0f, span, {h, 0.0f}, 0.0f));
  // Bodies on a jittered 10 x 10 grid of 12 m cells (no initial overlap: nothing to push apart).
  const int count = 20 + rng.below(80);
  for (int i = 0; i < count; ++i) {
    const float x = -54.0f + 12.0f * static_cast<float>(i % 10) + rng.uniform(-0.5f, 0.5f);
    const int row = i / 10;
    const float y = -54.0f + 12.0f * static_cast<float>(row) + rng.uniform(-0.5f, 0.5f);
    addBody(*e, rng, {x, y}, e->closed);
  }
  // Joints join a body to its right-hand neighbour in the grid, moved up against it (bounding
  // circles touching), so lever arms are the bodies' own sizes, as in a game's chains, ragdolls
  // and vehicles; the joined bodies keep their own random velocities (the joint's first step is
  // a violent, inelastic coupling). In index order, so chains stay chains.
  std::vector<std::size_t> joined;
  for (int j = 0; joints && j < count / 5; ++j) {
    const auto a = static_cast<std::size_t>(rng.below(count - 1));
    if (a % 10 != 9) {
      joined.push_back(a);
    }
  }
  std::sort(joined.begin(), joined.end());
  joined.erase(std::unique(joined.begin(), joined.end()), joined.end());
  for (const std::size_t a : joined) {
    const BodyId bodyA = e->bodies[a];
    const BodyId bodyB = e->bodies[a + 1];
    const float massA = e->world.mass(bodyA);
    const float massB = e->world.mass(bodyB);
    if (inside && std::max(massA, massB) > insideMaxJointMassRatio * std::min(massA, massB)) {
      continue; // outside the envelope: no joint between these two
    }
    const Vec2f at = e->world.position(bodyA) + Vec2f{e->extents[a] + e->extents[a + 1], 0.0f};
    e->world.setTransform(bodyB, at, e->world.angle(bodyB));
    addJoint(*e, rng, bodyA, bodyB, e->extents[a], e->closed, prismatic);
  }
  e->energy0 = mechanicalEnergy(*e);
  double scale = 0.0;
  for (const BodyId b : e->bodies) {
    scale += e->world.mass(b) * 10.0 * 2.0 * arenaHalfWidth;
  }
  e->energyScale = std::max(scale, std::abs(e->energy0));
  return e;
}

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

bool finite(const Vec2f& v) { return std::isfinite(v.x) && std::isfinite(v.y); }

/// Whether a kinematic body drives the body: a chain of joints and touching contacts through
/// dynamic bodies links the two. A kinematic body goes where it is sent, walls or not, with
/// infinite mass, and what it drives goes with it (a body on a paddle's slider pressed into a wall,
/// or squeezed between the paddle and a wall: no solver can hold both an infinitely heavy driver
/// and a wall). Such a body can reach anywhere its driver goes, so the arena bound does not hold
/// it; nor once freed, if it was left in a wall (it is pushed out of the nearer face).
/// docs/reliability.md ("Soak") lists the episodes that showed it.
bool drivenByKinematic(const Episode& e, BodyId b) {
  std::vector<ContactData> contacts;
  e.world.contacts(contacts);
  // Breadth first through joints and touching contacts, from b, across dynamic bodies only (a
  // static wall drives nothing, and through it everything would be linked).
  std::vector<BodyId> reached{b};
  const auto reach = [&](BodyId from, BodyId a, BodyId c) {
    const BodyId other = a == from ? c : (c == from ? a : from);
    if (other != from && std::find(reached.begin(), reached.end(), other) == reached.end()) {
      reached.push_back(other);
    }
  };
  for (std::size_t next = 0; next < reached.size(); ++next) {
    const BodyId at = reached[next];
    const BodyType type = e.world.bodyType(at);
    if (type == BodyType::kinematicBody) {
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
    if ((std::abs(c.x) > arenaHalfWidth || std::abs(c.y) > arenaHalfWidth) && !marked() && drivenByKinematic(e, b)) {
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
