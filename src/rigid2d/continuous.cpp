// Continuous collision: fast bodies against static shapes (a swept core circle), and bullets
// against everything (time of impact on GJK).
#include "rigid2d/world_impl.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impetus::rigid2d::detail {
namespace {

/// Whether a moving body may collide with a shape at all: some shape of the body passes the
/// shape's filter, and no joint between them turns their collision off.
bool mayCollide(const WorldState& w, const Body& b, const Shape& other) {
  if (other.sensor || w.jointBlocksCollision(b.id.index, other.body)) {
    return false;
  }
  return std::any_of(b.shapes.begin(), b.shapes.end(), [&](std::uint32_t slot) {
    const Shape& mine = w.shapes[slot];
    return !mine.sensor && shouldCollide(mine.filter, other.filter);
  });
}

/// A one-sided chain segment stops only what comes from its free side: whether the motion
/// starting at `start` (world) begins behind it.
bool behindChain(const Shape& s, const Transform2f& xf, const Vec2f& start) {
  const auto* chain = std::get_if<ChainSegment>(&s.geometry);
  if (chain == nullptr) {
    return false;
  }
  const Vec2f local = inverseTransformPoint(xf, start);
  const Vec2f edge = chain->segment.point2 - chain->segment.point1;
  const Vec2f freeSide{edge.y, -edge.x}; // rightPerp: the free side (chain.hpp)
  return dot(freeSide, local - chain->segment.point1) < 0.0f;
}

/// Where a point lies against a shape inflated by `skin` (shape frame): its signed distance to
/// the surface (negative inside) and the outward normal of the nearest surface.
struct PointDepth {
  float separation = 0.0f;
  Vec2f normal;
};

PointDepth segmentDepth(const Vec2f& p, const Vec2f& a, const Vec2f& b, float radius) {
  const Vec2f e = b - a;
  const float ee = lengthSquared(e);
  const float t = ee > 0.0f ? std::clamp(dot(p - a, e) / ee, 0.0f, 1.0f) : 0.0f;
  const Vec2f offset = p - (a + e * t);
  const float d = length(offset);
  // On the core itself the normal is undefined: take the segment's left normal (either would do).
  const Vec2f normal = d > 0.0f ? offset * (1.0f / d) : (ee > 0.0f ? normalize(Vec2f{-e.y, e.x}) : Vec2f{0.0f, 1.0f});
  return {d - radius, normal};
}

PointDepth pointDepth(const ShapeGeometry& geometry, const Vec2f& p, float skin) {
  return std::visit(
      [&](const auto& g) -> PointDepth {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, Circle>) {
          return segmentDepth(p, g.center, g.center, g.radius + skin);
        } else if constexpr (std::is_same_v<G, Capsule>) {
          return segmentDepth(p, g.center1, g.center2, g.radius + skin);
        } else if constexpr (std::is_same_v<G, Segment>) {
          return segmentDepth(p, g.point1, g.point2, skin);
        } else if constexpr (std::is_same_v<G, ChainSegment>) {
          return segmentDepth(p, g.segment.point1, g.segment.point2, skin);
        } else {
          // A polygon: the face the point is least deep behind (exact inside; outside, the
          // separating face, enough to tell inside from out).
          PointDepth best{-std::numeric_limits<float>::max(), {}};
          for (int i = 0; i < g.count; ++i) {
            const auto k = static_cast<std::size_t>(i);
            const float sep = dot(g.normals[k], p - g.vertices[k]);
            if (sep > best.separation) {
              best = {sep, g.normals[k]};
            }
          }
          best.separation -= g.radius + skin;
          return best;
        }
      },
      geometry);
}

} // namespace

/// The radius of the largest circle around the centre of mass inside all of the body's shapes
/// that contain it (its core): a swept circle of this radius cannot pass through anything the
/// body would collide with.
float computeCoreRadius(const WorldState& w, const Body& b) {
  float core = std::numeric_limits<float>::max();
  for (std::uint32_t slot : b.shapes) {
    const Shape& s = w.shapes[slot];
    if (s.sensor) {
      continue;
    }
    const float r = std::visit(
        [&](const auto& g) -> float {
          using G = std::decay_t<decltype(g)>;
          if constexpr (std::is_same_v<G, Circle>) {
            return g.radius - distance(g.center, b.localCenter);
          } else if constexpr (std::is_same_v<G, Capsule>) {
            return g.radius;
          } else if constexpr (std::is_same_v<G, Polygon>) {
            float inner = std::numeric_limits<float>::max();
            for (int i = 0; i < g.count; ++i) {
              const auto k = static_cast<std::size_t>(i);
              inner = std::min(inner, dot(g.normals[k], g.vertices[k] - b.localCenter));
            }
            return inner + g.radius;
          } else {
            return 0.0f;
          }
        },
        s.geometry);
    core = std::min(core, r);
  }
  return core == std::numeric_limits<float>::max() ? 0.0f : std::max(core, 0.0f);
}

/// Continuous collision against static shapes: a body that moved more than half its core radius
/// this step could have passed through a thin static shape, or been driven deep into a thick
/// one (a light 8 m plank struck by an 80 kg body at 162 m/s moves 1.5 m a step, less than its
/// 1.9 m core, and without the sweep goes 0.8 m into the floor and on out of its underside). A
/// circle of a quarter of its core radius about its centre is swept from `start` to `end` (a
/// ray against each static shape inflated by that much) and stopped just before the first hit;
/// the speculative contact takes over next step. Returns the allowed end.
///
/// A quarter, not the whole core (as Box2D v3's fallback sweep): a body touching a wall has its
/// centre a core radius from it, so a whole-core sweep hits at once whenever the body drifts
/// toward the wall, and a ball sliding down a wall at speed stays pinned where it is while
/// gravity winds its velocity up without end. A quarter of the core
/// still keeps the centre on its side of the thinnest wall; the contacts do the rest.
Vec2f sweepAgainstStatic(const WorldState& w, const Body& b, const Vec2f& start, const Vec2f& end) {
  const float core = b.coreRadius;
  if (core <= 0.0f || lengthSquared(end - start) <= 0.25f * core * core) {
    return end; // slow: the discrete contacts see everything it can meet
  }
  const float skin = 0.25f * core;
  const AABB swept = enlarge({min(start, end), max(start, end)}, skin);
  // A centre already inside a static shape's skin (a body pushed into a wall by a joint or by
  // a blow, or a long body turning into the floor) is out of the rays' reach: a ray from inside
  // sees no surface, and the centre would go on through the wall. It may move along the
  // surface it is nearest to or out, not deeper: the
  // motion loses its component into that surface, and the contacts push it out.
  Vec2f motion = end - start;
  w.staticTree.query(swept, [&](std::int32_t, std::uint64_t slot64) {
    const Shape& s = w.shapes[static_cast<std::size_t>(slot64)];
    const Body& other = w.bodies[s.body];
    if (other.type != BodyType::staticBody || !mayCollide(w, b, s) || behindChain(s, other.transform, start)) {
      return true;
    }
    const PointDepth depth = pointDepth(s.geometry, inverseTransformPoint(other.transform, start), skin);
    if (depth.separation < 0.0f) {
      const Vec2f normal = rotate(other.transform.q, depth.normal);
      motion -= normal * std::min(dot(motion, normal), 0.0f);
    }
    return true;
  });
  float first = 1.0f;
  w.staticTree.query(swept, [&](std::int32_t, std::uint64_t slot64) {
    const Shape& s = w.shapes[static_cast<std::size_t>(slot64)];
    const Body& other = w.bodies[s.body];
    if (other.type != BodyType::staticBody || !mayCollide(w, b, s) || behindChain(s, other.transform, start)) {
      return true;
    }
    const Transform2f& xf = other.transform;
    const RayCastInput ray{inverseTransformPoint(xf, start), inverseRotate(xf.q, motion), first};
    const CastOutput out = std::visit(
        [&](const auto& g) {
          using G = std::decay_t<decltype(g)>;
          if constexpr (std::is_same_v<G, Circle>) {
            return rayCast(Circle{g.center, g.radius + skin}, ray);
          } else if constexpr (std::is_same_v<G, Capsule>) {
            return rayCast(Capsule{g.center1, g.center2, g.radius + skin}, ray);
          } else if constexpr (std::is_same_v<G, Segment>) {
            return rayCast(Capsule{g.point1, g.point2, skin}, ray);
          } else if constexpr (std::is_same_v<G, ChainSegment>) {
            return rayCast(Capsule{g.segment.point1, g.segment.point2, skin}, ray);
          } else {
            Polygon inflated = g;
            inflated.radius += skin;
            return rayCast(inflated, ray);
          }
        },
        s.geometry);
    if (out.hit && out.fraction < first) {
      first = out.fraction;
    }
    return true;
  });
  if (first >= 1.0f) {
    return start + motion;
  }
  // Stop a linear slop short of the surface, along the motion.
  const float travelled = std::max(0.0f, first * length(motion) - linearSlop);
  return start + normalize(motion) * travelled;
}

bool sweepBullet(WorldState& w, Body& b, const Vec2f& startCenter, const Rot2f& startRotation) {
  const float core = b.coreRadius;
  const Vec2f motion = b.center - startCenter;
  if (core <= 0.0f || lengthSquared(motion) <= core * core) {
    return false; // slow this step: the discrete contacts see everything it can meet
  }
  const Sweep bulletSweep{b.localCenter, startCenter, b.center, startRotation, b.transform.q};
  const Transform2f startTransform{startCenter - rotate(startRotation, b.localCenter), startRotation};
  float first = 1.0f;
  for (std::uint32_t slot : b.shapes) {
    const Shape& bulletShape = w.shapes[slot];
    if (bulletShape.sensor) {
      continue;
    }
    const ShapeProxy bulletProxy = shapeProxy(bulletShape);
    const AABB swept = merge(shapeBox(bulletShape, startTransform), shapeBox(bulletShape, b.transform));
    const auto visit = [&](std::int32_t, std::uint64_t other64) {
      const Shape& other = w.shapes[static_cast<std::size_t>(other64)];
      const Body& otherBody = w.bodies[other.body];
      if (other.body == bulletShape.body || other.sensor || otherBody.bullet ||
          !shouldCollide(bulletShape.filter, other.filter) || w.jointBlocksCollision(bulletShape.body, other.body) ||
          behindChain(other, otherBody.transform, startCenter)) {
        return true; // bullets do not sweep against each other (as Box2D)
      }
      // The other body stands at its end-of-step place.
      const Sweep still{otherBody.localCenter, otherBody.center, otherBody.center, otherBody.transform.q,
                        otherBody.transform.q};
      const ShapeProxy otherProxy = shapeProxy(other);
      TOIOutput toi = timeOfImpact(otherProxy, still, bulletProxy, bulletSweep, first);
      if (toi.state == TOIOutput::State::hit && toi.fraction <= 0.0f) {
        // Touching already at the start (resting on, sliding along, or just bounced off it):
        // the contacts hold that. Only the centre's small circle could still tunnel through
        // (as Box2D v3's fallback). Stopping at time 0 instead would pin the bullet where it is
        // while its velocity grows without end.
        const ShapeProxy centre{{b.localCenter}, 1, 0.25f * core};
        toi = timeOfImpact(otherProxy, still, centre, bulletSweep, first);
      }
      if (toi.state == TOIOutput::State::hit && toi.fraction > 0.0f && toi.fraction < first) {
        first = toi.fraction;
      }
      return true;
    };
    w.staticTree.query(swept, visit);
    w.movingTree.query(swept, visit);
  }
  if (first >= 1.0f) {
    return false;
  }
  const Transform2f xf = sweepTransform(bulletSweep, first);
  b.transform = xf;
  b.center = transformPoint(xf, b.localCenter);
  return true;
}

} // namespace impetus::rigid2d::detail
