// The rigid2d scene loader's joints (docs/scene-format-2d.md, "joints"): the bodies a joint names,
// its anchors, axis and limits, checked with the JSON path of each value before the world sees it.
#include "json_fields.hpp"
#include "rigid2d_scene_loader.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>

#include <string>

namespace impetus::cli {

namespace {

using json_fields::angleDeg;
using json_fields::at;
using json_fields::fail;
using json_fields::Fields;
using json_fields::requiredVec2;
using json_fields::typeOf;
using json_fields::vec2;
using nlohmann::json;
using namespace rigid2d;

} // namespace

namespace rigid2d_loader {

BodyId Loader::bodyNamed(Fields& f, const std::string& key) {
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

Vec2f Loader::anchor(Fields& f, BodyId id, const char* end, bool shared) const {
  const std::string localKey = std::string("local_anchor_") + end;
  const std::string worldKey = std::string("anchor_") + end;
  const bool hasLocal = f.has(localKey);
  const bool hasWorld = f.has(worldKey);
  const bool hasShared = shared && f.has("anchor");
  if (static_cast<int>(hasLocal) + static_cast<int>(hasWorld) + static_cast<int>(hasShared) > 1) {
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

Vec2f Loader::axis(Fields& f, BodyId a, const Vec2f& fallbackWorld) const {
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

void Loader::base(Fields& f, JointDefBase& d, bool anchors) {
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
  d.constraintHertz = f.nonNegative("constraint_hertz", d.constraintHertz);
  d.constraintDampingRatio = f.nonNegative("constraint_damping_ratio", d.constraintDampingRatio);
}

void Loader::bodies(Fields& f, JointDefBase& d) {
  d.bodyA = bodyNamed(f, "body_a");
  d.bodyB = bodyNamed(f, "body_b");
  if (d.bodyA == d.bodyB) {
    fail(f.path("body_b"), "a joint needs two different bodies");
  }
}

void Loader::limits(Fields& f, const std::string& lowerKey, const std::string& upperKey, float& lower, float& upper,
                    bool degrees) {
  const float lo = f.real(lowerKey, 0.0);
  const float hi = f.real(upperKey, 0.0);
  if (lo > hi) {
    throwInvalid(f.path(upperKey), hi, "must be >= " + lowerKey + " (" + formatValue(lo) + ")");
  }
  lower = degrees ? degToRad(lo) : lo;
  upper = degrees ? degToRad(hi) : hi;
}

void Loader::joint(const json& j, const std::string& where) {
  Fields f(j, where);
  const std::string type =
      typeOf(f, {"revolute", "prismatic", "distance", "weld", "wheel", "motor", "mouse", "filter"}, "joint type");
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
  } else if (type == "filter") {
    FilterJointDef d;
    bodies(f, d);
    base(f, d, false);
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

} // namespace rigid2d_loader

} // namespace impetus::cli
