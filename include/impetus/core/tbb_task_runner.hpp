// A TaskRunner on oneTBB (Debian's libtbb-dev): for programs that already schedule their work with
// TBB, so the physics shares its thread pool instead of adding one. Header-only, so the library
// itself does not depend on TBB: include this and link TBB::tbb (CMake: find_package(TBB)).
//
//   impetus::TbbTaskRunner runner;            // TBB's default arena (all hardware threads)
//   impetus::rigid2d::WorldDef def;
//   def.taskRunner = &runner;
//
// Results are the same as with no runner or with impetus::ThreadPool: the engine only hands out
// loops whose ranges write disjoint data.
#pragma once

#include <impetus/core/task_runner.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace impetus {

class TbbTaskRunner final : public TaskRunner {
public:
  /// Uses TBB's current arena (as many threads as TBB chooses).
  TbbTaskRunner() = default;

  void parallelFor(std::uint32_t count, std::uint32_t minRange, const RangeTask& task) override {
    if (count == 0) {
      return;
    }
    const std::uint32_t grain = minRange == 0 ? 1 : minRange;
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, count, grain),
                      [&task](const tbb::blocked_range<std::uint32_t>& r) { task(r.begin(), r.end()); });
  }

  [[nodiscard]] int threadCount() const noexcept override { return tbb::this_task_arena::max_concurrency(); }
};

} // namespace impetus
