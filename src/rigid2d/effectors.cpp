// Force effectors (effectors.hpp): fields, wind drag, thrusters, spring-dampers, explosions.
// Buoyancy lives in buoyancy.cpp. Everything goes through the World's public API.
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/rigid2d/effectors.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace impetus::rigid2d {

namespace {

void requireStep(float dt) {
  if (!(dt > 0.0f && dt <= 1.0f)) {
    throwInvalid("dt", static_cast<double>(dt), "time step must be in (0, 1] s");
  }
}

void requireBody(const World& world, BodyId id, std::string_view field) {
  if (!world.isValid(id)) {
    throwInvalid(field, static_cast<double>(id.index), "is not a live body of this world");
  }
}

void requireRegion(const std::optional<AABB>& region) {
  if (!region) {
    return;
  }
  requireValid(*region, "region");
}

bool insideRegion(const AABB& box, const Vec2f& p) {
  return box.lower.x <= p.x && p.x <= box.upper.x && box.lower.y <= p.y && p.y <= box.upper.y;
}

/// The largest drag force (N) at offset r from the centre of mass along the unit direction u
/// that does no more than stop a relative point velocity of `speed` (m/s) in one step: the
/// point's effective mass along u, 1 / (1/m + (r x u)^2 / I), times speed / dt.
float dragLimit(const World& world, BodyId body, const Vec2f& r, const Vec2f& u, float speed, float dt) {
  const float m = world.mass(body);
  const float inertia = world.rotationalInertia(body);
  const float ru = cross(r, u);
  float inverseMass = m > 0.0f ? 1.0f / m : 0.0f;
  if (inertia > 0.0f) {
    inverseMass += ru * ru / inertia;
  }
  return inverseMass > 0.0f ? speed / (dt * inverseMass) : std::numeric_limits<float>::infinity();
}

} // namespace

float predictionFraction(const World& world) noexcept {
  const WorldDef& def = world.settings();
  if (def.solver == SolverKind::bookImpulse || def.substeps <= 1) {
    return 0.0f;
  }
  const auto k = static_cast<float>(def.substeps);
  return (k - 1.0f) / (2.0f * k);
}

// ---------------------------------------------------------------------------------------------

bool ForceEffectorSet::remove(const ForceEffector& effector) {
  const auto it = std::find_if(effectors_.begin(), effectors_.end(),
                               [&](const std::unique_ptr<ForceEffector>& e) { return e.get() == &effector; });
  if (it == effectors_.end()) {
    return false;
  }
  effectors_.erase(it);
  return true;
}

void ForceEffectorSet::apply(World& world, float dt) {
  requireStep(dt);
  for (const auto& effector : effectors_) {
    effector->apply(world, dt);
  }
}

// ---------------------------------------------------------------------------------------------

GravityField::GravityField(const GravityFieldSettings& settings) : settings_(settings) {
  requireFinite(settings_.acceleration, "acceleration");
  requireRegion(settings_.region);
}

void GravityField::setAcceleration(const Vec2f& acceleration) {
  settings_.acceleration = requireFinite(acceleration, "acceleration");
}

void GravityField::apply(World& world, float dt) {
  requireStep(dt);
  world.bodyIds(bodies_);
  for (const BodyId body : bodies_) {
    if (world.bodyType(body) != BodyType::dynamicBody || !world.isAwake(body)) {
      continue;
    }
    const Vec2f center = world.worldCenterOfMass(body);
    if (settings_.region && !insideRegion(*settings_.region, center)) {
      continue;
    }
    // F = m a at the centre of mass: no torque.
    world.applyForce(body, settings_.acceleration * world.mass(body), center);
  }
}

// ---------------------------------------------------------------------------------------------

PointAttractor::PointAttractor(const PointAttractorSettings& settings) : settings_(settings) {
  requireFinite(settings_.center, "center");
  requireFinite(static_cast<double>(settings_.mu), "mu");
  requireNonNegative(static_cast<double>(settings_.softening), "softening");
  if (settings_.maxRadius) {
    requirePositive(static_cast<double>(*settings_.maxRadius), "maxRadius");
  }
}

void PointAttractor::apply(World& world, float dt) {
  requireStep(dt);
  const float tau = predictionFraction(world) * dt;
  const float eps2 = settings_.softening * settings_.softening;
  world.bodyIds(bodies_);
  for (const BodyId body : bodies_) {
    if (world.bodyType(body) != BodyType::dynamicBody || !world.isAwake(body)) {
      continue;
    }
    const Vec2f center = world.worldCenterOfMass(body);
    // Evaluated at the centre of mass predicted tau = beta dt ahead (predictionFraction).
    const Vec2f predicted = center + world.linearVelocity(body) * tau;
    const Vec2f d = settings_.center - predicted;
    const float r2 = lengthSquared(d);
    if (settings_.maxRadius && r2 > *settings_.maxRadius * *settings_.maxRadius) {
      continue;
    }
    const float r = std::sqrt(r2);
    if (!(r > 0.0f)) {
      continue; // at the centre: no direction
    }
    // |a| = mu / (r^2 + eps^2), m/s^2, toward the centre. Without softening a body passing
    // (almost) through the centre would get an unbounded pull: skip it while the force would
    // not be finite (it is past the point where the model means anything).
    const float a = settings_.mu / (r2 + eps2);
    const Vec2f force = d * (world.mass(body) * a / r);
    if (std::isfinite(force.x) && std::isfinite(force.y)) {
      world.applyForce(body, force, center);
    }
  }
}

// ---------------------------------------------------------------------------------------------

WindDrag::WindDrag(const WindDragSettings& settings) : settings_(settings) {
  requireFinite(settings_.airVelocity, "airVelocity");
  requireNonNegative(static_cast<double>(settings_.airDensity), "airDensity");
  requireNonNegative(static_cast<double>(settings_.dragArea), "dragArea");
  requireNonNegative(static_cast<double>(settings_.linearDrag), "linearDrag");
  requireFinite(settings_.localCenterOfPressure, "localCenterOfPressure");
}

void WindDrag::setAirVelocity(const Vec2f& airVelocity) {
  settings_.airVelocity = requireFinite(airVelocity, "airVelocity");
}

void WindDrag::apply(World& world, float dt) {
  requireStep(dt);
  requireBody(world, settings_.body, "body");
  lastForce_ = {};
  const BodyId body = settings_.body;
  if (world.bodyType(body) != BodyType::dynamicBody) {
    return;
  }
  const Transform2f xf = world.transform(body);
  const Vec2f center = world.worldCenterOfMass(body);
  const Vec2f point = transformPoint(xf, settings_.localCenterOfPressure);
  const Vec2f r = point - center;
  // Velocity of the centre of pressure relative to the air: v + w x r - v_air.
  const Vec2f vRel = world.linearVelocity(body) + cross(world.angularVelocity(body), r) - settings_.airVelocity;
  const float speed = length(vRel);
  if (!(speed > 0.0f)) {
    return;
  }
  // |F| = 1/2 rho CdA |v|^2 + c_lin |v| (N), against v_rel; at most what stops the point in a step.
  const float k = 0.5f * settings_.airDensity * settings_.dragArea;
  float magnitude = (k * speed + settings_.linearDrag) * speed;
  const Vec2f u = vRel / speed;
  magnitude = std::min(magnitude, dragLimit(world, body, r, u, speed, dt));
  if (!(magnitude > 0.0f)) {
    return;
  }
  lastForce_ = u * -magnitude;
  world.applyForce(body, lastForce_, point);
}

// ---------------------------------------------------------------------------------------------

Thruster::Thruster(const ThrusterSettings& settings) : settings_(settings) {
  requireFinite(settings_.localPoint, "localPoint");
  requireFinite(settings_.localDirection, "localDirection");
  const float len = length(settings_.localDirection);
  if (!(len > 0.0f)) {
    throwInvalid("localDirection", static_cast<double>(len), "must be a non-zero direction");
  }
  settings_.localDirection = settings_.localDirection / len;
  requireFinite(static_cast<double>(settings_.thrust), "thrust");
}

void Thruster::setThrust(float thrust) {
  settings_.thrust = static_cast<float>(requireFinite(static_cast<double>(thrust), "thrust"));
}

void Thruster::apply(World& world, float dt) {
  requireStep(dt);
  requireBody(world, settings_.body, "body");
  if (settings_.thrust == 0.0f || world.bodyType(settings_.body) != BodyType::dynamicBody) {
    return;
  }
  const Transform2f xf = world.transform(settings_.body);
  const Vec2f force = rotate(xf.q, settings_.localDirection) * settings_.thrust;
  world.applyForce(settings_.body, force, transformPoint(xf, settings_.localPoint));
}

// ---------------------------------------------------------------------------------------------

SpringDamper::SpringDamper(const SpringDamperSettings& settings) : settings_(settings) {
  requireFinite(settings_.localAnchorA, "localAnchorA");
  requireFinite(settings_.localAnchorB, "localAnchorB");
  requireNonNegative(static_cast<double>(settings_.stiffness), "stiffness");
  requireNonNegative(static_cast<double>(settings_.damping), "damping");
  requireNonNegative(static_cast<double>(settings_.restLength), "restLength");
}

void SpringDamper::apply(World& world, float dt) {
  requireStep(dt);
  requireBody(world, settings_.bodyA, "bodyA");
  const bool hasB = !settings_.bodyB.isNull();
  if (hasB) {
    requireBody(world, settings_.bodyB, "bodyB");
  }
  lastTension_ = 0.0f;
  // An anchor's world point and velocity (v + w x r); a world-point end is fixed.
  struct End {
    Vec2f point;
    Vec2f velocity;
    bool dynamic = false;
  };
  const auto end = [&](BodyId body, const Vec2f& local) {
    const Vec2f point = transformPoint(world.transform(body), local);
    const Vec2f r = point - world.worldCenterOfMass(body);
    return End{point, world.linearVelocity(body) + cross(world.angularVelocity(body), r),
               world.bodyType(body) == BodyType::dynamicBody};
  };
  const End a = end(settings_.bodyA, settings_.localAnchorA);
  const End b = hasB ? end(settings_.bodyB, settings_.localAnchorB) : End{settings_.localAnchorB, {}, false};
  if (!a.dynamic && !b.dynamic) {
    return;
  }
  // The spring is evaluated at the anchors predicted tau = beta dt ahead (predictionFraction),
  // the damper at the current velocities.
  const float tau = predictionFraction(world) * dt;
  const Vec2f d = (b.point + b.velocity * tau) - (a.point + a.velocity * tau);
  const float len = length(d);
  if (!(len > 1e-6f)) {
    return;
  }
  const Vec2f u = d / len;
  const float rate = dot(b.velocity - a.velocity, u); // dL/dt, m/s
  // T = k (L - L0) + c dL/dt, N: positive pulls the anchors together.
  const float tension = settings_.stiffness * (len - settings_.restLength) + settings_.damping * rate;
  lastTension_ = tension;
  const Vec2f force = u * tension; // on A (toward B); -force on B
  if (a.dynamic) {
    world.applyForce(settings_.bodyA, force, a.point);
  }
  if (b.dynamic) {
    world.applyForce(settings_.bodyB, -force, b.point);
  }
}

// ---------------------------------------------------------------------------------------------

Explosion::Explosion(const ExplosionSettings& settings) : settings_(settings) {
  requireFinite(settings_.center, "center");
  requirePositive(static_cast<double>(settings_.radius), "radius");
  requireNonNegative(static_cast<double>(settings_.impulse), "impulse");
}

Vec2f Explosion::impulseAt(const Vec2f& point) const noexcept {
  const Vec2f d = point - settings_.center;
  const float r = length(d);
  if (!(r > 0.0f) || r >= settings_.radius) {
    return {};
  }
  // J = J0 (1 - r / R), radially outward.
  return d * (settings_.impulse * (1.0f - r / settings_.radius) / r);
}

void Explosion::apply(World& world, float dt) {
  requireStep(dt);
  if (fired_) {
    return;
  }
  fired_ = true;
  world.bodyIds(bodies_);
  for (const BodyId body : bodies_) {
    if (world.bodyType(body) != BodyType::dynamicBody) {
      continue;
    }
    const Vec2f center = world.worldCenterOfMass(body);
    const Vec2f impulse = impulseAt(center);
    if (impulse.x != 0.0f || impulse.y != 0.0f) {
      world.applyLinearImpulse(body, impulse, center);
    }
  }
}

} // namespace impetus::rigid2d
