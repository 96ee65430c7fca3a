// Mat22<T>: a 2x2 matrix stored by columns (cx, cy), for 2D constraint blocks and rotations.
#pragma once

#include <impetus/error.hpp>
#include <impetus/math/vec2.hpp>

namespace impetus {

template <Real T> struct Mat22 {
  Vec2<T> cx{}; ///< first column
  Vec2<T> cy{}; ///< second column

  constexpr Mat22() noexcept = default;
  constexpr Mat22(const Vec2<T>& c0, const Vec2<T>& c1) noexcept : cx(c0), cy(c1) {}
  /// Row-major element order, as a matrix is written on paper: [[a11, a12], [a21, a22]].
  constexpr Mat22(T a11, T a12, T a21, T a22) noexcept : cx(a11, a21), cy(a12, a22) {}

  [[nodiscard]] static constexpr Mat22 identity() noexcept { return {T(1), T(0), T(0), T(1)}; }
  [[nodiscard]] static constexpr Mat22 zero() noexcept { return {}; }

  /// Element at row r, column c (0-based).
  [[nodiscard]] constexpr T operator()(int r, int c) const noexcept {
    const Vec2<T>& col = c == 0 ? cx : cy;
    return r == 0 ? col.x : col.y;
  }

  constexpr Mat22& operator+=(const Mat22& m) noexcept {
    cx += m.cx;
    cy += m.cy;
    return *this;
  }
  constexpr Mat22& operator-=(const Mat22& m) noexcept {
    cx -= m.cx;
    cy -= m.cy;
    return *this;
  }
  constexpr Mat22& operator*=(T s) noexcept {
    cx *= s;
    cy *= s;
    return *this;
  }
  constexpr Mat22& operator/=(T s) noexcept {
    cx /= s;
    cy /= s;
    return *this;
  }

  friend constexpr bool operator==(const Mat22&, const Mat22&) noexcept = default;
};

template <Real T> [[nodiscard]] constexpr Mat22<T> operator+(Mat22<T> a, const Mat22<T>& b) noexcept { return a += b; }
template <Real T> [[nodiscard]] constexpr Mat22<T> operator-(Mat22<T> a, const Mat22<T>& b) noexcept { return a -= b; }
template <Real T> [[nodiscard]] constexpr Mat22<T> operator*(Mat22<T> m, T s) noexcept { return m *= s; }
template <Real T> [[nodiscard]] constexpr Mat22<T> operator*(T s, Mat22<T> m) noexcept { return m *= s; }
template <Real T> [[nodiscard]] constexpr Mat22<T> operator/(Mat22<T> m, T s) noexcept { return m /= s; }

/// M v (v as a column vector).
template <Real T> [[nodiscard]] constexpr Vec2<T> operator*(const Mat22<T>& m, const Vec2<T>& v) noexcept {
  return m.cx * v.x + m.cy * v.y;
}

template <Real T> [[nodiscard]] constexpr Mat22<T> operator*(const Mat22<T>& a, const Mat22<T>& b) noexcept {
  return {a * b.cx, a * b.cy};
}

template <Real T> [[nodiscard]] constexpr Mat22<T> transpose(const Mat22<T>& m) noexcept {
  return {m.cx.x, m.cx.y, m.cy.x, m.cy.y};
}

template <Real T> [[nodiscard]] constexpr T determinant(const Mat22<T>& m) noexcept {
  return m.cx.x * m.cy.y - m.cy.x * m.cx.y;
}

/// M^-1. Throws impetus::Error when det(M) is zero or not finite (the book would silently
/// return the adjugate).
template <Real T> [[nodiscard]] Mat22<T> inverse(const Mat22<T>& m) {
  const T det = determinant(m);
  if (det == T(0) || !std::isfinite(det)) {
    throwInvalid("determinant", static_cast<double>(det), "matrix is singular and has no inverse");
  }
  const T inv = T(1) / det;
  return {m.cy.y * inv, -m.cy.x * inv, -m.cx.y * inv, m.cx.x * inv};
}

/// Solves M x = b. Throws impetus::Error when M is singular.
template <Real T> [[nodiscard]] Vec2<T> solve(const Mat22<T>& m, const Vec2<T>& b) { return inverse(m) * b; }

/// The rotation matrix for a counter-clockwise angle in radians.
template <Real T> [[nodiscard]] Mat22<T> rotation22(T angle) noexcept {
  const T c = std::cos(angle);
  const T s = std::sin(angle);
  return {c, -s, s, c};
}

using Mat22f = Mat22<float>;
using Mat22d = Mat22<double>;

} // namespace impetus
