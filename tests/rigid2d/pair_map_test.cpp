// The contacts' pair index against std::map through random inserts and erases (the backward-shift
// deletion is the part that is easy to get wrong).
#include "rigid2d/pair_map.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>

namespace impetus::rigid2d::detail {
namespace {

TEST(PairMap, matches_std_map_through_random_inserts_and_erases) {
  PairMap map;
  std::map<std::uint64_t, std::uint32_t> reference;
  std::mt19937 rng(42);
  std::uniform_int_distribution<std::uint32_t> shape(0, 300);
  for (int op = 0; op < 200000; ++op) {
    std::uint32_t a = shape(rng);
    std::uint32_t b = shape(rng);
    if (a == b) {
      continue;
    }
    if (a > b) {
      std::swap(a, b);
    }
    const std::uint64_t key = (std::uint64_t{a} << 32) | b;
    if (reference.contains(key)) {
      map.erase(key);
      reference.erase(key);
    } else {
      const auto value = static_cast<std::uint32_t>(op);
      map.insert(key, value);
      reference.emplace(key, value);
    }
    ASSERT_EQ(map.size(), reference.size());
    if (op % 1000 == 0) {
      for (const auto& [k, v] : reference) {
        const std::uint32_t* found = map.find(k);
        ASSERT_NE(found, nullptr);
        ASSERT_EQ(*found, v);
      }
    }
  }
  // Keys never inserted are absent.
  EXPECT_FALSE(map.contains((std::uint64_t{500} << 32) | 501));
}

} // namespace
} // namespace impetus::rigid2d::detail
