// The world's joint API: creating and destroying joints, their readouts and run-time controls.
#include "rigid2d/joints.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace impetus::rigid2d {

using detail::Joint;
using detail::WorldState;

namespace detail {

Joint& WorldState::joint(JointId id) { return checkedSlot(jointIds, joints, id, "joint id", "joint"); }
const Joint& WorldState::joint(JointId id) const { return const_cast<WorldState*>(this)->joint(id); }

/// A joint's own stiffness (0 hertz: the world's) and damping ratio.
void validateConstraintTuning(float hertz, float dampingRatio) {
  if (!(std::isfinite(hertz) && hertz >= 0.0f)) {
    throwInvalid("constraintHertz", hertz, "must be a finite frequency >= 0 Hz (0: the world's jointHertz)");
  }
  if (!(std::isfinite(dampingRatio) && dampingRatio >= 0.0f)) {
    throwInvalid("constraintDampingRatio", dampingRatio, "must be a finite damping ratio >= 0");
  }
}

bool WorldState::jointBlocksCollision(std::uint32_t bodyA, std::uint32_t bodyB) const {
  const Body& a = bodies[bodyA];
  const Body& b = bodies[bodyB];
  const Body& fewer = a.joints.size() <= b.joints.size() ? a : b;
  const std::uint32_t other = &fewer == &a ? bodyB : bodyA;
  return std::any_of(fewer.joints.begin(), fewer.joints.end(), [&](std::uint32_t slot) {
    const Joint& j = joints[slot];
    return !j.collideConnected && (j.bodyA == other || j.bodyB == other);
  });
}

} // namespace detail

namespace {

/// A valid body of the joint, or an error naming the field.
std::uint32_t jointBody(WorldState& w, BodyId id, const char* field) {
  w.bodyIds.requireValid(id, field, "body");
  return id.index;
}

void validateBase(const JointDefBase& def) {
  requireFinite(def.localAnchorA, "localAnchorA");
  requireFinite(def.localAnchorB, "localAnchorB");
  if (std::isnan(def.breakForce) || def.breakForce < 0.0f) {
    throwInvalid("breakForce", def.breakForce, "must be >= 0 (infinity: unbreakable)");
  }
  if (std::isnan(def.breakTorque) || def.breakTorque < 0.0f) {
    throwInvalid("breakTorque", def.breakTorque, "must be >= 0 (infinity: unbreakable)");
  }
  detail::validateConstraintTuning(def.constraintHertz, def.constraintDampingRatio);
}

void validateSpring(float hertz, float dampingRatio) {
  requireNonNegative(hertz, "hertz");
  requireNonNegative(dampingRatio, "dampingRatio");
}

void validateLimits(float lower, float upper, const char* lowerField, const char* upperField) {
  requireFinite(lower, lowerField);
  requireFinite(upper, upperField);
  if (lower > upper) {
    throwInvalid(lowerField, lower, "lower limit above the upper one");
  }
}

/// The joint angle lives in (-pi, pi] (it is measured from the bodies' rotations), so limits
/// beyond half a turn could never be told apart from their wrap-around.
void validateRevoluteLimits(float lower, float upper) {
  validateLimits(lower, upper, "lowerAngle", "upperAngle");
  constexpr float pi = impetus::pi<float>;
  if (lower < -pi) {
    throwInvalid("lowerAngle", lower, "must be >= -pi");
  }
  if (upper > pi) {
    throwInvalid("upperAngle", upper, "must be <= pi");
  }
}

Vec2f unitAxis(const Vec2f& axis) {
  requireFinite(axis, "localAxisA");
  const float len = length(axis);
  if (len < 1e-6f) {
    throwInvalid("localAxisA", len, "axis has no direction");
  }
  return axis / len;
}

JointId addJoint(WorldState& w, const JointDefBase& base, detail::JointData data, bool needsBodyA = true) {
  validateBase(base);
  const std::uint32_t b = jointBody(w, base.bodyB, "bodyB");
  std::uint32_t a = b; // a joint to the world (the mouse joint) ignores bodyA
  if (needsBodyA) {
    a = jointBody(w, base.bodyA, "bodyA");
    if (a == b) {
      throwInvalid("bodyB", static_cast<double>(b), "a joint needs two different bodies");
    }
  }
  const JointId id = w.jointIds.allocateId<JointTag>();
  if (w.joints.size() <= id.index) {
    w.joints.resize(id.index + 1);
  }
  Joint& j = w.joints[id.index];
  j = Joint{};
  j.data = data;
  j.bodyA = a;
  j.bodyB = b;
  j.localAnchorA = base.localAnchorA;
  j.localAnchorB = base.localAnchorB;
  j.collideConnected = base.collideConnected;
  j.breakForce = base.breakForce;
  j.breakTorque = base.breakTorque;
  j.constraintHertz = base.constraintHertz;
  j.constraintDampingRatio = base.constraintDampingRatio;
  j.userData = base.userData;
  j.id = id;
  j.alive = true;
  detail::Body& bodyA = w.bodies[a];
  detail::Body& bodyB = w.bodies[b];
  bodyA.joints.push_back(id.index);
  if (a != b) {
    bodyB.joints.push_back(id.index);
  }
  detail::wakeBody(w, a);
  detail::wakeBody(w, b);
  // A joint joins its bodies' islands (a static body is in none).
  w.islands.link(a, b);
  if (w.bodies[a].moving() || w.bodies[b].moving()) {
    w.awakeJointSet.add(id.index);
  }
  if (!j.collideConnected && a != b) {
    // The two bodies stop colliding: their contacts go, and those that touched report their
    // end with the next step's events.
    // Body a's contacts, in slot order: those with b go.
    detail::bodyContacts(w, a, w.bodyContactScratch);
    for (const std::uint32_t slot : w.bodyContactScratch) {
      const detail::Contact& c = w.contacts[slot];
      if ((c.bodyA == a && c.bodyB == b) || (c.bodyA == b && c.bodyB == a)) {
        detail::destroyContact(w, slot, w.pendingEvents, w.pendingSensorEvents);
      }
    }
  }
  return id;
}

template <class T> T& jointData(WorldState& w, JointId id, const char* what) {
  Joint& j = w.joint(id);
  T* data = std::get_if<T>(&detail::jointDataOf(w, id.index));
  if (data == nullptr) {
    throwInvalid("joint id", static_cast<double>(id.index), std::string("not a ") + what + " joint");
  }
  detail::wakeBody(w, j.bodyA);
  detail::wakeBody(w, j.bodyB);
  return *data;
}

template <class T> const T& jointData(const WorldState& w, JointId id, const char* what) {
  static_cast<void>(w.joint(id)); // refuses an id that is not live
  const T* data = std::get_if<T>(&detail::jointDataOf(w, id.index));
  if (data == nullptr) {
    throwInvalid("joint id", static_cast<double>(id.index), std::string("not a ") + what + " joint");
  }
  return *data;
}

/// World anchors of a joint now.
std::pair<Vec2f, Vec2f> worldAnchors(const WorldState& w, const Joint& j) {
  return {transformPoint(w.bodies[j.bodyA].transform, j.localAnchorA),
          transformPoint(w.bodies[j.bodyB].transform, j.localAnchorB)};
}

} // namespace

RevoluteJointId World::createJoint(const RevoluteJointDef& def) {
  requireFinite(def.referenceAngle, "referenceAngle");
  if (def.enableLimit) {
    validateRevoluteLimits(def.lowerAngle, def.upperAngle);
  }
  requireFinite(def.motorSpeed, "motorSpeed");
  requireNonNegative(def.maxMotorTorque, "maxMotorTorque");
  requireNonNegative(def.frictionTorque, "frictionTorque");
  validateSpring(def.hertz, def.dampingRatio);
  detail::RevoluteJoint j;
  j.def = def;
  j.def.referenceAngle = detail::wrapAngle(def.referenceAngle);
  return {addJoint(*impl_, def, j)};
}

PrismaticJointId World::createJoint(const PrismaticJointDef& def) {
  requireFinite(def.referenceAngle, "referenceAngle");
  if (def.enableLimit) {
    validateLimits(def.lowerTranslation, def.upperTranslation, "lowerTranslation", "upperTranslation");
  }
  requireFinite(def.motorSpeed, "motorSpeed");
  requireNonNegative(def.maxMotorForce, "maxMotorForce");
  validateSpring(def.hertz, def.dampingRatio);
  detail::PrismaticJoint j;
  j.def = def;
  j.def.referenceAngle = detail::wrapAngle(def.referenceAngle);
  j.def.localAxisA = unitAxis(def.localAxisA);
  return {addJoint(*impl_, def, j)};
}

DistanceJointId World::createJoint(const DistanceJointDef& def) {
  requirePositive(def.length, "length");
  if (def.enableLimit) {
    requireNonNegative(def.minLength, "minLength");
    if (std::isnan(def.maxLength) || def.maxLength < def.minLength) {
      throwInvalid("maxLength", def.maxLength, "must be >= minLength");
    }
  }
  requireFinite(def.motorSpeed, "motorSpeed");
  requireNonNegative(def.maxMotorForce, "maxMotorForce");
  validateSpring(def.hertz, def.dampingRatio);
  detail::DistanceJoint j;
  j.def = def;
  return {addJoint(*impl_, def, j)};
}

WeldJointId World::createJoint(const WeldJointDef& def) {
  requireFinite(def.referenceAngle, "referenceAngle");
  requireNonNegative(def.linearHertz, "linearHertz");
  requireNonNegative(def.linearDampingRatio, "linearDampingRatio");
  requireNonNegative(def.angularHertz, "angularHertz");
  requireNonNegative(def.angularDampingRatio, "angularDampingRatio");
  detail::WeldJoint j;
  j.def = def;
  j.def.referenceAngle = detail::wrapAngle(def.referenceAngle);
  return {addJoint(*impl_, def, j)};
}

WheelJointId World::createJoint(const WheelJointDef& def) {
  if (def.enableLimit) {
    validateLimits(def.lowerTranslation, def.upperTranslation, "lowerTranslation", "upperTranslation");
  }
  requireFinite(def.motorSpeed, "motorSpeed");
  requireNonNegative(def.maxMotorTorque, "maxMotorTorque");
  validateSpring(def.hertz, def.dampingRatio);
  detail::WheelJoint j;
  j.def = def;
  j.def.localAxisA = unitAxis(def.localAxisA);
  return {addJoint(*impl_, def, j)};
}

MotorJointId World::createJoint(const MotorJointDef& def) {
  requireFinite(def.linearOffset, "linearOffset");
  requireFinite(def.angularOffset, "angularOffset");
  requireNonNegative(def.maxForce, "maxForce");
  requireNonNegative(def.maxTorque, "maxTorque");
  if (!(def.correctionFactor >= 0.0f && def.correctionFactor <= 1.0f)) {
    throwInvalid("correctionFactor", def.correctionFactor, "must be in [0, 1]");
  }
  detail::MotorJoint j;
  j.def = def;
  j.def.angularOffset = detail::wrapAngle(def.angularOffset);
  return {addJoint(*impl_, def, j)};
}

MouseJointId World::createJoint(const MouseJointDef& def) {
  requireFinite(def.target, "target");
  validateSpring(def.hertz, def.dampingRatio);
  requireNonNegative(def.maxForce, "maxForce");
  detail::MouseJoint j;
  j.def = def;
  // The mouse joint pulls B toward a world point: body A is a placeholder for B (the joint's
  // solver treats it as static).
  return {addJoint(*impl_, def, j, false)};
}

FilterJointId World::createJoint(const FilterJointDef& def) {
  if (def.collideConnected) {
    throwInvalid("collideConnected", 1.0, "a filter joint only stops its bodies colliding: it must be false");
  }
  return {addJoint(*impl_, def, detail::FilterJoint{})};
}

void World::destroyJoint(JointId id) {
  WorldState& w = *impl_;
  Joint& j = w.joint(id);
  w.islands.unlink(j.bodyA, j.bodyB);
  w.awakeJointSet.remove(id.index);
  for (std::uint32_t body : {j.bodyA, j.bodyB}) {
    detail::Body& b = w.bodies[body];
    std::erase(b.joints, id.index);
    detail::wakeBody(w, body);
    if (!j.collideConnected) {
      // The bodies may collide again: look for their pairs next step.
      for (std::uint32_t shape : b.shapes) {
        w.moveBuffer.push_back(shape);
      }
    }
  }
  detail::forgetJointSim(w, id.index);
  j = Joint{};
  w.jointIds.freeId(id);
}

bool World::isValid(JointId id) const noexcept { return impl_->jointIds.isValidId(id); }
std::size_t World::jointCount() const noexcept { return impl_->jointIds.size(); }
JointType World::jointType(JointId id) const { return impl_->joint(id).type(); }
void World::jointIds(std::vector<JointId>& out) const {
  out.clear();
  for (const Joint& j : impl_->joints) {
    if (j.alive) {
      out.push_back(j.id);
    }
  }
}
Vec2f World::jointAnchorA(JointId id) const { return worldAnchors(*impl_, impl_->joint(id)).first; }
Vec2f World::jointAnchorB(JointId id) const { return worldAnchors(*impl_, impl_->joint(id)).second; }
BodyId World::jointBodyA(JointId id) const { return impl_->bodies[impl_->joint(id).bodyA].id; }
BodyId World::jointBodyB(JointId id) const { return impl_->bodies[impl_->joint(id).bodyB].id; }
Vec2f World::jointReactionForce(JointId id) const {
  static_cast<void>(impl_->joint(id)); // refuses an id that is not live
  return detail::reactionOf(detail::jointDataOf(*impl_, id.index), impl_->lastInverseH).force;
}
float World::jointReactionTorque(JointId id) const {
  static_cast<void>(impl_->joint(id));
  return detail::reactionOf(detail::jointDataOf(*impl_, id.index), impl_->lastInverseH).torque;
}
const JointEvents& World::jointEvents() const noexcept { return impl_->jointEvents; }

namespace detail {
/// What the joint types' free functions reach of a world.
struct WorldAccess {
  static WorldState& state(World& world) { return *world.impl_; }
  static const WorldState& state(const World& world) { return *world.impl_; }
};
} // namespace detail

float revoluteAngle(const World& world, RevoluteJointId joint) {
  const detail::WorldState& w = detail::WorldAccess::state(world);
  const JointId id = joint.id;
  const auto& r = jointData<detail::RevoluteJoint>(w, id, "revolute");
  const Joint& j = w.joint(id);
  // Both in (-pi, pi] (the reference wrapped when the joint was made): one unwind suffices.
  return detail::unwindAngle(detail::relativeAngle(w.bodies[j.bodyB].transform.q, w.bodies[j.bodyA].transform.q) -
                             r.def.referenceAngle);
}

float revoluteMotorTorque(const World& world, RevoluteJointId joint) {
  const detail::WorldState& w = detail::WorldAccess::state(world);
  const JointId id = joint.id;
  const auto& r = jointData<detail::RevoluteJoint>(w, id, "revolute");
  return r.motor.impulse * w.lastInverseH;
}

void setRevoluteMotor(World& world, RevoluteJointId joint, bool enable, float speed, float maxTorque) {
  detail::WorldState& w = detail::WorldAccess::state(world);
  const JointId id = joint.id;
  requireFinite(speed, "motorSpeed");
  requireNonNegative(maxTorque, "maxMotorTorque");
  auto& r = jointData<detail::RevoluteJoint>(w, id, "revolute");
  r.def.enableMotor = enable;
  r.def.motorSpeed = speed;
  r.def.maxMotorTorque = maxTorque;
}

void setRevoluteLimit(World& world, RevoluteJointId joint, bool enable, float lower, float upper) {
  detail::WorldState& w = detail::WorldAccess::state(world);
  const JointId id = joint.id;
  validateRevoluteLimits(lower, upper);
  auto& r = jointData<detail::RevoluteJoint>(w, id, "revolute");
  r.def.enableLimit = enable;
  r.def.lowerAngle = lower;
  r.def.upperAngle = upper;
}

float prismaticTranslation(const World& world, PrismaticJointId joint) {
  const detail::WorldState& w = detail::WorldAccess::state(world);
  const JointId id = joint.id;
  const auto& p = jointData<detail::PrismaticJoint>(w, id, "prismatic");
  const Joint& j = w.joint(id);
  const auto [pA, pB] = worldAnchors(w, j);
  return dot(pB - pA, rotate(w.bodies[j.bodyA].transform.q, p.def.localAxisA));
}

float prismaticMotorForce(const World& world, PrismaticJointId joint) {
  const detail::WorldState& w = detail::WorldAccess::state(world);
  const JointId id = joint.id;
  const auto& p = jointData<detail::PrismaticJoint>(w, id, "prismatic");
  return p.motor.impulse * w.lastInverseH;
}

void setPrismaticMotor(World& world, PrismaticJointId joint, bool enable, float speed, float maxForce) {
  detail::WorldState& w = detail::WorldAccess::state(world);
  const JointId id = joint.id;
  requireFinite(speed, "motorSpeed");
  requireNonNegative(maxForce, "maxMotorForce");
  auto& p = jointData<detail::PrismaticJoint>(w, id, "prismatic");
  p.def.enableMotor = enable;
  p.def.motorSpeed = speed;
  p.def.maxMotorForce = maxForce;
}

void setPrismaticLimit(World& world, PrismaticJointId joint, bool enable, float lower, float upper) {
  detail::WorldState& w = detail::WorldAccess::state(world);
  const JointId id = joint.id;
  validateLimits(lower, upper, "lowerTranslation", "upperTranslation");
  auto& p = jointData<detail::PrismaticJoint>(w, id, "prismatic");
  p.def.enableLimit = enable;
  p.def.lowerTranslation = lower;
  p.def.upperTranslation = upper;
}

float distanceJointLength(const World& world, DistanceJointId joint) {
  const detail::WorldState& w = detail::WorldAccess::state(world);
  const JointId id = joint.id;
  (void)jointData<detail::DistanceJoint>(w, id, "distance");
  const auto [pA, pB] = worldAnchors(w, w.joint(id));
  return distance(pA, pB);
}

void setDistanceJointLength(World& world, DistanceJointId joint, float length) {
  detail::WorldState& w = detail::WorldAccess::state(world);
  const JointId id = joint.id;
  requirePositive(length, "length");
  jointData<detail::DistanceJoint>(w, id, "distance").def.length = length;
}

float wheelMotorTorque(const World& world, WheelJointId joint) {
  const detail::WorldState& w = detail::WorldAccess::state(world);
  const JointId id = joint.id;
  const auto& wj = jointData<detail::WheelJoint>(w, id, "wheel");
  return wj.motor.impulse * w.lastInverseH;
}

void setWheelMotor(World& world, WheelJointId joint, bool enable, float speed, float maxTorque) {
  detail::WorldState& w = detail::WorldAccess::state(world);
  const JointId id = joint.id;
  requireFinite(speed, "motorSpeed");
  requireNonNegative(maxTorque, "maxMotorTorque");
  auto& wj = jointData<detail::WheelJoint>(w, id, "wheel");
  wj.def.enableMotor = enable;
  wj.def.motorSpeed = speed;
  wj.def.maxMotorTorque = maxTorque;
}

void setMotorJointTarget(World& world, MotorJointId joint, const Vec2f& linearOffset, float angularOffset) {
  detail::WorldState& w = detail::WorldAccess::state(world);
  const JointId id = joint.id;
  requireFinite(linearOffset, "linearOffset");
  requireFinite(angularOffset, "angularOffset");
  auto& m = jointData<detail::MotorJoint>(w, id, "motor");
  m.def.linearOffset = linearOffset;
  m.def.angularOffset = detail::wrapAngle(angularOffset);
}

void setMouseTarget(World& world, MouseJointId joint, const Vec2f& target) {
  detail::WorldState& w = detail::WorldAccess::state(world);
  const JointId id = joint.id;
  requireFinite(target, "target");
  jointData<detail::MouseJoint>(w, id, "mouse").def.target = target;
}

} // namespace impetus::rigid2d
