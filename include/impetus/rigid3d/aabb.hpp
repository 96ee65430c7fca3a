// Axis-aligned bounding boxes in 3D: the broadphase's currency. Their free functions are what
// the dynamic tree needs of a box (impetus::TreeBox, core/dynamic_tree.hpp), the same ones as
// rigid2d::AABB's in 2D.
#pragma once

#include <impetus/core/aabb_common.hpp>
#include <impetus/math/vec3.hpp>

#include <string_view>

namespace impetus::rigid3d {

struct AABB {
  Vec3f lower; ///< minimum corner, m
  Vec3f upper; ///< maximum corner, m

  friend constexpr bool operator==(const AABB&, const AABB&) noexcept = default;
};

[[nodiscard]] inline bool isValid(const AABB& a) noexcept {
  return isFinite(a.lower) && isFinite(a.upper) && a.lower.x <= a.upper.x && a.lower.y <= a.upper.y &&
         a.lower.z <= a.upper.z;
}
/// Whether the boxes share a point (touching counts).
[[nodiscard]] inline bool overlaps(const AABB& a, const AABB& b) noexcept {
  return !(b.lower.x > a.upper.x || b.lower.y > a.upper.y || b.lower.z > a.upper.z || a.lower.x > b.upper.x ||
           a.lower.y > b.upper.y || a.lower.z > b.upper.z);
}
/// Whether `outer` contains `inner` entirely.
[[nodiscard]] inline bool contains(const AABB& outer, const AABB& inner) noexcept {
  return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y && outer.lower.z <= inner.lower.z &&
         inner.upper.x <= outer.upper.x && inner.upper.y <= outer.upper.y && inner.upper.z <= outer.upper.z;
}
[[nodiscard]] inline AABB merge(const AABB& a, const AABB& b) noexcept {
  return {min(a.lower, b.lower), max(a.upper, b.upper)};
}
/// The surface area, m^2.
[[nodiscard]] inline float surfaceArea(const AABB& a) noexcept {
  const Vec3f e = a.upper - a.lower;
  return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}
/// The dynamic tree's surface-area heuristic cost: the surface area in 3D, m^2.
[[nodiscard]] inline float sahCost(const AABB& a) noexcept { return surfaceArea(a); }
/// The axis the dynamic tree's median rebuild splits a box of centres across: its longest extent
/// (0 = x, 1 = y, 2 = z; of equal ones the later, as rigid2d's).
[[nodiscard]] inline int splitAxis(const AABB& a) noexcept {
  const Vec3f e = a.upper - a.lower;
  if (e.x > e.y && e.x > e.z) {
    return 0;
  }
  return e.y > e.z ? 1 : 2;
}
[[nodiscard]] inline AABB enlarge(const AABB& a, float margin) noexcept {
  const Vec3f m{margin, margin, margin};
  return {a.lower - m, a.upper + m};
}
[[nodiscard]] inline Vec3f center(const AABB& a) noexcept { return (a.lower + a.upper) * 0.5f; }

/// Whether the segment p1 -> p2 crosses the box (slab test), and the entry fraction.
[[nodiscard]] inline bool segmentOverlaps(const AABB& box, const Vec3f& p1, const Vec3f& p2, float* entry = nullptr) {
  return segmentCrossesBox<3>(box.lower, box.upper, p1, p2, entry);
}

/// Returns `box` when it is finite with lower <= upper; otherwise throws impetus::Error naming
/// the bad component under `field` ("box.lower.z = nan: must be finite").
inline const AABB& requireValid(const AABB& box, std::string_view field) {
  if (!isValid(box)) [[unlikely]] {
    const float lower[] = {box.lower.x, box.lower.y, box.lower.z};
    const float upper[] = {box.upper.x, box.upper.y, box.upper.z};
    throwInvalidBounds(field, lower, upper);
  }
  return box;
}

} // namespace impetus::rigid3d
