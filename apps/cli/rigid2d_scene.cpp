// The rigid2d scene loader (docs/scene-format-2d.md). Every value is checked here, with the JSON
// path of the value in the message, before the world sees it; the world's and the effectors' own
// checks stay as a backstop, and an error they raise is re-labelled with the element's path.
#include "rigid2d_scene.hpp"

#include "json_fields.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <utility>

namespace impetus::cli {

std::size_t Rigid2dScene::bodyNumber(rigid2d::BodyId id) const { return bodyBySlot.at(id.index); }
std::size_t Rigid2dScene::jointNumber(rigid2d::JointId id) const { return jointBySlot.at(id.index); }

namespace {

using json_fields::angleDeg;
using json_fields::arrayOf;
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
using json_fields::vec2At;
using nlohmann::json;
using namespace rigid2d;

constexpr std::size_t maxBodies = 1'000'000;

/// A name that can go in a CSV field as it is.
std::string nameOf(Fields& f) {
  const std::string name = f.text("name", "");
  for (const char c : name) {
    if (c == ',' || c == '"' || std::iscntrl(static_cast<unsigned char>(c)) != 0) {
      fail(f.path("name"), "'" + name + "' must not contain commas, quotes or control characters");
    }
  }
  return name;
}

// Effectors: every effector runs only in its time window [start, stop). ---------------------

class Scheduled final : public ForceEffector {
public:
  Scheduled(std::unique_ptr<ForceEffector> inner, double start, double stop)
      : inner_(std::move(inner)), start_(start), stop_(stop) {}
  void apply(World& world, float dt) override {
    if (time_ >= start_ && time_ < stop_) {
      inner_->apply(world, dt);
    }
    ++steps_;
    time_ = static_cast<double>(steps_) * static_cast<double>(dt);
  }

private:
  std::unique_ptr<ForceEffector> inner_;
  double start_;
  double stop_;
  double time_ = 0.0;
  std::int64_t steps_ = 0;
};

struct Material {
  float density = 1.0f;
  float friction = 0.6f;
  float restitution = 0.0f;
  float rollingResistance = 0.0f;
};

class Loader {
public:
  Loader(Rigid2dScene& scene, TaskRunner* runner) : scene_(scene), runner_(runner) {}

  void load(const json& doc) {
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
    scene_.world = World(def);
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

private:
  static WorldDef worldDef(const json& j) {
    Fields f(j, "world");
    WorldDef d;
    d.gravity = vec2(f, "gravity", {0.0f, -9.81f});
    d.solver = choice(f, "solver", "soft", {"soft", "book"}, "solver") == "book" ? SolverKind::bookImpulse
                                                                                 : SolverKind::softStep;
    d.substeps = static_cast<int>(f.integer("substeps", d.substeps, 1, 64));
    d.contactHertz = f.nonNegative("contact_hertz", d.contactHertz);
    d.contactDampingRatio = f.nonNegative("contact_damping_ratio", d.contactDampingRatio);
    d.maxContactPushSpeed = f.positive("max_contact_push_speed", d.maxContactPushSpeed);
    d.jointHertz = f.nonNegative("joint_hertz", d.jointHertz);
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

  /// "materials": {"name": {density, friction, restitution, rolling_resistance}}.
  void materials(const json& j) {
    if (!j.is_object()) {
      fail("materials", "expected an object of named materials, got " + j.dump());
    }
    for (const auto& item : j.items()) {
      Fields f(item.value(), "materials." + item.key());
      materials_[item.key()] = material(f, Material{});
      f.done();
    }
  }

  static Material material(Fields& f, Material m) {
    m.density = f.nonNegative("density", m.density);
    m.friction = f.nonNegative("friction", m.friction);
    m.restitution = f.fraction("restitution", m.restitution);
    m.rollingResistance = f.nonNegative("rolling_resistance", m.rollingResistance);
    return m;
  }

  // Bodies and shapes ------------------------------------------------------------------------

  void body(const json& j, const std::string& where) {
    Fields f(j, where);
    if (scene_.bodies.size() >= maxBodies) {
      fail(where, "more than " + std::to_string(maxBodies) + " bodies in the scene");
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

  /// {"mass", "center", "inertia"}: overrides what the shapes' densities give. Without a
  /// centre the shapes' centre of mass stays; without an inertia the shapes' inertia about the
  /// centre of mass is scaled by the new mass (the same shapes, a uniformly scaled density).
  void massProperties(BodyId id, const json& j, const std::string& where) {
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

  ShapeDef shapeDef(Fields& f) {
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

  void shape(BodyId id, BodyType bodyType, const json& j, const std::string& where) {
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
      const Polygon p = at(where, [&] { return makeOffsetBox(half.x, half.y, center, angle); });
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
        fail(f.path("center2"),
             "must differ from center1 by more than " + formatValue(linearSlop) + " m (use a circle)");
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

  // Joints -----------------------------------------------------------------------------------

  /// A body named in a joint or an effector.
  BodyId bodyNamed(Fields& f, const std::string& key) {
    const json& j = f.require(key);
    if (!j.is_string()) {
      fail(f.path(key), "expected a body name, got " + j.dump());
    }
    const auto it = names_.find(j.get<std::string>());
    if (it == names_.end()) {
      fail(f.path(key), "no body named '" + j.get<std::string>() + "'");
    }
    return scene_.bodies[it->second];
  }
  float initialAngle(BodyId id) const { return angles_[scene_.bodyNumber(id)]; }

  /// One end's anchor in its body's frame: "local_anchor_<e>" (body frame), "anchor_<e>"
  /// (a world point) or the shared "anchor" (a world point); at most one; default the origin.
  Vec2f anchor(Fields& f, BodyId id, const char* end, bool shared) {
    const std::string localKey = std::string("local_anchor_") + end;
    const std::string worldKey = std::string("anchor_") + end;
    const bool hasLocal = f.has(localKey);
    const bool hasWorld = f.has(worldKey);
    const bool hasShared = shared && f.has("anchor");
    if (int{hasLocal} + int{hasWorld} + int{hasShared} > 1) {
      fail(f.path(hasLocal ? localKey : worldKey),
           std::string("give at most one of anchor, ") + worldKey + " (world) and " + localKey + " (body frame)");
    }
    if (hasLocal) {
      return requiredVec2(f, localKey);
    }
    const Transform2f xf = scene_.world.transform(id);
    if (hasWorld) {
      return inverseTransformPoint(xf, requiredVec2(f, worldKey));
    }
    if (hasShared) {
      return inverseTransformPoint(xf, requiredVec2(f, "anchor"));
    }
    return {};
  }

  /// An axis in body A's frame: "local_axis_a" or "axis" (a world direction).
  Vec2f axis(Fields& f, BodyId a, const Vec2f& fallbackWorld) {
    if (f.has("local_axis_a") && f.has("axis")) {
      fail(f.path("axis"), "give at most one of axis (world) and local_axis_a (body A's frame)");
    }
    const std::string key = f.has("local_axis_a") ? "local_axis_a" : "axis";
    const Vec2f v = vec2(f, key, fallbackWorld);
    if (!(length(v) > 1e-6f)) {
      fail(f.path(key), "must be non-zero");
    }
    return key == "axis" ? inverseRotate(scene_.world.transform(a).q, v) : v;
  }

  /// What every joint has. B's anchor, A's anchor, collide_connected, break limits.
  void base(Fields& f, JointDefBase& d, bool anchors) {
    if (anchors) {
      d.localAnchorA = anchor(f, d.bodyA, "a", true);
      d.localAnchorB = anchor(f, d.bodyB, "b", true);
    }
    d.collideConnected = f.boolean("collide_connected", d.collideConnected);
    if (f.has("break_force")) {
      d.breakForce = f.nonNegative("break_force", 0.0);
    }
    if (f.has("break_torque")) {
      d.breakTorque = f.nonNegative("break_torque", 0.0);
    }
  }

  void bodies(Fields& f, JointDefBase& d) {
    d.bodyA = bodyNamed(f, "body_a");
    d.bodyB = bodyNamed(f, "body_b");
    if (d.bodyA == d.bodyB) {
      fail(f.path("body_b"), "a joint needs two different bodies");
    }
  }

  /// Lower and upper limits (lower <= upper); angles in degrees when `degrees`.
  static void limits(Fields& f, const std::string& lowerKey, const std::string& upperKey, float& lower, float& upper,
                     bool degrees) {
    const float lo = f.real(lowerKey, 0.0);
    const float hi = f.real(upperKey, 0.0);
    if (lo > hi) {
      throwInvalid(f.path(upperKey), hi, "must be >= " + lowerKey + " (" + formatValue(lo) + ")");
    }
    lower = degrees ? degToRad(lo) : lo;
    upper = degrees ? degToRad(hi) : hi;
  }

  void joint(const json& j, const std::string& where) {
    Fields f(j, where);
    const std::string type =
        typeOf(f, {"revolute", "prismatic", "distance", "weld", "wheel", "motor", "mouse"}, "joint type");
    const std::string name = nameOf(f);
    if (!name.empty() && !jointNames_.insert(name).second) {
      fail(f.path("name"), "duplicate joint name '" + name + "'");
    }
    World& world = scene_.world;
    JointId id;
    if (type == "revolute") {
      RevoluteJointDef d;
      bodies(f, d);
      base(f, d, true);
      d.referenceAngle = angleDeg(f, "reference_angle_deg", initialAngle(d.bodyB) - initialAngle(d.bodyA));
      d.enableLimit = f.boolean("enable_limit", d.enableLimit);
      limits(f, "lower_angle_deg", "upper_angle_deg", d.lowerAngle, d.upperAngle, true);
      if (d.enableLimit) {
        // The joint angle lives in (-180, 180] degrees. Checked here, in the file's unit and under
        // its keys: the world would name lowerAngle in radians.
        for (const char* key : {"lower_angle_deg", "upper_angle_deg"}) {
          if (const float deg = f.real(key, 0.0); deg < -180.0f || deg > 180.0f) {
            throwInvalid(f.path(key), deg, "must be in [-180, 180] degrees");
          }
        }
      }
      d.enableMotor = f.boolean("enable_motor", d.enableMotor);
      d.motorSpeed = f.real("motor_speed", d.motorSpeed);
      d.maxMotorTorque = f.nonNegative("max_motor_torque", d.maxMotorTorque);
      d.enableSpring = f.boolean("enable_spring", d.enableSpring);
      d.hertz = f.nonNegative("hertz", d.hertz);
      d.dampingRatio = f.nonNegative("damping_ratio", d.dampingRatio);
      d.frictionTorque = f.nonNegative("friction_torque", d.frictionTorque);
      f.done();
      id = at(where, [&] { return world.createJoint(d); });
    } else if (type == "prismatic") {
      PrismaticJointDef d;
      bodies(f, d);
      base(f, d, true);
      d.localAxisA = axis(f, d.bodyA, {1.0f, 0.0f});
      d.referenceAngle = angleDeg(f, "reference_angle_deg", initialAngle(d.bodyB) - initialAngle(d.bodyA));
      d.enableLimit = f.boolean("enable_limit", d.enableLimit);
      limits(f, "lower_translation", "upper_translation", d.lowerTranslation, d.upperTranslation, false);
      d.enableMotor = f.boolean("enable_motor", d.enableMotor);
      d.motorSpeed = f.real("motor_speed", d.motorSpeed);
      d.maxMotorForce = f.nonNegative("max_motor_force", d.maxMotorForce);
      d.enableSpring = f.boolean("enable_spring", d.enableSpring);
      d.hertz = f.nonNegative("hertz", d.hertz);
      d.dampingRatio = f.nonNegative("damping_ratio", d.dampingRatio);
      f.done();
      id = at(where, [&] { return world.createJoint(d); });
    } else if (type == "distance") {
      DistanceJointDef d;
      bodies(f, d);
      base(f, d, true);
      const float initial = distance(transformPoint(world.transform(d.bodyA), d.localAnchorA),
                                     transformPoint(world.transform(d.bodyB), d.localAnchorB));
      if (f.has("length")) {
        d.length = f.positive("length", 1.0);
      } else if (initial > linearSlop) {
        d.length = initial;
      } else {
        fail(f.path("length"), "missing (the anchors start together, so the length cannot be taken from them)");
      }
      d.enableLimit = f.boolean("enable_limit", d.enableLimit);
      d.minLength = f.nonNegative("min_length", d.minLength);
      if (f.has("max_length")) {
        d.maxLength = f.nonNegative("max_length", 0.0);
        if (d.maxLength < d.minLength) {
          throwInvalid(f.path("max_length"), d.maxLength, "must be >= min_length");
        }
      }
      d.enableSpring = f.boolean("enable_spring", d.enableSpring);
      d.hertz = f.nonNegative("hertz", d.hertz);
      d.dampingRatio = f.nonNegative("damping_ratio", d.dampingRatio);
      d.enableMotor = f.boolean("enable_motor", d.enableMotor);
      d.motorSpeed = f.real("motor_speed", d.motorSpeed);
      d.maxMotorForce = f.nonNegative("max_motor_force", d.maxMotorForce);
      f.done();
      id = at(where, [&] { return world.createJoint(d); });
    } else if (type == "weld") {
      WeldJointDef d;
      bodies(f, d);
      base(f, d, true);
      d.referenceAngle = angleDeg(f, "reference_angle_deg", initialAngle(d.bodyB) - initialAngle(d.bodyA));
      d.linearHertz = f.nonNegative("linear_hertz", d.linearHertz);
      d.linearDampingRatio = f.nonNegative("linear_damping_ratio", d.linearDampingRatio);
      d.angularHertz = f.nonNegative("angular_hertz", d.angularHertz);
      d.angularDampingRatio = f.nonNegative("angular_damping_ratio", d.angularDampingRatio);
      f.done();
      id = at(where, [&] { return world.createJoint(d); });
    } else if (type == "wheel") {
      WheelJointDef d;
      bodies(f, d);
      base(f, d, true);
      d.localAxisA = axis(f, d.bodyA, {0.0f, 1.0f});
      d.enableSpring = f.boolean("enable_spring", d.enableSpring);
      d.hertz = f.nonNegative("hertz", d.hertz);
      d.dampingRatio = f.nonNegative("damping_ratio", d.dampingRatio);
      d.enableLimit = f.boolean("enable_limit", d.enableLimit);
      limits(f, "lower_translation", "upper_translation", d.lowerTranslation, d.upperTranslation, false);
      d.enableMotor = f.boolean("enable_motor", d.enableMotor);
      d.motorSpeed = f.real("motor_speed", d.motorSpeed);
      d.maxMotorTorque = f.nonNegative("max_motor_torque", d.maxMotorTorque);
      f.done();
      id = at(where, [&] { return world.createJoint(d); });
    } else if (type == "motor") {
      MotorJointDef d;
      bodies(f, d);
      base(f, d, false);
      const Transform2f xfA = world.transform(d.bodyA);
      d.linearOffset = vec2(f, "linear_offset", inverseTransformPoint(xfA, world.position(d.bodyB)));
      d.angularOffset = angleDeg(f, "angular_offset_deg", initialAngle(d.bodyB) - initialAngle(d.bodyA));
      d.maxForce = f.nonNegative("max_force", d.maxForce);
      d.maxTorque = f.nonNegative("max_torque", d.maxTorque);
      d.correctionFactor = f.fraction("correction_factor", d.correctionFactor);
      f.done();
      id = at(where, [&] { return world.createJoint(d); });
    } else {
      MouseJointDef d;
      d.bodyB = bodyNamed(f, "body_b");
      d.localAnchorB = anchor(f, d.bodyB, "b", true);
      base(f, d, false);
      d.target = vec2(f, "target", transformPoint(world.transform(d.bodyB), d.localAnchorB));
      d.hertz = f.nonNegative("hertz", d.hertz);
      d.dampingRatio = f.nonNegative("damping_ratio", d.dampingRatio);
      d.maxForce = f.nonNegative("max_force", d.maxForce);
      f.done();
      id = at(where, [&] { return world.createJoint(d); });
    }
    if (scene_.jointBySlot.size() <= id.index) {
      scene_.jointBySlot.resize(id.index + 1, 0);
    }
    scene_.jointBySlot[id.index] = scene_.joints.size();
    scene_.joints.push_back(id);
    scene_.jointNames.push_back(name);
  }

  // Effectors --------------------------------------------------------------------------------

  template <class E, class S> void addEffector(Fields& f, const std::string& where, const S& settings) {
    const double start = f.nonNegative("start", 0.0);
    double stop = std::numeric_limits<double>::infinity();
    if (f.has("stop")) {
      stop = f.nonNegative("stop", 0.0);
      if (stop < start) {
        throwInvalid(f.path("stop"), stop, "must be >= start");
      }
    }
    f.done();
    auto effector = at(where, [&] { return std::make_unique<E>(settings); });
    scene_.effectors.add(Scheduled(std::move(effector), start, stop));
  }

  void effector(const json& j, const std::string& where) {
    Fields f(j, where);
    const std::string type = typeOf(
        f, {"gravity_field", "point_attractor", "wind_drag", "thruster", "spring_damper", "explosion", "buoyancy"},
        "effector type");
    World& world = scene_.world;
    if (type == "gravity_field") {
      GravityFieldSettings s;
      s.acceleration = requiredVec2(f, "acceleration");
      if (const json* r = f.find("region")) {
        Fields rf(*r, f.path("region"));
        const Vec2f lo = requiredVec2(rf, "min");
        const Vec2f hi = requiredVec2(rf, "max");
        rf.done();
        if (!(hi.x >= lo.x && hi.y >= lo.y)) {
          fail(rf.path("max"), "must be >= min in both components");
        }
        s.region = AABB{lo, hi};
      }
      addEffector<GravityField>(f, where, s);
    } else if (type == "point_attractor") {
      PointAttractorSettings s;
      s.center = requiredVec2(f, "center");
      s.mu = f.requiredReal("mu");
      s.softening = f.nonNegative("softening", s.softening);
      if (f.has("max_radius")) {
        s.maxRadius = f.positive("max_radius", 1.0);
      }
      addEffector<PointAttractor>(f, where, s);
    } else if (type == "wind_drag") {
      WindDragSettings s;
      s.body = bodyNamed(f, "body");
      s.airVelocity = vec2(f, "air_velocity", s.airVelocity);
      s.airDensity = f.nonNegative("air_density", s.airDensity);
      s.dragArea = f.nonNegative("drag_area", s.dragArea);
      s.linearDrag = f.nonNegative("linear_drag", s.linearDrag);
      s.localCenterOfPressure = vec2(f, "local_center_of_pressure", s.localCenterOfPressure);
      addEffector<WindDrag>(f, where, s);
    } else if (type == "thruster") {
      ThrusterSettings s;
      s.body = bodyNamed(f, "body");
      s.localPoint = vec2(f, "local_point", s.localPoint);
      s.localDirection = vec2(f, "local_direction", s.localDirection);
      if (!(length(s.localDirection) > 1e-6f)) {
        fail(f.path("local_direction"), "must be non-zero");
      }
      s.thrust = f.requiredReal("thrust");
      addEffector<Thruster>(f, where, s);
    } else if (type == "spring_damper") {
      SpringDamperSettings s;
      s.bodyA = bodyNamed(f, "body_a");
      s.localAnchorA = anchor(f, s.bodyA, "a", false);
      Vec2f worldB;
      if (f.has("body_b")) {
        s.bodyB = bodyNamed(f, "body_b");
        if (s.bodyB == s.bodyA) {
          fail(f.path("body_b"), "a spring needs two different bodies (or a world point: leave out body_b)");
        }
        s.localAnchorB = anchor(f, s.bodyB, "b", false);
        worldB = transformPoint(world.transform(s.bodyB), s.localAnchorB);
      } else {
        s.localAnchorB = requiredVec2(f, "anchor_b");
        worldB = s.localAnchorB;
      }
      s.stiffness = f.nonNegative("stiffness", s.stiffness);
      s.damping = f.nonNegative("damping", s.damping);
      s.restLength = f.has("rest_length") ? f.nonNegative("rest_length", 0.0)
                                          : distance(transformPoint(world.transform(s.bodyA), s.localAnchorA), worldB);
      addEffector<SpringDamper>(f, where, s);
    } else if (type == "explosion") {
      ExplosionSettings s;
      s.center = requiredVec2(f, "center");
      s.radius = f.requiredPositive("radius");
      s.impulse = f.nonNegative("impulse", s.impulse);
      addEffector<Explosion>(f, where, s);
    } else {
      BuoyancySettings s;
      s.surfaceHeight = f.requiredReal("surface_height");
      if (f.has("x_min")) {
        s.xMin = f.real("x_min", 0.0);
      }
      if (f.has("x_max")) {
        s.xMax = f.real("x_max", 0.0);
      }
      if (s.xMax < s.xMin) {
        throwInvalid(f.path("x_max"), s.xMax, "must be >= x_min");
      }
      s.fluidDensity = f.positive("fluid_density", s.fluidDensity);
      s.gravity = gravity_;
      s.fluidVelocity = vec2(f, "fluid_velocity", s.fluidVelocity);
      s.linearDrag = f.nonNegative("linear_drag", s.linearDrag);
      s.angularDrag = f.nonNegative("angular_drag", s.angularDrag);
      addEffector<Buoyancy>(f, where, s);
    }
  }

  Rigid2dScene& scene_;
  TaskRunner* runner_ = nullptr; ///< steps the world's parallel loops (not owned)
  Vec2f gravity_;
  std::map<std::string, Material> materials_;
  std::map<std::string, std::size_t> names_;
  std::set<std::string> jointNames_;
  std::vector<float> angles_; ///< each body's initial angle, rad, as the file gave it
};

} // namespace

std::string sceneKind(const json& doc) {
  const auto it = doc.find("kind");
  if (it == doc.end()) {
    return "particles";
  }
  if (!it->is_string()) {
    fail("kind", "expected \"particles\" or \"rigid2d\", got " + it->dump());
  }
  const std::string kind = it->get<std::string>();
  if (kind != "particles" && kind != "rigid2d") {
    fail("kind", "unknown scene kind '" + kind + "' (particles, rigid2d)");
  }
  return kind;
}

Rigid2dScene parseRigid2dScene(const json& doc, TaskRunner* runner) {
  Rigid2dScene scene;
  Loader(scene, runner).load(doc);
  return scene;
}

Rigid2dScene parseRigid2dScene(const std::string& jsonText) {
  return parseRigid2dScene(json_fields::parseObject(jsonText, "a JSON object (docs/scene-format-2d.md)"));
}

} // namespace impetus::cli
