// The world's settings: their validation (at creation and for every run-time change) and the
// run-time setters, after Box2D v3's b2World_SetGravity, b2World_SetContactTuning,
// b2World_SetJointTuning and b2World_EnableWarmStarting.
#include "rigid2d/joints.hpp"

#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>

#include <cmath>
#include <string>

namespace impetus::rigid2d {

namespace detail {

void validateWorldDef(const WorldDef& def) {
  requireFinite(def.gravity, "gravity");
  // In double: 1e38 m/s^2 squares past a float.
  if (const double g = std::hypot(static_cast<double>(def.gravity.x), static_cast<double>(def.gravity.y));
      g > maxGravity) {
    throw Error("gravity", "gravity = " + formatFloat(static_cast<float>(g)) +
                               " m/s^2: must be at most 1e4 m/s^2 in magnitude (1000 g)");
  }
  if (def.substeps < 1 || def.substeps > 64) {
    throwInvalid("substeps", def.substeps, "must be between 1 and 64");
  }
  requireNonNegative(def.contactHertz, "contactHertz");
  requireNonNegative(def.contactDampingRatio, "contactDampingRatio");
  requirePositive(def.maxContactPushSpeed, "maxContactPushSpeed");
  requirePositive(def.maxJointPushSpeed, "maxJointPushSpeed");
  requireNonNegative(def.restitutionThreshold, "restitutionThreshold");
  requirePositive(def.maxLinearSpeed, "maxLinearSpeed");
  requireNonNegative(def.jointHertz, "jointHertz");
  requireNonNegative(def.jointDampingRatio, "jointDampingRatio");
  requireNonNegative(def.hitEventThreshold, "hitEventThreshold");
  requireNonNegative(def.contactReuseDistance, "contactReuseDistance");
  if (!(def.contactReuseAngle >= 0.0f && def.contactReuseAngle < 1.0f)) {
    throwInvalid("contactReuseAngle", def.contactReuseAngle, "must be at least 0 rad and under 1 rad");
  }
  requireNonNegative(def.timeToSleep, "timeToSleep");
  requireNonNegative(def.sleepLinearTolerance, "sleepLinearTolerance");
  requireNonNegative(def.sleepAngularTolerance, "sleepAngularTolerance");
  if (def.simd != SimdLevel::widest && def.simd != SimdLevel::baseline) {
    throwInvalid("simd", static_cast<int>(def.simd), "must be SimdLevel::widest or SimdLevel::baseline");
  }
  if (def.solver != SolverKind::softStep && def.solver != SolverKind::bookImpulse) {
    throwInvalid("solver", static_cast<int>(def.solver), "unknown solver kind");
  }
}

} // namespace detail

namespace {

/// Applies `change` to a copy of the world's settings and takes it if it is valid; an invalid
/// value leaves the world as it was and throws impetus::Error naming the field.
template <class Change> void changeSettings(detail::WorldState& w, Change&& change) {
  WorldDef def = w.def;
  change(def);
  detail::validateWorldDef(def);
  w.def = def;
}

} // namespace

const WorldDef& World::settings() const noexcept { return impl_->def; }

void World::setGravity(const Vec2f& gravity) {
  changeSettings(*impl_, [&](WorldDef& d) { d.gravity = gravity; });
}

void World::setContactTuning(float hertz, float dampingRatio, float pushSpeed) {
  changeSettings(*impl_, [&](WorldDef& d) {
    d.contactHertz = hertz;
    d.contactDampingRatio = dampingRatio;
    d.maxContactPushSpeed = pushSpeed;
  });
}

void World::setJointTuning(float hertz, float dampingRatio) {
  changeSettings(*impl_, [&](WorldDef& d) {
    d.jointHertz = hertz;
    d.jointDampingRatio = dampingRatio;
  });
}

void World::setRestitutionThreshold(float speed) {
  changeSettings(*impl_, [&](WorldDef& d) { d.restitutionThreshold = speed; });
}

void World::setHitEventThreshold(float speed) {
  changeSettings(*impl_, [&](WorldDef& d) { d.hitEventThreshold = speed; });
}

void World::enableWarmStarting(bool enable) { impl_->def.enableWarmStarting = enable; }

void World::setJointConstraintTuning(JointId id, float hertz, float dampingRatio) {
  detail::validateConstraintTuning(hertz, dampingRatio);
  detail::Joint& j = impl_->joint(id);
  j.constraintHertz = hertz;
  j.constraintDampingRatio = dampingRatio;
  detail::wakeBody(*impl_, j.bodyA);
  detail::wakeBody(*impl_, j.bodyB);
}

} // namespace impetus::rigid2d
