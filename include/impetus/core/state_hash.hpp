// A hash of a simulation's exact state, for determinism checks, replays and lockstep games: two
// runs that hash alike hold the same bits (up to the hash's 2^-64 chance of a collision).
#pragma once

#include <bit>
#include <cstdint>

namespace impetus {

/// 64-bit FNV-1a over the bytes of the values fed to it, in order. Floats are hashed by their
/// bits, so -0.0 and 0.0 (and NaNs with different payloads) hash differently: it tells whether
/// two states are identical, not whether they are close.
class StateHash {
public:
  void add(std::uint64_t bits, int bytes = 8) noexcept {
    for (int i = 0; i < bytes; ++i) {
      value_ = (value_ ^ ((bits >> (8 * i)) & 0xffU)) * prime;
    }
  }
  void add(std::uint32_t bits) noexcept { add(bits, 4); }
  void add(float x) noexcept { add(std::bit_cast<std::uint32_t>(x), 4); }
  void add(double x) noexcept { add(std::bit_cast<std::uint64_t>(x), 8); }
  void add(bool b) noexcept { add(std::uint64_t{b ? 1U : 0U}, 1); }

  [[nodiscard]] std::uint64_t value() const noexcept { return value_; }

private:
  static constexpr std::uint64_t offsetBasis = 14695981039346656037ULL;
  static constexpr std::uint64_t prime = 1099511628211ULL;
  std::uint64_t value_ = offsetBasis;
};

} // namespace impetus
