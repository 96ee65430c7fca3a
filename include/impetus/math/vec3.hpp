// Vec3<T>: a 3D vector in a right-handed frame (appendix A's Vector). Cross and dot are named
// functions; there is deliberately no `^` operator (it binds looser than + and ==).
#pragma once

#include <impetus/math/scalar.hpp>

namespace impetus {

template <Real T> struct Vec3 {
  T x{};
  T y{};
  T z{};

  constexpr Vec3() noexcept = default;
  constexpr Vec3(T x_, T y_, T z_) noexcept : x(x_), y(y_), z(z_) {}

  [[nodiscard]] static constexpr Vec3 zero() noexcept { return {}; }
  [[nodiscard]] static constexpr Vec3 unitX() noexcept { return {T(1), T(0), T(0)}; }
  [[nodiscard]] static constexpr Vec3 unitY() noexcept { return {T(0), T(1), T(0)}; }
  [[nodiscard]] static constexpr Vec3 unitZ() noexcept { return {T(0), T(0), T(1)}; }

  /// Component i (0 = x, 1 = y, 2 = z).
  [[nodiscard]] constexpr T operator[](int i) const noexcept { return i == 0 ? x : (i == 1 ? y : z); }
  [[nodiscard]] constexpr T& operator[](int i) noexcept { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Vec3& operator+=(const Vec3& v) noexcept {
    x += v.x;
    y += v.y;
    z += v.z;
    return *this;
  }
  constexpr Vec3& operator-=(const Vec3& v) noexcept {
    x -= v.x;
    y -= v.y;
    z -= v.z;
    return *this;
  }
  constexpr Vec3& operator*=(T s) noexcept {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  constexpr Vec3& operator/=(T s) noexcept {
    x /= s;
    y /= s;
    z /= s;
    return *this;
  }

  friend constexpr bool operator==(const Vec3&, const Vec3&) noexcept = default;
};

/// The book's "Reverse" and unary minus.
template <Real T> [[nodiscard]] constexpr Vec3<T> operator-(const Vec3<T>& v) noexcept { return {-v.x, -v.y, -v.z}; }
template <Real T> [[nodiscard]] constexpr Vec3<T> operator+(Vec3<T> a, const Vec3<T>& b) noexcept { return a += b; }
template <Real T> [[nodiscard]] constexpr Vec3<T> operator-(Vec3<T> a, const Vec3<T>& b) noexcept { return a -= b; }
template <Real T> [[nodiscard]] constexpr Vec3<T> operator*(Vec3<T> v, T s) noexcept { return v *= s; }
template <Real T> [[nodiscard]] constexpr Vec3<T> operator*(T s, Vec3<T> v) noexcept { return v *= s; }
template <Real T> [[nodiscard]] constexpr Vec3<T> operator/(Vec3<T> v, T s) noexcept { return v /= s; }

/// u . v = |u||v| cos(theta).
template <Real T> [[nodiscard]] constexpr T dot(const Vec3<T>& a, const Vec3<T>& b) noexcept {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// u x v: perpendicular to both by the right-hand rule, |u x v| = |u||v| sin(theta).
template <Real T> [[nodiscard]] constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) noexcept {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// u . (v x w): the signed volume of the parallelepiped spanned by u, v, w.
template <Real T>
[[nodiscard]] constexpr T tripleScalarProduct(const Vec3<T>& u, const Vec3<T>& v, const Vec3<T>& w) noexcept {
  return dot(u, cross(v, w));
}

template <Real T> [[nodiscard]] constexpr T lengthSquared(const Vec3<T>& v) noexcept { return dot(v, v); }
template <Real T> [[nodiscard]] T length(const Vec3<T>& v) noexcept { return std::sqrt(lengthSquared(v)); }
template <Real T> [[nodiscard]] T distance(const Vec3<T>& a, const Vec3<T>& b) noexcept { return length(b - a); }

/// v / |v|. A vector of (near) zero length has no direction: the result is the zero vector,
/// never NaN (the book's choice too). Non-finite input stays non-finite.
template <Real T> [[nodiscard]] Vec3<T> normalize(const Vec3<T>& v) noexcept {
  T len = length(v);
  if (std::isinf(len)) {
    len = std::hypot(v.x, v.y, v.z); // |v|^2 overflowed (|v| > 1e154 in double): slow, exact path
  }
  if (len <= normalizeTolerance<T>) {
    return {};
  }
  return v / len;
}

/// Component-wise product.
template <Real T> [[nodiscard]] constexpr Vec3<T> hadamard(const Vec3<T>& a, const Vec3<T>& b) noexcept {
  return {a.x * b.x, a.y * b.y, a.z * b.z};
}
template <Real T> [[nodiscard]] constexpr Vec3<T> lerp(const Vec3<T>& a, const Vec3<T>& b, T t) noexcept {
  return a + (b - a) * t;
}
template <Real T> [[nodiscard]] Vec3<T> min(const Vec3<T>& a, const Vec3<T>& b) noexcept {
  return {b.x < a.x ? b.x : a.x, b.y < a.y ? b.y : a.y, b.z < a.z ? b.z : a.z};
}
template <Real T> [[nodiscard]] Vec3<T> max(const Vec3<T>& a, const Vec3<T>& b) noexcept {
  return {a.x < b.x ? b.x : a.x, a.y < b.y ? b.y : a.y, a.z < b.z ? b.z : a.z};
}
template <Real T> [[nodiscard]] Vec3<T> abs(const Vec3<T>& v) noexcept {
  return {std::abs(v.x), std::abs(v.y), std::abs(v.z)};
}
template <Real T> [[nodiscard]] bool isFinite(const Vec3<T>& v) noexcept {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

using Vec3f = Vec3<float>;
using Vec3d = Vec3<double>;

} // namespace impetus
