// Axis-aligned bounding boxes: the broadphase's currency. Their free functions are what the
// dynamic tree needs of a box (impetus::TreeBox, core/dynamic_tree.hpp); rigid3d::AABB has the
// same ones in 3D.
#pragma once

#include <impetus/core/aabb_common.hpp>
#include <impetus/math/vec2.hpp>

#include <string_view>

namespace impetus::rigid2d {

struct AABB {
  Vec2f lower; ///< minimum corner, m
  Vec2f upper; ///< maximum corner, m

  friend constexpr bool operator==(const AABB&, const AABB&) noexcept = default;
};

[[nodiscard]] inline bool isValid(const AABB& a) noexcept {
  return isFinite(a.lower) && isFinite(a.upper) && a.lower.x <= a.upper.x && a.lower.y <= a.upper.y;
}
[[nodiscard]] inline bool overlaps(const AABB& a, const AABB& b) noexcept {
  return !(b.lower.x > a.upper.x || b.lower.y > a.upper.y || a.lower.x > b.upper.x || a.lower.y > b.upper.y);
}
/// Whether `outer` contains `inner` entirely.
[[nodiscard]] inline bool contains(const AABB& outer, const AABB& inner) noexcept {
  return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y && inner.upper.x <= outer.upper.x &&
         inner.upper.y <= outer.upper.y;
}
[[nodiscard]] inline AABB merge(const AABB& a, const AABB& b) noexcept {
  return {min(a.lower, b.lower), max(a.upper, b.upper)};
}
/// The perimeter, m.
[[nodiscard]] inline float perimeter(const AABB& a) noexcept {
  return 2.0f * ((a.upper.x - a.lower.x) + (a.upper.y - a.lower.y));
}
/// The dynamic tree's surface-area heuristic cost: the perimeter in 2D, m.
[[nodiscard]] inline float sahCost(const AABB& a) noexcept { return perimeter(a); }
/// The axis the dynamic tree's median rebuild splits a box of centres across: its longer extent
/// (0 = x, 1 = y; y when they are equal).
[[nodiscard]] inline int splitAxis(const AABB& a) noexcept {
  return a.upper.x - a.lower.x > a.upper.y - a.lower.y ? 0 : 1;
}
[[nodiscard]] inline AABB enlarge(const AABB& a, float margin) noexcept {
  return {a.lower - Vec2f{margin, margin}, a.upper + Vec2f{margin, margin}};
}
[[nodiscard]] inline Vec2f center(const AABB& a) noexcept { return (a.lower + a.upper) * 0.5f; }

/// Whether the segment p1 -> p2 crosses the box (slab test), and the entry fraction.
[[nodiscard]] inline bool segmentOverlaps(const AABB& box, const Vec2f& p1, const Vec2f& p2, float* entry = nullptr) {
  return segmentCrossesBox<2>(box.lower, box.upper, p1, p2, entry);
}

/// Returns `box` when it is finite with lower <= upper; otherwise throws impetus::Error naming
/// the bad component under `field` ("box.upper.x = -1: must be >= box.lower.x").
inline const AABB& requireValid(const AABB& box, std::string_view field) {
  if (!isValid(box)) [[unlikely]] {
    const float lower[] = {box.lower.x, box.lower.y};
    const float upper[] = {box.upper.x, box.upper.y};
    throwInvalidBounds(field, lower, upper);
  }
  return box;
}

} // namespace impetus::rigid2d
