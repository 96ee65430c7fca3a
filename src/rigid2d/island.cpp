// Islands and sleeping: the awake set (the bodies and contacts a step walks) and the persistent
// islands (solver::Islands) that fall asleep and wake as a whole. A sleeping island's bodies and
// contacts leave the awake set, so they cost the step nothing; touching one of its bodies, or
// any call that changes one, wakes the whole island.
#include "rigid2d/joints.hpp"
#include "rigid2d/world_impl.hpp"

#include <algorithm>
#include <limits>

namespace impetus::rigid2d::detail {

void updateContactColour(WorldState& w, std::uint32_t slot) {
  const Contact& c = w.contacts[slot];
  const bool solved = solvedByStep(w, c);
  if (solved == w.contactGraph.contains(slot)) {
    return;
  }
  if (solved) {
    w.contactGraph.add(slot, graphBodyOf(w, c.bodyA), graphBodyOf(w, c.bodyB));
  } else {
    w.contactGraph.remove(slot);
  }
}

void wakeIsland(WorldState& w, std::uint32_t island) {
  for (const std::uint32_t slot : w.islands.bodies(island)) {
    Body& b = w.bodies[slot];
    b.awake = true;
    b.sleepTime = 0.0f;
    w.awakeBodySet.add(slot);
  }
  // Their contacts and joints come back with them (those with another awake body never left).
  for (const std::uint32_t slot : w.islands.bodies(island)) {
    for (const std::uint32_t joint : w.bodies[slot].joints) {
      w.awakeJointSet.add(joint);
    }
    for (std::uint32_t key = w.bodies[slot].contactHead; key != noContactEdge;) {
      w.awakeContactSet.add(key >> 1);
      updateContactColour(w, key >> 1);
      key = w.contacts[key >> 1].next[key & 1U];
    }
  }
}

void wakeBody(WorldState& w, std::uint32_t slot) {
  Body& b = w.bodies[slot];
  if (!b.alive || b.type == BodyType::staticBody) {
    return;
  }
  b.sleepTime = 0.0f;
  if (!b.awake) {
    wakeIsland(w, w.islands.islandOf(slot));
  }
}

void sleepIsland(WorldState& w, std::uint32_t island) {
  for (const std::uint32_t slot : w.islands.bodies(island)) {
    Body& b = w.bodies[slot];
    b.awake = false;
    b.linearVelocity = {};
    b.angularVelocity = 0.0f;
    w.awakeBodySet.remove(slot);
    w.bodyInfo[slot].solverIndex = noSolverIndex;
  }
  // A contact or joint stays awake while either body is.
  for (const std::uint32_t slot : w.islands.bodies(island)) {
    for (const std::uint32_t j : w.bodies[slot].joints) {
      const Joint& joint = w.joints[j];
      if (!w.bodies[joint.bodyA].moving() && !w.bodies[joint.bodyB].moving()) {
        w.awakeJointSet.remove(j);
      }
    }
    for (std::uint32_t key = w.bodies[slot].contactHead; key != noContactEdge;) {
      const Contact& c = w.contacts[key >> 1];
      if (!w.bodies[c.bodyA].moving() && !w.bodies[c.bodyB].moving()) {
        w.awakeContactSet.remove(key >> 1);
        w.contactGraph.remove(key >> 1);
      }
      key = c.next[key & 1U];
    }
  }
}

bool joinsIslands(const WorldState& w, const Contact& c) {
  return !c.sensor && w.bodies[c.bodyA].type != BodyType::staticBody && w.bodies[c.bodyB].type != BodyType::staticBody;
}

void splitIsland(WorldState& w, std::uint32_t island) {
  // An island's bodies are joined by touching contacts and joints; static bodies, in no
  // island, are never visited.
  const auto neighbours = [&w](std::uint32_t slot, const auto& visit) {
    const Body& b = w.bodies[slot];
    for (std::uint32_t key = b.contactHead; key != noContactEdge;) {
      const Contact& c = w.contacts[key >> 1];
      if (c.manifold.pointCount > 0 && !c.sensor) {
        visit((key & 1U) == 0 ? c.bodyB : c.bodyA);
      }
      key = c.next[key & 1U];
    }
    for (const std::uint32_t j : b.joints) {
      const Joint& joint = w.joints[j];
      visit(joint.bodyA == slot ? joint.bodyB : joint.bodyA);
    }
  };
  w.islands.split(island, neighbours, w.islandPieces);
}

void sleepBodyIsland(WorldState& w, std::uint32_t slot) {
  const std::uint32_t island = w.islands.islandOf(slot);
  if (island == solver::Islands::none) {
    return;
  }
  if (w.islands.mayBeApart(island)) {
    splitIsland(w, island);
  }
  sleepIsland(w, w.islands.islandOf(slot));
}

namespace {

/// Puts a whole island to sleep, in pieces when it has come apart (so that each wakes alone).
void sleepWholeIsland(WorldState& w, std::uint32_t island) {
  if (!w.islands.mayBeApart(island)) {
    sleepIsland(w, island);
    return;
  }
  splitIsland(w, island);
  for (const std::uint32_t piece : w.islandPieces) {
    sleepIsland(w, piece);
  }
}

} // namespace

/// Accumulates rest time and puts islands to sleep whose every body has rested long enough.
/// An island that may have come apart is split first; and of the islands kept awake by one
/// part while another rests, the one with the longest-resting body is split each step (as
/// Box2D v3), so that a pile at rest does not stay awake for a neighbour that once touched it.
void updateSleep(WorldState& w, float dt) {
  const WorldDef& d = w.def;
  std::vector<float>& islandRest = w.islandRest;
  for (const std::uint32_t slot : w.awakeBodies) {
    Body& b = w.bodies[slot];
    const bool slow = lengthSquared(b.linearVelocity) <= d.sleepLinearTolerance * d.sleepLinearTolerance &&
                      std::abs(b.angularVelocity) <= d.sleepAngularTolerance && b.stepSpeed <= d.sleepLinearTolerance &&
                      b.stepSpin <= d.sleepAngularTolerance;
    b.sleepTime = (b.enableSleep && slow) ? b.sleepTime + dt : 0.0f;
    const std::uint32_t island = w.islands.islandOf(slot);
    if (island >= islandRest.size()) {
      islandRest.resize(island + 1);
    }
    islandRest[island] = std::numeric_limits<float>::max();
  }
  // The least rest time of each awake island.
  for (const std::uint32_t slot : w.awakeBodies) {
    float& rest = islandRest[w.islands.islandOf(slot)];
    rest = std::min(rest, w.bodies[slot].sleepTime);
  }
  std::uint32_t splitCandidate = noSolverIndex; // a body of it
  float splitRest = 0.0f;
  for (const std::uint32_t slot : w.awakeBodies) {
    const Body& b = w.bodies[slot];
    if (!b.awake) {
      continue; // its island fell asleep already
    }
    const std::uint32_t island = w.islands.islandOf(slot);
    if (islandRest[island] >= d.timeToSleep) {
      sleepWholeIsland(w, island);
    } else if (b.sleepTime >= d.timeToSleep && w.islands.mayBeApart(island) && b.sleepTime > splitRest) {
      splitCandidate = slot;
      splitRest = b.sleepTime;
    }
  }
  if (splitCandidate == noSolverIndex || !w.bodies[splitCandidate].awake) {
    return;
  }
  splitIsland(w, w.islands.islandOf(splitCandidate));
  // The pieces that have all rested long enough sleep now.
  for (const std::uint32_t piece : w.islandPieces) {
    float rest = std::numeric_limits<float>::max();
    for (const std::uint32_t slot : w.islands.bodies(piece)) {
      rest = std::min(rest, w.bodies[slot].sleepTime);
    }
    if (rest >= d.timeToSleep) {
      sleepIsland(w, piece);
    }
  }
}

} // namespace impetus::rigid2d::detail
