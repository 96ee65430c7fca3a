// Persistent islands (the solver layer: no dimension in it): the sets of bodies joined by
// constraints (touching contacts and joints), kept from step to step instead of found again
// each step, as Box2D v3. A constraint that begins joins two islands into one (the smaller's
// bodies move to the larger). A constraint that goes only counts: the island may have come
// apart, and is split (a flood fill over its own constraints) only when the world wants it to
// sleep, so that a stack losing and regaining contacts every step costs nothing.
//
// Static bodies are in no island: they join nothing (a floor does not make one island of
// everything resting on it).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace impetus::solver {

class Islands {
public:
  static constexpr std::uint32_t none = 0xffffffffU;

  /// The body (a slot) becomes an island of its own.
  void addBody(std::uint32_t body);
  /// The body leaves its island (destroyed, say): what it held together may have come apart.
  void removeBody(std::uint32_t body);
  /// A constraint began between two bodies (both in islands): their islands become one.
  void link(std::uint32_t bodyA, std::uint32_t bodyB);
  /// A constraint between two bodies went: their island may have come apart.
  void unlink(std::uint32_t bodyA, std::uint32_t bodyB);

  [[nodiscard]] std::uint32_t islandOf(std::uint32_t body) const noexcept {
    return body < islandOf_.size() ? islandOf_[body] : none;
  }
  [[nodiscard]] std::span<const std::uint32_t> bodies(std::uint32_t island) const noexcept {
    return islands_[island].bodies;
  }
  /// Whether a constraint of the island went since it was last whole (a split may find pieces).
  [[nodiscard]] bool mayBeApart(std::uint32_t island) const noexcept { return islands_[island].removed > 0; }
  /// How many islands there are.
  [[nodiscard]] std::size_t count() const noexcept { return islands_.size() - free_.size(); }

  /// Splits the island into its connected pieces: `neighbours(body, visit)` calls visit(other)
  /// for every body joined to `body` by a constraint. The first piece keeps the island's slot;
  /// `pieces` receives every piece's (the first included), in the order of the island's bodies.
  template <class Neighbours>
  void split(std::uint32_t island, Neighbours&& neighbours, std::vector<std::uint32_t>& pieces);

  /// Every island in slot order, for a snapshot: `out.put(value)` for its scalars.
  template <class Out> void save(Out& out) const;
  /// Reads what save wrote; `in.template get<T>()` reads a scalar. Body slots at or past
  /// `bodyBound` are a malformed snapshot: `fail(slot)` is called (it must throw).
  template <class In, class Fail> void load(In& in, std::size_t bodyBound, Fail&& fail);

private:
  struct Island {
    std::vector<std::uint32_t> bodies;
    std::uint32_t removed = 0; ///< constraints gone since the island was last whole
    bool alive = false;
  };
  /// Marks a body of an island being split that no piece holds yet.
  static constexpr std::uint32_t unvisited = 0xfffffffeU;

  std::uint32_t newIsland();
  void freeIsland(std::uint32_t island);
  void place(std::uint32_t body, std::uint32_t island);

  std::vector<Island> islands_;
  std::vector<std::uint32_t> free_;       ///< island slots to reuse, last freed first
  std::vector<std::uint32_t> islandOf_;   ///< by body slot
  std::vector<std::uint32_t> positionOf_; ///< by body slot: index in its island's bodies
  std::vector<std::uint32_t> members_;    ///< scratch of split
  std::vector<std::uint32_t> stack_;      ///< scratch of split
};

template <class Neighbours>
void Islands::split(std::uint32_t island, Neighbours&& neighbours, std::vector<std::uint32_t>& pieces) {
  pieces.clear();
  members_.swap(islands_[island].bodies);
  islands_[island].bodies.clear();
  islands_[island].removed = 0;
  for (const std::uint32_t body : members_) {
    islandOf_[body] = unvisited;
  }
  for (const std::uint32_t seed : members_) {
    if (islandOf_[seed] != unvisited) {
      continue;
    }
    const std::uint32_t piece = pieces.empty() ? island : newIsland();
    pieces.push_back(piece);
    place(seed, piece);
    stack_.assign(1, seed);
    while (!stack_.empty()) {
      const std::uint32_t body = stack_.back();
      stack_.pop_back();
      neighbours(body, [&](std::uint32_t other) {
        if (other < islandOf_.size() && islandOf_[other] == unvisited) {
          place(other, piece);
          stack_.push_back(other);
        }
      });
    }
  }
  members_.clear();
}

template <class Out> void Islands::save(Out& out) const {
  out.put(static_cast<std::uint32_t>(islands_.size()));
  for (const Island& island : islands_) {
    out.put(island.alive);
    out.put(island.removed);
    out.put(static_cast<std::uint32_t>(island.bodies.size()));
    for (const std::uint32_t body : island.bodies) {
      out.put(body);
    }
  }
  out.put(static_cast<std::uint32_t>(free_.size()));
  for (const std::uint32_t slot : free_) {
    out.put(slot);
  }
}

template <class In, class Fail> void Islands::load(In& in, std::size_t bodyBound, Fail&& fail) {
  // Into the islands' own storage (a restore in a warmed-up world allocates nothing).
  free_.clear();
  islandOf_.assign(bodyBound, none);
  positionOf_.assign(bodyBound, none);
  const auto count = in.template get<std::uint32_t>();
  islands_.resize(count);
  for (std::uint32_t slot = 0; slot < count; ++slot) {
    Island& island = islands_[slot];
    island.bodies.clear();
    island.alive = in.template get<bool>();
    island.removed = in.template get<std::uint32_t>();
    const auto size = in.template get<std::uint32_t>();
    if (island.alive != (size > 0)) {
      fail(slot); // a live island has bodies, a free one none
    }
    for (std::uint32_t k = 0; k < size; ++k) {
      const auto body = in.template get<std::uint32_t>();
      if (body >= bodyBound || islandOf_[body] != none) {
        fail(body);
      }
      islands_[slot].bodies.push_back(body);
      islandOf_[body] = slot;
      positionOf_[body] = k;
    }
  }
  const auto freeCount = in.template get<std::uint32_t>();
  for (std::uint32_t k = 0; k < freeCount; ++k) {
    const auto slot = in.template get<std::uint32_t>();
    if (slot >= count || islands_[slot].alive) {
      fail(slot);
    }
    free_.push_back(slot);
  }
}

} // namespace impetus::solver
