// impetus-soak's episodes: the random bodies and joints of one episode (episode.hpp).
#include "episode.hpp"

#include <algorithm>
#include <array>

namespace soak {

namespace {

/// m: how far a slider's B may slide either way along A's rail.
constexpr float sliderTravel = 1.0f;

WorldDef worldDef(TaskRunner* runner) {
  WorldDef def;
  def.taskRunner = runner;
  return def;
}

/// A body's effective mass at a lever arm r from its centre of mass, kg: m k^2 / (k^2 + r^2), k its
/// radius of gyration (the mass a push across the arm meets: the body turns as much as it moves).
double effectiveMass(const World& world, BodyId body, double lever) {
  const double m = world.mass(body);
  const double k2 = world.rotationalInertia(body) / m;
  return m * k2 / (k2 + lever * lever);
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
  // Inside the envelope the two bodies' effective masses at the joint's lever arms are within
  // 10:1 (the mass ratio's rule, with turning counted): the pin `mid` for the revolute, prismatic
  // and weld joints (and, on the rail's body, the slider's travel), the centres for the distance
  // and motor joints, B's centre on A for the wheel.
  if (e.inside) {
    const auto lever = [&](BodyId body, const Vec2f& p) { return length(p - e.world.worldCenterOfMass(body)); };
    const bool pinned = kind == 0 || kind == 2 || kind == 3;
    const double leverA = pinned ? lever(a, mid) + (kind == 2 ? sliderTravel : 0.0f)
                                 : (kind == 4 ? lever(a, pb) : lever(a, e.world.position(a)));
    const double leverB = pinned ? lever(b, mid) : (kind == 4 ? 0.0 : lever(b, e.world.position(b)));
    const double massA = effectiveMass(e.world, a, leverA);
    const double massB = effectiveMass(e.world, b, leverB);
    if (std::max(massA, massB) > insideMaxJointMassRatio * std::min(massA, massB)) {
      return; // outside the envelope: no joint between these two
    }
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
    d.lowerTranslation = -sliderTravel;
    d.upperTranslation = sliderTravel;
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

} // namespace

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

} // namespace soak
