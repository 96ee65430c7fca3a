// The 2D benchmark scenes built in Box2D 2.4.1 (see box2d_scenes.hpp).
#include "box2d_scenes.hpp"

#include <impetus/error.hpp>

#include <string>

namespace impetus::bench {

Box2DScene buildBox2DScene(const Rigid2dScene& scene, bool continuous) {
  Box2DScene built{std::make_unique<b2World>(b2Vec2(scene.gravity.x, scene.gravity.y)), {}};
  built.world->SetAllowSleeping(scene.enableSleep);
  built.world->SetContinuousPhysics(continuous);
  built.bodies.reserve(scene.bodies.size());
  for (const SceneBody& b : scene.bodies) {
    b2BodyDef bd;
    bd.type = peerBodyType(b.type, b2_staticBody, b2_kinematicBody, b2_dynamicBody);
    bd.position.Set(b.position.x, b.position.y);
    bd.angularVelocity = b.angularVelocity;
    bd.linearVelocity = b2Vec2(b.linearVelocity.x, b.linearVelocity.y);
    bd.bullet = b.bullet;
    bd.allowSleep = scene.enableSleep;
    bd.awake = b.awake;
    built.bodies.push_back(built.world->CreateBody(&bd));
  }
  for (const SceneShape& s : scene.shapes) {
    b2FixtureDef fd;
    fd.density = s.density;
    fd.friction = s.friction;
    fd.restitution = 0.0f;
    fd.filter.groupIndex = static_cast<int16_t>(s.group);
    fd.filter.categoryBits = static_cast<uint16_t>(s.categoryBits); // 2.4.1's filters have 16 bits
    fd.filter.maskBits = static_cast<uint16_t>(s.maskBits);
    b2PolygonShape box;
    b2CircleShape circle;
    b2EdgeShape edge;
    switch (s.kind) {
    case SceneShape::Kind::circle:
      circle.m_p.Set(s.center.x, s.center.y);
      circle.m_radius = s.radius;
      fd.shape = &circle;
      break;
    case SceneShape::Kind::segment:
      edge.SetTwoSided(b2Vec2(s.point1.x, s.point1.y), b2Vec2(s.point2.x, s.point2.y));
      fd.shape = &edge;
      break;
    case SceneShape::Kind::box:
      box.SetAsBox(s.halfWidth, s.halfHeight, b2Vec2(s.center.x, s.center.y), s.angle);
      fd.shape = &box;
      break;
    case SceneShape::Kind::capsule:
    case SceneShape::Kind::polygon:
      throw Error("scene", "Box2D 2.4.1 has no capsules or rounded polygons (scene '" + scene.name + "')");
    }
    built.bodies[s.body]->CreateFixture(&fd);
  }
  for (const SceneJoint& j : scene.joints) {
    b2RevoluteJointDef jd;
    jd.Initialize(built.bodies[j.bodyA], built.bodies[j.bodyB], b2Vec2(j.anchor.x, j.anchor.y));
    setLimitAndMotor(j, jd);
    built.world->CreateJoint(&jd);
  }
  return built;
}

std::vector<Transform2f> bodyTransforms(const Box2DScene& built) {
  std::vector<Transform2f> out;
  out.reserve(built.bodies.size());
  for (const b2Body* body : built.bodies) {
    const b2Transform& xf = body->GetTransform();
    out.push_back({{xf.p.x, xf.p.y}, {xf.q.c, xf.q.s}});
  }
  return out;
}

} // namespace impetus::bench
