// The oneTBB task runner gives the same bits as no runner (built when CMake finds TBB).
#include "mixed_scene.hpp"

#include <impetus/core/tbb_task_runner.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

namespace impetus::rigid2d {
namespace {

TEST(TbbTaskRunner, visits_every_index_exactly_once) {
  TbbTaskRunner runner;
  EXPECT_GE(runner.threadCount(), 1);
  std::vector<std::atomic<int>> visits(10000);
  runner.parallelFor(10000, 7, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t i = begin; i < end; ++i) {
      visits[i].fetch_add(1);
    }
  });
  for (const std::atomic<int>& v : visits) {
    ASSERT_EQ(v.load(), 1);
  }
}

TEST(TbbTaskRunner, world_steps_bit_identical_to_no_runner) {
  TbbTaskRunner runner;
  EXPECT_EQ(test::runMixedScene(&runner), test::runMixedScene(nullptr));
}

} // namespace
} // namespace impetus::rigid2d
