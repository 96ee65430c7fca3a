#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/sensors/sensor_filters.hpp>

namespace impetus::sensors {
namespace {

/// RC = 1 / (2 pi f_c), after checking f_c against Nyquist.
double timeConstant(double cutoffHz, double sampleRateHz) {
  requirePositive(sampleRateHz, "sampleRateHz");
  requirePositive(cutoffHz, "cutoffHz");
  if (cutoffHz >= 0.5 * sampleRateHz) {
    throwInvalid("cutoffHz", cutoffHz, "must be below the Nyquist frequency, half the sample rate");
  }
  return 1.0 / (2.0 * pi<double> * cutoffHz);
}

} // namespace

LowPassFilter::LowPassFilter(double cutoffHz, double sampleRateHz)
    : cutoffHz_(cutoffHz), rc_(timeConstant(cutoffHz, sampleRateHz)), dt_(1.0 / sampleRateHz) {}

double LowPassFilter::update(double x) { return update(x, dt_); }

double LowPassFilter::update(double x, double dt) {
  requireFinite(x, "x");
  requirePositive(dt, "dt");
  if (!primed_) {
    primed_ = true;
    y_ = x;
    return y_;
  }
  y_ += alpha(dt) * (x - y_);
  return y_;
}

HighPassFilter::HighPassFilter(double cutoffHz, double sampleRateHz)
    : cutoffHz_(cutoffHz), rc_(timeConstant(cutoffHz, sampleRateHz)), dt_(1.0 / sampleRateHz) {}

double HighPassFilter::update(double x) { return update(x, dt_); }

double HighPassFilter::update(double x, double dt) {
  requireFinite(x, "x");
  requirePositive(dt, "dt");
  if (!primed_) {
    primed_ = true;
    y_ = 0.0;
    xPrevious_ = x;
    return y_;
  }
  y_ = beta(dt) * (y_ + x - xPrevious_);
  xPrevious_ = x;
  return y_;
}

} // namespace impetus::sensors
