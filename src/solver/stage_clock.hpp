// Wall time of a step's stages, for the profile a world reports (never for a result: the clock
// differs from run to run, and nothing the solver computes reads it).
#pragma once

#include <chrono>

namespace impetus::solver {

class StageClock {
public:
  StageClock() : start_(Clock::now()), last_(start_) {}
  /// Milliseconds since the last lap (or since the clock started).
  float lap() {
    const Clock::time_point now = Clock::now();
    const float ms = std::chrono::duration<float, std::milli>(now - last_).count();
    last_ = now;
    return ms;
  }
  /// Milliseconds since the clock started, up to the last lap.
  [[nodiscard]] float total() const { return std::chrono::duration<float, std::milli>(last_ - start_).count(); }

private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
  Clock::time_point last_;
};

} // namespace impetus::solver
