// The closest points of two segments, shared by the capsule pairs (round_manifold.cpp) and the
// edge contact of two hulls (hull_hull_manifold.cpp).
#pragma once

#include <impetus/math/vec3.hpp>

#include <algorithm>

namespace impetus::rigid3d {

/// The closest points of segments [p1, q1] and [p2, q2] (Ericson, Real-Time Collision Detection
/// 5.1.9), as the fractions s and t along them. Both have a length (it divides by their squared
/// lengths): a capsule's is at least linearSlop, a hull's edges join distinct points.
inline void closestBetweenSegments(const Vec3f& p1, const Vec3f& q1, const Vec3f& p2, const Vec3f& q2, float& s,
                                   float& t) {
  const Vec3f d1 = q1 - p1;
  const Vec3f d2 = q2 - p2;
  const Vec3f r = p1 - p2;
  const float a = dot(d1, d1);
  const float e = dot(d2, d2);
  const float f = dot(d2, r);
  const float c = dot(d1, r);
  const float b = dot(d1, d2);
  const float denominator = a * e - b * b; // >= 0; 0 when parallel
  s = denominator > 0.0f ? std::clamp((b * f - c * e) / denominator, 0.0f, 1.0f) : 0.0f;
  t = (b * s + f) / e;
  if (t < 0.0f) {
    t = 0.0f;
    s = std::clamp(-c / a, 0.0f, 1.0f);
  } else if (t > 1.0f) {
    t = 1.0f;
    s = std::clamp((b - c) / a, 0.0f, 1.0f);
  }
}

} // namespace impetus::rigid3d
