// Islands and sleeping in the 3D world: the persistent islands of the shared solver layer
// (solver::Islands: dynamic bodies joined by touching contacts), which fall asleep when all their
// bodies have been slow for timeToSleep and wake as a whole. A sleeping body leaves the awake
// set: it is neither integrated nor solved, and its contacts with other sleeping or static bodies
// are not collided again until it wakes.
#include "rigid3d/world_impl.hpp"

#include <algorithm>
#include <vector>

namespace impetus::rigid3d::detail {

namespace {

/// Whether a contact joins its bodies' islands: touching, between two dynamic bodies.
bool joins(const WorldState& w, const Contact& c) {
  return c.touching && !c.sensor && w.bodies[c.bodyA].type == BodyType::dynamicBody &&
         w.bodies[c.bodyB].type == BodyType::dynamicBody;
}

} // namespace

void sleepIsland(WorldState& w, std::uint32_t island) {
  for (const std::uint32_t slot : w.islands.bodies(island)) {
    Body& b = w.bodies[slot];
    b.awake = false;
    b.linearVelocity = {};
    b.angularVelocity = {};
    w.awakeBodySet.remove(slot);
  }
}

void wakeIsland(WorldState& w, std::uint32_t island) {
  for (const std::uint32_t slot : w.islands.bodies(island)) {
    Body& b = w.bodies[slot];
    if (!b.awake) {
      b.awake = true;
      w.awakeBodySet.add(slot);
    }
    b.sleepTime = 0.0f;
  }
}

void wakeBody(WorldState& w, std::uint32_t slot) {
  Body& b = w.bodies[slot];
  b.sleepTime = 0.0f;
  if (b.awake || b.type == BodyType::staticBody) {
    return;
  }
  if (const std::uint32_t island = w.islands.islandOf(slot); island != solver::Islands::none) {
    wakeIsland(w, island);
  } else {
    b.awake = true;
    w.awakeBodySet.add(slot);
  }
}

void linkContact(WorldState& w, const Contact& c, bool began) {
  if (w.bodies[c.bodyA].type != BodyType::dynamicBody || w.bodies[c.bodyB].type != BodyType::dynamicBody) {
    return;
  }
  if (began) {
    w.islands.link(c.bodyA, c.bodyB);
  } else {
    w.islands.unlink(c.bodyA, c.bodyB);
  }
}

void updateSleep(WorldState& w, float dt) {
  const float linear2 = w.def.sleepLinearTolerance * w.def.sleepLinearTolerance;
  const float angular2 = w.def.sleepAngularTolerance * w.def.sleepAngularTolerance;
  for (const std::uint32_t slot : w.awakeBodies) {
    Body& b = w.bodies[slot];
    const bool slow = lengthSquared(b.linearVelocity) < linear2 && lengthSquared(b.angularVelocity) < angular2;
    b.sleepTime = (w.def.enableSleep && b.enableSleep && slow) ? b.sleepTime + dt : 0.0f;
  }
  if (!w.def.enableSleep) {
    return;
  }
  // Each island once, in the order of its first awake body: it sleeps when its slowest-to-rest
  // body has rested long enough (a moving kinematic body keeps what it carries moving, so awake).
  w.sleepCandidates.clear();
  for (const std::uint32_t slot : w.awakeBodies) {
    const Body& b = w.bodies[slot];
    const std::uint32_t island = w.islands.islandOf(slot);
    if (b.type == BodyType::dynamicBody && b.awake && island != solver::Islands::none &&
        std::find(w.sleepCandidates.begin(), w.sleepCandidates.end(), island) == w.sleepCandidates.end()) {
      w.sleepCandidates.push_back(island);
    }
  }
  const auto rested = [&](std::uint32_t island) {
    const auto bodies = w.islands.bodies(island);
    return std::all_of(bodies.begin(), bodies.end(),
                       [&](std::uint32_t slot) { return w.bodies[slot].sleepTime >= w.def.timeToSleep; });
  };
  std::vector<std::vector<std::uint32_t>> neighbours;
  std::vector<std::uint32_t> pieces;
  for (const std::uint32_t island : w.sleepCandidates) {
    if (!rested(island)) {
      continue;
    }
    if (!w.islands.mayBeApart(island)) {
      sleepIsland(w, island);
      continue;
    }
    // A contact went since the island was last whole: split it into its connected pieces (over
    // its touching contacts), and the pieces at rest sleep.
    if (neighbours.empty()) {
      neighbours.resize(w.bodies.size());
      for (const Contact& c : w.contacts) {
        if (joins(w, c)) {
          neighbours[c.bodyA].push_back(c.bodyB);
          neighbours[c.bodyB].push_back(c.bodyA);
        }
      }
    }
    w.islands.split(
        island,
        [&](std::uint32_t body, auto&& visit) {
          for (const std::uint32_t other : neighbours[body]) {
            visit(other);
          }
        },
        pieces);
    for (const std::uint32_t piece : pieces) {
      if (rested(piece)) {
        sleepIsland(w, piece);
      }
    }
  }
}

} // namespace impetus::rigid3d::detail
