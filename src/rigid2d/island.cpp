// Islands and sleeping.
#include "rigid2d/joints.hpp"
#include "rigid2d/world_impl.hpp"

#include <algorithm>
#include <limits>

namespace impetus::rigid2d::detail {
/// A sleeping body touched by a moving one, or joined to one, wakes up (before the solve, so it
/// takes part).
void wakeTouched(WorldState& w, bool sleeperTouched) {
  // A wake spreads through a sleeping stack or ragdoll one contact or joint at a time: repeat
  // until nothing new wakes (almost always one pass, which finds nothing to do).
  const auto wakeOther = [](Body& a, Body& b) {
    if (a.moving() && b.alive && b.type != BodyType::staticBody && !b.awake) {
      b.wake();
      return true;
    }
    if (b.moving() && a.alive && a.type != BodyType::staticBody && !a.awake) {
      a.wake();
      return true;
    }
    return false;
  };
  bool changed = true;
  if (!sleeperTouched) {
    // No touching contact joins a moving body to a sleeping one: only a joint can start a wake.
    changed = false;
    for (const Joint& joint : w.joints) {
      if (joint.alive) {
        changed = wakeOther(w.bodies[joint.bodyA], w.bodies[joint.bodyB]) || changed;
      }
    }
  }
  while (changed) {
    changed = false;
    for (const Joint& joint : w.joints) {
      if (joint.alive) {
        changed = wakeOther(w.bodies[joint.bodyA], w.bodies[joint.bodyB]) || changed;
      }
    }
    for (const Contact& contact : w.contacts) {
      if (contact.alive && !contact.sensor && contact.manifold.pointCount > 0) {
        changed = wakeOther(w.bodies[contact.bodyA], w.bodies[contact.bodyB]) || changed;
      }
    }
  }
}

/// Accumulates rest time and puts islands to sleep whose every body has rested long enough.
/// Islands are the connected sets of moving bodies joined by touching contacts and joints (static
/// bodies do not join islands), found by union-find each step.
void updateSleep(WorldState& w, float dt) {
  const WorldDef& d = w.def;
  for (Body& b : w.bodies) {
    if (!b.moving()) {
      continue;
    }
    const bool slow = lengthSquared(b.linearVelocity) <= d.sleepLinearTolerance * d.sleepLinearTolerance &&
                      std::abs(b.angularVelocity) <= d.sleepAngularTolerance && b.stepSpeed <= d.sleepLinearTolerance &&
                      b.stepSpin <= d.sleepAngularTolerance;
    b.sleepTime = (b.enableSleep && slow) ? b.sleepTime + dt : 0.0f;
  }
  std::vector<std::uint32_t>& parent = w.islandParent;
  parent.resize(w.bodies.size());
  for (std::uint32_t i = 0; i < parent.size(); ++i) {
    parent[i] = i;
  }
  for (const Contact& contact : w.contacts) {
    if (!contact.alive || contact.sensor || contact.manifold.pointCount == 0 || !w.bodies[contact.bodyA].moving() ||
        !w.bodies[contact.bodyB].moving()) {
      continue;
    }
    const std::uint32_t ra = findRoot(parent, contact.bodyA);
    const std::uint32_t rb = findRoot(parent, contact.bodyB);
    if (ra != rb) {
      parent[std::max(ra, rb)] = std::min(ra, rb); // deterministic: the lower slot is the root
    }
  }
  for (const Joint& joint : w.joints) {
    if (!joint.alive || !w.bodies[joint.bodyA].moving() || !w.bodies[joint.bodyB].moving()) {
      continue;
    }
    const std::uint32_t ra = findRoot(parent, joint.bodyA);
    const std::uint32_t rb = findRoot(parent, joint.bodyB);
    if (ra != rb) {
      parent[std::max(ra, rb)] = std::min(ra, rb);
    }
  }
  // The least rest time of each island, at its root.
  std::vector<float>& islandRest = w.islandRest;
  islandRest.assign(w.bodies.size(), std::numeric_limits<float>::max());
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
