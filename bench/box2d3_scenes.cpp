// The 2D benchmark scenes built in Box2D v3 (see box2d3_scenes.hpp). Compiled only when CMake is
// pointed at a Box2D v3 build (IMPETUS_BOX2D3_DIR), with its headers ahead of Debian's 2.4.1.
#include "box2d3_scenes.hpp"

#include <box2d/box2d.h>

namespace impetus::bench {

struct Box2D3Scene::Impl {
  b2WorldId world{};
  std::vector<b2BodyId> bodies;
  bool enableSleep = false;
  float sleepThreshold = 0.05f;
  std::vector<std::vector<b2BodyId>> groups; ///< spawned by the scene's script
};

namespace {

/// Adds bodies with their shapes and joints to a v3 world; their ids, in order.
std::vector<b2BodyId> addContent(b2WorldId world, const SceneContent& content, bool enableSleep, float sleepThreshold) {
  std::vector<b2BodyId> bodies;
  bodies.reserve(content.bodies.size());
  for (const SceneBody& b : content.bodies) {
    b2BodyDef bd = b2DefaultBodyDef();
    bd.type = peerBodyType(b.type, b2_staticBody, b2_kinematicBody, b2_dynamicBody);
    bd.position = {b.position.x, b.position.y};
    bd.linearVelocity = {b.linearVelocity.x, b.linearVelocity.y};
    bd.angularVelocity = b.angularVelocity;
    bd.linearDamping = b.linearDamping;
    bd.isBullet = b.bullet;
    bd.enableSleep = enableSleep;
    bd.sleepThreshold = sleepThreshold;
    bd.isAwake = b.awake;
    bodies.push_back(b2CreateBody(world, &bd));
  }
  for (const SceneShape& s : content.shapes) {
    b2ShapeDef sd = b2DefaultShapeDef();
    sd.density = s.density;
    sd.material.friction = s.friction;
    sd.material.restitution = 0.0f;
    sd.filter.groupIndex = s.group;
    sd.filter.categoryBits = s.categoryBits;
    sd.filter.maskBits = s.maskBits;
    const b2BodyId body = bodies[s.body];
    switch (s.kind) {
    case SceneShape::Kind::circle: {
      const b2Circle circle{{s.center.x, s.center.y}, s.radius};
      b2CreateCircleShape(body, &sd, &circle);
      break;
    }
    case SceneShape::Kind::segment: {
      const b2Segment segment{{s.point1.x, s.point1.y}, {s.point2.x, s.point2.y}};
      b2CreateSegmentShape(body, &sd, &segment);
      break;
    }
    case SceneShape::Kind::capsule: {
      const b2Capsule capsule{{s.point1.x, s.point1.y}, {s.point2.x, s.point2.y}, s.radius};
      b2CreateCapsuleShape(body, &sd, &capsule);
      break;
    }
    case SceneShape::Kind::polygon: {
      std::vector<b2Vec2> points;
      for (const Vec2f& p : s.points) {
        points.push_back({p.x, p.y});
      }
      const b2Hull hull = b2ComputeHull(points.data(), static_cast<int>(points.size()));
      const b2Polygon polygon = b2MakePolygon(&hull, s.radius);
      b2CreatePolygonShape(body, &sd, &polygon);
      break;
    }
    case SceneShape::Kind::box: {
      const b2Polygon box = b2MakeOffsetBox(s.halfWidth, s.halfHeight, {s.center.x, s.center.y}, b2MakeRot(s.angle));
      b2CreatePolygonShape(body, &sd, &box);
      break;
    }
    }
  }
  for (const SceneJoint& j : content.joints) {
    // The scene's bodies start unrotated: the anchor's local point is its offset from the origin;
    // the reference angle is frame A's rotation (v3's joint angle is frame B's relative to A's).
    const SceneBody& a = content.bodies[j.bodyA];
    const SceneBody& b = content.bodies[j.bodyB];
    b2RevoluteJointDef jd = b2DefaultRevoluteJointDef();
    jd.base.bodyIdA = bodies[j.bodyA];
    jd.base.bodyIdB = bodies[j.bodyB];
    jd.base.localFrameA.p = {j.anchor.x - a.position.x, j.anchor.y - a.position.y};
    jd.base.localFrameA.q = b2MakeRot(j.referenceAngle);
    jd.base.localFrameB.p = {j.anchor.x - b.position.x, j.anchor.y - b.position.y};
    setLimitAndMotor(j, jd);
    jd.enableSpring = j.enableSpring;
    jd.hertz = j.hertz;
    jd.dampingRatio = j.dampingRatio;
    b2CreateRevoluteJoint(world, &jd);
  }
  return bodies;
}

} // namespace

Box2D3Scene::Box2D3Scene(const Rigid2dScene& scene, int workers, bool continuous) : impl_(std::make_unique<Impl>()) {
  b2WorldDef wd = b2DefaultWorldDef();
  wd.gravity = {scene.gravity.x, scene.gravity.y};
  wd.enableSleep = scene.enableSleep;
  wd.enableContinuous = continuous;
  wd.workerCount = workers; // above 1: Box2D v3's own threads and scheduler
  impl_->world = b2CreateWorld(&wd);
  impl_->enableSleep = scene.enableSleep;
  impl_->sleepThreshold = scene.sleepThreshold;
  impl_->bodies = addContent(impl_->world, scene, scene.enableSleep, scene.sleepThreshold);
}

std::uint32_t Box2D3Scene::spawn(const SceneContent& group) {
  impl_->groups.push_back(addContent(impl_->world, group, impl_->enableSleep, impl_->sleepThreshold));
  return static_cast<std::uint32_t>(impl_->groups.size() - 1);
}

void Box2D3Scene::destroy(std::uint32_t group) {
  for (const b2BodyId body : impl_->groups[group]) {
    b2DestroyBody(body);
  }
  impl_->groups[group].clear();
}

Box2D3Scene::~Box2D3Scene() { b2DestroyWorld(impl_->world); }

void Box2D3Scene::step() { b2World_Step(impl_->world, sceneTimeStep, box2d3Substeps); }

rigid2d::StepProfile Box2D3Scene::profile() const {
  const b2Profile p = b2World_GetProfile(impl_->world);
  rigid2d::StepProfile out;
  out.step = p.step;
  out.pairs = p.pairs;
  out.collide = p.collide;
  out.solve = p.solve;
  out.prepare = p.solverSetup + p.prepareConstraints;
  out.integrateVelocities = p.integrateVelocities;
  out.warmStart = p.warmStart;
  out.solveConstraints = p.solveImpulses;
  out.integratePositions = p.integratePositions;
  out.relax = p.relaxImpulses + p.applyRestitution;
  out.storeImpulses = p.storeImpulses + p.jointEvents;
  out.finalize = p.transforms + p.splitIslands + p.sleepIslands + p.hitEvents + p.refit + p.bullets + p.sensorHits;
  return out;
}

float Box2D3Scene::height(std::uint32_t body) const {
  return static_cast<float>(b2Body_GetPosition(impl_->bodies[body]).y);
}

std::vector<Transform2f> Box2D3Scene::transforms() const {
  std::vector<Transform2f> out;
  out.reserve(impl_->bodies.size());
  for (const b2BodyId body : impl_->bodies) {
    const b2WorldTransform xf = b2Body_GetTransform(body);
    out.push_back({{static_cast<float>(xf.p.x), static_cast<float>(xf.p.y)}, {xf.q.c, xf.q.s}});
  }
  return out;
}

std::size_t Box2D3Scene::touchingContacts() const {
  // Each body lists its touching contacts (Box2D v3 keeps only those with points); a contact is
  // counted at its first shape's body, so once.
  std::size_t count = 0;
  std::vector<b2ContactData> data;
  for (const b2BodyId body : impl_->bodies) {
    data.resize(static_cast<std::size_t>(b2Body_GetContactCapacity(body)));
    const int n = b2Body_GetContactData(body, data.data(), static_cast<int>(data.size()));
    for (int i = 0; i < n; ++i) {
      const b2ContactData& c = data[static_cast<std::size_t>(i)];
      if (c.manifold.pointCount > 0 && B2_ID_EQUALS(b2Shape_GetBody(c.shapeIdA), body)) {
        ++count;
      }
    }
  }
  return count;
}

std::string Box2D3Scene::version() {
  const b2Version v = b2GetVersion();
  return "box2d " + std::to_string(v.major) + "." + std::to_string(v.minor) + "." + std::to_string(v.revision);
}

} // namespace impetus::bench
