// A deterministic generator for the 3D tests' point clouds: the same values on every machine.
#pragma once

#include <cstdint>

namespace impetus::rigid3d {

/// A 64-bit linear congruential generator (Knuth's MMIX constants), its top 53 bits as values in
/// [-1, 1).
struct Lcg {
  std::uint64_t state = 0;

  explicit Lcg(std::uint64_t seed) : state(seed) {}
  float next() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<float>(static_cast<double>(state >> 11) / 4503599627370496.0 - 1.0);
  }
};

} // namespace impetus::rigid3d
