// Transform3<T>: a 3D rigid transform (unit-quaternion rotation, then translation).
#pragma once

#include <impetus/math/quat.hpp>

namespace impetus {

template <Real T> struct Transform3 {
  Vec3<T> p{};                    ///< translation (origin of the local frame in the parent), m
  Quat<T> q{Quat<T>::identity()}; ///< rotation of the local frame (unit quaternion)

  [[nodiscard]] static constexpr Transform3 identity() noexcept { return {}; }

  friend constexpr bool operator==(const Transform3&, const Transform3&) noexcept = default;
};

/// A point given in the local frame, in the parent frame: q v q* + p.
template <Real T> [[nodiscard]] constexpr Vec3<T> transformPoint(const Transform3<T>& t, const Vec3<T>& v) noexcept {
  return rotate(t.q, v) + t.p;
}
/// A point given in the parent frame, in the local frame.
template <Real T>
[[nodiscard]] constexpr Vec3<T> inverseTransformPoint(const Transform3<T>& t, const Vec3<T>& v) noexcept {
  return inverseRotate(t.q, v - t.p);
}
/// a b: apply b, then a.
template <Real T> [[nodiscard]] constexpr Transform3<T> mul(const Transform3<T>& a, const Transform3<T>& b) noexcept {
  return {rotate(a.q, b.p) + a.p, a.q * b.q};
}
/// a^-1 b: b expressed in a's frame.
template <Real T>
[[nodiscard]] constexpr Transform3<T> invMul(const Transform3<T>& a, const Transform3<T>& b) noexcept {
  return {inverseRotate(a.q, b.p - a.p), conjugate(a.q) * b.q};
}
template <Real T> [[nodiscard]] constexpr Transform3<T> inverse(const Transform3<T>& t) noexcept {
  return invMul(t, Transform3<T>::identity());
}

using Transform3f = Transform3<float>;
using Transform3d = Transform3<double>;

} // namespace impetus
