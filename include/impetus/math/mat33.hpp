// Mat33<T>: a 3x3 matrix stored by columns (cx, cy, cz): appendix B's Matrix3x3, used for
// rotations and inertia tensors. Element (r, c) is the book's e_{r+1,c+1}.
#pragma once

#include <impetus/error.hpp>
#include <impetus/math/vec3.hpp>

namespace impetus {

template <Real T> struct Mat33 {
  Vec3<T> cx{}; ///< first column
  Vec3<T> cy{}; ///< second column
  Vec3<T> cz{}; ///< third column

  /// The zero matrix (the book's default too; use identity() for the identity).
  constexpr Mat33() noexcept = default;
  constexpr Mat33(const Vec3<T>& c0, const Vec3<T>& c1, const Vec3<T>& c2) noexcept : cx(c0), cy(c1), cz(c2) {}
  /// Nine values in row-major order (e11, e12, e13, e21, ..., e33), as the book writes them.
  constexpr Mat33(T e11, T e12, T e13, T e21, T e22, T e23, T e31, T e32, T e33) noexcept
      : cx(e11, e21, e31), cy(e12, e22, e32), cz(e13, e23, e33) {}

  [[nodiscard]] static constexpr Mat33 identity() noexcept { return diagonal({T(1), T(1), T(1)}); }
  [[nodiscard]] static constexpr Mat33 zero() noexcept { return {}; }
  [[nodiscard]] static constexpr Mat33 diagonal(const Vec3<T>& d) noexcept {
    return {d.x, T(0), T(0), T(0), d.y, T(0), T(0), T(0), d.z};
  }
  [[nodiscard]] static constexpr Mat33 fromRows(const Vec3<T>& r0, const Vec3<T>& r1, const Vec3<T>& r2) noexcept {
    return {r0.x, r0.y, r0.z, r1.x, r1.y, r1.z, r2.x, r2.y, r2.z};
  }

  [[nodiscard]] constexpr const Vec3<T>& column(int c) const noexcept { return c == 0 ? cx : (c == 1 ? cy : cz); }
  [[nodiscard]] constexpr Vec3<T>& column(int c) noexcept { return c == 0 ? cx : (c == 1 ? cy : cz); }
  [[nodiscard]] constexpr Vec3<T> row(int r) const noexcept { return {cx[r], cy[r], cz[r]}; }
  /// Element at row r, column c (0-based).
  [[nodiscard]] constexpr T operator()(int r, int c) const noexcept { return column(c)[r]; }
  [[nodiscard]] constexpr T& operator()(int r, int c) noexcept { return column(c)[r]; }

  constexpr Mat33& operator+=(const Mat33& m) noexcept {
    cx += m.cx;
    cy += m.cy;
    cz += m.cz;
    return *this;
  }
  constexpr Mat33& operator-=(const Mat33& m) noexcept {
    cx -= m.cx;
    cy -= m.cy;
    cz -= m.cz;
    return *this;
  }
  constexpr Mat33& operator*=(T s) noexcept {
    cx *= s;
    cy *= s;
    cz *= s;
    return *this;
  }
  constexpr Mat33& operator/=(T s) noexcept {
    cx /= s;
    cy /= s;
    cz /= s;
    return *this;
  }

  friend constexpr bool operator==(const Mat33&, const Mat33&) noexcept = default;
};

template <Real T> [[nodiscard]] constexpr Mat33<T> operator-(const Mat33<T>& m) noexcept {
  return {-m.cx, -m.cy, -m.cz};
}
template <Real T> [[nodiscard]] constexpr Mat33<T> operator+(Mat33<T> a, const Mat33<T>& b) noexcept { return a += b; }
template <Real T> [[nodiscard]] constexpr Mat33<T> operator-(Mat33<T> a, const Mat33<T>& b) noexcept { return a -= b; }
template <Real T> [[nodiscard]] constexpr Mat33<T> operator*(Mat33<T> m, T s) noexcept { return m *= s; }
template <Real T> [[nodiscard]] constexpr Mat33<T> operator*(T s, Mat33<T> m) noexcept { return m *= s; }
template <Real T> [[nodiscard]] constexpr Mat33<T> operator/(Mat33<T> m, T s) noexcept { return m /= s; }

/// M u, u a column vector.
template <Real T> [[nodiscard]] constexpr Vec3<T> operator*(const Mat33<T>& m, const Vec3<T>& u) noexcept {
  return m.cx * u.x + m.cy * u.y + m.cz * u.z;
}

/// u^T M, u a row vector (= M^T u): the book's Vector * Matrix3x3.
template <Real T> [[nodiscard]] constexpr Vec3<T> operator*(const Vec3<T>& u, const Mat33<T>& m) noexcept {
  return {dot(u, m.cx), dot(u, m.cy), dot(u, m.cz)};
}

/// Matrix product (AB)_ij = sum_k a_ik b_kj.
template <Real T> [[nodiscard]] constexpr Mat33<T> operator*(const Mat33<T>& a, const Mat33<T>& b) noexcept {
  return {a * b.cx, a * b.cy, a * b.cz};
}

template <Real T> [[nodiscard]] constexpr Mat33<T> transpose(const Mat33<T>& m) noexcept {
  return Mat33<T>::fromRows(m.cx, m.cy, m.cz);
}

/// det M = c0 . (c1 x c2).
template <Real T> [[nodiscard]] constexpr T determinant(const Mat33<T>& m) noexcept {
  return tripleScalarProduct(m.cx, m.cy, m.cz);
}

template <Real T> [[nodiscard]] constexpr T trace(const Mat33<T>& m) noexcept { return m.cx.x + m.cy.y + m.cz.z; }

/// M^-1 as the adjugate over the determinant. Throws impetus::Error when det(M) is zero or not
/// finite: the book's Inverse() silently returns the adjugate (it sets det = 1), which turns a
/// degenerate inertia tensor into a wrong but plausible one.
template <Real T> [[nodiscard]] Mat33<T> inverse(const Mat33<T>& m) {
  const T det = determinant(m);
  if (det == T(0) || !std::isfinite(det)) {
    throwInvalid("determinant", static_cast<double>(det), "matrix is singular and has no inverse");
  }
  // The rows of the inverse are the cross products of the columns, divided by det.
  const T inv = T(1) / det;
  return Mat33<T>::fromRows(cross(m.cy, m.cz) * inv, cross(m.cz, m.cx) * inv, cross(m.cx, m.cy) * inv);
}

/// Solves M x = b. Throws impetus::Error when M is singular.
template <Real T> [[nodiscard]] Vec3<T> solve(const Mat33<T>& m, const Vec3<T>& b) { return inverse(m) * b; }

/// The cross-product matrix: skew(a) b = a x b.
template <Real T> [[nodiscard]] constexpr Mat33<T> skew(const Vec3<T>& a) noexcept {
  return {T(0), -a.z, a.y, a.z, T(0), -a.x, -a.y, a.x, T(0)};
}

/// a b^T.
template <Real T> [[nodiscard]] constexpr Mat33<T> outer(const Vec3<T>& a, const Vec3<T>& b) noexcept {
  return {a * b.x, a * b.y, a * b.z};
}

/// Re-orthonormalizes a rotation matrix that has drifted (Gram-Schmidt on the columns, keeping
/// the first column's direction and a right-handed frame).
template <Real T> [[nodiscard]] Mat33<T> orthonormalize(const Mat33<T>& m) noexcept {
  const Vec3<T> x = normalize(m.cx);
  const Vec3<T> z = normalize(cross(x, m.cy));
  const Vec3<T> y = cross(z, x);
  return {x, y, z};
}

/// Rotation matrices about one axis (right-handed: positive angles turn +y toward +z about x,
/// +z toward +x about y, +x toward +y about z). Radians.
template <Real T> [[nodiscard]] Mat33<T> rotationX(T angle) noexcept {
  const T c = std::cos(angle);
  const T s = std::sin(angle);
  return {T(1), T(0), T(0), T(0), c, -s, T(0), s, c};
}
template <Real T> [[nodiscard]] Mat33<T> rotationY(T angle) noexcept {
  const T c = std::cos(angle);
  const T s = std::sin(angle);
  return {c, T(0), s, T(0), T(1), T(0), -s, T(0), c};
}
template <Real T> [[nodiscard]] Mat33<T> rotationZ(T angle) noexcept {
  const T c = std::cos(angle);
  const T s = std::sin(angle);
  return {c, -s, T(0), s, c, T(0), T(0), T(0), T(1)};
}

template <Real T> [[nodiscard]] bool isFinite(const Mat33<T>& m) noexcept {
  return isFinite(m.cx) && isFinite(m.cy) && isFinite(m.cz);
}

using Mat33f = Mat33<float>;
using Mat33d = Mat33<double>;

} // namespace impetus
