// Same inputs, same bits: the mixed scene stepped with no task runner and with thread pools of
// 1, 2 and 4 threads must end in bit-identical states, and so must two runs of the same
// configuration.
#include "mixed_scene.hpp"

#include <gtest/gtest.h>

namespace impetus::rigid2d {
namespace {

using test::runMixedScene;

TEST(Determinism2D, identical_run_after_run_and_at_any_thread_count) {
  const std::uint64_t reference = runMixedScene(nullptr);
  EXPECT_EQ(runMixedScene(nullptr), reference) << "two runs differ";
  for (int threads : {1, 2, 4}) {
    ThreadPool pool(threads);
    EXPECT_EQ(runMixedScene(&pool), reference) << threads << " threads";
  }
}

} // namespace
} // namespace impetus::rigid2d
