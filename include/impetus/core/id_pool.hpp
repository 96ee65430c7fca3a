// Generational ids: the worlds hand out small ids, never pointers. An id is an index into a
// pool plus the generation of the slot when it was allocated; freeing a slot bumps its
// generation, so a stale id is detected instead of silently reaching the slot's next occupant.
// Each id also records the world that made it, so that an id passed to another world is refused
// instead of naming whatever that world keeps in the same slot.
#pragma once

#include <cstdint>
#include <vector>

namespace impetus {

/// A typed handle: Id<struct BodyTag> and Id<struct ShapeTag> do not convert into each other.
/// The default-constructed id (generation 0) is null: no pool ever hands it out.
template <typename Tag> struct Id {
  std::uint32_t index = 0;
  std::uint32_t generation = 0;
  std::uint32_t world = 0; ///< the number of the world (its pools) that made it: nextWorldNumber()

  [[nodiscard]] constexpr bool isNull() const noexcept { return generation == 0; }
  friend constexpr bool operator==(const Id&, const Id&) noexcept = default;
};

/// A number for a new world, never 0 and different for every world made in the process (until
/// 2^32 of them: then it wraps, skipping 0). Thread-safe.
[[nodiscard]] std::uint32_t nextWorldNumber() noexcept;

/// Allocates slot indices and tracks their generations. Freed slots are reused last-in
/// first-out, which is deterministic: the same sequence of calls always yields the same ids.
class IdPool {
public:
  /// A pool whose ids carry `world` (0: ids that record no world, for pools outside a world).
  explicit IdPool(std::uint32_t world = 0) noexcept : world_(world) {}

  struct Slot {
    std::uint32_t index;
    std::uint32_t generation;
  };

  /// Takes a free slot (reusing the most recently freed one) or grows the pool.
  Slot allocate();

  /// Frees a slot held by a valid id. Throws impetus::Error when the id is stale or unknown.
  void free(Slot slot);

  /// Whether `slot` names a live allocation of this pool.
  [[nodiscard]] bool isValid(Slot slot) const noexcept;

  /// Number of live allocations.
  [[nodiscard]] std::uint32_t size() const noexcept { return liveCount_; }
  /// Number of slots ever created (live or free): the range of valid indices.
  [[nodiscard]] std::uint32_t capacity() const noexcept { return static_cast<std::uint32_t>(generations_.size()); }

  /// The world number its ids carry.
  [[nodiscard]] std::uint32_t world() const noexcept { return world_; }
  template <typename Tag> [[nodiscard]] Id<Tag> allocateId() {
    const Slot s = allocate();
    return {s.index, s.generation, world_};
  }
  template <typename Tag> void freeId(Id<Tag> id) {
    if (id.world != world_) {
      reportInvalid({id.index, id.generation}, id.world, "id.index", "id");
    }
    free({id.index, id.generation});
  }
  template <typename Tag> [[nodiscard]] bool isValidId(Id<Tag> id) const noexcept {
    return id.world == world_ && isValid({id.index, id.generation});
  }
  /// Throws impetus::Error naming `field` unless `id` is live in this pool: "<what> belongs to
  /// another world" or "<what> does not exist (destroyed or never created)".
  template <typename Tag> void requireValid(Id<Tag> id, const char* field, const char* what) const {
    if (!isValidId(id)) {
      reportInvalid({id.index, id.generation}, id.world, field, what);
    }
  }

private:
  [[noreturn]] void reportInvalid(Slot slot, std::uint32_t world, const char* field, const char* what) const;

  std::uint32_t world_ = 0;
  // Generation of each slot; odd = live, even = free. Starting at 1 on first use keeps
  // generation 0 for the null id.
  std::vector<std::uint32_t> generations_;
  std::vector<std::uint32_t> freeList_;
  std::uint32_t liveCount_ = 0;
};

} // namespace impetus
