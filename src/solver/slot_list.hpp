// The awake set's lists (the solver layer: no dimension in it): the slots of the bodies,
// contacts or joints that are simulated, as one dense array, so that a step walks only what is
// awake and a sleeping island costs nothing. Adding appends; removing leaves a hole that
// compact() closes, keeping the order, so that a list can lose items while it is being walked.
// The order is the history of adds and removes: deterministic, whatever the thread count.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace impetus::solver {

class SlotList {
public:
  /// Marks a hole in items() (a removed slot not yet compacted away).
  static constexpr std::uint32_t hole = 0xffffffffU;

  [[nodiscard]] bool contains(std::uint32_t slot) const noexcept {
    return slot < position_.size() && position_[slot] != hole;
  }

  /// Appends `slot`; nothing when it is already in the list.
  void add(std::uint32_t slot) {
    if (contains(slot)) {
      return;
    }
    if (slot >= position_.size()) {
      position_.resize(slot + 1, hole);
    }
    position_[slot] = static_cast<std::uint32_t>(items_.size());
    items_.push_back(slot);
  }

  /// Leaves a hole where `slot` was; nothing when it is not in the list.
  void remove(std::uint32_t slot) noexcept {
    if (!contains(slot)) {
      return;
    }
    items_[position_[slot]] = hole;
    position_[slot] = hole;
    ++holes_;
  }

  /// Closes the holes, keeping the order of what is left.
  void compact() {
    if (holes_ == 0) {
      return;
    }
    std::uint32_t to = 0;
    for (const std::uint32_t slot : items_) {
      if (slot != hole) {
        position_[slot] = to;
        items_[to++] = slot;
      }
    }
    items_.resize(to);
    holes_ = 0;
  }

  /// The slots in order, holes (`hole`) included until compact().
  [[nodiscard]] std::span<const std::uint32_t> items() const noexcept { return items_; }
  /// How many slots are in the list (holes not counted).
  [[nodiscard]] std::size_t size() const noexcept { return items_.size() - holes_; }

  void clear() noexcept {
    items_.clear();
    position_.clear();
    holes_ = 0;
  }

private:
  std::vector<std::uint32_t> items_;
  std::vector<std::uint32_t> position_; ///< by slot: index into items_, or hole
  std::uint32_t holes_ = 0;
};

} // namespace impetus::solver
