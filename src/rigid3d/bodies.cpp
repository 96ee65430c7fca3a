// The 3D world's bodies: creation, destruction, mass properties, state, forces and impulses.
#include "rigid3d/world_impl.hpp"

#include <impetus/core/mass_properties.hpp>
#include <impetus/error.hpp>
#include <impetus/math/symmetric_eigen.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/rigid3d/world.hpp>

#include <cmath>
#include <string>
#include <utility>

namespace impetus::rigid3d {

namespace detail {

namespace {

/// How far an inertia tensor may be from symmetric, or its principal moments from the triangle
/// inequality, relative to its trace: a tensor computed in float (a thin plate's, whose moments
/// meet the inequality with equality) misses them by its rounding, a few ulps (1e-7 each).
constexpr double inertiaTolerance = 1.0e-5;

/// A unit quaternion from the user's rotation: finite and not (near) zero, normalised.
Quatf requireRotation(const Quatf& q, std::string_view field) {
  for (const float c : {q.w, q.x, q.y, q.z}) {
    if (!std::isfinite(c)) {
      throwInvalid(std::string(field), c, "must be finite");
    }
  }
  const float len = length(q);
  if (!(len > 1.0e-6f)) {
    throwInvalid(std::string(field) + " length", len, "must be a rotation (a non-zero quaternion)");
  }
  return q / len;
}

} // namespace

void requireValidMassData(const MassData& data) {
  requirePositive(data.mass, "mass");
  requireFinite(data.center, "center");
  Mat33d inertia;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      inertia(r, c) = data.inertia(r, c);
    }
  }
  requirePhysicalInertia(inertia, "inertia", inertiaTolerance);
  // A dynamic body turns under any torque: no principal moment may be zero.
  if (const double least = symmetricEigen(inertia).values.x; !(least > 0.0)) {
    throwInvalid("inertia principal moment", least, "must be positive (a dynamic body's tensor is positive definite)");
  }
}

void applyMassData(Body& b, const MassData& data) {
  if (b.type != BodyType::dynamicBody) {
    b.mass = b.inverseMass = 0.0f;
    b.inertia = b.inverseInertia = Mat33f{};
    return;
  }
  // The centre moves with the new mass distribution; the origin stays.
  b.mass = data.mass;
  b.inverseMass = 1.0f / data.mass;
  const Mat33f& i = data.inertia;
  // Symmetrised: the solver relies on it, and rounding may have left a few ulps.
  b.inertia = Mat33f{i(0, 0), 0.5f * (i(0, 1) + i(1, 0)), 0.5f * (i(0, 2) + i(2, 0)), 0.5f * (i(0, 1) + i(1, 0)),
                     i(1, 1), 0.5f * (i(1, 2) + i(2, 1)), 0.5f * (i(0, 2) + i(2, 0)), 0.5f * (i(1, 2) + i(2, 1)),
                     i(2, 2)};
  b.inverseInertia = inverse(b.inertia);
  b.localCenter = data.center;
  b.center = transformPoint(b.transform, b.localCenter);
}

} // namespace detail

BodyId World::createBody(const BodyDef& def) {
  detail::WorldState& w = *impl_;
  detail::Body b;
  b.type = def.type;
  b.transform = {requireFinite(def.position, "position"), detail::requireRotation(def.rotation, "rotation")};
  b.linearVelocity = requireFinite(def.linearVelocity, "linearVelocity");
  b.angularVelocity = requireFinite(def.angularVelocity, "angularVelocity");
  b.linearDamping = static_cast<float>(requireNonNegative(def.linearDamping, "linearDamping"));
  b.angularDamping = static_cast<float>(requireNonNegative(def.angularDamping, "angularDamping"));
  b.gravityScale = static_cast<float>(requireFinite(def.gravityScale, "gravityScale"));
  b.locks = def.locks;
  b.allowFastRotation = def.allowFastRotation;
  b.isBullet = def.isBullet;
  b.enableSleep = def.enableSleep;
  b.awake = def.isAwake || def.type == BodyType::staticBody;
  b.userData = def.userData;
  const MassData mass = def.massData.value_or(MassData{});
  if (def.type == BodyType::dynamicBody) {
    detail::requireValidMassData(mass);
  }
  if (def.type == BodyType::staticBody) {
    b.linearVelocity = b.angularVelocity = {};
  }
  b.center = b.transform.p;
  detail::applyMassData(b, mass);
  const bool moving = b.type != BodyType::staticBody;
  const bool awake = b.awake;
  const BodyId id = detail::placeRecord<BodyTag>(w.bodyIds, w.bodies, std::move(b));
  if (def.type == BodyType::dynamicBody) {
    w.islands.addBody(id.index);
  }
  if (moving && awake) {
    w.awakeBodySet.add(id.index);
  }
  return id;
}

void World::destroyBody(BodyId id) {
  detail::Body& b = impl_->body(id);
  // What rested on it falls.
  detail::wakeBody(*impl_, id.index);
  impl_->islands.removeBody(id.index);
  for (const std::uint32_t slot : b.shapes) {
    impl_->shapeIds.freeId(impl_->shapes[slot].id);
    impl_->shapes[slot] = detail::Shape{};
  }
  impl_->awakeBodySet.remove(id.index);
  impl_->bodyIds.freeId(id);
  b = detail::Body{};
}

bool World::isAwake(BodyId id) const { return impl_->body(id).awake; }

void World::setAwake(BodyId id, bool awake) {
  detail::WorldState& w = *impl_;
  detail::Body& b = w.body(id);
  if (awake) {
    detail::wakeBody(w, id.index);
  } else if (b.awake && b.type == BodyType::dynamicBody) {
    // Its whole island sleeps with it: a body cannot sleep on what is still moving.
    detail::sleepIsland(w, w.islands.islandOf(id.index));
  }
}

bool World::isValid(BodyId id) const noexcept {
  return id.world == impl_->bodyIds.world() && impl_->bodyIds.isValid({id.index, id.generation});
}

std::uint32_t World::bodyCount() const noexcept { return impl_->bodyIds.size(); }

void World::bodyIds(std::vector<BodyId>& out) const {
  out.clear();
  for (const detail::Body& b : impl_->bodies) {
    if (b.alive) {
      out.push_back(b.id);
    }
  }
}

BodyType World::bodyType(BodyId id) const { return impl_->body(id).type; }
Transform3f World::transform(BodyId id) const { return impl_->body(id).transform; }
Vec3f World::position(BodyId id) const { return impl_->body(id).transform.p; }
Quatf World::rotation(BodyId id) const { return impl_->body(id).transform.q; }
Vec3f World::worldCenter(BodyId id) const { return impl_->body(id).center; }
Vec3f World::linearVelocity(BodyId id) const { return impl_->body(id).linearVelocity; }
Vec3f World::angularVelocity(BodyId id) const { return impl_->body(id).angularVelocity; }
std::uint64_t World::userData(BodyId id) const { return impl_->body(id).userData; }

Vec3f World::velocityAt(BodyId id, const Vec3f& worldPoint) const {
  const detail::Body& b = impl_->body(id);
  return b.linearVelocity + cross(b.angularVelocity, requireFinite(worldPoint, "worldPoint") - b.center);
}

MassData World::massData(BodyId id) const {
  const detail::Body& b = impl_->body(id);
  return {b.mass, b.localCenter, b.inertia};
}

Mat33f World::worldInertia(BodyId id) const {
  const detail::Body& b = impl_->body(id);
  const Mat33f r = toMat33(b.transform.q);
  return r * b.inertia * transpose(r);
}

double World::kineticEnergy(BodyId id) const {
  const detail::Body& b = impl_->body(id);
  const Vec3d v{b.linearVelocity.x, b.linearVelocity.y, b.linearVelocity.z};
  const Vec3d l = angularMomentum(id);
  const Vec3d w{b.angularVelocity.x, b.angularVelocity.y, b.angularVelocity.z};
  return 0.5 * static_cast<double>(b.mass) * dot(v, v) + 0.5 * dot(w, l);
}

Vec3d World::angularMomentum(BodyId id) const {
  const detail::Body& b = impl_->body(id);
  // L = R I R^T w, in double.
  const Quatd q{b.transform.q.w, b.transform.q.x, b.transform.q.y, b.transform.q.z};
  Mat33d inertia;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      inertia(r, c) = b.inertia(r, c);
    }
  }
  const Vec3d w{b.angularVelocity.x, b.angularVelocity.y, b.angularVelocity.z};
  return rotate(q, inertia * inverseRotate(q, w));
}

void World::setTransform(BodyId id, const Vec3f& position, const Quatf& rotation) {
  detail::Body& b = impl_->body(id);
  b.transform = {requireFinite(position, "position"), detail::requireRotation(rotation, "rotation")};
  b.center = transformPoint(b.transform, b.localCenter);
  detail::wakeBody(*impl_, id.index);
}

void World::setLinearVelocity(BodyId id, const Vec3f& velocity) {
  detail::Body& b = impl_->body(id);
  if (b.type != BodyType::staticBody) {
    b.linearVelocity = requireFinite(velocity, "velocity");
    detail::wakeBody(*impl_, id.index);
  }
}

void World::setAngularVelocity(BodyId id, const Vec3f& velocity) {
  detail::Body& b = impl_->body(id);
  if (b.type != BodyType::staticBody) {
    b.angularVelocity = requireFinite(velocity, "velocity");
    detail::wakeBody(*impl_, id.index);
  }
}

void World::setMassData(BodyId id, const MassData& data) {
  detail::Body& b = impl_->body(id);
  detail::requireValidMassData(data);
  detail::applyMassData(b, data);
  detail::updateExtents(*impl_, b);
  detail::wakeBody(*impl_, id.index);
}

void World::setLinearDamping(BodyId id, float damping) {
  impl_->body(id).linearDamping = static_cast<float>(requireNonNegative(damping, "linearDamping"));
}
void World::setAngularDamping(BodyId id, float damping) {
  impl_->body(id).angularDamping = static_cast<float>(requireNonNegative(damping, "angularDamping"));
}
void World::setGravityScale(BodyId id, float scale) {
  impl_->body(id).gravityScale = static_cast<float>(requireFinite(scale, "gravityScale"));
}
void World::setAxisLocks(BodyId id, const AxisLocks& locks) { impl_->body(id).locks = locks; }

void World::applyForce(BodyId id, const Vec3f& force, const Vec3f& worldPoint) {
  detail::Body& b = impl_->body(id);
  requireFinite(force, "force");
  requireFinite(worldPoint, "worldPoint");
  if (b.type == BodyType::dynamicBody) {
    b.force += force;
    b.torque += cross(worldPoint - b.center, force);
    detail::wakeBody(*impl_, id.index);
  }
}

void World::applyForceToCenter(BodyId id, const Vec3f& force) {
  detail::Body& b = impl_->body(id);
  requireFinite(force, "force");
  if (b.type == BodyType::dynamicBody) {
    b.force += force;
    detail::wakeBody(*impl_, id.index);
  }
}

void World::applyTorque(BodyId id, const Vec3f& torque) {
  detail::Body& b = impl_->body(id);
  requireFinite(torque, "torque");
  if (b.type == BodyType::dynamicBody) {
    b.torque += torque;
    detail::wakeBody(*impl_, id.index);
  }
}

void World::applyLinearImpulse(BodyId id, const Vec3f& impulse, const Vec3f& worldPoint) {
  detail::Body& b = impl_->body(id);
  requireFinite(impulse, "impulse");
  requireFinite(worldPoint, "worldPoint");
  if (b.type == BodyType::dynamicBody) {
    detail::wakeBody(*impl_, id.index);
    b.linearVelocity = detail::withoutLockedLinear(b.linearVelocity + impulse * b.inverseMass, b.locks);
    applyAngularImpulse(id, cross(worldPoint - b.center, impulse));
  }
}

void World::applyAngularImpulse(BodyId id, const Vec3f& impulse) {
  detail::Body& b = impl_->body(id);
  requireFinite(impulse, "impulse");
  if (b.type == BodyType::dynamicBody) {
    detail::wakeBody(*impl_, id.index);
    const Mat33f inverseInertia = detail::worldInverseInertia(b.transform.q, b.inertia, b.inverseInertia, b.locks);
    b.angularVelocity = detail::withoutLockedAngular(b.angularVelocity + inverseInertia * impulse, b.locks);
  }
}

} // namespace impetus::rigid3d
