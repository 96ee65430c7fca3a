// Building a 3D benchmark scene in Impetus (see rigid3d_impetus_scene.hpp).
#include "rigid3d_impetus_scene.hpp"

#include <impetus/rigid3d/geometry.hpp>
#include <impetus/rigid3d/hull.hpp>

#include <map>
#include <tuple>

namespace impetus::bench {

Impetus3dScene buildImpetus3dScene(const Rigid3dScene& scene, const Impetus3dSettings& settings) {
  rigid3d::WorldDef def;
  def.gravity = scene.gravity;
  def.substeps = settings.substeps;
  def.contactHertz = settings.contactHertz;
  def.enableSleep = settings.enableSleep;
  Impetus3dScene built{rigid3d::World(def), {}};
  built.bodies.reserve(scene.bodies.size());
  // One hull per size: the world copies it into each shape, but it is built once.
  std::map<std::tuple<float, float, float>, rigid3d::ShapeGeometry> boxes;
  for (const Scene3dBody& b : scene.bodies) {
    rigid3d::BodyDef bd;
    bd.type = b.type == Scene3dBody::Type::staticBody ? rigid3d::BodyType::staticBody : rigid3d::BodyType::dynamicBody;
    bd.position = b.position;
    bd.rotation = b.rotation;
    const rigid3d::BodyId body = built.world.createBody(bd);
    built.bodies.push_back(body);
    rigid3d::ShapeDef sd;
    sd.density = b.density;
    sd.friction = b.friction;
    sd.restitution = 0.0f;
    if (b.shape == Scene3dBody::Shape::sphere) {
      built.world.createShape(body, sd, rigid3d::Sphere{{}, b.radius});
      continue;
    }
    const auto key = std::make_tuple(b.halfExtents.x, b.halfExtents.y, b.halfExtents.z);
    auto it = boxes.find(key);
    if (it == boxes.end()) {
      it = boxes.emplace(key, rigid3d::makeBoxHull(b.halfExtents)).first;
    }
    built.world.createShape(body, sd, it->second);
  }
  return built;
}

std::vector<Transform3f> bodyPoses(const Impetus3dScene& built) {
  std::vector<Transform3f> poses;
  poses.reserve(built.bodies.size());
  for (const rigid3d::BodyId id : built.bodies) {
    poses.push_back(built.world.transform(id));
  }
  return poses;
}

} // namespace impetus::bench
