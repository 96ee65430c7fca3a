// What the fuzz harnesses share: a failed check that stops the run with a message (libFuzzer
// then saves the input; the replay test fails), and a reader that turns the fuzzer's bytes into
// numbers and choices.
#pragma once

#include <impetus/math/vec2.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace impetus::fuzz {

/// Prints what failed and aborts: an abort is what libFuzzer records as a crash (and saves the
/// input), and what makes a replay test fail.
[[noreturn]] inline void fail(const char* file, int line, const std::string& what) {
  std::fprintf(stderr, "\n%s:%d: fuzz check failed: %s\n", file, line, what.c_str());
  std::fflush(stderr);
  std::abort();
}

/// Open findings: bugs in the library that a harness found and nobody has fixed yet. Each has
/// its input under regressions/<harness>/open-*, and its check stays on, so that the fuzzers
/// (./run fuzz) keep reporting it. IMPETUS_FUZZ_SKIP_OPEN=1 in the environment lets the open
/// findings pass, so that a long run can search past them for other bugs.
inline bool skipOpenFindings() {
  static const bool skip = [] {
    const char* v = std::getenv("IMPETUS_FUZZ_SKIP_OPEN");
    return v != nullptr && v[0] == '1';
  }();
  return skip;
}

} // namespace impetus::fuzz

/// A property every input must keep; `what` (a std::string expression) says which and why.
#define FUZZ_CHECK(condition, what)                                                                                    \
  do {                                                                                                                 \
    if (!(condition)) {                                                                                                \
      ::impetus::fuzz::fail(__FILE__, __LINE__, std::string(#condition) + ": " + (what));                              \
    }                                                                                                                  \
  } while (false)

namespace impetus::fuzz {

/// Reads the fuzzer's bytes front to back; past the end every read gives zeros, so any input,
/// however short, decodes to something.
class Reader {
public:
  Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  [[nodiscard]] std::size_t remaining() const { return size_ - offset_; }

  [[nodiscard]] std::uint8_t byte() { return offset_ < size_ ? data_[offset_++] : std::uint8_t{0}; }

  [[nodiscard]] std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) {
      v = (v << 8) | byte();
    }
    return v;
  }

  /// Any float bit pattern at all: NaN, infinities, denormals, -0 included.
  [[nodiscard]] float rawFloat() {
    const std::uint32_t bits = u32();
    float f = 0.0f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
  }

  /// A finite float in [-bound, bound]: the raw bits when they already are one (exact zeros,
  /// integers, tiny values: the edge cases), otherwise the bits read as a fraction of the range.
  [[nodiscard]] float bounded(float bound) {
    const std::uint32_t bits = u32();
    float f = 0.0f;
    std::memcpy(&f, &bits, sizeof f);
    if (std::isfinite(f) && std::abs(f) <= bound) {
      return f;
    }
    const double unit = static_cast<double>(bits) / 4294967295.0; // [0, 1]
    return static_cast<float>((2.0 * unit - 1.0) * static_cast<double>(bound));
  }

  /// A float in [lo, hi] (lo >= 0), as bounded() but folded into the interval.
  [[nodiscard]] float inRange(float lo, float hi) {
    const float f = std::abs(bounded(hi));
    return f < lo ? lo + (hi - lo) * (f / hi) : f;
  }

  [[nodiscard]] Vec2f vec2(float bound) {
    const float x = bounded(bound);
    const float y = bounded(bound);
    return {x, y};
  }

private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t offset_ = 0;
};

/// "1.5" and such, round-trip, for the failure messages.
inline std::string str(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", v);
  return buffer;
}
inline std::string str(const Vec2f& v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "(%.9g, %.9g)", static_cast<double>(v.x), static_cast<double>(v.y));
  return buffer;
}

} // namespace impetus::fuzz
