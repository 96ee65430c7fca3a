#include <impetus/error.hpp>
#include <impetus/sensors/moving_average.hpp>

#include <cmath>

namespace impetus::sensors {

WeightedMovingAverage::WeightedMovingAverage(std::vector<double> weights) : weights_(std::move(weights)) {
  if (weights_.empty() || weights_.size() > 100000) {
    throwInvalid("weights", static_cast<double>(weights_.size()), "must hold 1 to 100000 weights");
  }
  double sum = 0.0;
  for (const double w : weights_) {
    requireNonNegative(w, "weights");
    sum += w;
  }
  if (!(sum > 0.0)) {
    throwInvalid("weights", sum, "must not all be zero");
  }
  // Their sum divides every average: an overflowing one would make each inf / inf = NaN.
  if (!std::isfinite(sum)) {
    throwInvalid("weights", sum, "must have a finite sum");
  }
}

WeightedMovingAverage WeightedMovingAverage::simple(std::size_t length) {
  if (length < 1 || length > 100000) {
    throwInvalid("length", static_cast<double>(length), "must be 1 to 100000 samples");
  }
  return WeightedMovingAverage(std::vector<double>(length, 1.0));
}

WeightedMovingAverage WeightedMovingAverage::linear(std::size_t length) {
  if (length < 1 || length > 100000) {
    throwInvalid("length", static_cast<double>(length), "must be 1 to 100000 samples");
  }
  std::vector<double> w(length);
  for (std::size_t k = 0; k < length; ++k) {
    w[k] = static_cast<double>(length - k);
  }
  return WeightedMovingAverage(std::move(w));
}

double WeightedMovingAverage::update(double x) {
  requireFinite(x, "x");
  samples_.push_front(x);
  if (samples_.size() > weights_.size()) {
    samples_.pop_back();
  }
  double sum = 0.0;
  double weightSum = 0.0;
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    sum += weights_[k] * samples_[k];
    weightSum += weights_[k];
  }
  // The leading samples may all carry zero weight until more arrive: hold the newest then.
  value_ = weightSum > 0.0 ? sum / weightSum : x;
  return value_;
}

double WeightedMovingAverage::rampLag() const noexcept {
  double moment = 0.0;
  double sum = 0.0;
  for (std::size_t k = 0; k < weights_.size(); ++k) {
    moment += static_cast<double>(k) * weights_[k];
    sum += weights_[k];
  }
  return moment / sum;
}

} // namespace impetus::sensors
