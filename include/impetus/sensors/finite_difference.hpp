// Finite differences (ch. 25): velocity and acceleration from sampled positions.
//
// A tracker (a camera, Kinect) gives positions x_i at times t_i, 20-30 times a second. The
// derivatives come from Taylor's series x(t +- h) = x +- h x' + h^2 x''/2 +- h^3 x'''/6 + ...:
//   backward  v_i = (x_i - x_{i-1}) / h                       error -h x''/2:   O(h)  (past data only: real time)
//   forward   v_i = (x_{i+1} - x_i) / h                       error +h x''/2:   O(h)
//   central   v_i = (x_{i+1} - x_{i-1}) / (2h)                error h^2 x'''/6: O(h^2)
//   second    a_i = (x_{i+1} - 2 x_i + x_{i-1}) / h^2         error h^2 x''''/12: O(h^2)
// The book's findAcceleration applies the second difference to the three latest samples (so it
// is the acceleration at the middle one, one sample late) but divides by h, not h^2: its result
// is h times too small and in m/s, not m/s^2 (`bookFindAcceleration` keeps it for the errata).
// With uneven steps h1 = t_i - t_{i-1}, h2 = t_{i+1} - t_i:
//   v_i = (h1^2 x_{i+1} + (h2^2 - h1^2) x_i - h2^2 x_{i-1}) / (h1 h2 (h1 + h2))   O(h^2)
//   a_i = 2 [(x_{i+1} - x_i)/h2 - (x_i - x_{i-1})/h1] / (h1 + h2)                 O(h) (O(h^2) when even)
// Differencing amplifies noise: by ~1/h for velocity and ~1/h^2 for acceleration, so smooth first
// (savitzky_golay.hpp). And sample faster than twice the motion's frequency: sin(2 pi t / T)
// sampled at h = T or T/2 has a central slope of zero everywhere (aliasing).
//
// Each function works on doubles, Vec2d or Vec3d, and throws impetus::Error (field "h", "h1" or
// "h2") unless the steps are finite and positive, or "x" ("x.y" for a vector's component) when a sample is not finite.
#pragma once

#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/math/vec2.hpp>
#include <impetus/math/vec3.hpp>

#include <initializer_list>

namespace impetus::sensors {

namespace detail {
/// "x = nan: must be finite" (a vector sample names its component, "x.y").
template <class V> void requireSamples(std::initializer_list<V> xs) {
  for (const V& x : xs) {
    requireFinite(x, "x");
  }
}
} // namespace detail

template <class V> [[nodiscard]] V backwardDifference(const V& previous, const V& current, double h) {
  requirePositive(h, "h");
  detail::requireSamples<V>({previous, current});
  return (current - previous) * (1.0 / h);
}

template <class V> [[nodiscard]] V forwardDifference(const V& current, const V& next, double h) {
  requirePositive(h, "h");
  detail::requireSamples<V>({current, next});
  return (next - current) * (1.0 / h);
}

template <class V> [[nodiscard]] V centralDifference(const V& previous, const V& next, double h) {
  requirePositive(h, "h");
  detail::requireSamples<V>({previous, next});
  return (next - previous) * (0.5 / h);
}

template <class V> [[nodiscard]] V secondDifference(const V& previous, const V& current, const V& next, double h) {
  requirePositive(h, "h");
  detail::requireSamples<V>({previous, current, next});
  return (next - current * 2.0 + previous) * (1.0 / (h * h));
}

/// The book's findAcceleration(x_{i-2}, x_{i-1}, x_i, h): the second difference divided by h.
[[nodiscard]] inline double bookFindAcceleration(double x0, double x1, double x2, double h) noexcept {
  return (x2 - 2.0 * x1 + x0) / h;
}

template <class V>
[[nodiscard]] V centralDifferenceUneven(const V& previous, const V& current, const V& next, double h1, double h2) {
  requirePositive(h1, "h1");
  requirePositive(h2, "h2");
  detail::requireSamples<V>({previous, current, next});
  return (next * (h1 * h1) + current * (h2 * h2 - h1 * h1) - previous * (h2 * h2)) * (1.0 / (h1 * h2 * (h1 + h2)));
}

template <class V>
[[nodiscard]] V secondDifferenceUneven(const V& previous, const V& current, const V& next, double h1, double h2) {
  requirePositive(h1, "h1");
  requirePositive(h2, "h2");
  detail::requireSamples<V>({previous, current, next});
  return ((next - current) * (1.0 / h2) - (current - previous) * (1.0 / h1)) * (2.0 / (h1 + h2));
}

} // namespace impetus::sensors
