// Input checks for the math types: each throws impetus::Error naming the first non-finite
// component ("velocity.y = nan: must be finite") and returns its argument otherwise.
#pragma once

#include <impetus/error.hpp>
#include <impetus/math/mat33.hpp>
#include <impetus/math/vec2.hpp>

#include <string>

namespace impetus {

template <Real T> const Vec2<T>& requireFinite(const Vec2<T>& v, std::string_view field) {
  if (!isFinite(v)) {
    const bool badX = !std::isfinite(v.x);
    throwInvalid(std::string(field) + (badX ? ".x" : ".y"), static_cast<double>(badX ? v.x : v.y), "must be finite");
  }
  return v;
}

template <Real T> const Vec3<T>& requireFinite(const Vec3<T>& v, std::string_view field) {
  if (!isFinite(v)) {
    const int i = !std::isfinite(v.x) ? 0 : (!std::isfinite(v.y) ? 1 : 2);
    throwInvalid(std::string(field) + "." + "xyz"[i], static_cast<double>(v[i]), "must be finite");
  }
  return v;
}

template <Real T> const Mat33<T>& requireFinite(const Mat33<T>& m, std::string_view field) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(m(r, c))) {
        throwInvalid(std::string(field) + "(" + std::to_string(r) + "," + std::to_string(c) + ")",
                     static_cast<double>(m(r, c)), "must be finite");
      }
    }
  }
  return m;
}

} // namespace impetus
