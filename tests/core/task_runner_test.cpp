#include "support/error_field.hpp"

#include <impetus/core/task_runner.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

namespace impetus {
namespace {

// Every index of every loop is visited exactly once, whatever the count, range size and thread
// count, and loops run back to back (hundreds per world step) do not bleed into each other.
TEST(ThreadPool, visits_every_index_exactly_once) {
  for (int threads : {1, 2, 3, 8}) {
    ThreadPool pool(threads);
    EXPECT_EQ(pool.threadCount(), threads);
    for (std::uint32_t count : {0U, 1U, 7U, 64U, 1000U, 4097U}) {
      for (std::uint32_t minRange : {1U, 16U, 256U}) {
        std::vector<std::atomic<int>> visits(count);
        pool.parallelFor(count, minRange, [&](std::uint32_t begin, std::uint32_t end) {
          ASSERT_LE(begin, end);
          ASSERT_LE(end, count);
          for (std::uint32_t i = begin; i < end; ++i) {
            visits[i].fetch_add(1);
          }
        });
        for (std::uint32_t i = 0; i < count; ++i) {
          ASSERT_EQ(visits[i].load(), 1) << "index " << i << " of " << count << ", " << threads << " threads";
        }
      }
    }
  }
}

TEST(ThreadPool, many_short_loops_in_a_row) {
  ThreadPool pool(4);
  std::vector<std::uint64_t> sums(2000, 0);
  for (std::size_t loop = 0; loop < sums.size(); ++loop) {
    std::vector<std::uint32_t> out(100, 0);
    pool.parallelFor(100, 1, [&](std::uint32_t begin, std::uint32_t end) {
      for (std::uint32_t i = begin; i < end; ++i) {
        out[i] = i + static_cast<std::uint32_t>(loop);
      }
    });
    for (std::uint32_t v : out) {
      sums[loop] += v;
    }
    ASSERT_EQ(sums[loop], 4950U + 100U * loop);
  }
}

// Back-to-back loops of very different sizes: a thread still finishing one loop must never run
// a range of the next one (each index is counted, so a range run twice shows).
TEST(ThreadPool, lagging_threads_never_run_a_range_of_the_next_loop_twice) {
  ThreadPool pool(4);
  std::vector<std::atomic<int>> visits(1000);
  for (int loop = 0; loop < 20000; ++loop) {
    const std::uint32_t count = loop % 2 == 0 ? 3U : 1000U;
    pool.parallelFor(count, 1, [&](std::uint32_t begin, std::uint32_t end) {
      for (std::uint32_t i = begin; i < end; ++i) {
        visits[i].fetch_add(1, std::memory_order_relaxed);
      }
    });
  }
  for (std::uint32_t i = 0; i < 1000; ++i) {
    ASSERT_EQ(visits[i].load(), i < 3 ? 20000 : 10000) << "index " << i;
  }
}

TEST(ThreadPool, rejects_bad_thread_counts) {
  expectErrorField([] { ThreadPool pool(0); }, "threadCount");
  expectErrorField([] { ThreadPool pool(-3); }, "threadCount");
}

} // namespace
} // namespace impetus
