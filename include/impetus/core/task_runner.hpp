// Parallel loops for the engines. A world given a TaskRunner splits the independent parts of its
// step (integrating bodies, each colour of the constraint graph, narrowphase) into ranges and
// hands them to the runner; without one it runs them in order on the caller's thread.
//
// Results never depend on the runner: the engine only passes loops whose ranges write disjoint
// data and that read nothing another range writes, and it gathers anything ordered (events,
// new contacts) serially afterwards. So a step is bit-identical with 1 thread or 16.
#pragma once

#include <cstdint>
#include <memory>
#include <type_traits>

namespace impetus {

/// A non-owning reference to a callable `void(std::uint32_t begin, std::uint32_t end)` that works
/// on the indices [begin, end). Unlike std::function it never allocates: a world step hands out
/// hundreds of loops and must not allocate once warmed up. It refers to the callable, which must
/// outlive it (a lambda passed straight to parallelFor does).
class RangeTask {
public:
  // Implicit, from lambdas; the constraint keeps it from hiding the copy constructor.
  template <class F, class = std::enable_if_t<!std::is_same_v<std::remove_cvref_t<F>, RangeTask> &&
                                              std::is_invocable_v<F&, std::uint32_t, std::uint32_t>>>
  RangeTask(F&& f) noexcept // NOLINT(google-explicit-constructor,bugprone-forwarding-reference-overload)
      : object_(const_cast<void*>(static_cast<const void*>(std::addressof(f)))),
        call_([](void* object, std::uint32_t begin, std::uint32_t end) {
          (*static_cast<std::remove_reference_t<F>*>(object))(begin, end);
        }) {}

  void operator()(std::uint32_t begin, std::uint32_t end) const { call_(object_, begin, end); }

private:
  void* object_;
  void (*call_)(void*, std::uint32_t, std::uint32_t);
};

class TaskRunner {
public:
  using RangeTask = impetus::RangeTask;

  TaskRunner() = default;
  TaskRunner(const TaskRunner&) = delete;
  TaskRunner& operator=(const TaskRunner&) = delete;
  virtual ~TaskRunner() = default;

  /// Calls `task` over disjoint ranges that together cover [0, count), each at least `minRange`
  /// long (except possibly the last), possibly at the same time on several threads, and returns
  /// when every range is done. `task` must not throw.
  virtual void parallelFor(std::uint32_t count, std::uint32_t minRange, const RangeTask& task) = 0;

  /// Threads that may run ranges at once (the caller's included).
  [[nodiscard]] virtual int threadCount() const noexcept = 0;
};

/// A TaskRunner over a fixed pool of std::threads; the calling thread works too. Idle workers
/// spin briefly for the next loop (a step runs hundreds of short loops) and then sleep.
/// It runs one loop at a time: call parallelFor from one thread at a time (worlds stepped on
/// different threads need a pool each) and never from inside a task.
class ThreadPool final : public TaskRunner {
public:
  /// threadCount >= 1 threads in all, the caller's included (1: everything on the caller).
  /// Throws impetus::Error naming `threadCount` otherwise.
  explicit ThreadPool(int threadCount);
  ~ThreadPool() override;

  void parallelFor(std::uint32_t count, std::uint32_t minRange, const RangeTask& task) override;
  [[nodiscard]] int threadCount() const noexcept override;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace impetus
