// Vec2<T>: a 2D vector (x right, y up). Appendix A's Vector operations restricted to the plane,
// plus the 2D cross products the rigid-body solver needs.
#pragma once

#include <impetus/math/scalar.hpp>

namespace impetus {

template <Real T> struct Vec2 {
  T x{};
  T y{};

  constexpr Vec2() noexcept = default;
  constexpr Vec2(T x_, T y_) noexcept : x(x_), y(y_) {}

  [[nodiscard]] static constexpr Vec2 zero() noexcept { return {}; }

  /// Component i (0 = x, 1 = y).
  [[nodiscard]] constexpr T operator[](int i) const noexcept { return i == 0 ? x : y; }
  [[nodiscard]] constexpr T& operator[](int i) noexcept { return i == 0 ? x : y; }

  constexpr Vec2& operator+=(const Vec2& v) noexcept {
    x += v.x;
    y += v.y;
    return *this;
  }
  constexpr Vec2& operator-=(const Vec2& v) noexcept {
    x -= v.x;
    y -= v.y;
    return *this;
  }
  constexpr Vec2& operator*=(T s) noexcept {
    x *= s;
    y *= s;
    return *this;
  }
  constexpr Vec2& operator/=(T s) noexcept {
    x /= s;
    y /= s;
    return *this;
  }

  friend constexpr bool operator==(const Vec2&, const Vec2&) noexcept = default;
};

template <Real T> [[nodiscard]] constexpr Vec2<T> operator-(const Vec2<T>& v) noexcept { return {-v.x, -v.y}; }
template <Real T> [[nodiscard]] constexpr Vec2<T> operator+(Vec2<T> a, const Vec2<T>& b) noexcept { return a += b; }
template <Real T> [[nodiscard]] constexpr Vec2<T> operator-(Vec2<T> a, const Vec2<T>& b) noexcept { return a -= b; }
template <Real T> [[nodiscard]] constexpr Vec2<T> operator*(Vec2<T> v, T s) noexcept { return v *= s; }
template <Real T> [[nodiscard]] constexpr Vec2<T> operator*(T s, Vec2<T> v) noexcept { return v *= s; }
template <Real T> [[nodiscard]] constexpr Vec2<T> operator/(Vec2<T> v, T s) noexcept { return v /= s; }

template <Real T> [[nodiscard]] constexpr T dot(const Vec2<T>& a, const Vec2<T>& b) noexcept {
  return a.x * b.x + a.y * b.y;
}

/// The z component of the 3D cross product (a.x, a.y, 0) x (b.x, b.y, 0).
template <Real T> [[nodiscard]] constexpr T cross(const Vec2<T>& a, const Vec2<T>& b) noexcept {
  return a.x * b.y - a.y * b.x;
}

/// (0, 0, w) x v: the velocity of a point at offset v on a body spinning at w rad/s.
template <Real T> [[nodiscard]] constexpr Vec2<T> cross(T w, const Vec2<T>& v) noexcept { return {-w * v.y, w * v.x}; }

/// v x (0, 0, w).
template <Real T> [[nodiscard]] constexpr Vec2<T> cross(const Vec2<T>& v, T w) noexcept { return {w * v.y, -w * v.x}; }

/// v rotated +90 degrees (counter-clockwise).
template <Real T> [[nodiscard]] constexpr Vec2<T> perp(const Vec2<T>& v) noexcept { return {-v.y, v.x}; }

template <Real T> [[nodiscard]] constexpr T lengthSquared(const Vec2<T>& v) noexcept { return dot(v, v); }
template <Real T> [[nodiscard]] T length(const Vec2<T>& v) noexcept { return std::sqrt(lengthSquared(v)); }
template <Real T> [[nodiscard]] T distance(const Vec2<T>& a, const Vec2<T>& b) noexcept { return length(b - a); }

/// v / |v|. A vector of (near) zero length has no direction: the result is the zero vector,
/// never NaN (the book's choice too). Non-finite input stays non-finite.
template <Real T> [[nodiscard]] Vec2<T> normalize(const Vec2<T>& v) noexcept {
  T len = length(v);
  if (std::isinf(len)) {
    len = std::hypot(v.x, v.y); // |v|^2 overflowed: slow, exact path
  }
  if (len <= normalizeTolerance<T>) {
    return {};
  }
  return v / len;
}

template <Real T> [[nodiscard]] constexpr Vec2<T> lerp(const Vec2<T>& a, const Vec2<T>& b, T t) noexcept {
  return a + (b - a) * t;
}
template <Real T> [[nodiscard]] Vec2<T> min(const Vec2<T>& a, const Vec2<T>& b) noexcept {
  return {b.x < a.x ? b.x : a.x, b.y < a.y ? b.y : a.y};
}
template <Real T> [[nodiscard]] Vec2<T> max(const Vec2<T>& a, const Vec2<T>& b) noexcept {
  return {a.x < b.x ? b.x : a.x, a.y < b.y ? b.y : a.y};
}
template <Real T> [[nodiscard]] Vec2<T> abs(const Vec2<T>& v) noexcept { return {std::abs(v.x), std::abs(v.y)}; }
template <Real T> [[nodiscard]] bool isFinite(const Vec2<T>& v) noexcept {
  return std::isfinite(v.x) && std::isfinite(v.y);
}

using Vec2f = Vec2<float>;
using Vec2d = Vec2<double>;

} // namespace impetus
