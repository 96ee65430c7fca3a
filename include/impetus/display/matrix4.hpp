// A 4x4 matrix for the display layer's projection and view matrices, in OpenGL's layout.
//
// Stored column-major (element (row r, column c) at index 4c + r), as glLoadMatrixd,
// glUniformMatrix4dv and glm expect: `data()` can be handed to OpenGL as is (convert to float for
// glUniformMatrix4fv). Points are column vectors, transformed as M p; clip coordinates divide by w.
#pragma once

#include <impetus/math/vec3.hpp>

#include <array>

namespace impetus::display {

struct Vec4d {
  double x = 0.0, y = 0.0, z = 0.0, w = 0.0;
};

struct Matrix4 {
  std::array<double, 16> m{}; ///< column-major

  [[nodiscard]] static constexpr Matrix4 identity() noexcept {
    Matrix4 r;
    r.m[0] = r.m[5] = r.m[10] = r.m[15] = 1.0;
    return r;
  }
  [[nodiscard]] constexpr double& operator()(int row, int column) noexcept { return m[4 * column + row]; }
  [[nodiscard]] constexpr double operator()(int row, int column) const noexcept { return m[4 * column + row]; }
  [[nodiscard]] const double* data() const noexcept { return m.data(); }
};

[[nodiscard]] constexpr Matrix4 operator*(const Matrix4& a, const Matrix4& b) noexcept {
  Matrix4 r;
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) {
      double s = 0.0;
      for (int k = 0; k < 4; ++k) {
        s += a(row, k) * b(k, col);
      }
      r(row, col) = s;
    }
  }
  return r;
}

[[nodiscard]] constexpr Vec4d operator*(const Matrix4& a, const Vec4d& v) noexcept {
  const double in[4] = {v.x, v.y, v.z, v.w};
  double out[4] = {0.0, 0.0, 0.0, 0.0};
  for (int row = 0; row < 4; ++row) {
    for (int k = 0; k < 4; ++k) {
      out[row] += a(row, k) * in[k];
    }
  }
  return {out[0], out[1], out[2], out[3]};
}

/// M (p, 1): a point.
[[nodiscard]] constexpr Vec4d transformPoint(const Matrix4& a, const Vec3d& p) noexcept {
  return a * Vec4d{p.x, p.y, p.z, 1.0};
}

/// Normalized device coordinates: clip / w.
[[nodiscard]] constexpr Vec3d perspectiveDivide(const Vec4d& clip) noexcept {
  return {clip.x / clip.w, clip.y / clip.w, clip.z / clip.w};
}

} // namespace impetus::display
