// Eigen-decomposition of a symmetric 3x3 matrix by cyclic Jacobi rotations: the principal
// moments and axes of an inertia tensor. Jacobi is slower than a closed-form cubic but accurate
// to rounding for every input, including repeated eigenvalues, and fully deterministic.
#pragma once

#include <impetus/math/mat33.hpp>

#include <utility>

namespace impetus {

template <Real T> struct SymmetricEigen3 {
  Vec3<T> values;   ///< eigenvalues in ascending order
  Mat33<T> vectors; ///< unit eigenvectors as columns (column i belongs to values[i]); det = +1
};

/// Eigenvalues and eigenvectors of the symmetric part of `m` (m is assumed symmetric; only
/// its upper triangle is read). A = V diag(values) V^T.
template <Real T> [[nodiscard]] SymmetricEigen3<T> symmetricEigen(const Mat33<T>& m) noexcept {
  T a[3][3];
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      a[r][c] = r <= c ? m(r, c) : m(c, r);
    }
  }
  Mat33<T> v = Mat33<T>::identity();
  for (int sweep = 0; sweep < 32; ++sweep) {
    const T off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const T diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off <= std::numeric_limits<T>::min() ||
        off <= diag * std::numeric_limits<T>::epsilon() * std::numeric_limits<T>::epsilon()) {
      break;
    }
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        const T apq = a[p][q];
        if (apq == T(0)) {
          continue;
        }
        // Rotation angle that zeroes a[p][q]: tan(2 theta) = 2 a_pq / (a_qq - a_pp), taking the
        // smaller root for t = tan(theta) (Numerical Recipes' stable form).
        const T theta = (a[q][q] - a[p][p]) / (T(2) * apq);
        const T t = std::copysign(T(1), theta) / (std::abs(theta) + std::sqrt(theta * theta + T(1)));
        const T c = T(1) / std::sqrt(t * t + T(1));
        const T s = t * c;
        for (auto& row : a) {
          // A' = J^T A J: first A J (columns p and q of every row)...
          const T akp = row[p];
          const T akq = row[q];
          row[p] = c * akp - s * akq;
          row[q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) { // ...then J^T (A J): rows p and q.
          const T apk = a[p][k];
          const T aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {
          const T vkp = v(k, p);
          const T vkq = v(k, q);
          v(k, p) = c * vkp - s * vkq;
          v(k, q) = s * vkp + c * vkq;
        }
      }
    }
  }
  // Sort ascending (three elements: a fixed exchange network keeps it deterministic).
  Vec3<T> values{a[0][0], a[1][1], a[2][2]};
  const auto order = [&](int i, int j) {
    if (values[j] < values[i]) {
      std::swap(values[i], values[j]);
      std::swap(v.column(i), v.column(j));
    }
  };
  order(0, 1);
  order(1, 2);
  order(0, 1);
  if (determinant(v) < T(0)) {
    v.cz = -v.cz;
  }
  return {values, v};
}

using SymmetricEigen3f = SymmetricEigen3<float>;
using SymmetricEigen3d = SymmetricEigen3<double>;

} // namespace impetus
