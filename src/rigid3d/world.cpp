// The 3D world: its settings, the step, the whole-world operations.
#include "rigid3d/world_impl.hpp"

#include <impetus/core/state_hash.hpp>
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/rigid3d/world.hpp>

#include <algorithm>

namespace impetus::rigid3d {

namespace detail {

namespace {

const WorldDef& requireValidWorldDef(const WorldDef& def) {
  requireFinite(def.gravity, "gravity");
  if (def.substeps < 1 || def.substeps > 64) {
    throwInvalid("substeps", def.substeps, "must be between 1 and 64");
  }
  requirePositive(def.maxLinearSpeed, "maxLinearSpeed");
  requireNonNegative(def.contactHertz, "contactHertz");
  requireNonNegative(def.contactDampingRatio, "contactDampingRatio");
  requirePositive(def.maxContactPushSpeed, "maxContactPushSpeed");
  requireNonNegative(def.restitutionThreshold, "restitutionThreshold");
  requireNonNegative(def.hitEventThreshold, "hitEventThreshold");
  requireNonNegative(def.timeToSleep, "timeToSleep");
  requireNonNegative(def.sleepLinearTolerance, "sleepLinearTolerance");
  requireNonNegative(def.sleepAngularTolerance, "sleepAngularTolerance");
  return def;
}

} // namespace

WorldState::WorldState(const WorldDef& d)
    : def(requireValidWorldDef(d)), bodyIds(nextWorldNumber()), shapeIds(bodyIds.world()) {}

Body& WorldState::body(BodyId id) {
  if (id.world != bodyIds.world() || !bodyIds.isValid({id.index, id.generation})) {
    throwInvalid("body", id.index, "is not a live body of this world (destroyed, null or another world's)");
  }
  return bodies[id.index];
}

const Body& WorldState::body(BodyId id) const { return const_cast<WorldState*>(this)->body(id); }

Shape& WorldState::shape(ShapeId id) {
  if (id.world != shapeIds.world() || !shapeIds.isValid({id.index, id.generation})) {
    throwInvalid("shape", id.index, "is not a live shape of this world (destroyed, null or another world's)");
  }
  return shapes[id.index];
}

const Shape& WorldState::shape(ShapeId id) const { return const_cast<WorldState*>(this)->shape(id); }

} // namespace detail

World::World(const WorldDef& def) : impl_(std::make_unique<Impl>(def)) {}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

void World::step(float dt) {
  if (!(dt > 0.0f && dt <= 1.0f)) {
    throwInvalid("dt", dt, "time step must be in (0, 1] s");
  }
  detail::solve(*impl_, dt);
}

Vec3f World::gravity() const noexcept { return impl_->def.gravity; }
void World::setGravity(const Vec3f& gravity) { impl_->def.gravity = requireFinite(gravity, "gravity"); }

void World::shiftOrigin(const Vec3f& newOrigin) {
  requireFinite(newOrigin, "newOrigin");
  for (detail::Body& b : impl_->bodies) {
    if (b.alive) {
      b.transform.p -= newOrigin;
      b.center -= newOrigin;
    }
  }
}

const ContactEvents& World::contactEvents() const noexcept { return impl_->contactEvents; }
const SensorEvents& World::sensorEvents() const noexcept { return impl_->sensorEvents; }

void World::contacts(std::vector<ContactData>& out) const {
  out.clear();
  for (const detail::Contact& c : impl_->contacts) {
    if (!c.touching || c.sensor) {
      continue;
    }
    ContactData d;
    d.shapeA = impl_->shapes[c.shapeA].id;
    d.shapeB = impl_->shapes[c.shapeB].id;
    d.manifold = c.manifold;
    for (int k = 0; k < c.manifold.pointCount; ++k) {
      const detail::PointImpulse& p = c.impulses[static_cast<std::size_t>(k)];
      d.normalImpulses[static_cast<std::size_t>(k)] = p.normal;
      d.tangentImpulses[static_cast<std::size_t>(k)] = c.tangent1 * p.tangent1 + c.tangent2 * p.tangent2;
    }
    out.push_back(d);
  }
}

std::uint32_t World::contactCount() const noexcept {
  return static_cast<std::uint32_t>(std::count_if(impl_->contacts.begin(), impl_->contacts.end(),
                                                  [](const detail::Contact& c) { return c.touching && !c.sensor; }));
}

std::uint64_t World::stateHash() const {
  StateHash hash;
  for (const detail::Body& b : impl_->bodies) {
    if (!b.alive) {
      continue;
    }
    for (const float x : {b.transform.p.x, b.transform.p.y, b.transform.p.z, b.transform.q.w, b.transform.q.x,
                          b.transform.q.y, b.transform.q.z, b.linearVelocity.x, b.linearVelocity.y, b.linearVelocity.z,
                          b.angularVelocity.x, b.angularVelocity.y, b.angularVelocity.z}) {
      hash.add(x);
    }
  }
  return hash.value();
}

} // namespace impetus::rigid3d
