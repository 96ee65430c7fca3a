// The awake set's lists (the solver layer: no dimension in it): the slots of the bodies,
// contacts or joints that are simulated, as one dense array, so that a step walks only what is
// awake and a sleeping island costs nothing. Adding appends; removing leaves a hole; compact()
// closes the holes and puts what was added since in its place, so that after it the list is in
// slot order (the order the pools lay their items out in memory: a walk over the list reads
// them front to back, and the order does not depend on the history of sleeping and waking).
// Until then a list can grow and lose items while it is being walked by index.
#pragma once

#include <algorithm>
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

  /// Closes the holes and merges what was added since the last compact into slot order: the
  /// cost of the list's length, only when it changed; nothing is allocated once the list has
  /// been as long before.
  void compact() {
    if (holes_ == 0 && sorted_ == items_.size()) {
      return;
    }
    const auto isHole = [](std::uint32_t slot) { return slot == hole; };
    const auto tail = items_.begin() + static_cast<std::ptrdiff_t>(sorted_);
    const auto sortedEnd = std::remove_if(items_.begin(), tail, isHole);
    const auto end = std::remove_if(tail, items_.end(), isHole);
    std::sort(tail, end);
    merged_.resize(static_cast<std::size_t>((sortedEnd - items_.begin()) + (end - tail)));
    std::merge(items_.begin(), sortedEnd, tail, end, merged_.begin());
    items_.swap(merged_);
    for (std::uint32_t i = 0; i < items_.size(); ++i) {
      position_[items_[i]] = i;
    }
    holes_ = 0;
    sorted_ = items_.size();
  }

  /// The slots in order, holes (`hole`) included until compact().
  [[nodiscard]] std::span<const std::uint32_t> items() const noexcept { return items_; }
  /// Whether items() is in slot order without holes (compacted since the last change).
  [[nodiscard]] bool compacted() const noexcept { return holes_ == 0 && sorted_ == items_.size(); }
  /// How many slots are in the list (holes not counted).
  [[nodiscard]] std::size_t size() const noexcept { return items_.size() - holes_; }

  void clear() noexcept {
    items_.clear();
    position_.clear();
    holes_ = 0;
    sorted_ = 0;
  }

private:
  std::vector<std::uint32_t> items_;
  std::vector<std::uint32_t> position_; ///< by slot: index into items_, or hole
  std::vector<std::uint32_t> merged_;   ///< compact's scratch
  std::size_t sorted_ = 0;              ///< items_ before this are in slot order (holes aside)
  std::uint32_t holes_ = 0;
};

} // namespace impetus::solver
