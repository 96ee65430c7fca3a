// Which shapes collide, the same rule in every world (Box2D's filter): categories and masks of up
// to 64 bits, and groups that override them.
#pragma once

#include <cstdint>

namespace impetus {

/// Which shapes collide: A and B collide when (A.category & B.mask) and (B.category & A.mask) are
/// non-zero, unless they share a non-zero group (positive: always collide, negative: never).
struct CollisionFilter {
  std::uint64_t category = 1;
  std::uint64_t mask = ~std::uint64_t{0};
  std::int32_t group = 0;
};

/// Whether two shapes' filters let them collide (CollisionFilter's rule).
[[nodiscard]] constexpr bool shouldCollide(const CollisionFilter& a, const CollisionFilter& b) noexcept {
  if (a.group == b.group && a.group != 0) {
    return a.group > 0;
  }
  return (a.category & b.mask) != 0 && (b.category & a.mask) != 0;
}

} // namespace impetus
