// Building a benchmark scene in Impetus, and the quality figures measured the same way in every
// engine from body transforms alone (see rigid2d_scenes.hpp).
#include "rigid2d_scenes.hpp"

#include <impetus/rigid2d/manifold.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <variant>

namespace impetus::bench {
namespace {

using rigid2d::BodyType;

using Geometry = std::variant<rigid2d::Polygon, rigid2d::Circle, rigid2d::Segment, rigid2d::Capsule>;

Geometry geometryOf(const SceneShape& s) {
  switch (s.kind) {
  case SceneShape::Kind::circle:
    return rigid2d::Circle{s.center, s.radius};
  case SceneShape::Kind::segment:
    return rigid2d::Segment{s.point1, s.point2};
  case SceneShape::Kind::capsule:
    return rigid2d::Capsule{s.point1, s.point2, s.radius};
  case SceneShape::Kind::polygon:
    return rigid2d::makePolygon(s.points, s.radius);
  case SceneShape::Kind::box:
    break;
  }
  return rigid2d::makeOffsetBox(s.halfWidth, s.halfHeight, s.center, s.angle);
}

/// The smallest separation of the manifold's points (positive when apart; large when none).
float separation(const rigid2d::Manifold& m) {
  float least = 1.0e30f;
  for (int i = 0; i < m.pointCount; ++i) {
    least = std::min(least, m.points[static_cast<std::size_t>(i)].separation);
  }
  return least;
}

float separation(const Geometry& a, const Transform2f& xfA, const Geometry& b, const Transform2f& xfB) {
  // A segment or capsule as the narrowphase sees it: a two-vertex polygon (rounded).
  if (const auto* ca = std::get_if<rigid2d::Capsule>(&a)) {
    return separation(Geometry{rigid2d::asPolygon(*ca)}, xfA, b, xfB);
  }
  if (const auto* cb = std::get_if<rigid2d::Capsule>(&b)) {
    return separation(a, xfA, Geometry{rigid2d::asPolygon(*cb)}, xfB);
  }
  if (const auto* sa = std::get_if<rigid2d::Segment>(&a)) {
    return separation(Geometry{rigid2d::asPolygon(*sa)}, xfA, b, xfB);
  }
  if (const auto* sb = std::get_if<rigid2d::Segment>(&b)) {
    return separation(a, xfA, Geometry{rigid2d::asPolygon(*sb)}, xfB);
  }
  const auto* ca = std::get_if<rigid2d::Circle>(&a);
  const auto* cb = std::get_if<rigid2d::Circle>(&b);
  if (ca != nullptr && cb != nullptr) {
    return separation(rigid2d::collideCircles(*ca, xfA, *cb, xfB));
  }
  if (ca != nullptr) {
    return separation(rigid2d::collidePolygonAndCircle(std::get<rigid2d::Polygon>(b), xfB, *ca, xfA));
  }
  if (cb != nullptr) {
    return separation(rigid2d::collidePolygonAndCircle(std::get<rigid2d::Polygon>(a), xfA, *cb, xfB));
  }
  return separation(rigid2d::collidePolygons(std::get<rigid2d::Polygon>(a), xfA, std::get<rigid2d::Polygon>(b), xfB));
}

} // namespace

std::vector<rigid2d::BodyId> addToImpetusWorld(rigid2d::World& world, const SceneContent& content) {
  std::vector<rigid2d::BodyId> bodies;
  bodies.reserve(content.bodies.size());
  for (const SceneBody& b : content.bodies) {
    rigid2d::BodyDef bd;
    bd.type = b.type;
    bd.position = b.position;
    bd.angularVelocity = b.angularVelocity;
    bd.linearVelocity = b.linearVelocity;
    bd.linearDamping = b.linearDamping;
    bd.bullet = b.bullet;
    bd.isAwake = b.awake;
    bodies.push_back(world.createBody(bd));
  }
  for (const SceneShape& s : content.shapes) {
    rigid2d::ShapeDef sd;
    sd.friction = s.friction;
    sd.density = s.density;
    sd.filter = {s.categoryBits, s.maskBits, s.group};
    std::visit([&](const auto& shape) { world.createShape(bodies[s.body], sd, shape); }, geometryOf(s));
  }
  for (const SceneJoint& j : content.joints) {
    rigid2d::RevoluteJointDef jd;
    jd.bodyA = bodies[j.bodyA];
    jd.bodyB = bodies[j.bodyB];
    jd.localAnchorA = j.anchor - content.bodies[j.bodyA].position; // bodies start unrotated
    jd.localAnchorB = j.anchor - content.bodies[j.bodyB].position;
    jd.referenceAngle = j.referenceAngle;
    setLimitAndMotor(j, jd);
    jd.enableSpring = j.enableSpring;
    jd.hertz = j.hertz;
    jd.dampingRatio = j.dampingRatio;
    world.createJoint(jd);
  }
  return bodies;
}

ImpetusScene buildImpetusScene(const Rigid2dScene& scene, const ImpetusSettings& settings) {
  rigid2d::WorldDef def;
  def.taskRunner = settings.runner;
  def.substeps = settings.substeps;
  def.contactHertz = settings.contactHertz;
  def.contactReuseDistance = settings.contactReuseDistance;
  def.simd = settings.simd;
  def.gravity = scene.gravity;
  def.enableSleep = settings.enableSleep || scene.enableSleep;
  def.sleepLinearTolerance = scene.sleepThreshold;
  ImpetusScene built{rigid2d::World(def), {}};
  built.bodies = addToImpetusWorld(built.world, scene);
  return built;
}

std::uint32_t ImpetusSpawner::spawn(const SceneContent& group) {
  groups_.push_back(addToImpetusWorld(world_, group));
  return static_cast<std::uint32_t>(groups_.size() - 1);
}

void ImpetusSpawner::destroy(std::uint32_t group) {
  for (const rigid2d::BodyId b : groups_[group]) {
    world_.destroyBody(b);
  }
  groups_[group].clear();
}

std::size_t ImpetusSpawner::liveBodies() const {
  std::size_t n = 0;
  for (const std::vector<rigid2d::BodyId>& g : groups_) {
    n += g.size();
  }
  return n;
}

std::vector<rigid2d::BodyId> ImpetusSpawner::bodies() const {
  std::vector<rigid2d::BodyId> out;
  for (const std::vector<rigid2d::BodyId>& g : groups_) {
    out.insert(out.end(), g.begin(), g.end());
  }
  return out;
}

std::vector<Transform2f> bodyTransforms(const ImpetusScene& built) {
  std::vector<Transform2f> out;
  out.reserve(built.bodies.size());
  for (const rigid2d::BodyId id : built.bodies) {
    out.push_back(built.world.transform(id));
  }
  return out;
}

float topSink(const Rigid2dScene& scene, std::span<const Transform2f> transforms) {
  if (scene.tops.empty()) {
    return 0.0f;
  }
  float sink = -std::numeric_limits<float>::infinity();
  for (const std::uint32_t top : scene.tops) {
    sink = std::max(sink, scene.bodies[top].position.y - transforms[top].p.y);
  }
  return sink;
}

float largestOverlap(const Rigid2dScene& scene, std::span<const Transform2f> transforms) {
  const std::size_t n = scene.shapes.size();
  std::vector<Geometry> geometry;
  std::vector<rigid2d::AABB> boxes;
  geometry.reserve(n);
  boxes.reserve(n);
  for (const SceneShape& s : scene.shapes) {
    geometry.push_back(geometryOf(s));
    const Transform2f& xf = transforms[s.body];
    boxes.push_back(std::visit([&](const auto& g) { return rigid2d::computeAABB(g, xf); }, geometry.back()));
  }
  // Sort and sweep along x: each shape meets the shapes that start before it ends.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return boxes[a].lower.x != boxes[b].lower.x ? boxes[a].lower.x < boxes[b].lower.x : a < b;
  });
  float deepest = 0.0f;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = order[k];
    const SceneShape& sa = scene.shapes[a];
    for (std::size_t m = k + 1; m < n && boxes[order[m]].lower.x <= boxes[a].upper.x; ++m) {
      const std::size_t b = order[m];
      const SceneShape& sb = scene.shapes[b];
      if (sa.body == sb.body || boxes[b].lower.y > boxes[a].upper.y || boxes[a].lower.y > boxes[b].upper.y) {
        continue;
      }
      if (scene.bodies[sa.body].type != BodyType::dynamicBody && scene.bodies[sb.body].type != BodyType::dynamicBody) {
        continue;
      }
      deepest = std::max(deepest, -separation(geometry[a], transforms[sa.body], geometry[b], transforms[sb.body]));
    }
  }
  return deepest;
}

bool allFinite(std::span<const Transform2f> transforms) {
  return std::all_of(transforms.begin(), transforms.end(), [](const Transform2f& xf) {
    return std::isfinite(xf.p.x) && std::isfinite(xf.p.y) && std::isfinite(xf.q.c) && std::isfinite(xf.q.s);
  });
}

std::size_t dynamicBodyCount(const Rigid2dScene& scene) {
  return static_cast<std::size_t>(std::count_if(scene.bodies.begin(), scene.bodies.end(),
                                                [](const SceneBody& b) { return b.type == BodyType::dynamicBody; }));
}

float largestJointGap(const Rigid2dScene& scene, std::span<const Transform2f> transforms) {
  float widest = 0.0f;
  for (const SceneJoint& j : scene.joints) {
    const Vec2f localA = j.anchor - scene.bodies[j.bodyA].position; // bodies start unrotated
    const Vec2f localB = j.anchor - scene.bodies[j.bodyB].position;
    widest = std::max(
        widest, distance(transformPoint(transforms[j.bodyA], localA), transformPoint(transforms[j.bodyB], localB)));
  }
  return widest;
}

} // namespace impetus::bench
