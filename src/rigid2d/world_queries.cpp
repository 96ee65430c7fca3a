// Ray casts and overlap queries against the world's shapes.
#include "rigid2d/world_impl.hpp"

#include <impetus/core/state_hash.hpp>
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>

#include <algorithm>
#include <string>

namespace impetus::rigid2d {

using detail::Shape;
using detail::shapeBox;

std::optional<RayHit> World::castRayClosest(const Vec2f& origin, const Vec2f& translation) const {
  requireFinite(origin, "origin");
  requireFinite(translation, "translation");
  const Impl& w = *impl_;
  std::optional<RayHit> best;
  const auto visit = [&](std::int32_t, std::uint64_t slot64, const Vec2f&, const Vec2f&) {
    const Shape& s = w.shapes[static_cast<std::size_t>(slot64)];
    const float maxFraction = best ? best->fraction : 1.0f;
    if (s.sensor) {
      return maxFraction;
    }
    const Transform2f& xf = w.bodies[s.body].transform;
    const RayCastInput local{inverseTransformPoint(xf, origin), inverseRotate(xf.q, translation), maxFraction};
    const CastOutput out = std::visit([&](const auto& g) { return rayCast(g, local); }, s.geometry);
    if (!out.hit) {
      return maxFraction;
    }
    best = RayHit{s.id, transformPoint(xf, out.point), rotate(xf.q, out.normal), out.fraction};
    return out.fraction;
  };
  w.staticTree.rayCast(origin, origin + translation, visit);
  w.movingTree.rayCast(origin, origin + translation, visit);
  return best;
}

std::vector<RayHit> World::castRayAll(const Vec2f& origin, const Vec2f& translation) const {
  requireFinite(origin, "origin");
  requireFinite(translation, "translation");
  const Impl& w = *impl_;
  std::vector<RayHit> hits;
  const auto visit = [&](std::int32_t, std::uint64_t slot64, const Vec2f&, const Vec2f&) {
    const Shape& s = w.shapes[static_cast<std::size_t>(slot64)];
    if (s.sensor) {
      return 1.0f;
    }
    const Transform2f& xf = w.bodies[s.body].transform;
    const RayCastInput local{inverseTransformPoint(xf, origin), inverseRotate(xf.q, translation), 1.0f};
    const CastOutput out = std::visit([&](const auto& g) { return rayCast(g, local); }, s.geometry);
    if (out.hit) {
      hits.push_back({s.id, transformPoint(xf, out.point), rotate(xf.q, out.normal), out.fraction});
    }
    return 1.0f; // keep going: every hit
  };
  w.staticTree.rayCast(origin, origin + translation, visit);
  w.movingTree.rayCast(origin, origin + translation, visit);
  std::sort(hits.begin(), hits.end(), [](const RayHit& a, const RayHit& b) {
    return a.fraction != b.fraction ? a.fraction < b.fraction : a.shape.index < b.shape.index;
  });
  return hits;
}

std::vector<ShapeId> World::queryAABB(const AABB& box) const {
  requireValid(box, "box");
  const Impl& w = *impl_;
  std::vector<ShapeId> found;
  const auto visit = [&](std::int32_t, std::uint64_t slot64) {
    const Shape& s = w.shapes[static_cast<std::size_t>(slot64)];
    if (overlaps(shapeBox(s, w.bodies[s.body].transform), box)) {
      found.push_back(s.id);
    }
    return true;
  };
  w.staticTree.query(box, visit);
  w.movingTree.query(box, visit);
  std::sort(found.begin(), found.end(), [](ShapeId a, ShapeId b) { return a.index < b.index; });
  return found;
}

std::vector<ShapeId> World::queryPoint(const Vec2f& point) const {
  requireFinite(point, "point");
  const Impl& w = *impl_;
  std::vector<ShapeId> found;
  const auto visit = [&](std::int32_t, std::uint64_t slot64) {
    const Shape& s = w.shapes[static_cast<std::size_t>(slot64)];
    const Vec2f local = inverseTransformPoint(w.bodies[s.body].transform, point);
    const bool inside = std::visit(
        [&](const auto& g) {
          using G = std::decay_t<decltype(g)>;
          if constexpr (std::is_same_v<G, Segment> || std::is_same_v<G, ChainSegment>) {
            return false;
          } else {
            return containsPoint(g, local);
          }
        },
        s.geometry);
    if (inside) {
      found.push_back(s.id);
    }
    return true;
  };
  w.staticTree.query(AABB{point, point}, visit);
  w.movingTree.query(AABB{point, point}, visit);
  std::sort(found.begin(), found.end(), [](ShapeId a, ShapeId b) { return a.index < b.index; });
  return found;
}

std::optional<RayHit> World::castShape(const ShapeProxy& proxy, const Transform2f& transform,
                                       const Vec2f& translation) const {
  if (proxy.count < 1 || proxy.count > maxPolygonVertices) {
    throwInvalid("proxy.count", proxy.count, "must be 1 to 8 points");
  }
  // Checked here, under the caller's names: the swept box below is built before shapeCast
  // would check them (as "xfB"), and a NaN point or radius would give a NaN box.
  for (std::size_t i = 0; i < static_cast<std::size_t>(proxy.count); ++i) {
    requireFinite(proxy.points[i], "proxy.points[" + std::to_string(i) + "]");
  }
  requireNonNegative(proxy.radius, "proxy.radius");
  requireFinite(transform.p, "transform.p");
  requireFinite(transform.q.c, "transform.q.c");
  requireFinite(transform.q.s, "transform.q.s");
  requireFinite(translation, "translation");
  const Impl& w = *impl_;
  // The box the proxy sweeps through.
  AABB start{transformPoint(transform, proxy.points[0]), transformPoint(transform, proxy.points[0])};
  for (int i = 1; i < proxy.count; ++i) {
    const Vec2f p = transformPoint(transform, proxy.points[static_cast<std::size_t>(i)]);
    start = {min(start.lower, p), max(start.upper, p)};
  }
  start = enlarge(start, proxy.radius);
  const AABB swept = merge(start, AABB{start.lower + translation, start.upper + translation});
  std::optional<RayHit> best;
  const auto visit = [&](std::int32_t, std::uint64_t slot64) {
    const Shape& s = w.shapes[static_cast<std::size_t>(slot64)];
    if (s.sensor) {
      return true;
    }
    const float maxFraction = best ? best->fraction : 1.0f;
    const ShapeCastInput input{
        detail::shapeProxy(s), w.bodies[s.body].transform, proxy, transform, translation, maxFraction};
    const CastOutput out = shapeCast(input);
    if (out.hit && (!best || out.fraction < best->fraction ||
                    (out.fraction == best->fraction && s.id.index < best->shape.index))) {
      best = RayHit{s.id, out.point, out.normal, out.fraction};
    }
    return true;
  };
  w.staticTree.query(swept, visit);
  w.movingTree.query(swept, visit);
  return best;
}

std::uint64_t World::stateHash() const {
  StateHash hash;
  for (const detail::Body& b : impl_->bodies) {
    if (!b.alive) {
      continue;
    }
    hash.add(b.transform.p.x);
    hash.add(b.transform.p.y);
    hash.add(b.transform.q.c);
    hash.add(b.transform.q.s);
    hash.add(b.linearVelocity.x);
    hash.add(b.linearVelocity.y);
    hash.add(b.angularVelocity);
    hash.add(b.awake);
  }
  return hash.value();
}

bool World::isBullet(BodyId id) const { return impl_->body(id).bullet; }
bool World::isSleepEnabled(BodyId id) const { return impl_->body(id).enableSleep; }
bool World::isValid(ShapeId id) const noexcept { return impl_->shapeIds.isValidId(id); }

void World::contacts(std::vector<ContactData>& out) const {
  out.clear();
  for (const detail::Contact& c : impl_->contacts) {
    if (c.alive && !c.sensor && c.manifold.pointCount > 0) {
      out.push_back({impl_->shapes[c.shapeA].id, impl_->shapes[c.shapeB].id, c.manifold});
    }
  }
}

void World::bodyIds(std::vector<BodyId>& out) const {
  out.clear();
  for (const detail::Body& b : impl_->bodies) {
    if (b.alive) {
      out.push_back(b.id);
    }
  }
}

void World::bodyShapes(BodyId body, std::vector<ShapeId>& out) const {
  const detail::Body& b = impl_->body(body);
  out.clear();
  for (std::uint32_t slot : b.shapes) {
    out.push_back(impl_->shapes[slot].id);
  }
}

BodyType World::bodyType(BodyId id) const { return impl_->body(id).type; }

ShapeGeometry World::shapeGeometry(ShapeId shape) const { return impl_->shape(shape).geometry; }
float World::shapeDensity(ShapeId shape) const { return impl_->shape(shape).density; }
float World::shapeFriction(ShapeId shape) const { return impl_->shape(shape).friction; }
bool World::isSensor(ShapeId shape) const { return impl_->shape(shape).sensor; }

BodyId World::shapeBody(ShapeId shape) const { return impl_->bodies[impl_->shape(shape).body].id; }

} // namespace impetus::rigid2d
