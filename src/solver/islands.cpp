// Persistent islands: joining, leaving and the bookkeeping of island slots (split is a template
// in islands.hpp, over the world's own constraint lists).
#include "solver/islands.hpp"

#include <utility>

namespace impetus::solver {

std::uint32_t Islands::newIsland() {
  std::uint32_t island = 0;
  if (!free_.empty()) {
    island = free_.back();
    free_.pop_back();
  } else {
    island = static_cast<std::uint32_t>(islands_.size());
    islands_.emplace_back();
  }
  Island& i = islands_[island];
  i.bodies.clear();
  i.removed = 0;
  i.alive = true;
  return island;
}

void Islands::freeIsland(std::uint32_t island) {
  Island& i = islands_[island];
  i.bodies.clear();
  i.removed = 0;
  i.alive = false;
  free_.push_back(island);
}

void Islands::place(std::uint32_t body, std::uint32_t island) {
  std::vector<std::uint32_t>& bodies = islands_[island].bodies;
  islandOf_[body] = island;
  positionOf_[body] = static_cast<std::uint32_t>(bodies.size());
  bodies.push_back(body);
}

void Islands::addBody(std::uint32_t body) {
  if (body >= islandOf_.size()) {
    islandOf_.resize(body + 1, none);
    positionOf_.resize(body + 1, none);
  }
  place(body, newIsland());
}

void Islands::removeBody(std::uint32_t body) {
  const std::uint32_t island = islandOf(body);
  if (island == none) {
    return;
  }
  std::vector<std::uint32_t>& bodies = islands_[island].bodies;
  // The last body takes its place.
  const std::uint32_t at = positionOf_[body];
  const std::uint32_t last = bodies.back();
  bodies[at] = last;
  positionOf_[last] = at;
  bodies.pop_back();
  islandOf_[body] = none;
  positionOf_[body] = none;
  if (bodies.empty()) {
    freeIsland(island);
  } else {
    ++islands_[island].removed;
  }
}

void Islands::link(std::uint32_t bodyA, std::uint32_t bodyB) {
  std::uint32_t into = islandOf(bodyA);
  std::uint32_t from = islandOf(bodyB);
  if (into == none || from == none || into == from) {
    return;
  }
  // The smaller island's bodies move (each body moves O(log n) times over any sequence of
  // links); between equals, the higher slot's, so the result does not depend on argument order.
  const std::size_t sizeInto = islands_[into].bodies.size();
  const std::size_t sizeFrom = islands_[from].bodies.size();
  if (sizeFrom > sizeInto || (sizeFrom == sizeInto && from < into)) {
    std::swap(into, from);
  }
  for (const std::uint32_t body : islands_[from].bodies) {
    place(body, into);
  }
  islands_[into].removed += islands_[from].removed;
  freeIsland(from);
}

void Islands::unlink(std::uint32_t bodyA, std::uint32_t bodyB) {
  const std::uint32_t island = islandOf(bodyA);
  if (island != none && island == islandOf(bodyB)) {
    ++islands_[island].removed;
  }
}

} // namespace impetus::solver
