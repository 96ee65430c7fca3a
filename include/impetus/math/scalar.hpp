// Scalar helpers shared by the math types: constants, angle conversion, tolerant comparison.
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

} // namespace impetus
