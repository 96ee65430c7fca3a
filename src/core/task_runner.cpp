// A TaskRunner over std::threads: one loop at a time, its ranges claimed from an atomic counter.
#include <impetus/core/task_runner.hpp>
#include <impetus/error.hpp>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace impetus {
namespace {

/// Tells the core this thread is spinning (x86's pause: the sibling hyperthread gets the
/// pipeline, and leaving the loop costs no memory-order flush).
inline void cpuRelax() noexcept {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

/// How many relaxed polls a waiting thread makes before it yields its core: loops come every few
/// microseconds while a world steps, and a poll is tens of nanoseconds where a yield (a system
/// call) is hundreds. About 256 pauses (5 to 40 us, by the processor) cover the gap between two
/// loops of a step without holding a core long from a thread that needs it (more threads than
/// cores).
constexpr int relaxedPolls = 256;

} // namespace

struct ThreadPool::Impl {
  int threadCount = 1;
  std::vector<std::thread> workers;

  // The loop being run: published by bumping `generation`.
  const RangeTask* task = nullptr;
  std::uint32_t count = 0;
  std::uint32_t rangeSize = 1;
  std::uint32_t rangeCount = 0; ///< of the current loop (the calling thread's copy)
  /// The loop's generation (bits 32-63), its range count (bits 16-31) and its next unclaimed
  /// range (bits 0-15), in one word: a thread that lags behind checks and claims against the
  /// same value, so it can never claim a range of a later loop while thinking it belongs to an
  /// earlier one. (A loop has at most 2 ranges per thread, so 16 bits are plenty.)
  std::atomic<std::uint64_t> claim{0};
  std::atomic<std::uint32_t> doneRanges{0};
  std::atomic<std::uint64_t> generation{0};
  std::atomic<bool> stopping{false};
  /// Workers blocked on `wakeUp` (changed under `mutex`): the caller pays for a notify only when
  /// someone sleeps.
  std::atomic<int> sleepers{0};
  std::mutex mutex;
  std::condition_variable wakeUp;

  /// Claims and runs ranges of loop `gen` until none is left. The loop's fields are read only
  /// after a successful claim, which proves the loop is still running (the caller starts the
  /// next loop only when every range of this one is done).
  void work(std::uint64_t gen) {
    for (;;) {
      std::uint64_t current = claim.load(std::memory_order_acquire);
      for (;;) {
        const std::uint64_t ranges = (current >> 16) & 0xffffU;
        if ((current >> 32) != (gen & 0xffffffffU) || (current & 0xffffU) >= ranges) {
          return;
        }
        if (claim.compare_exchange_weak(current, current + 1, std::memory_order_acq_rel)) {
          break;
        }
      }
      const auto r = static_cast<std::uint32_t>(current & 0xffffU);
      const std::uint32_t begin = r * rangeSize;
      (*task)(begin, std::min(count, begin + rangeSize));
      doneRanges.fetch_add(1, std::memory_order_acq_rel);
    }
  }

  void workerLoop() {
    std::uint64_t seen = 0;
    for (;;) {
      // Spin a little for the next loop before sleeping: loops come every few microseconds
      // while a world steps.
      std::uint64_t g = generation.load(std::memory_order_acquire);
      for (int poll = 0; g == seen && poll < relaxedPolls; ++poll) {
        cpuRelax();
        g = generation.load(std::memory_order_acquire);
      }
      for (int spin = 0; g == seen && spin < 20000; ++spin) {
        std::this_thread::yield();
        g = generation.load(std::memory_order_acquire);
      }
      if (g == seen) {
        std::unique_lock lock(mutex);
        sleepers.fetch_add(1, std::memory_order_relaxed);
        wakeUp.wait(lock, [&] {
          return stopping.load(std::memory_order_acquire) || generation.load(std::memory_order_acquire) != seen;
        });
        sleepers.fetch_sub(1, std::memory_order_relaxed);
        g = generation.load(std::memory_order_acquire);
      }
      if (stopping.load(std::memory_order_acquire)) {
        return;
      }
      seen = g;
      work(g);
    }
  }
};

ThreadPool::ThreadPool(int threadCount) : impl_(std::make_unique<Impl>()) {
  if (threadCount < 1 || threadCount > 256) {
    throwInvalid("threadCount", threadCount, "must be between 1 and 256");
  }
  impl_->threadCount = threadCount;
  for (int i = 1; i < threadCount; ++i) {
    impl_->workers.emplace_back([this] { impl_->workerLoop(); });
  }
}

ThreadPool::~ThreadPool() {
  {
    const std::lock_guard lock(impl_->mutex);
    impl_->stopping.store(true, std::memory_order_release);
  }
  impl_->wakeUp.notify_all();
  for (std::thread& t : impl_->workers) {
    t.join();
  }
}

int ThreadPool::threadCount() const noexcept { return impl_->threadCount; }

void ThreadPool::parallelFor(std::uint32_t count, std::uint32_t minRange, const RangeTask& task) {
  if (count == 0) {
    return;
  }
  Impl& p = *impl_;
  minRange = std::max<std::uint32_t>(minRange, 1);
  const auto threads = static_cast<std::uint32_t>(p.threadCount);
  if (threads == 1 || count <= minRange) {
    task(0, count);
    return;
  }
  // About two ranges per thread balance the load: each claim and each range done is an atomic on
  // a line the threads share, which moves from core to core, so the step's many short loops
  // (a colour's constraints in a substep) pay for every range.
  const std::uint32_t target = std::max<std::uint32_t>(minRange, (count + 2 * threads - 1) / (2 * threads));
  std::uint64_t gen = 0;
  {
    const std::lock_guard lock(p.mutex);
    p.task = &task;
    p.count = count;
    p.rangeSize = target;
    p.rangeCount = (count + target - 1) / target; // <= 2 per thread: fits the claim's 16 bits
    p.doneRanges.store(0, std::memory_order_relaxed);
    gen = p.generation.load(std::memory_order_relaxed) + 1;
    p.claim.store(((gen & 0xffffffffU) << 32) | (std::uint64_t{p.rangeCount} << 16), std::memory_order_release);
    p.generation.store(gen, std::memory_order_release);
  }
  // A worker that went to sleep did so under the mutex before the loop was published, so it is
  // counted here; one that checks later sees the new generation and does not sleep.
  if (p.sleepers.load(std::memory_order_relaxed) > 0) {
    p.wakeUp.notify_all();
  }
  p.work(gen);
  for (int poll = 0; p.doneRanges.load(std::memory_order_acquire) < p.rangeCount; ++poll) {
    if (poll < relaxedPolls) {
      cpuRelax();
    } else {
      std::this_thread::yield();
    }
  }
}

} // namespace impetus
