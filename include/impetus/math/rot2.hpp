// Rot2<T>: a 2D rotation stored as (cos, sin) of its angle, so rotating a vector costs four
// multiplies and no trigonometry (as Box2D v3's b2Rot).
#pragma once

#include <impetus/math/mat22.hpp>

namespace impetus {

template <Real T> struct Rot2 {
  T c{1}; ///< cosine of the angle
  T s{0}; ///< sine of the angle

  [[nodiscard]] static constexpr Rot2 identity() noexcept { return {T(1), T(0)}; }
  /// The rotation by `angle` radians, counter-clockwise.
  [[nodiscard]] static Rot2 fromAngle(T angle) noexcept { return {std::cos(angle), std::sin(angle)}; }

  /// The angle in (-pi, pi].
  [[nodiscard]] T angle() const noexcept { return std::atan2(s, c); }
  [[nodiscard]] constexpr Mat22<T> toMat22() const noexcept { return {c, -s, s, c}; }

  friend constexpr bool operator==(const Rot2&, const Rot2&) noexcept = default;
};

template <Real T> [[nodiscard]] constexpr Vec2<T> rotate(const Rot2<T>& q, const Vec2<T>& v) noexcept {
  return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y};
}
template <Real T> [[nodiscard]] constexpr Vec2<T> inverseRotate(const Rot2<T>& q, const Vec2<T>& v) noexcept {
  return {q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y};
}
/// The composition: rotate(mul(a, b), v) = rotate(a, rotate(b, v)).
template <Real T> [[nodiscard]] constexpr Rot2<T> mul(const Rot2<T>& a, const Rot2<T>& b) noexcept {
  return {a.c * b.c - a.s * b.s, a.s * b.c + a.c * b.s};
}
/// a^-1 b.
template <Real T> [[nodiscard]] constexpr Rot2<T> invMul(const Rot2<T>& a, const Rot2<T>& b) noexcept {
  return {a.c * b.c + a.s * b.s, a.c * b.s - a.s * b.c};
}
/// Rescales (c, s) to unit length after integration has drifted it; identity when degenerate.
template <Real T> [[nodiscard]] Rot2<T> normalize(const Rot2<T>& q) noexcept {
  // sqrt, not hypot: this runs for every body every substep, and hypot is a slow library call;
  // only a (c, s) beyond ~1e19 (float) overflows the squares, and then hypot takes over.
  T len = std::sqrt(q.c * q.c + q.s * q.s);
  if (std::isinf(len)) {
    len = std::hypot(q.c, q.s);
  }
  if (len <= normalizeTolerance<T>) {
    return Rot2<T>::identity();
  }
  return {q.c / len, q.s / len};
}

using Rot2f = Rot2<float>;
using Rot2d = Rot2<double>;

} // namespace impetus
