// The rigid2d scene loader (docs/scene-format-2d.md): the document's top level, world settings,
// materials, bodies and shapes; joints are read in rigid2d_scene_joints.cpp and effectors in
// rigid2d_scene_effectors.cpp. Every value is checked in the loader, with the JSON path of the
// value in the message, before the world sees it; the world's and the effectors' own checks stay
// as a backstop, and an error they raise is re-labelled with the element's path.
#include "rigid2d_scene.hpp"

#include "json_fields.hpp"
#include "rigid2d_scene_loader.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>

#include <cctype>
#include <cstdint>
#include <string>
#include <vector>

namespace impetus::cli {

namespace {

using json_fields::angleDeg;
using json_fields::at;
using json_fields::bits;
using json_fields::choice;
using json_fields::fail;
using json_fields::Fields;
using json_fields::forEach;
using json_fields::index;
using json_fields::points;
using json_fields::requiredVec2;
using json_fields::typeOf;
using json_fields::vec2;
using nlohmann::json;
using namespace rigid2d;

} // namespace

namespace rigid2d_loader {

std::string nameOf(Fields& f) {
  std::string name = f.text("name", "");
  for (const char c : name) {
    if (c == ',' || c == '"' || std::iscntrl(static_cast<unsigned char>(c)) != 0) {
      fail(f.path("name"), "'" + name + "' must not contain commas, quotes or control characters");
    }
  }
  return name;
}

void Loader::load(const json& doc) {
  Fields top(doc, "");
  (void)top.text("kind", "rigid2d");
  scene_.description = top.text("description", "");
  WorldDef def;
  def.gravity = {0.0f, -9.81f};
  if (const json* w = top.find("world")) {
    def = worldDef(*w);
  }
  gravity_ = def.gravity;
  def.taskRunner = runner_;
  scene_.world = at("world", [&] { return World(def); });
  if (const json* m = top.find("materials")) {
    materials(*m);
  }
  for (const char* key : {"bodies", "joints", "effectors"}) {
    (void)top.has(key);
  }
  top.done();
  forEach(doc, "bodies", [&](const json& j, const std::string& where) { body(j, where); });
  forEach(doc, "joints", [&](const json& j, const std::string& where) { joint(j, where); });
  forEach(doc, "effectors", [&](const json& j, const std::string& where) { effector(j, where); });
}

WorldDef Loader::worldDef(const json& j) {
  Fields f(j, "world");
  WorldDef d;
  d.gravity = vec2(f, "gravity", {0.0f, -9.81f});
  d.solver = choice(f, "solver", "soft", {"soft", "book"}, "solver") == "book" ? SolverKind::bookImpulse
                                                                               : SolverKind::softStep;
  d.substeps = static_cast<int>(f.integer("substeps", d.substeps, 1, 64));
  d.contactHertz = f.nonNegative("contact_hertz", d.contactHertz);
  d.contactDampingRatio = f.nonNegative("contact_damping_ratio", d.contactDampingRatio);
  d.maxContactPushSpeed = f.positive("max_contact_push_speed", d.maxContactPushSpeed);
  d.maxJointPushSpeed = f.positive("max_joint_push_speed", d.maxJointPushSpeed);
  d.jointHertz = f.nonNegative("joint_hertz", d.jointHertz);
  d.enableWarmStarting = f.boolean("enable_warm_starting", d.enableWarmStarting);
  d.jointDampingRatio = f.nonNegative("joint_damping_ratio", d.jointDampingRatio);
  d.restitutionThreshold = f.nonNegative("restitution_threshold", d.restitutionThreshold);
  d.maxLinearSpeed = f.positive("max_linear_speed", d.maxLinearSpeed);
  d.hitEventThreshold = f.nonNegative("hit_event_threshold", d.hitEventThreshold);
  d.contactReuseDistance = f.nonNegative("contact_reuse_distance", d.contactReuseDistance);
  d.enableSleep = f.boolean("enable_sleep", d.enableSleep);
  d.timeToSleep = f.nonNegative("time_to_sleep", d.timeToSleep);
  d.sleepLinearTolerance = f.nonNegative("sleep_linear_tolerance", d.sleepLinearTolerance);
  d.sleepAngularTolerance = f.nonNegative("sleep_angular_tolerance", d.sleepAngularTolerance);
  f.done();
  return d;
}

void Loader::materials(const json& j) {
  if (!j.is_object()) {
    fail("materials", "expected an object of named materials, got " + j.dump());
  }
  for (const auto& item : j.items()) {
    Fields f(item.value(), "materials." + item.key());
    materials_[item.key()] = material(f, Material{});
    f.done();
  }
}

Material Loader::material(Fields& f, Material m) {
  m.density = f.nonNegative("density", m.density);
  m.friction = f.nonNegative("friction", m.friction);
  m.restitution = f.fraction("restitution", m.restitution);
  m.rollingResistance = f.nonNegative("rolling_resistance", m.rollingResistance);
  m.tangentSpeed = f.real("tangent_speed", m.tangentSpeed);
  return m;
}

void Loader::body(const json& j, const std::string& where) {
  Fields f(j, where);
  if (scene_.bodies.size() >= maxSceneBodies) {
    fail(where, "more than " + std::to_string(maxSceneBodies) + " bodies in the scene");
  }
  const std::string name = nameOf(f);
  if (!name.empty()) {
    const auto [it, fresh] = names_.try_emplace(name, scene_.bodies.size());
    if (!fresh) {
      fail(f.path("name"), "duplicate body name '" + name + "' (also bodies[" + std::to_string(it->second) + "])");
    }
  }
  BodyDef def;
  const std::string type = choice(f, "type", "dynamic", {"static", "kinematic", "dynamic"}, "body type");
  def.type = type == "static"      ? BodyType::staticBody
             : type == "kinematic" ? BodyType::kinematicBody
                                   : BodyType::dynamicBody;
  def.position = vec2(f, "position", def.position);
  def.angle = angleDeg(f, "angle_deg", 0.0f);
  def.linearVelocity = vec2(f, "linear_velocity", def.linearVelocity);
  def.angularVelocity = f.real("angular_velocity", def.angularVelocity);
  def.linearDamping = f.nonNegative("linear_damping", def.linearDamping);
  def.angularDamping = f.nonNegative("angular_damping", def.angularDamping);
  def.gravityScale = f.real("gravity_scale", def.gravityScale);
  def.fixedRotation = f.boolean("fixed_rotation", def.fixedRotation);
  def.bullet = f.boolean("bullet", def.bullet);
  def.enableSleep = f.boolean("enable_sleep", def.enableSleep);
  def.isAwake = f.boolean("awake", def.isAwake);
  const json* massJson = f.find("mass_properties");
  if (massJson != nullptr && def.type != BodyType::dynamicBody) {
    fail(f.path("mass_properties"), "only a dynamic body has a mass to set");
  }
  const json* shapesJson = f.find("shapes");
  if (shapesJson != nullptr && !shapesJson->is_array()) {
    fail(f.path("shapes"), "expected an array of shapes, got " + shapesJson->dump());
  }
  f.done();

  const BodyId id = at(where, [&] { return scene_.world.createBody(def); });
  if (scene_.bodyBySlot.size() <= id.index) {
    scene_.bodyBySlot.resize(id.index + 1, 0);
  }
  scene_.bodyBySlot[id.index] = scene_.bodies.size();
  scene_.bodies.push_back(id);
  scene_.bodyNames.push_back(name);
  scene_.gravityScales.push_back(def.gravityScale);
  angles_.push_back(def.angle);
  if (shapesJson != nullptr) {
    for (std::size_t k = 0; k < shapesJson->size(); ++k) {
      shape(id, def.type, (*shapesJson)[k], index(f.path("shapes"), k));
    }
  }
  if (massJson != nullptr) {
    massProperties(id, *massJson, f.path("mass_properties"));
  }
}

void Loader::massProperties(BodyId id, const json& j, const std::string& where) {
  Fields f(j, where);
  MassData m;
  m.mass = f.requiredPositive("mass");
  const Transform2f xf = scene_.world.transform(id);
  const Vec2f shapesCenter = inverseTransformPoint(xf, scene_.world.worldCenterOfMass(id));
  m.center = vec2(f, "center", shapesCenter);
  if (f.has("inertia")) {
    m.rotationalInertia = f.positive("inertia", 1.0);
  } else {
    const float oldMass = scene_.world.mass(id);
    const float oldInertia = scene_.world.rotationalInertia(id);
    if (!(oldMass > 0.0f && oldInertia > 0.0f) || !(distance(m.center, shapesCenter) <= 0.0f)) {
      fail(f.path("inertia"), "missing (needed when the body has no shapes with area, or with a new center)");
    }
    m.rotationalInertia = oldInertia * m.mass / oldMass;
  }
  f.done();
  at(where, [&] { scene_.world.setMassData(id, m); });
}

ShapeDef Loader::shapeDef(Fields& f) {
  Material m;
  if (f.has("material")) {
    const std::string name = f.text("material", "");
    const auto it = materials_.find(name);
    if (it == materials_.end()) {
      fail(f.path("material"), "no material named '" + name + "' in materials");
    }
    m = it->second;
  }
  m = material(f, m);
  ShapeDef def;
  def.density = m.density;
  def.friction = m.friction;
  def.restitution = m.restitution;
  def.rollingResistance = m.rollingResistance;
  def.tangentSpeed = m.tangentSpeed;
  def.isSensor = f.boolean("sensor", def.isSensor);
  if (const json* filter = f.find("filter")) {
    Fields ff(*filter, f.path("filter"));
    def.filter.category = bits(ff, "category", def.filter.category);
    def.filter.mask = bits(ff, "mask", def.filter.mask);
    def.filter.group = static_cast<std::int32_t>(ff.integer("group", def.filter.group, -2147483647, 2147483647));
    ff.done();
  }
  return def;
}

void Loader::shape(BodyId id, BodyType bodyType, const json& j, const std::string& where) {
  Fields f(j, where);
  const std::string type = typeOf(f, {"circle", "box", "polygon", "capsule", "segment", "chain"}, "shape type");
  const ShapeDef def = shapeDef(f);
  if (bodyType == BodyType::dynamicBody && !(def.density > 0.0f) && type != "segment" && type != "chain") {
    throwInvalid(f.path("density"), def.density, "a shape on a dynamic body needs a positive density");
  }
  World& world = scene_.world;
  if (type == "circle") {
    Circle c;
    c.radius = f.requiredPositive("radius");
    c.center = vec2(f, "center", c.center);
    f.done();
    (void)at(where, [&] { return world.createShape(id, def, c); });
  } else if (type == "box") {
    const Vec2f half = requiredVec2(f, "half_extents");
    for (std::size_t a = 0; a < 2; ++a) {
      requirePositive(a == 0 ? half.x : half.y, index(f.path("half_extents"), a));
    }
    const Vec2f center = vec2(f, "center", {});
    const float angle = angleDeg(f, "angle_deg", 0.0f);
    f.done();
    const Polygon p = at(where, [&] { return makeOffsetBox(half.x, half.y, center, angle); },
                         {{"halfWidth", "half_extents[0]"},
                          {"halfHeight", "half_extents[1]"},
                          {"center.x", "center[0]"},
                          {"center.y", "center[1]"},
                          {"angle", "angle_deg"}});
    (void)at(where, [&] { return world.createShape(id, def, p); });
  } else if (type == "polygon") {
    const std::vector<Vec2f> pts = points(f, "points", 3, maxPolygonVertices);
    const float radius = f.nonNegative("radius", 0.0);
    f.done();
    const Polygon p = at(where, [&] { return makePolygon(pts, radius); });
    (void)at(where, [&] { return world.createShape(id, def, p); });
  } else if (type == "capsule") {
    Capsule c;
    c.center1 = requiredVec2(f, "center1");
    c.center2 = requiredVec2(f, "center2");
    c.radius = f.requiredPositive("radius");
    f.done();
    if (!(distance(c.center1, c.center2) > linearSlop)) {
      fail(f.path("center2"), "must differ from center1 by more than " + formatValue(linearSlop) + " m (use a circle)");
    }
    (void)at(where, [&] { return world.createShape(id, def, c); });
  } else if (type == "segment") {
    Segment s;
    s.point1 = requiredVec2(f, "point1");
    s.point2 = requiredVec2(f, "point2");
    f.done();
    if (!(distance(s.point1, s.point2) > linearSlop)) {
      fail(f.path("point2"), "must differ from point1 by more than " + formatValue(linearSlop) + " m");
    }
    (void)at(where, [&] { return world.createShape(id, def, s); });
  } else {
    ChainDef chain;
    chain.isLoop = f.boolean("loop", false);
    chain.points = points(f, "points", chain.isLoop ? 3 : 2, 100'000);
    f.done();
    (void)at(where, [&] { return world.createChain(id, def, chain); });
  }
  ++scene_.shapeCount;
}

} // namespace rigid2d_loader

std::size_t Rigid2dScene::bodyNumber(rigid2d::BodyId id) const { return bodyBySlot.at(id.index); }
std::size_t Rigid2dScene::jointNumber(rigid2d::JointId id) const { return jointBySlot.at(id.index); }

std::string sceneKind(const json& doc) {
  const auto it = doc.find("kind");
  if (it == doc.end()) {
    return "particles";
  }
  if (!it->is_string()) {
    fail("kind", R"(expected "particles" or "rigid2d", got )" + it->dump());
  }
  std::string kind = it->get<std::string>();
  if (kind != "particles" && kind != "rigid2d") {
    fail("kind", "unknown scene kind '" + kind + "' (particles, rigid2d)");
  }
  return kind;
}

Rigid2dScene parseRigid2dScene(const json& doc, TaskRunner* runner) {
  Rigid2dScene scene;
  rigid2d_loader::Loader(scene, runner).load(doc);
  return scene;
}

Rigid2dScene parseRigid2dScene(const std::string& jsonText) {
  return parseRigid2dScene(json_fields::parseObject(jsonText, "a JSON object (docs/scene-format-2d.md)"));
}

} // namespace impetus::cli
