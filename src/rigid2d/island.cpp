// Islands and sleeping.
#include "rigid2d/world_impl.hpp"

#include <algorithm>
#include <limits>

namespace impetus::rigid2d::detail {
namespace {

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]]; // path halving
    i = parent[i];
  }
  return i;
}

} // namespace

/// A sleeping body touched by a moving one wakes up (before the solve, so it takes part).
void wakeTouched(WorldState& w) {
  for (const auto& [key, contact] : w.contacts) {
    const Shape& sa = w.shapes[contact.shapeA];
    const Shape& sb = w.shapes[contact.shapeB];
    if (contact.manifold.pointCount == 0 || sa.sensor || sb.sensor) {
      continue;
    }
    Body& a = w.bodies[sa.body];
    Body& b = w.bodies[sb.body];
    if (a.moving() && b.alive && b.type != BodyType::staticBody && !b.awake) {
      b.wake();
    } else if (b.moving() && a.alive && a.type != BodyType::staticBody && !a.awake) {
      a.wake();
    }
  }
}

/// Accumulates rest time and puts islands to sleep whose every body has rested long enough.
/// Islands are the connected sets of moving bodies joined by touching contacts (static bodies
/// do not join islands), found by union-find each step.
void updateSleep(WorldState& w, float dt) {
  const WorldDef& d = w.def;
  for (Body& b : w.bodies) {
    if (!b.moving()) {
      continue;
    }
    const bool slow = lengthSquared(b.linearVelocity) <= d.sleepLinearTolerance * d.sleepLinearTolerance &&
                      std::abs(b.angularVelocity) <= d.sleepAngularTolerance;
    b.sleepTime = (b.enableSleep && slow) ? b.sleepTime + dt : 0.0f;
  }
  std::vector<std::uint32_t> parent(w.bodies.size());
  for (std::uint32_t i = 0; i < parent.size(); ++i) {
    parent[i] = i;
  }
  for (const auto& [key, contact] : w.contacts) {
    const Shape& sa = w.shapes[contact.shapeA];
    const Shape& sb = w.shapes[contact.shapeB];
    if (contact.manifold.pointCount == 0 || sa.sensor || sb.sensor || !w.bodies[sa.body].moving() ||
        !w.bodies[sb.body].moving()) {
      continue;
    }
    const std::uint32_t ra = findRoot(parent, sa.body);
    const std::uint32_t rb = findRoot(parent, sb.body);
    if (ra != rb) {
      parent[std::max(ra, rb)] = std::min(ra, rb); // deterministic: the lower slot is the root
    }
  }
  // The least rest time of each island, at its root.
  std::vector<float> islandRest(w.bodies.size(), std::numeric_limits<float>::max());
  for (const Body& b : w.bodies) {
    if (b.moving()) {
      float& rest = islandRest[findRoot(parent, b.id.index)];
      rest = std::min(rest, b.sleepTime);
    }
  }
  for (Body& b : w.bodies) {
    if (b.moving() && islandRest[findRoot(parent, b.id.index)] >= d.timeToSleep) {
      b.awake = false;
      b.linearVelocity = {};
      b.angularVelocity = 0.0f;
    }
  }
}

} // namespace impetus::rigid2d::detail
