// Axis-aligned bounding boxes: the broadphase's currency.
#pragma once

#include <impetus/math/vec2.hpp>

#include <algorithm>

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
/// Perimeter: the surface-area heuristic's cost of a box in 2D.
[[nodiscard]] inline float perimeter(const AABB& a) noexcept {
  return 2.0f * ((a.upper.x - a.lower.x) + (a.upper.y - a.lower.y));
}
[[nodiscard]] inline AABB enlarge(const AABB& a, float margin) noexcept {
  return {a.lower - Vec2f{margin, margin}, a.upper + Vec2f{margin, margin}};
}
[[nodiscard]] inline Vec2f center(const AABB& a) noexcept { return (a.lower + a.upper) * 0.5f; }

/// Whether the segment p1 -> p2 crosses the box (slab test), and the entry fraction.
[[nodiscard]] inline bool segmentOverlaps(const AABB& box, const Vec2f& p1, const Vec2f& p2, float* entry = nullptr) {
  float tmin = 0.0f;
  float tmax = 1.0f;
  const Vec2f d = p2 - p1;
  const float start[2] = {p1.x, p1.y};
  const float dir[2] = {d.x, d.y};
  const float lo[2] = {box.lower.x, box.lower.y};
  const float hi[2] = {box.upper.x, box.upper.y};
  for (int i = 0; i < 2; ++i) {
    if (dir[i] == 0.0f) {
      if (start[i] < lo[i] || start[i] > hi[i]) {
        return false;
      }
      continue;
    }
    const float inv = 1.0f / dir[i];
    float t1 = (lo[i] - start[i]) * inv;
    float t2 = (hi[i] - start[i]) * inv;
    if (t1 > t2) {
      std::swap(t1, t2);
    }
    tmin = std::max(tmin, t1);
    tmax = std::min(tmax, t2);
    if (tmin > tmax) {
      return false;
    }
  }
  if (entry != nullptr) {
    *entry = tmin;
  }
  return true;
}

} // namespace impetus::rigid2d
