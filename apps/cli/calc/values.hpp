// Shared parameter parsing and output conversions for the calc models.
#pragma once

#include "calc/calc.hpp"

#include <impetus/math/mat33.hpp>

#include <optional>

namespace impetus::cli {

/// As a calc output (negative zeros, e.g. from negating a zero component, shown as 0).
[[nodiscard]] inline Vector toVector(const Vec3d& v) {
  const Vec3d w = v + Vec3d{};
  return {w.x, w.y, w.z};
}

/// Row by row.
[[nodiscard]] inline Matrix toMatrix(const Mat33d& m) {
  return {toVector(m.row(0)), toVector(m.row(1)), toVector(m.row(2))};
}

/// A vector parameter, given as "x,y,z" (commas or spaces).
[[nodiscard]] Param vectorParam(std::string name, std::string unit, std::string help,
                                std::optional<std::string> defaultValue);

/// A number the user may leave out (the model then works without it).
[[nodiscard]] Param optionalParam(std::string name, std::string unit, std::string help);

/// The value of an optionalParam, or none when it was left out.
[[nodiscard]] std::optional<double> optionalNumber(const Args& args, const std::string& name);

/// The value of a vectorParam. Throws impetus::Error naming the parameter unless it is exactly
/// three numbers.
[[nodiscard]] Vec3d vector3(const Args& args, const std::string& name);

} // namespace impetus::cli
