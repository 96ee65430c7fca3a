// Continuous collision: a body that moves more in a step than half its thinnest extent is swept
// from its pose at the step's start to its pose at the end against the static shapes (a bullet
// also against the other dynamic bodies where they end the step), and stopped at its first time
// of impact, so it cannot pass through a wall thinner than its step (Box2D v3's way: the contact
// that begins there next step stops it).
#include "rigid3d/placed_shape.hpp"
#include "rigid3d/world_impl.hpp"

#include <impetus/rigid3d/constants.hpp>
#include <impetus/rigid3d/distance.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

namespace impetus::rigid3d::detail {

namespace {

/// The most conservative-advancement iterations a time of impact takes: each advances by the
/// distance over the motion's bound, and a convex pair closes within a few; a grazing pass
/// that takes more is let go at the step's end.
constexpr int maxAdvancementIterations = 30;

/// A body swept through its step: its centre of mass from c0 to c1, its rotation from q0 to q1
/// at a uniform rate (slerp).
struct Sweep {
  Vec3f localCenter;
  Vec3f c0, c1;
  Quatf q0, q1;
  /// How far any point of the body's shapes may move over the whole sweep, m: |c1 - c0| plus
  /// the angle turned times the farthest reach from the centre of mass.
  float bound = 0.0f;

  [[nodiscard]] Transform3f at(float t) const {
    const Quatf q = slerp(q0, q1, t);
    const Vec3f c = c0 + (c1 - c0) * t;
    return {c - rotate(q, localCenter), q};
  }
};

/// The first time in [0, 1] at which a shape carried by `sweep` comes within `target` of a
/// fixed shape (conservative advancement: each step advances by the distance over the sweep's
/// bound, so it never passes the contact), or 1 when it does not. A shape that starts closer
/// than `target` (its contact this step did not hold it: a tumbling rod stopped at one end
/// turns on through the wall) is stopped at half its starting distance; one that starts
/// overlapping is left to its contact.
float timeOfImpact(const ShapeGeometry& moving, const Sweep& sweep, const PlacedShape& fixed, float target,
                   PlacedShape& scratch) {
  if (!(sweep.bound > 0.0f)) {
    return 1.0f;
  }
  float t = 0.0f;
  float tolerance = 0.25f * linearSlop;
  for (int iteration = 0; iteration < maxAdvancementIterations; ++iteration) {
    scratch.place(moving, sweep.at(t));
    const float d = surfaceDistance(scratch, fixed);
    if (iteration == 0) {
      if (!(d > 0.0f)) {
        return 1.0f;
      }
      if (d <= target + tolerance) {
        target = 0.5f * d;
        tolerance = 0.5f * target;
      }
    }
    if (d <= target + tolerance) {
      return t;
    }
    t += (d - target) / sweep.bound;
    if (t >= 1.0f) {
      return 1.0f;
    }
  }
  return t;
}

bool boxesOverlap(const Vec3f& lowerA, const Vec3f& upperA, const Vec3f& lowerB, const Vec3f& upperB) {
  return lowerA.x <= upperB.x && lowerB.x <= upperA.x && lowerA.y <= upperB.y && lowerB.y <= upperA.y &&
         lowerA.z <= upperB.z && lowerB.z <= upperA.z;
}

} // namespace

void updateExtents(const WorldState& w, Body& b) {
  b.reach = 0.0f;
  b.thinnest = b.shapes.empty() ? 0.0f : 3.4e38f;
  for (const std::uint32_t slot : b.shapes) {
    std::visit(
        [&](const auto& g) {
          using G = std::decay_t<decltype(g)>;
          if constexpr (std::is_same_v<G, Sphere>) {
            b.reach = std::max(b.reach, length(g.center - b.localCenter) + g.radius);
            b.thinnest = std::min(b.thinnest, g.radius);
          } else if constexpr (std::is_same_v<G, Capsule>) {
            b.reach = std::max(b.reach, std::max(length(g.center1 - b.localCenter), length(g.center2 - b.localCenter)) +
                                            g.radius);
            b.thinnest = std::min(b.thinnest, g.radius);
          } else {
            Vec3f centroid;
            for (const Vec3f& p : g.points) {
              b.reach = std::max(b.reach, length(p - b.localCenter));
              centroid += p;
            }
            centroid = centroid * (1.0f / static_cast<float>(g.points.size()));
            for (const HullPlane& plane : g.planes) {
              b.thinnest = std::min(b.thinnest, plane.offset - dot(plane.normal, centroid));
            }
          }
        },
        w.shapes[slot].geometry);
  }
}

void sweepFastBodies(WorldState& w) {
  PlacedShape scratch;
  PlacedShape fixed;
  for (std::size_t i = 0; i < w.awakeBodies.size(); ++i) {
    Body& b = w.bodies[w.awakeBodies[i]];
    const BodyState& s = w.states[i];
    if (b.type != BodyType::dynamicBody || b.shapes.empty()) {
      continue;
    }
    const float moved = length(s.dp);
    // A body moving less than half its thinnest extent in a step meets anything in its way
    // within the speculative contacts; faster, it could pass a thin wall between two steps.
    if (!b.isBullet && moved < 0.5f * b.thinnest) {
      continue;
    }
    Sweep sweep;
    sweep.localCenter = b.localCenter;
    sweep.c0 = b.center;
    sweep.c1 = b.center + s.dp;
    sweep.q0 = b.transform.q;
    sweep.q1 = normalize(s.dq * b.transform.q);
    sweep.bound = moved + angle(s.dq) * b.reach;
    const Vec3f grow{b.reach, b.reach, b.reach};
    const Vec3f lower = min(sweep.c0, sweep.c1) - grow;
    const Vec3f upper = max(sweep.c0, sweep.c1) + grow;
    float first = 1.0f;
    for (const Shape& other : w.shapes) {
      if (!other.alive || other.sensor || other.body == b.id.index) {
        continue;
      }
      const Body& ob = w.bodies[other.body];
      // Static shapes for every fast body; a bullet also meets the dynamic bodies (not other
      // bullets) where they end the step.
      const bool target = ob.type == BodyType::staticBody ||
                          (b.isBullet && ob.type == BodyType::dynamicBody && !ob.isBullet && ob.moving());
      if (!target || !std::any_of(b.shapes.begin(), b.shapes.end(), [&](std::uint32_t slot) {
            return shouldCollide(w.shapes[slot].filter, other.filter);
          })) {
        continue;
      }
      const Transform3f xf =
          ob.type == BodyType::staticBody
              ? ob.transform
              : Transform3f{ob.center + w.states[ob.solverIndex].dp -
                                rotate(normalize(w.states[ob.solverIndex].dq * ob.transform.q), ob.localCenter),
                            normalize(w.states[ob.solverIndex].dq * ob.transform.q)};
      fixed.place(other.geometry, xf);
      Vec3f otherLower = fixed.points[0];
      Vec3f otherUpper = fixed.points[0];
      for (int k = 1; k < fixed.count; ++k) {
        otherLower = min(otherLower, fixed.points[static_cast<std::size_t>(k)]);
        otherUpper = max(otherUpper, fixed.points[static_cast<std::size_t>(k)]);
      }
      const Vec3f r{fixed.radius, fixed.radius, fixed.radius};
      if (!boxesOverlap(lower, upper, otherLower - r, otherUpper + r)) {
        continue;
      }
      for (const std::uint32_t slot : b.shapes) {
        if (!w.shapes[slot].sensor && shouldCollide(w.shapes[slot].filter, other.filter)) {
          first = std::min(first, timeOfImpact(w.shapes[slot].geometry, sweep, fixed, linearSlop, scratch));
        }
      }
    }
    if (first < 1.0f) {
      // Stopped at the first impact, its velocity kept: the contact that begins there next step
      // meets it.
      BodyState& moving = w.states[i];
      const Transform3f at = sweep.at(first);
      moving.dp = sweep.c0 + (sweep.c1 - sweep.c0) * first - b.center;
      moving.dq = normalize(at.q * conjugate(b.transform.q));
    }
  }
}

} // namespace impetus::rigid3d::detail
