// Weighted moving averages (ch. 23): smoothing a noisy sensor stream (load cells, pressure).
//
// y_n = sum_k w_k x_{n-k} / sum_k w_k over the last N samples, w_0 weighing the newest. Equal
// weights give the simple moving average (noise variance / N, lag (N - 1)/2 samples on a ramp);
// the linearly weighted average (w_k = N - k) reacts faster: on a ramp it lags by
// sum_k k (N - k) / sum_k (N - k) = (N - 1)/3 samples. Until N samples have arrived the average is
// over those there are (with their weights). For an exponential average (infinite memory) use the
// low-pass filter of sensor_filters.hpp.
#pragma once

#include <cstddef>
#include <deque>
#include <span>
#include <vector>

namespace impetus::sensors {

class WeightedMovingAverage {
public:
  /// `weights[0]` for the newest sample. Each weight >= 0, their sum > 0 and finite, at most
  /// 100000 of them.
  /// Throws impetus::Error (field "weights").
  explicit WeightedMovingAverage(std::vector<double> weights);

  /// N equal weights (N >= 1; field "length").
  static WeightedMovingAverage simple(std::size_t length);
  /// Weights N, N-1, ..., 1 (newest heaviest).
  static WeightedMovingAverage linear(std::size_t length);

  /// Adds a sample (finite; field "x") and returns the average.
  double update(double x);
  [[nodiscard]] double value() const noexcept { return value_; }
  [[nodiscard]] std::span<const double> weights() const noexcept { return weights_; }
  /// The lag on a steady ramp, in samples: sum k w_k / sum w_k.
  [[nodiscard]] double rampLag() const noexcept;

private:
  std::vector<double> weights_;
  std::deque<double> samples_; ///< newest first
  double value_ = 0.0;
};

} // namespace impetus::sensors
