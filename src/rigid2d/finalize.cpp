// The step's end for the bodies (its finalize): each moving body takes its velocities and pose
// from the solver's state, its centre swept against static shapes, and its shapes' fat boxes
// grown where they left them, on threads; then, in body order, the grown boxes go into the
// broadphase trees and the move buffer, and bullets sweep last against where everything else
// ended up.
#include "rigid2d/world_impl.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/constants.hpp>

#include <cmath>
#include <cstddef>

namespace impetus::rigid2d::detail {

namespace {

/// Gives the shape a new fat box if its box (a moving shape's reach) left the old one; true if
/// so. Writes only the shape's own fat box, so bodies run on threads.
bool growFatBox(WorldState& w, const Shape& s, std::uint32_t slot, const Body& b) {
  const bool isStatic = b.type == BodyType::staticBody;
  const AABB box = isStatic ? shapeBox(s, b.transform) : reachBox(s, b.transform);
  if (AABB& fatBox = w.fatBoxes[slot]; !contains(fatBox, box)) {
    fatBox = enlarge(box, isStatic ? 0.0f : s.margin);
    return true;
  }
  return false;
}

/// Grows each of the body's shapes' fat boxes that its box left and marks the shape; true if any
/// grew.
bool growFatBoxes(WorldState& w, const Body& b) {
  bool grew = false;
  for (const std::uint32_t slot : b.shapes) {
    Shape& s = w.shapes[slot];
    if (growFatBox(w, s, slot, b)) {
      s.fatBoxGrown = true;
      grew = true;
    }
  }
  return grew;
}

/// growFatBoxes for a moving body with one shape in the moving tree (most bodies): notes the
/// proxy in `grown` instead of marking the shape, so that the serial pass touches neither.
bool growOnlyFatBox(WorldState& w, const Body& b, GrownProxy& grown) {
  const std::uint32_t slot = b.shapes.front();
  const Shape& s = w.shapes[slot];
  if (growFatBox(w, s, slot, b)) {
    grown = {slot, s.proxy};
    return true;
  }
  return false;
}

/// The body's grown fat boxes into their trees and the move buffer: serial, in body order (the
/// trees and the buffer are shared, and the pair update depends on the buffer's order).
void moveGrownProxies(WorldState& w, const Body& b) {
  for (const std::uint32_t slot : b.shapes) {
    Shape& s = w.shapes[slot];
    if (!s.fatBoxGrown) {
      continue;
    }
    s.fatBoxGrown = false;
    // The moving tree is grown in place and rebuilt before the next pair update.
    if (s.inStaticTree) {
      w.staticTree.moveProxy(s.proxy, w.fatBoxes[slot]);
    } else {
      w.movingTree.enlargeProxy(s.proxy, w.fatBoxes[slot]);
    }
    w.moveBuffer.push_back(slot);
  }
}

/// The step's end for one moving body: velocities and pose from the solver's state, the centre
/// swept against static shapes, the measures the sleep test reads, forces cleared. Writes only
/// the body and reads the static tree (which the finalize does not change), so bodies run on
/// threads.
void finishBody(const WorldState& w, Body& b, const BodyState& s, float dt) {
  b.linearVelocity = s.v;
  b.angularVelocity = s.w;
  const Vec2f start = b.center;
  b.center += s.dp;
  if (b.type == BodyType::dynamicBody) {
    b.center = sweepAgainstStatic(w, b, start, b.center);
  }
  const Rot2f q = normalize(mul(s.dq, b.transform.q));
  b.stepSpeed = length(b.center - start) / dt;
  // The turn's sine (the angle to third order; a half turn or more when the cosine is
  // negative): enough for the sleep test, without an atan2 per body per step.
  b.stepSpin = (s.dq.c < 0.0f ? pi<float> : std::abs(s.dq.s)) / dt;
  b.transform = {b.center - rotate(q, b.localCenter), q};
  b.force = {};
  b.torque = 0.0f;
}

/// The fewest bodies the finalize finishes as one task: a body costs tens of nanoseconds (more
/// with a continuous sweep), so a smaller task costs more to hand out than it does.
constexpr std::uint32_t minFinishBodiesPerTask = 128;

/// How many bodies ahead the finalize asks the cache for a body's record; its shape list is
/// asked for two thirds as far ahead and its shapes one third (each read through the one before,
/// by then in the cache). A body's shapes are a chain of dependent loads (body, its list of
/// slots, each shape) far apart in memory: too sparse for the hardware to follow.
constexpr std::uint32_t finishPrefetchDistance = 12;

/// Asks the cache for a body's record.
[[gnu::always_inline]] inline void prefetchBody(const Body& b) {
  const auto* bytes = reinterpret_cast<const char*>(&b);
  for (std::size_t offset = 0; offset < sizeof(Body); offset += 64) {
    __builtin_prefetch(bytes + offset);
  }
}

/// Asks the cache for the lines of a body's shapes that growFatBoxes reads (a polygon's first
/// vertices and, after the geometry, its count, radius and fat-box fields), and their fat boxes.
[[gnu::always_inline]] inline void prefetchShapes(const WorldState& w, const Body& b) {
  for (const std::uint32_t slot : b.shapes) {
    const auto* bytes = reinterpret_cast<const char*>(&w.shapes[slot]);
    __builtin_prefetch(bytes);
    __builtin_prefetch(bytes + offsetof(Shape, margin));
    __builtin_prefetch(&w.fatBoxes[slot]);
  }
}

/// What the finalize's serial pass does with a body the parallel pass finished: nothing, its
/// one shape's proxy grown (GrownProxy), its shapes marked fatBoxGrown, or its bullet sweep.
enum FinishMark : std::uint8_t { finishedInPlace = 0, proxyGrew = 1, fatBoxesGrew = 2, bulletToSweep = 3 };

/// How many bodies ahead the serial pass asks the cache for a grown proxy's leaf (and half as
/// far, its parent): enlargeProxy's first reads, nodes anywhere in the tree.
constexpr std::uint32_t enlargePrefetchDistance = 16;

} // namespace

void synchronizeShapes(WorldState& w, const Body& b) {
  if (growFatBoxes(w, b)) {
    moveGrownProxies(w, b);
  }
}

void finalizeBodies(WorldState& w, float dt) {
  const auto count = static_cast<std::uint32_t>(w.awakeBodies.size());
  w.finishMarks.resize(count);
  w.grownProxies.resize(count);
  w.parallelFor(count, minFinishBodiesPerTask, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t i = begin; i < end; ++i) {
      if (i + finishPrefetchDistance < end) {
        prefetchBody(w.bodies[w.awakeBodies[i + finishPrefetchDistance]]);
      }
      if (i + 2 * finishPrefetchDistance / 3 < end) {
        __builtin_prefetch(w.bodies[w.awakeBodies[i + 2 * finishPrefetchDistance / 3]].shapes.data());
      }
      if (i + finishPrefetchDistance / 3 < end) {
        prefetchShapes(w, w.bodies[w.awakeBodies[i + finishPrefetchDistance / 3]]);
      }
      Body& b = w.bodies[w.awakeBodies[i]];
      if (b.bullet && b.type == BodyType::dynamicBody) {
        w.finishMarks[i] = bulletToSweep; // finished serially, where its start is recorded
        continue;
      }
      finishBody(w, b, w.states[i], dt);
      if (b.shapes.size() == 1 && !w.shapes[b.shapes.front()].inStaticTree) {
        w.finishMarks[i] = growOnlyFatBox(w, b, w.grownProxies[i]) ? proxyGrew : finishedInPlace;
      } else {
        w.finishMarks[i] = growFatBoxes(w, b) ? fatBoxesGrew : finishedInPlace;
      }
    }
  });
  w.bullets.clear();
  for (std::uint32_t i = 0; i < count; ++i) {
    if (const std::uint32_t ahead = i + enlargePrefetchDistance; ahead < count && w.finishMarks[ahead] == proxyGrew) {
      w.movingTree.prefetchLeaf(w.grownProxies[ahead].proxy);
      __builtin_prefetch(&w.fatBoxes[w.grownProxies[ahead].shape]);
    }
    if (const std::uint32_t ahead = i + enlargePrefetchDistance / 2;
        ahead < count && w.finishMarks[ahead] == proxyGrew) {
      w.movingTree.prefetchParent(w.grownProxies[ahead].proxy);
    }
    switch (w.finishMarks[i]) {
    case proxyGrew: {
      const GrownProxy& grown = w.grownProxies[i];
      w.movingTree.enlargeProxy(grown.proxy, w.fatBoxes[grown.shape]);
      w.moveBuffer.push_back(grown.shape);
      break;
    }
    case fatBoxesGrew:
      moveGrownProxies(w, w.bodies[w.awakeBodies[i]]);
      break;
    case bulletToSweep: {
      Body& b = w.bodies[w.awakeBodies[i]];
      w.bullets.push_back({w.awakeBodies[i], b.center, b.transform.q});
      finishBody(w, b, w.states[i], dt);
      break;
    }
    default:
      break;
    }
  }
  for (const BulletStart& bullet : w.bullets) {
    Body& b = w.bodies[bullet.body];
    sweepBullet(w, b, bullet.center, bullet.rotation);
    synchronizeShapes(w, b);
  }
}

} // namespace impetus::rigid2d::detail
