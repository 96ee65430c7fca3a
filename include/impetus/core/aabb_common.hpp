// What the 2D and the 3D axis-aligned boxes (rigid2d::AABB, rigid3d::AABB) share, written once
// over their number of axes: the error that names a bad component, and the slab test of a
// segment. A point is anything with components p[i] (Vec2f, Vec3f), in m.
#pragma once

#include <algorithm>
#include <span>
#include <string_view>
#include <utility>

namespace impetus {

/// Throws impetus::Error naming under `field` the first bad component of the box lower..upper
/// (as many components as `lower` has: 2 or 3): a non-finite one ("box.lower.y = nan: must be
/// finite"), then an inside-out axis ("box.upper.x = -1: must be >= box.lower.x"). For the boxes'
/// requireValid, once their isValid has failed: compiled once, out of the callers' way.
[[noreturn]] void throwInvalidBounds(std::string_view field, std::span<const float> lower,
                                     std::span<const float> upper);

/// The slab test: whether the segment p1 -> p2 crosses the box lower..upper (`Axes` components
/// each), and at `entry` (when not null) the fraction along the segment where it enters the box
/// (0 when it starts inside). A segment parallel to an axis crosses only if it lies within that
/// axis's slab.
template <int Axes, class Point> [[nodiscard]] bool
segmentCrossesBox(const Point& lower, const Point& upper, const Point& p1, const Point& p2, float* entry) noexcept {
  float tmin = 0.0f;
  float tmax = 1.0f;
  const Point d = p2 - p1;
  for (int i = 0; i < Axes; ++i) {
    if (d[i] == 0.0f) {
      if (p1[i] < lower[i] || p1[i] > upper[i]) {
        return false;
      }
      continue;
    }
    const float inv = 1.0f / d[i];
    float t1 = (lower[i] - p1[i]) * inv;
    float t2 = (upper[i] - p1[i]) * inv;
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

} // namespace impetus
