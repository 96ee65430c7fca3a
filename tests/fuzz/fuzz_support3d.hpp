// What the 3D harnesses (fuzz_hull3d, fuzz_manifold3d) share on top of fuzz_support.hpp: vectors
// and rotations from the fuzzer's bytes, double-precision helpers for the checks, and the
// failure messages' formatting.
#pragma once

#include "fuzz_support.hpp"

#include <impetus/math/quat.hpp>
#include <impetus/math/transform3.hpp>
#include <impetus/math/vec3.hpp>

#include <cmath>
#include <cstdio>
#include <span>
#include <string>

namespace impetus::fuzz {

/// A vector of three bounded() floats: finite, each within [-bound, bound].
[[nodiscard]] inline Vec3f vec3(Reader& in, float bound) {
  const float x = in.bounded(bound);
  const float y = in.bounded(bound);
  const float z = in.bounded(bound);
  return {x, y, z};
}

/// A vector of three rawFloat()s: any bit pattern (NaN, infinities, 1e38, denormals).
[[nodiscard]] inline Vec3f rawVec3(Reader& in) {
  const float x = in.rawFloat();
  const float y = in.rawFloat();
  const float z = in.rawFloat();
  return {x, y, z};
}

/// A unit quaternion: four bounded components normalised (normalize() gives the identity for
/// the zero quaternion), or exactly the identity.
[[nodiscard]] inline Quatf rotation(Reader& in) {
  const float w = in.bounded(1.0f);
  const float x = in.bounded(1.0f);
  const float y = in.bounded(1.0f);
  const float z = in.bounded(1.0f);
  return normalize(Quatf{w, x, y, z});
}

/// Checks in double: the library's floats, widened.
struct V3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};
inline V3 d3(const Vec3f& v) { return {v.x, v.y, v.z}; }
inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double len(V3 a) { return std::sqrt(dot(a, a)); }
inline bool finite(V3 a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

inline std::string str(const Vec3f& v) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.9g, %.9g, %.9g)", static_cast<double>(v.x), static_cast<double>(v.y),
                static_cast<double>(v.z));
  return buffer;
}
inline std::string str(const Quatf& q) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "[%.9g, %.9g, %.9g, %.9g]", static_cast<double>(q.w), static_cast<double>(q.x),
                static_cast<double>(q.y), static_cast<double>(q.z));
  return buffer;
}
inline std::string str(const Transform3f& xf) { return "p " + str(xf.p) + " q " + str(xf.q); }

inline std::string describe(std::span<const Vec3f> points) {
  std::string s;
  for (const Vec3f& p : points) {
    s += s.empty() ? "" : " ";
    s += str(p);
  }
  return s;
}

} // namespace impetus::fuzz
