// Scalar helpers shared by the math types: constants, angle conversion, tolerant comparison, and
// an arctangent that gives the same bits on every platform.
#pragma once

#include <cmath>
#include <concepts>
#include <limits>
#include <numbers>

namespace impetus {

/// The math types are templated on a floating-point scalar: float for the game worlds, double
/// for the models where accuracy matters.
template <typename T>
concept Real = std::floating_point<T>;

template <Real T> inline constexpr T pi = std::numbers::pi_v<T>;

template <Real T> [[nodiscard]] constexpr T degToRad(T degrees) noexcept { return degrees * (pi<T> / T(180)); }

template <Real T> [[nodiscard]] constexpr T radToDeg(T radians) noexcept { return radians * (T(180) / pi<T>); }

/// |a - b| <= absTol + relTol * max(|a|, |b|).
template <Real T> [[nodiscard]] bool nearlyEqual(T a, T b, T absTol = T(1e-6), T relTol = T(1e-6)) noexcept {
  return std::abs(a - b) <= absTol + relTol * std::fmax(std::abs(a), std::abs(b));
}

/// Lengths at or below this are treated as zero when normalizing: just above the length whose
/// square underflows (about 1e-19 for float, 1e-154 for double), so any vector longer than it
/// normalizes to full precision.
template <Real T> inline constexpr T normalizeTolerance = sizeof(T) <= sizeof(float) ? T(1e-18) : T(1e-150);

/// atan2(y, x) in [-pi, pi], for the solvers' angles: the same bits on every platform and
/// compiler (a C library's atan2f may round differently: the step's results must not), and
/// faster. The octant's ratio a = min/max in [0, 1] is brought to |a| <= tan(pi/8) by
/// atan(a) = pi/4 + atan((a - 1)/(a + 1)), where Cephes' atanf polynomial is accurate to a few
/// units in the last place; the error is within 3e-7 rad of the exact value (libm's float
/// atan2f: 2.5e-7); 0 for (0, 0) and NaN for a NaN.
[[nodiscard]] inline float portableAtan2(float y, float x) noexcept {
  if (std::isnan(x) || std::isnan(y)) {
    return std::numeric_limits<float>::quiet_NaN();
  }
  const float ax = std::abs(x);
  const float ay = std::abs(y);
  const float largest = ax > ay ? ax : ay;
  if (largest == 0.0f) {
    return 0.0f;
  }
  float a = (ax > ay ? ay : ax) / largest; // in [0, 1] (an infinity over itself: NaN, as 0/0 is not)
  float angle = 0.0f;
  constexpr float tanEighthTurn = 0.41421356f; // tan(pi/8)
  if (a > tanEighthTurn) {
    a = (a - 1.0f) / (a + 1.0f);
    angle = 0.25f * pi<float>;
  }
  const float z = a * a;
  angle += (((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z - 3.33329491539e-1f) * z * a + a;
  if (ay > ax) {
    angle = 0.5f * pi<float> - angle;
  }
  if (x < 0.0f) {
    angle = pi<float> - angle;
  }
  return std::signbit(y) ? -angle : angle; // (-0, -1): -pi, as atan2
}

} // namespace impetus
