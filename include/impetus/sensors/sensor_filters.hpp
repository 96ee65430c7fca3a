// First-order low-pass and high-pass filters for sensor streams (ch. 21), with the cut-off in Hz.
//
// The book names low-pass filtering (to keep gravity: the tilt) and high-pass filtering (to keep
// the user's quick moves: shakes, taps) and leaves the rest to DSP texts. These are the discrete
// RC filters: with RC = 1 / (2 pi f_c) and the sample interval dt,
//   low-pass   y_n = y_{n-1} + alpha (x_n - y_{n-1}),       alpha = dt / (RC + dt)
//   high-pass  y_n = beta (y_{n-1} + x_n - x_{n-1}),       beta  = RC / (RC + dt)
// Their response is the RC circuit's for f << 1/dt: unity gain at 0 Hz (low-pass) or at high
// frequency (high-pass), 1/sqrt(2) (-3 dB) at f_c, a 6 dB/octave roll-off beyond it.
//
// A phone's sensor events arrive late and irregularly (the OS is not real time), so alpha and
// beta are recomputed from each sample's real interval (`update(x, dt)`); `update(x)` uses the
// nominal rate. A cut-off at or above the Nyquist frequency (half the sample rate) cannot be
// represented by the samples and is refused.
#pragma once

namespace impetus::sensors {

class LowPassFilter {
public:
  /// cutoffHz > 0 and below sampleRateHz / 2. Throws impetus::Error naming "cutoffHz" or
  /// "sampleRateHz".
  LowPassFilter(double cutoffHz, double sampleRateHz);

  /// One sample at the nominal interval. The first sample primes the filter (output = input).
  double update(double x);
  /// One sample `dt` s after the previous one (dt > 0, field "dt").
  double update(double x, double dt);

  [[nodiscard]] double value() const noexcept { return y_; }
  /// alpha for an interval dt: dt / (RC + dt).
  [[nodiscard]] double alpha(double dt) const noexcept { return dt / (rc_ + dt); }
  [[nodiscard]] double cutoffHz() const noexcept { return cutoffHz_; }
  [[nodiscard]] double sampleRateHz() const noexcept { return 1.0 / dt_; }
  void reset() noexcept { primed_ = false; }

private:
  double cutoffHz_;
  double rc_;
  double dt_;
  double y_ = 0.0;
  bool primed_ = false;
};

class HighPassFilter {
public:
  /// As LowPassFilter's.
  HighPassFilter(double cutoffHz, double sampleRateHz);

  /// One sample at the nominal interval. The first sample primes the filter (output 0).
  double update(double x);
  double update(double x, double dt);

  [[nodiscard]] double value() const noexcept { return y_; }
  /// beta for an interval dt: RC / (RC + dt).
  [[nodiscard]] double beta(double dt) const noexcept { return rc_ / (rc_ + dt); }
  [[nodiscard]] double cutoffHz() const noexcept { return cutoffHz_; }
  [[nodiscard]] double sampleRateHz() const noexcept { return 1.0 / dt_; }
  void reset() noexcept { primed_ = false; }

private:
  double cutoffHz_;
  double rc_;
  double dt_;
  double y_ = 0.0;
  double xPrevious_ = 0.0;
  bool primed_ = false;
};

} // namespace impetus::sensors
