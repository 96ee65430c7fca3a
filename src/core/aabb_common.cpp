// The error of an invalid box, for the 2D and the 3D boxes alike: which component is bad.
#include <impetus/core/aabb_common.hpp>
#include <impetus/error.hpp>

#include <cmath>
#include <string>

namespace impetus {

void throwInvalidBounds(std::string_view field, std::span<const float> lower, std::span<const float> upper) {
  const auto name = [&](std::string_view corner, std::size_t i) {
    return std::string(field).append(".").append(corner).append(".").append(1, "xyz"[i]);
  };
  for (std::size_t i = 0; i < lower.size(); ++i) {
    if (!std::isfinite(lower[i])) {
      throwInvalid(name("lower", i), static_cast<double>(lower[i]), "must be finite");
    }
  }
  for (std::size_t i = 0; i < upper.size(); ++i) {
    if (!std::isfinite(upper[i])) {
      throwInvalid(name("upper", i), static_cast<double>(upper[i]), "must be finite");
    }
  }
  for (std::size_t i = 0; i < lower.size(); ++i) {
    if (upper[i] < lower[i]) {
      throwInvalid(name("upper", i), static_cast<double>(upper[i]), "must be >= " + name("lower", i));
    }
  }
  throwInvalid(field, 0.0, "must be a valid box"); // not reached: the caller's isValid failed
}

} // namespace impetus
