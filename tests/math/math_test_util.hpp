// Shared helpers for the math tests: gtest printers for the math types, tolerant comparisons
// that report both values on failure, and a seeded random source for the identity tests.
#pragma once

#include <impetus/error.hpp>
#include <impetus/math/math.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <ostream>
#include <random>
#include <string>

namespace impetus {

// gtest finds these by argument-dependent lookup when it prints a failing value.
template <Real T> void PrintTo(const Vec2<T>& v, std::ostream* os) {
  os->precision(std::numeric_limits<T>::max_digits10);
  *os << "(" << v.x << ", " << v.y << ")";
}
template <Real T> void PrintTo(const Vec3<T>& v, std::ostream* os) {
  os->precision(std::numeric_limits<T>::max_digits10);
  *os << "(" << v.x << ", " << v.y << ", " << v.z << ")";
}
template <Real T> void PrintTo(const Quat<T>& q, std::ostream* os) {
  os->precision(std::numeric_limits<T>::max_digits10);
  *os << "(w " << q.w << "; " << q.x << ", " << q.y << ", " << q.z << ")";
}
template <Real T> void PrintTo(const Mat22<T>& m, std::ostream* os) {
  os->precision(std::numeric_limits<T>::max_digits10);
  *os << "[[" << m(0, 0) << ", " << m(0, 1) << "], [" << m(1, 0) << ", " << m(1, 1) << "]]";
}
template <Real T> void PrintTo(const Mat33<T>& m, std::ostream* os) {
  os->precision(std::numeric_limits<T>::max_digits10);
  *os << "[";
  for (int r = 0; r < 3; ++r) {
    *os << (r == 0 ? "[" : ", [") << m(r, 0) << ", " << m(r, 1) << ", " << m(r, 2) << "]";
  }
  *os << "]";
}
template <Real T> void PrintTo(const EulerAngles<T>& e, std::ostream* os) {
  os->precision(std::numeric_limits<T>::max_digits10);
  *os << "(yaw " << e.yaw << ", pitch " << e.pitch << ", roll " << e.roll << ")";
}
template <Real T> void PrintTo(const Rot2<T>& r, std::ostream* os) {
  os->precision(std::numeric_limits<T>::max_digits10);
  *os << "Rot2(c " << r.c << ", s " << r.s << ")";
}

namespace test {

template <typename V> std::string show(const V& v) { return ::testing::PrintToString(v); }

// Largest absolute component difference. Unlike std::fmax, worse() propagates NaN, and the
// callers test d <= tol, so a NaN anywhere fails the comparison instead of passing it.
template <Real T> T worse(T a, T b) { return (a > b || std::isnan(a)) ? a : b; }
template <Real T> T maxDiff(const Vec2<T>& a, const Vec2<T>& b) {
  return worse(std::abs(a.x - b.x), std::abs(a.y - b.y));
}
template <Real T> T maxDiff(const Vec3<T>& a, const Vec3<T>& b) {
  return worse(std::abs(a.x - b.x), worse(std::abs(a.y - b.y), std::abs(a.z - b.z)));
}
template <Real T> T maxDiff(const Quat<T>& a, const Quat<T>& b) {
  return worse(worse(std::abs(a.w - b.w), std::abs(a.x - b.x)), worse(std::abs(a.y - b.y), std::abs(a.z - b.z)));
}
template <Real T> T maxDiff(const Mat22<T>& a, const Mat22<T>& b) {
  return worse(maxDiff(a.cx, b.cx), maxDiff(a.cy, b.cy));
}
template <Real T> T maxDiff(const Mat33<T>& a, const Mat33<T>& b) {
  return worse(maxDiff(a.cx, b.cx), worse(maxDiff(a.cy, b.cy), maxDiff(a.cz, b.cz)));
}
template <Real T> T maxDiff(const Rot2<T>& a, const Rot2<T>& b) {
  return worse(std::abs(a.c - b.c), std::abs(a.s - b.s));
}

/// Every component of `actual` within `tol` of `expected` (absolute); NaN never passes.
template <typename V, Real T>::testing::AssertionResult isNear(const V& actual, const V& expected, T tol) {
  const T d = maxDiff(actual, expected);
  if (d <= tol) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << show(actual) << " differs from " << show(expected) << " by " << d << " > "
                                       << tol;
}

/// The distance between two rotations up to the quaternion sign: min(|p - q|, |p + q|), taken
/// component-wise. Unlike 1 - |dot(p, q)|, which is quadratic in the error, this is linear, so
/// a tolerance on it means the same thing as a tolerance on the components.
template <Real T> T rotationDiff(const Quat<T>& p, const Quat<T>& q) {
  const T plus = maxDiff(p, q);
  const T minus = maxDiff(p, -q);
  return (std::isnan(plus) || std::isnan(minus)) ? std::numeric_limits<T>::quiet_NaN() : std::fmin(plus, minus);
}

template <Real T>::testing::AssertionResult sameRotation(const Quat<T>& actual, const Quat<T>& expected, T tol) {
  const T d = rotationDiff(actual, expected);
  if (d <= tol) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << show(actual) << " is not +-" << show(expected) << ": off by " << d << " > "
                                       << tol;
}

/// The angle of the rotation that takes p to q, in [0, pi]. atan2 of the relative quaternion's
/// vector and scalar parts keeps full accuracy for small angles, where 2 acos(|dot|) would not.
template <Real T> T relativeAngle(const Quat<T>& p, const Quat<T>& q) {
  const Quat<T> r = conjugate(p) * q;
  return T(2) * std::atan2(length(r.vector()), std::abs(r.w));
}

/// a - b wrapped into [-pi, pi]: the difference of two angles on the circle.
inline double angleDiff(double a, double b) { return std::remainder(a - b, 2.0 * pi<double>); }

/// The message of the impetus::Error that `f` throws, or a marker when it throws none.
inline std::string errorMessageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "<no impetus::Error thrown>";
}

/// Seeded inputs for the identity tests: the same values on every run and platform family.
class Random {
public:
  explicit Random(std::uint32_t seed = 20240611U) : gen_(seed) {}

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen_); }

  Vec2d vec2(double lo = -10.0, double hi = 10.0) { return {uniform(lo, hi), uniform(lo, hi)}; }
  Vec3d vec3(double lo = -10.0, double hi = 10.0) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }

  /// A uniformly distributed random rotation (Shoemake's subgroup algorithm).
  Quatd unitQuat() {
    const double u1 = uniform(0.0, 1.0);
    const double u2 = uniform(0.0, 2.0 * pi<double>);
    const double u3 = uniform(0.0, 2.0 * pi<double>);
    const double a = std::sqrt(1.0 - u1);
    const double b = std::sqrt(u1);
    return {a * std::cos(u2), a * std::sin(u2), b * std::cos(u3), b * std::sin(u3)};
  }

  /// A unit vector, uniform on the sphere.
  Vec3d unitVec3() { return rotate(unitQuat(), Vec3d::unitX()); }

  /// Entries uniform in [lo, hi].
  Mat33d mat33(double lo = -1.0, double hi = 1.0) {
    return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi), uniform(lo, hi), uniform(lo, hi),
            uniform(lo, hi), uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)};
  }

  /// Random entries in [-1, 1] plus 4 I: strictly diagonally dominant (diagonal >= 3, each row's
  /// other entries sum to <= 2), so ||M||_inf <= 7 and ||M^-1||_inf <= 1: condition number <= 7,
  /// which keeps inverse identities accurate to a few hundred ulps.
  Mat33d wellConditioned33() { return mat33() + 4.0 * Mat33d::identity(); }
  Mat22d wellConditioned22() {
    return Mat22d{uniform(-1.0, 1.0), uniform(-1.0, 1.0), uniform(-1.0, 1.0), uniform(-1.0, 1.0)} +
           3.0 * Mat22d::identity();
  }

private:
  std::mt19937 gen_;
};

/// Number of random cases per identity test.
inline constexpr int kCases = 200;

} // namespace test
} // namespace impetus
