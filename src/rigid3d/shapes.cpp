// The 3D world's shapes: creation, destruction, and the mass properties they give their bodies.
#include "rigid3d/world_impl.hpp"

#include <impetus/core/mass_properties.hpp>
#include <impetus/error.hpp>

#include <algorithm>
#include <utility>
#include <vector>

namespace impetus::rigid3d {

namespace detail {

namespace {

/// A dynamic body's mass properties from its shapes, applied.
void massFromShapes(const WorldState& w, Body& b) {
  std::vector<MassPart> parts;
  parts.reserve(b.shapes.size());
  for (const std::uint32_t slot : b.shapes) {
    const Shape& s = w.shapes[slot];
    const MassProperties3 m = massProperties(s.geometry, s.density);
    if (m.mass > 0.0) {
      parts.push_back({m.mass, m.centerOfMass, m.inertia, Mat33d::identity()});
    }
  }
  if (parts.empty()) {
    applyMassData(b, MassData{});
    return;
  }
  const MassProperties3 total = combine(parts);
  MassData data;
  data.mass = static_cast<float>(total.mass);
  data.center = {static_cast<float>(total.centerOfMass.x), static_cast<float>(total.centerOfMass.y),
                 static_cast<float>(total.centerOfMass.z)};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      data.inertia(r, c) = static_cast<float>(total.inertia(r, c));
    }
  }
  applyMassData(b, data);
}

} // namespace

void updateMassFromShapes(WorldState& w, Body& b) {
  if (b.type != BodyType::dynamicBody) {
    return;
  }
  massFromShapes(w, b);
  updateExtents(w, b);
}

} // namespace detail

ShapeId World::createShape(BodyId body, const ShapeDef& def, const ShapeGeometry& geometry) {
  detail::WorldState& w = *impl_;
  detail::Body& b = w.body(body);
  requireValidGeometry(geometry);
  detail::Shape s;
  s.geometry = geometry;
  s.body = body.index;
  s.density = static_cast<float>(requireNonNegative(def.density, "density"));
  s.friction = static_cast<float>(requireNonNegative(def.friction, "friction"));
  s.restitution = static_cast<float>(requireNonNegative(def.restitution, "restitution"));
  s.rollingResistance = static_cast<float>(requireNonNegative(def.rollingResistance, "rollingResistance"));
  if (s.restitution > 1.0f) {
    throwInvalid("restitution", s.restitution, "must be at most 1 (a bounce gains no energy)");
  }
  s.filter = def.filter;
  s.sensor = def.isSensor;
  s.userData = def.userData;
  const ShapeId id = detail::placeRecord<ShapeTag>(w.shapeIds, w.shapes, std::move(s));
  b.shapes.push_back(id.index);
  detail::updateMassFromShapes(w, b);
  return id;
}

void World::destroyShape(ShapeId id) {
  detail::WorldState& w = *impl_;
  detail::Shape& s = w.shape(id);
  detail::Body& b = w.bodies[s.body];
  b.shapes.erase(std::find(b.shapes.begin(), b.shapes.end(), id.index));
  w.shapeIds.freeId(id);
  s = detail::Shape{};
  detail::updateMassFromShapes(w, b);
}

bool World::isValid(ShapeId id) const noexcept {
  return id.world == impl_->shapeIds.world() && impl_->shapeIds.isValid({id.index, id.generation});
}

BodyId World::shapeBody(ShapeId id) const { return impl_->bodies[impl_->shape(id).body].id; }
ShapeGeometry World::shapeGeometry(ShapeId id) const { return impl_->shape(id).geometry; }

void World::bodyShapes(BodyId body, std::vector<ShapeId>& out) const {
  const detail::Body& b = impl_->body(body);
  out.clear();
  for (const std::uint32_t slot : b.shapes) {
    out.push_back(impl_->shapes[slot].id);
  }
}

} // namespace impetus::rigid3d
