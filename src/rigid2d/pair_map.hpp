// The contacts' index by shape pair: an open-addressing hash table (linear probing, backward-shift
// deletion) over one vector. Unlike std::unordered_map it allocates only when it grows past its
// largest size so far, so contacts that come and go every step (a swinging chain, a rolling pile)
// cost no allocation once the world has warmed up. Keys are (lower shape << 32 | higher shape),
// never 0, which marks an empty slot.
#pragma once

#include <cstdint>
#include <vector>

namespace impetus::rigid2d::detail {

class PairMap {
public:
  /// The value stored for `key`, or nullptr.
  [[nodiscard]] const std::uint32_t* find(std::uint64_t key) const {
    if (slots_.empty()) {
      return nullptr;
    }
    for (std::size_t i = home(key);; i = (i + 1) & mask()) {
      if (slots_[i].key == key) {
        return &slots_[i].value;
      }
      if (slots_[i].key == 0) {
        return nullptr;
      }
    }
  }
  [[nodiscard]] bool contains(std::uint64_t key) const { return find(key) != nullptr; }

  /// Adds a key that is not in the map yet.
  void insert(std::uint64_t key, std::uint32_t value) {
    if (2 * (count_ + 1) > slots_.size()) {
      grow();
    }
    place(key, value);
    ++count_;
  }

  /// Removes a key if present.
  void erase(std::uint64_t key) {
    if (slots_.empty()) {
      return;
    }
    std::size_t i = home(key);
    while (slots_[i].key != key) {
      if (slots_[i].key == 0) {
        return;
      }
      i = (i + 1) & mask();
    }
    // Backward shift: pull later members of the probe run into the hole, so lookups never stop
    // early at it (no tombstones).
    for (std::size_t j = (i + 1) & mask(); slots_[j].key != 0; j = (j + 1) & mask()) {
      const std::size_t ideal = home(slots_[j].key);
      // Move j into the hole at i unless its home lies cyclically in (i, j].
      const bool homeBetween = i <= j ? (ideal > i && ideal <= j) : (ideal > i || ideal <= j);
      if (!homeBetween) {
        slots_[i] = slots_[j];
        i = j;
      }
    }
    slots_[i] = Slot{};
    --count_;
  }

  [[nodiscard]] std::size_t size() const noexcept { return count_; }
  /// Empties the map, keeping its capacity.
  void clear() noexcept {
    for (Slot& slot : slots_) {
      slot = Slot{};
    }
    count_ = 0;
  }

private:
  struct Slot {
    std::uint64_t key = 0;
    std::uint32_t value = 0;
  };

  [[nodiscard]] std::size_t mask() const noexcept { return slots_.size() - 1; }
  /// The splitmix64 finalizer: shape indices are small and sequential, so mix them well.
  [[nodiscard]] std::size_t home(std::uint64_t key) const noexcept {
    key ^= key >> 30;
    key *= 0xbf58476d1ce4e5b9ULL;
    key ^= key >> 27;
    key *= 0x94d049bb133111ebULL;
    key ^= key >> 31;
    return static_cast<std::size_t>(key) & mask();
  }
  void place(std::uint64_t key, std::uint32_t value) {
    std::size_t i = home(key);
    while (slots_[i].key != 0) {
      i = (i + 1) & mask();
    }
    slots_[i] = {key, value};
  }
  void grow() {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(old.empty() ? 64 : 2 * old.size(), Slot{});
    for (const Slot& s : old) {
      if (s.key != 0) {
        place(s.key, s.value);
      }
    }
  }

  std::vector<Slot> slots_;
  std::size_t count_ = 0;
};

} // namespace impetus::rigid2d::detail
