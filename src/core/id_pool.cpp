#include <impetus/core/id_pool.hpp>
#include <impetus/error.hpp>

#include <atomic>
#include <string>

namespace impetus {

IdPool::Slot IdPool::allocate() {
  ++liveCount_;
  if (!freeList_.empty()) {
    const std::uint32_t index = freeList_.back();
    freeList_.pop_back();
    // Free slots have even generations, so this makes it odd (live) and never 0, even when the
    // counter wraps after 2^31 reuses of one slot.
    const std::uint32_t generation = ++generations_[index];
    return {index, generation};
  }
  generations_.push_back(1);
  return {static_cast<std::uint32_t>(generations_.size() - 1), 1};
}

void IdPool::free(Slot slot) {
  if (!isValid(slot)) {
    throwInvalid("id.index", static_cast<double>(slot.index), "id is stale, null or was never allocated");
  }
  ++generations_[slot.index];
  freeList_.push_back(slot.index);
  --liveCount_;
}

std::uint32_t nextWorldNumber() noexcept {
  static std::atomic<std::uint32_t> last{0};
  std::uint32_t number = 0;
  while (number == 0) {
    number = last.fetch_add(1, std::memory_order_relaxed) + 1;
  }
  return number;
}

void IdPool::reportInvalid(Slot slot, std::uint32_t world, const char* field, const char* what) const {
  if (world != world_ && slot.generation != 0) {
    throwInvalid(field, static_cast<double>(slot.index),
                 std::string(what) + " belongs to another world (world " + std::to_string(world) + ", this is world " +
                     std::to_string(world_) + ")");
  }
  throwInvalid(field, static_cast<double>(slot.index),
               std::string(what) + " does not exist (destroyed or never created)");
}

bool IdPool::isValid(Slot slot) const noexcept {
  return slot.generation != 0 && slot.index < generations_.size() && generations_[slot.index] == slot.generation &&
         (slot.generation & 1U) == 1U;
}

} // namespace impetus
