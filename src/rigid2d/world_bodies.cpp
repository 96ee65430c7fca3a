// The world's body and shape API: creating and destroying bodies, attaching shapes (the body's
// mass from their densities), the bodies' state, forces, impulses and sleep.
#include "rigid2d/joints.hpp"
#include "rigid2d/world_impl.hpp"

#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace impetus::rigid2d {

namespace {

using detail::Body;
using detail::Contact;
using detail::Shape;
using detail::shapeBox;
using detail::WorldState;

/// Mass, centre of mass and inertia of a body from its shapes' densities.
void updateMass(WorldState& w, Body& b) {
  b.mass = b.inverseMass = b.inertia = b.inverseInertia = 0.0f;
  b.localCenter = {};
  if (b.type != BodyType::dynamicBody) {
    b.center = transformPoint(b.transform, b.localCenter);
    b.coreRadius = 0.0f;
    return;
  }
  float mass = 0.0f;
  Vec2f moment;
  float inertiaAboutOrigin = 0.0f;
  for (std::uint32_t slot : b.shapes) {
    const Shape& s = w.shapes[slot];
    if (s.density == 0.0f || detail::isLine(s.geometry)) {
      continue;
    }
    const MassData md = std::visit(
        [&](const auto& g) -> MassData {
          using G = std::decay_t<decltype(g)>;
          if constexpr (std::is_same_v<G, Segment> || std::is_same_v<G, ChainSegment>) {
            return {};
          } else {
            return computeMass(g, s.density);
          }
        },
        s.geometry);
    mass += md.mass;
    moment += md.center * md.mass;
    inertiaAboutOrigin += md.rotationalInertia + md.mass * lengthSquared(md.center);
  }
  if (mass > 0.0f) {
    b.mass = mass;
    b.inverseMass = 1.0f / mass;
    b.localCenter = moment / mass;
    const float inertia = inertiaAboutOrigin - mass * lengthSquared(b.localCenter);
    if (inertia > 0.0f && !b.fixedRotation) {
      b.inertia = inertia;
      b.inverseInertia = 1.0f / inertia;
    }
  } else {
    // A dynamic body needs mass: without shapes (or with zero density) it behaves as 1 kg.
    b.mass = 1.0f;
    b.inverseMass = 1.0f;
  }
  b.center = transformPoint(b.transform, b.localCenter);
  b.coreRadius = detail::computeCoreRadius(w, b);
}

} // namespace

BodyId World::createBody(const BodyDef& def) {
  detail::requireWorldPosition(def.position);
  requireFinite(def.angle, "angle");
  detail::requireWithinSpeedLimit(def.linearVelocity, impl_->def.maxLinearSpeed);
  requireFinite(def.angularVelocity, "angularVelocity");
  requireNonNegative(def.linearDamping, "linearDamping");
  requireNonNegative(def.angularDamping, "angularDamping");
  requireFinite(def.gravityScale, "gravityScale");
  // A cast integer would otherwise be treated as no known type: neither moved nor solved.
  if (def.type != BodyType::staticBody && def.type != BodyType::kinematicBody && def.type != BodyType::dynamicBody) {
    throwInvalid("type", static_cast<int>(def.type), "must be BodyType::staticBody, kinematicBody or dynamicBody");
  }
  Impl& w = *impl_;
  const BodyId id = w.bodyIds.allocateId<BodyTag>();
  if (w.bodies.size() <= id.index) {
    w.bodies.resize(id.index + 1);
  }
  Body& b = w.bodies[id.index];
  b = Body{};
  b.type = def.type;
  b.transform = {def.position, Rot2f::fromAngle(def.angle)};
  b.linearVelocity = def.type == BodyType::staticBody ? Vec2f{} : def.linearVelocity;
  b.angularVelocity = (def.type == BodyType::staticBody || def.fixedRotation) ? 0.0f : def.angularVelocity;
  b.linearDamping = def.linearDamping;
  b.angularDamping = def.angularDamping;
  b.gravityScale = def.gravityScale;
  b.fixedRotation = def.fixedRotation;
  b.bullet = def.bullet;
  b.allowFastRotation = def.allowFastRotation;
  b.enableSleep = def.enableSleep;
  b.awake = def.isAwake;
  b.userData = def.userData;
  b.id = id;
  b.alive = true;
  updateMass(w, b);
  if (w.bodyInfo.size() <= id.index) {
    w.bodyInfo.resize(id.index + 1);
  }
  w.bodyInfo[id.index] = detail::SolverBodyInfo{};
  if (b.type != BodyType::staticBody) {
    w.islands.addBody(id.index);
    if (b.awake) {
      w.awakeBodySet.add(id.index);
    }
  }
  return id;
}

void World::destroyBody(BodyId id) {
  Impl& w = *impl_;
  Body& b = w.body(id);
  while (!b.joints.empty()) {
    destroyJoint(w.joints[b.joints.back()].id);
  }
  const std::uint32_t bodySlot = id.index;
  // Its own contacts only, in slot order (the order of their end events and of the free list).
  detail::bodyContacts(w, bodySlot, w.bodyContactScratch);
  for (const std::uint32_t slot : w.bodyContactScratch) {
    const Contact& c = w.contacts[slot];
    detail::wakeBody(w, c.bodyA == bodySlot ? c.bodyB : c.bodyA); // what rested on it must fall
    detail::destroyContact(w, slot, w.pendingEvents, w.pendingSensorEvents);
  }
  for (std::uint32_t slot : b.shapes) {
    Shape& s = w.shapes[slot];
    w.treeOf(s).destroyProxy(s.proxy);
    w.shapeIds.freeId(s.id);
    s = Shape{};
  }
  w.islands.removeBody(bodySlot);
  w.awakeBodySet.remove(bodySlot);
  w.bodyInfo[bodySlot] = detail::SolverBodyInfo{};
  b = Body{};
  w.bodyIds.freeId(id);
}

bool World::isValid(BodyId id) const noexcept { return impl_->bodyIds.isValidId(id); }
std::size_t World::bodyCount() const noexcept { return impl_->bodyIds.size(); }
std::size_t World::shapeCount() const noexcept { return impl_->shapeIds.size(); }

namespace {

ShapeId addShape(WorldState& w, BodyId bodyId, const ShapeDef& def, const detail::Geometry& geometry) {
  Body& b = w.body(bodyId);
  requireNonNegative(def.density, "density");
  requireNonNegative(def.friction, "friction");
  requireNonNegative(def.rollingResistance, "rollingResistance");
  if (!std::isfinite(def.tangentSpeed)) {
    throwInvalid("tangentSpeed", def.tangentSpeed, "must be a finite speed (m/s)");
  }
  if (!(def.restitution >= 0.0f && def.restitution <= 1.0f)) {
    throwInvalid("restitution", def.restitution, "must be in [0, 1]");
  }
  if (b.type == BodyType::dynamicBody && def.density == 0.0f && !def.isSensor && !detail::isLine(geometry)) {
    throwInvalid("density", def.density, "a shape on a dynamic body needs a positive density");
  }
  const ShapeId id = w.shapeIds.allocateId<ShapeTag>();
  if (w.shapes.size() <= id.index) {
    w.shapes.resize(id.index + 1);
    w.fatBoxes.resize(id.index + 1);
  }
  Shape& s = w.shapes[id.index];
  s = Shape{};
  s.geometry = geometry;
  if (const auto* polygon = std::get_if<Polygon>(&geometry)) {
    s.collisionPolygon = *polygon;
  } else if (const auto* capsule = std::get_if<Capsule>(&geometry)) {
    s.collisionPolygon = asPolygon(*capsule);
  } else if (const auto* segment = std::get_if<Segment>(&geometry)) {
    s.collisionPolygon = asPolygon(*segment);
  } else if (const auto* chain = std::get_if<ChainSegment>(&geometry)) {
    s.collisionPolygon = asPolygon(chain->segment);
  }
  s.body = bodyId.index;
  s.density = def.density;
  s.friction = def.friction;
  s.rollingResistance = def.rollingResistance;
  s.tangentSpeed = def.tangentSpeed;
  s.customFiltering = def.enableCustomFiltering;
  s.preSolve = def.enablePreSolveEvents;
  s.restitution = def.restitution;
  s.filter = def.filter;
  s.sensor = def.isSensor;
  s.userData = def.userData;
  s.id = id;
  s.alive = true;
  s.inStaticTree = b.type == BodyType::staticBody;
  s.margin = detail::fatBoxMargin(geometry);
  w.fatBoxes[id.index] = s.inStaticTree ? shapeBox(s, b.transform) : enlarge(reachBox(s, b.transform), s.margin);
  s.proxy = w.treeOf(s).createProxy(w.fatBoxes[id.index], id.index);
  w.moveBuffer.push_back(id.index);
  b.shapes.push_back(id.index);
  updateMass(w, b);
  return id;
}

} // namespace

namespace {

/// Refuses, naming `density`, a shape whose mass data would not be usable (computeMass: not
/// finite, or with no finite inverse), or would make its body's not finite: updateMass sums, in
/// float, each shape's mass, mass moment and inertia about the body origin (its own plus
/// m |c|^2, up to 1e12 m^2 times the mass within maxPolygonCoordinate). Checked before the shape
/// is added (a throw from updateMass would leave it half added), on any body type (a static body
/// may be made dynamic later). An invalid density is left to addShape to name.
template <class G> void requireUsableBodyMass(const WorldState& w, BodyId bodyId, const ShapeDef& def, const G& shape) {
  const Body& b = w.body(bodyId);
  if (!(std::isfinite(def.density) && def.density > 0.0f)) {
    return;
  }
  const MassData added = computeMass(shape, def.density);
  float mass = 0.0f;
  Vec2f moment;
  float inertiaAboutOrigin = 0.0f;
  const auto add = [&](const MassData& md) {
    mass += md.mass;
    moment += md.center * md.mass;
    inertiaAboutOrigin += md.rotationalInertia + md.mass * lengthSquared(md.center);
  };
  for (std::uint32_t slot : b.shapes) { // as updateMass, in its order, the new shape last
    const Shape& s = w.shapes[slot];
    if (s.density == 0.0f || detail::isLine(s.geometry)) {
      continue;
    }
    std::visit(
        [&](const auto& g) {
          using S = std::decay_t<decltype(g)>;
          if constexpr (!std::is_same_v<S, Segment> && !std::is_same_v<S, ChainSegment>) {
            add(computeMass(g, s.density));
          }
        },
        s.geometry);
  }
  add(added);
  const Vec2f center = moment / mass;
  const float inertia = inertiaAboutOrigin - mass * lengthSquared(center);
  if (!std::isfinite(mass) || !isFinite(moment) || !std::isfinite(inertiaAboutOrigin) || !std::isfinite(inertia)) {
    throwInvalid("density", def.density,
                 "the body's mass or rotational inertia with this shape overflows float (" + formatValue(mass) +
                     " kg, " + formatValue(inertiaAboutOrigin) + " kg m^2 about the body origin)");
  }
}

} // namespace

ShapeId World::createShape(BodyId body, const ShapeDef& def, const Circle& circle) {
  validateShape(circle);
  requireUsableBodyMass(*impl_, body, def, circle);
  return addShape(*impl_, body, def, circle);
}
ShapeId World::createShape(BodyId body, const ShapeDef& def, const Capsule& capsule) {
  validateShape(capsule);
  requireUsableBodyMass(*impl_, body, def, capsule);
  return addShape(*impl_, body, def, capsule);
}
ShapeId World::createShape(BodyId body, const ShapeDef& def, const Polygon& polygon) {
  // Polygon is a plain struct: one filled in by hand (or corrupted) would otherwise reach the
  // broadphase and the narrowphase with NaN bounds, normals of no direction, or a winding the
  // separating-axis tests do not expect.
  validateShape(polygon);
  requireUsableBodyMass(*impl_, body, def, polygon);
  return addShape(*impl_, body, def, polygon);
}
ShapeId World::createShape(BodyId body, const ShapeDef& def, const Segment& segment) {
  validateShape(segment); // a segment has no mass
  return addShape(*impl_, body, def, segment);
}

std::vector<ShapeId> World::createChain(BodyId body, const ShapeDef& def, const ChainDef& chain) {
  impl_->body(body); // a clear error for a bad id before the points are checked
  std::vector<ShapeId> ids;
  for (const ChainSegment& segment : makeChainSegments(chain)) {
    ids.push_back(addShape(*impl_, body, def, segment));
  }
  return ids;
}

Transform2f World::transform(BodyId id) const { return impl_->body(id).transform; }
Vec2f World::position(BodyId id) const { return impl_->body(id).transform.p; }
float World::angle(BodyId id) const { return impl_->body(id).transform.q.angle(); }
Vec2f World::worldCenterOfMass(BodyId id) const { return impl_->body(id).center; }
Vec2f World::linearVelocity(BodyId id) const { return impl_->body(id).linearVelocity; }
float World::angularVelocity(BodyId id) const { return impl_->body(id).angularVelocity; }
float World::mass(BodyId id) const { return impl_->body(id).mass; }
float World::rotationalInertia(BodyId id) const { return impl_->body(id).inertia; }

void World::setMassData(BodyId id, const MassData& massData) {
  Body& b = impl_->body(id);
  if (b.type != BodyType::dynamicBody) {
    throwInvalid("body id", static_cast<double>(id.index), "only a dynamic body has a mass to set");
  }
  requirePositive(massData.mass, "mass");
  requireFinite(massData.center, "center");
  requirePositive(massData.rotationalInertia, "rotationalInertia");
  b.mass = massData.mass;
  b.inverseMass = 1.0f / massData.mass;
  b.localCenter = massData.center;
  b.inertia = b.fixedRotation ? 0.0f : massData.rotationalInertia;
  b.inverseInertia = b.fixedRotation ? 0.0f : 1.0f / massData.rotationalInertia;
  b.center = transformPoint(b.transform, b.localCenter);
  b.coreRadius = detail::computeCoreRadius(*impl_, b);
  detail::wakeBody(*impl_, id.index);
}

void World::setLinearVelocity(BodyId id, const Vec2f& v) {
  Body& b = impl_->body(id);
  // Checked before the body's type: a NaN is a caller's bug even where the value is ignored.
  detail::requireWithinSpeedLimit(v, impl_->def.maxLinearSpeed);
  if (b.type != BodyType::staticBody) {
    b.linearVelocity = v;
    detail::wakeBody(*impl_, id.index);
  }
}
void World::setAngularVelocity(BodyId id, float av) {
  Body& b = impl_->body(id);
  requireFinite(av, "angularVelocity");
  if (b.type != BodyType::staticBody && !b.fixedRotation) {
    b.angularVelocity = av;
    detail::wakeBody(*impl_, id.index);
  }
}
void World::applyForce(BodyId id, const Vec2f& force, const Vec2f& point) {
  Body& b = impl_->body(id);
  requireFinite(force, "force");
  requireFinite(point, "point");
  b.force += force;
  b.torque += cross(point - b.center, force);
  detail::wakeBody(*impl_, id.index);
}
void World::applyTorque(BodyId id, float torque) {
  Body& b = impl_->body(id);
  b.torque += static_cast<float>(requireFinite(torque, "torque"));
  detail::wakeBody(*impl_, id.index);
}
void World::applyLinearImpulse(BodyId id, const Vec2f& impulse, const Vec2f& point) {
  Body& b = impl_->body(id);
  requireFinite(impulse, "impulse");
  requireFinite(point, "point");
  b.linearVelocity += impulse * b.inverseMass;
  b.angularVelocity += b.inverseInertia * cross(point - b.center, impulse);
  detail::wakeBody(*impl_, id.index);
}

bool World::isAwake(BodyId id) const { return impl_->body(id).awake; }
void World::setAwake(BodyId id, bool awake) {
  const Body& b = impl_->body(id);
  if (awake) {
    detail::wakeBody(*impl_, id.index);
  } else if (b.moving()) {
    detail::sleepBodyIsland(*impl_, id.index); // its island sleeps with it, as Box2D v3
  }
}
std::size_t World::awakeBodyCount() const noexcept { return impl_->awakeBodySet.size(); }

} // namespace impetus::rigid2d
