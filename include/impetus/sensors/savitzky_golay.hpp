// Savitzky-Golay smoothing differentiators (ch. 25): derivatives of noisy tracked positions.
//
// Differencing raw positions amplifies the tracker's noise (finite_difference.hpp). Savitzky and
// Golay (Anal. Chem. 36, 1627, 1964) fit a polynomial of degree p by least squares to the 2m + 1
// samples around a point and take the fit's value or derivative there. The fit is linear in the
// samples, so it is a fixed convolution:
//   x^(d)(t_i) ~ (1 / h^d) sum_{k=-m..m} c_k x_{i+k}
// with c = the d-th derivative at t = 0 of the least-squares polynomial, d! [(A^T A)^-1 A^T]_d,
// A_kj = k^j. It is exact for polynomials of degree <= p and averages noise over the window
// (the 5-point quadratic first derivative, (-2, -1, 0, 1, 2)/10h, has sqrt(10)/10 = 0.32 of the
// noise gain of the central difference's 1/(2h) x sqrt(2) = 0.71). For the newest sample (real
// time, no future data) the same fit is evaluated at the window's end (`atOffset(m)`): no lag,
// more noise.
//
// Samples must be evenly spaced (h). The coefficients are computed in double with the abscissae
// scaled to [-1, 1] for conditioning.
#pragma once

#include <span>
#include <vector>

namespace impetus::sensors {

class SavitzkyGolay {
public:
  /// Window 2 halfWidth + 1 samples (1 <= halfWidth <= 100), polynomial degree `order`
  /// (0 <= order <= min(2 halfWidth, 10)), derivative 0 <= derivative <= order. Throws
  /// impetus::Error naming "halfWidth", "order" or "derivative".
  SavitzkyGolay(int halfWidth, int order, int derivative = 0);

  /// c_k for k = -m..m, evaluated at the window's centre (divide the sum by h^d).
  [[nodiscard]] std::span<const double> coefficients() const noexcept { return centre_; }
  /// c_k evaluated at offset `offset` in [-m, m] from the centre (m: the newest sample).
  [[nodiscard]] std::vector<double> atOffset(int offset) const;

  /// The derivative at the window's centre from 2m + 1 samples spaced h > 0 apart. Throws
  /// impetus::Error naming "window" (wrong size or a non-finite value) or "h".
  [[nodiscard]] double apply(std::span<const double> window, double h) const;
  /// The derivative at the newest (last) sample of the window.
  [[nodiscard]] double applyLatest(std::span<const double> window, double h) const;

  /// The derivative at every sample of an evenly spaced series (at least 2m + 1 samples): the
  /// centred fit inside, the same end windows evaluated off centre for the first and last m.
  [[nodiscard]] std::vector<double> filter(std::span<const double> series, double h) const;

  [[nodiscard]] int halfWidth() const noexcept { return m_; }
  [[nodiscard]] int order() const noexcept { return p_; }
  [[nodiscard]] int derivative() const noexcept { return d_; }

private:
  int m_;
  int p_;
  int d_;
  std::vector<double> projector_; ///< (p+1) x (2m+1): (A^T A)^-1 A^T on scaled abscissae, row by row
  std::vector<double> centre_;
  std::vector<double> latest_;
  [[nodiscard]] double dot(std::span<const double> c, std::span<const double> window, double h) const;
};

} // namespace impetus::sensors
