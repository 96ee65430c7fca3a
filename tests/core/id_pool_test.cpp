// Generational ids: allocation, validity, stale-id detection after free and reuse, the
// deterministic last-in first-out reuse order, and the null id.
#include <impetus/core/id_pool.hpp>
#include <impetus/error.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace impetus {
namespace {

struct BodyTag;
using BodyId = Id<BodyTag>;

TEST(IdPool, allocate_free_and_is_valid) {
  IdPool pool;
  EXPECT_EQ(pool.size(), 0U);
  EXPECT_EQ(pool.capacity(), 0U);
  const BodyId a = pool.allocateId<BodyTag>();
  const BodyId b = pool.allocateId<BodyTag>();
  EXPECT_FALSE(a.isNull());
  EXPECT_FALSE(b.isNull());
  EXPECT_NE(a, b);
  EXPECT_NE(a.index, b.index);
  EXPECT_TRUE(pool.isValidId(a));
  EXPECT_TRUE(pool.isValidId(b));
  EXPECT_EQ(pool.size(), 2U);
  EXPECT_EQ(pool.capacity(), 2U);

  pool.freeId(a);
  EXPECT_FALSE(pool.isValidId(a));
  EXPECT_TRUE(pool.isValidId(b));
  EXPECT_EQ(pool.size(), 1U);
  EXPECT_EQ(pool.capacity(), 2U); // the slot stays, free
}

TEST(IdPool, stale_id_is_rejected_after_its_slot_is_reused) {
  IdPool pool;
  const BodyId old = pool.allocateId<BodyTag>();
  pool.freeId(old);
  const BodyId reused = pool.allocateId<BodyTag>();
  // Same slot, new generation: the old handle must not reach the new occupant.
  EXPECT_EQ(reused.index, old.index);
  EXPECT_NE(reused.generation, old.generation);
  EXPECT_FALSE(pool.isValidId(old));
  EXPECT_TRUE(pool.isValidId(reused));
  EXPECT_EQ(pool.capacity(), 1U);
  // Many cycles on one slot: every generation is new and only the latest is valid.
  std::vector<BodyId> history{old, reused};
  for (int i = 0; i < 100; ++i) {
    pool.freeId(history.back());
    history.push_back(pool.allocateId<BodyTag>());
  }
  for (std::size_t i = 0; i + 1 < history.size(); ++i) {
    EXPECT_FALSE(pool.isValidId(history[i])) << i;
    EXPECT_NE(history[i].generation, history.back().generation) << i;
  }
  EXPECT_TRUE(pool.isValidId(history.back()));
}

TEST(IdPool, freed_slots_are_reused_last_in_first_out) {
  IdPool pool;
  std::vector<IdPool::Slot> slots;
  for (int i = 0; i < 5; ++i) {
    slots.push_back(pool.allocate());
  }
  pool.free(slots[1]);
  pool.free(slots[3]);
  pool.free(slots[0]);
  EXPECT_EQ(pool.allocate().index, slots[0].index);
  EXPECT_EQ(pool.allocate().index, slots[3].index);
  EXPECT_EQ(pool.allocate().index, slots[1].index);
  // Free list empty: the pool grows.
  EXPECT_EQ(pool.allocate().index, 5U);
  EXPECT_EQ(pool.capacity(), 6U);
  EXPECT_EQ(pool.size(), 6U);
}

TEST(IdPool, same_calls_give_the_same_ids) {
  const auto run = [] {
    IdPool pool;
    std::vector<BodyId> live;
    std::vector<BodyId> issued;
    for (int step = 0; step < 200; ++step) {
      // A fixed, irregular pattern of allocations and frees.
      if (step % 3 == 2 && !live.empty()) {
        const std::size_t victim = static_cast<std::size_t>(step * 7) % live.size();
        pool.freeId(live[victim]);
        live.erase(live.begin() + static_cast<std::ptrdiff_t>(victim));
      } else {
        live.push_back(pool.allocateId<BodyTag>());
        issued.push_back(live.back());
      }
    }
    return issued;
  };
  const std::vector<BodyId> first = run();
  const std::vector<BodyId> second = run();
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i], second[i]) << i;
  }
}

TEST(IdPool, freeing_a_stale_null_or_unknown_id_throws) {
  IdPool pool;
  const BodyId id = pool.allocateId<BodyTag>();
  pool.freeId(id);
  // Double free (stale).
  EXPECT_THROW(pool.freeId(id), Error);
  // After reuse, the old id is still stale and must not free the new occupant.
  const BodyId reused = pool.allocateId<BodyTag>();
  try {
    pool.freeId(id);
    ADD_FAILURE() << "freeing a stale id did not throw";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "id.index");
  }
  EXPECT_TRUE(pool.isValidId(reused));
  EXPECT_EQ(pool.size(), 1U);
  // Null and never-allocated ids.
  EXPECT_THROW(pool.freeId(BodyId{}), Error);
  EXPECT_THROW(pool.freeId(BodyId{7, 1}), Error);
  // A free slot's own (even) generation does not name a live allocation.
  const BodyId other = pool.allocateId<BodyTag>();
  pool.freeId(other);
  const BodyId freeSlot{other.index, other.generation + 1};
  EXPECT_FALSE(pool.isValidId(freeSlot));
  EXPECT_THROW(pool.freeId(freeSlot), Error);
  // A live index with a forged even (free-looking) generation.
  EXPECT_THROW(pool.freeId(BodyId{reused.index, reused.generation + 1}), Error);
  EXPECT_TRUE(pool.isValidId(reused));
  EXPECT_EQ(pool.size(), 1U);
}

TEST(IdPool, default_id_is_null_and_never_valid) {
  const BodyId null{};
  EXPECT_TRUE(null.isNull());
  IdPool pool;
  EXPECT_FALSE(pool.isValidId(null));
  // Slot 0 is live with generation 1; the null id (index 0, generation 0) still is not valid.
  const BodyId first = pool.allocateId<BodyTag>();
  EXPECT_EQ(first.index, 0U);
  EXPECT_FALSE(pool.isValidId(null));
  EXPECT_NE(first, null);
  for (int i = 0; i < 10; ++i) {
    EXPECT_FALSE(pool.allocateId<BodyTag>().isNull());
  }
  EXPECT_FALSE(pool.isValidId(null));
}

} // namespace
} // namespace impetus
