#include <impetus/error.hpp>
#include <impetus/sensors/savitzky_golay.hpp>

#include <algorithm>
#include <cmath>

namespace impetus::sensors {

SavitzkyGolay::SavitzkyGolay(int halfWidth, int order, int derivative) : m_(halfWidth), p_(order), d_(derivative) {
  if (halfWidth < 1 || halfWidth > 100) {
    throwInvalid("halfWidth", halfWidth, "must be 1 to 100 (window 3 to 201 samples)");
  }
  if (order < 0 || order > std::min(2 * halfWidth, 10)) {
    throwInvalid("order", order, "must be 0 to min(2 halfWidth, 10): the window must determine the polynomial");
  }
  if (derivative < 0 || derivative > order) {
    throwInvalid("derivative", derivative, "must be 0 to order (a degree-p fit has no higher derivative)");
  }
  const auto n = static_cast<std::size_t>(2 * m_ + 1);
  const auto q = static_cast<std::size_t>(p_ + 1);
  // A_kj = u_k^j with u_k = k / m in [-1, 1].
  std::vector<double> a(n * q);
  for (std::size_t k = 0; k < n; ++k) {
    const double u = (static_cast<double>(k) - m_) / m_;
    double power = 1.0;
    for (std::size_t j = 0; j < q; ++j) {
      a[k * q + j] = power;
      power *= u;
    }
  }
  // Solve (A^T A) P = A^T by Gaussian elimination with partial pivoting on [G | A^T].
  const std::size_t width = q + n;
  std::vector<double> m(q * width, 0.0);
  for (std::size_t i = 0; i < q; ++i) {
    for (std::size_t j = 0; j < q; ++j) {
      double s = 0.0;
      for (std::size_t k = 0; k < n; ++k) {
        s += a[k * q + i] * a[k * q + j];
      }
      m[i * width + j] = s;
    }
    for (std::size_t k = 0; k < n; ++k) {
      m[i * width + q + k] = a[k * q + i];
    }
  }
  for (std::size_t col = 0; col < q; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < q; ++r) {
      if (std::abs(m[r * width + col]) > std::abs(m[pivot * width + col])) {
        pivot = r;
      }
    }
    if (pivot != col) {
      for (std::size_t c = 0; c < width; ++c) {
        std::swap(m[col * width + c], m[pivot * width + c]);
      }
    }
    const double diag = m[col * width + col];
    for (std::size_t c = 0; c < width; ++c) {
      m[col * width + c] /= diag;
    }
    for (std::size_t r = 0; r < q; ++r) {
      if (r != col) {
        const double f = m[r * width + col];
        if (f != 0.0) {
          for (std::size_t c = 0; c < width; ++c) {
            m[r * width + c] -= f * m[col * width + c];
          }
        }
      }
    }
  }
  projector_.resize(q * n);
  for (std::size_t j = 0; j < q; ++j) {
    for (std::size_t k = 0; k < n; ++k) {
      projector_[j * n + k] = m[j * width + q + k];
    }
  }
  centre_ = atOffset(0);
  latest_ = atOffset(m_);
}

std::vector<double> SavitzkyGolay::atOffset(int offset) const {
  if (offset < -m_ || offset > m_) {
    throwInvalid("offset", offset, "must lie in the window, -halfWidth to halfWidth");
  }
  const auto n = static_cast<std::size_t>(2 * m_ + 1);
  const double u0 = static_cast<double>(offset) / m_;
  std::vector<double> c(n, 0.0);
  // d^d/dk^d = m^-d d^d/du^d; d^d/du^d u^j = j!/(j-d)! u^(j-d).
  for (int j = d_; j <= p_; ++j) {
    double factor = 1.0;
    for (int f = j - d_ + 1; f <= j; ++f) {
      factor *= f;
    }
    factor *= std::pow(u0, j - d_) / std::pow(static_cast<double>(m_), d_);
    for (std::size_t k = 0; k < n; ++k) {
      c[k] += factor * projector_[static_cast<std::size_t>(j) * n + k];
    }
  }
  return c;
}

double SavitzkyGolay::dot(std::span<const double> c, std::span<const double> window, double h) const {
  requirePositive(h, "h");
  if (window.size() != c.size()) {
    throwInvalid("window", static_cast<double>(window.size()), "must hold 2 halfWidth + 1 samples");
  }
  double s = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    requireFinite(window[k], "window");
    s += c[k] * window[k];
  }
  return s / std::pow(h, d_);
}

double SavitzkyGolay::apply(std::span<const double> window, double h) const { return dot(centre_, window, h); }

double SavitzkyGolay::applyLatest(std::span<const double> window, double h) const { return dot(latest_, window, h); }

std::vector<double> SavitzkyGolay::filter(std::span<const double> series, double h) const {
  const auto n = static_cast<std::size_t>(2 * m_ + 1);
  if (series.size() < n) {
    throwInvalid("series", static_cast<double>(series.size()), "must hold at least 2 halfWidth + 1 samples");
  }
  std::vector<double> out(series.size());
  const std::size_t last = series.size() - n; // start of the last window
  for (std::size_t i = 0; i < series.size(); ++i) {
    const std::size_t start = i < static_cast<std::size_t>(m_) ? 0 : std::min(i - static_cast<std::size_t>(m_), last);
    const int offset = static_cast<int>(i - start) - m_;
    const std::span<const double> window = series.subspan(start, n);
    out[i] = offset == 0 ? dot(centre_, window, h) : dot(atOffset(offset), window, h);
  }
  return out;
}

} // namespace impetus::sensors
