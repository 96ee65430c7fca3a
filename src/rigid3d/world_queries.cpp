// The 3D world's queries: ray casts (the closest hit, or all of them) and overlap tests against
// the shapes a filter lets through, in a fixed order.
#include "rigid3d/placed_shape.hpp"
#include "rigid3d/world_impl.hpp"

#include <impetus/math/validate.hpp>
#include <impetus/rigid3d/ray_cast.hpp>

#include <algorithm>

namespace impetus::rigid3d {

namespace {

/// The box of a placed shape, grown by its radius.
void placedBox(const detail::PlacedShape& s, Vec3f& lower, Vec3f& upper) {
  lower = upper = s.points[0];
  for (int k = 1; k < s.count; ++k) {
    lower = min(lower, s.points[static_cast<std::size_t>(k)]);
    upper = max(upper, s.points[static_cast<std::size_t>(k)]);
  }
  const Vec3f r{s.radius, s.radius, s.radius};
  lower -= r;
  upper += r;
}

/// Every shape the filter lets through, hit by the ray, in slot order.
template <class Visit> void forEachRayHit(const detail::WorldState& w, const Vec3f& origin, const Vec3f& translation,
                                          const CollisionFilter& filter, Visit&& visit) {
  requireFinite(origin, "origin");
  requireFinite(translation, "translation");
  const RayCastInput input{origin, translation, 1.0f};
  for (const detail::Shape& s : w.shapes) {
    if (!s.alive || s.sensor || !shouldCollide(filter, s.filter)) {
      continue;
    }
    const CastOutput out = rayCast(s.geometry, w.bodies[s.body].transform, input);
    if (out.hit) {
      visit(RayHit{s.id, out.point, out.normal, out.fraction});
    }
  }
}

} // namespace

std::optional<RayHit> World::castRayClosest(const Vec3f& origin, const Vec3f& translation,
                                            const CollisionFilter& filter) const {
  std::optional<RayHit> closest;
  forEachRayHit(*impl_, origin, translation, filter, [&](const RayHit& hit) {
    if (!closest || hit.fraction < closest->fraction) {
      closest = hit;
    }
  });
  return closest;
}

std::vector<RayHit> World::castRayAll(const Vec3f& origin, const Vec3f& translation,
                                      const CollisionFilter& filter) const {
  std::vector<RayHit> hits;
  forEachRayHit(*impl_, origin, translation, filter, [&](const RayHit& hit) { hits.push_back(hit); });
  std::stable_sort(hits.begin(), hits.end(), [](const RayHit& a, const RayHit& b) { return a.fraction < b.fraction; });
  return hits;
}

std::vector<ShapeId> World::overlapShape(const ShapeGeometry& shape, const Transform3f& transform,
                                         const CollisionFilter& filter) const {
  requireValidGeometry(shape);
  requireFinite(transform.p, "transform.p");
  const detail::WorldState& w = *impl_;
  detail::PlacedShape query;
  query.place(shape, {transform.p, normalize(transform.q)});
  Vec3f lower, upper;
  placedBox(query, lower, upper);
  std::vector<ShapeId> out;
  detail::PlacedShape other;
  for (const detail::Shape& s : w.shapes) {
    if (!s.alive || s.sensor || !shouldCollide(filter, s.filter)) {
      continue;
    }
    other.place(s.geometry, w.bodies[s.body].transform);
    Vec3f otherLower, otherUpper;
    placedBox(other, otherLower, otherUpper);
    const bool boxes = lower.x <= otherUpper.x && otherLower.x <= upper.x && lower.y <= otherUpper.y &&
                       otherLower.y <= upper.y && lower.z <= otherUpper.z && otherLower.z <= upper.z;
    if (boxes && detail::surfaceDistance(query, other) < 0.0f) {
      out.push_back(s.id);
    }
  }
  return out;
}

} // namespace impetus::rigid3d
