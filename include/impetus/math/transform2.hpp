// Transform2<T>: a 2D rigid transform (rotation, then translation): body frame to world frame.
#pragma once

#include <impetus/math/rot2.hpp>

namespace impetus {

template <Real T> struct Transform2 {
  Vec2<T> p{};                    ///< translation (origin of the local frame in the parent), m
  Rot2<T> q{Rot2<T>::identity()}; ///< rotation of the local frame

  [[nodiscard]] static constexpr Transform2 identity() noexcept { return {}; }

  friend constexpr bool operator==(const Transform2&, const Transform2&) noexcept = default;
};

/// A point given in the local frame, in the parent frame: q v + p.
template <Real T> [[nodiscard]] constexpr Vec2<T> transformPoint(const Transform2<T>& t, const Vec2<T>& v) noexcept {
  return rotate(t.q, v) + t.p;
}
/// A point given in the parent frame, in the local frame: q^-1 (v - p).
template <Real T>
[[nodiscard]] constexpr Vec2<T> inverseTransformPoint(const Transform2<T>& t, const Vec2<T>& v) noexcept {
  return inverseRotate(t.q, v - t.p);
}
/// a b: apply b, then a.
template <Real T> [[nodiscard]] constexpr Transform2<T> mul(const Transform2<T>& a, const Transform2<T>& b) noexcept {
  return {rotate(a.q, b.p) + a.p, mul(a.q, b.q)};
}
/// a^-1 b: b expressed in a's frame.
template <Real T>
[[nodiscard]] constexpr Transform2<T> invMul(const Transform2<T>& a, const Transform2<T>& b) noexcept {
  return {inverseRotate(a.q, b.p - a.p), invMul(a.q, b.q)};
}
template <Real T> [[nodiscard]] constexpr Transform2<T> inverse(const Transform2<T>& t) noexcept {
  return invMul(t, Transform2<T>::identity());
}

using Transform2f = Transform2<float>;
using Transform2d = Transform2<double>;

} // namespace impetus
