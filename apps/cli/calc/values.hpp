// Conversions from the math types to calc output values.
#pragma once

#include "calc/calc.hpp"

#include <impetus/math/mat33.hpp>

namespace impetus::cli {

[[nodiscard]] inline Vector toVector(const Vec3d& v) { return {v.x, v.y, v.z}; }

/// Row by row.
[[nodiscard]] inline Matrix toMatrix(const Mat33d& m) {
  return {toVector(m.row(0)), toVector(m.row(1)), toVector(m.row(2))};
}

} // namespace impetus::cli
