#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/sensors/finite_difference.hpp>
#include <impetus/sensors/optical_tracking.hpp>
#include <impetus/sensors/savitzky_golay.hpp>

#include <cmath>

namespace impetus::sensors {
namespace {

void requireSamples(std::span<const TrackSample> samples, std::size_t minimum) {
  if (samples.size() < minimum) {
    throwInvalid("samples", static_cast<double>(samples.size()),
                 "too few samples for the method (3, or 2 halfWidth + 1 for Savitzky-Golay)");
  }
  for (std::size_t i = 0; i < samples.size(); ++i) {
    requireFinite(samples[i].time, "samples");
    requireFinite(samples[i].position, "samples");
    if (i > 0 && !(samples[i].time > samples[i - 1].time)) {
      throwInvalid("samples", samples[i].time, "times must increase strictly");
    }
  }
}

/// The common step, after checking the steps agree within the tolerance.
double evenStep(std::span<const TrackSample> samples, double tolerance) {
  const double h = (samples.back().time - samples.front().time) / static_cast<double>(samples.size() - 1);
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const double step = samples[i].time - samples[i - 1].time;
    if (std::abs(step - h) > tolerance * h) {
      throwInvalid("samples", step, "steps must be even for Savitzky-Golay (resample first)");
    }
  }
  return h;
}

void requireOptions(const TrackOptions& o) {
  requireNonNegative(o.evenTolerance, "evenTolerance");
  if (o.method == TrackMethod::savitzkyGolay) {
    if (o.order < 2) {
      throwInvalid("order", o.order, "must be at least 2 to give an acceleration");
    }
    (void)SavitzkyGolay(o.halfWidth, o.order, 2); // validates halfWidth and order
  }
}

/// Savitzky-Golay per coordinate: value, first and second derivative at each sample.
std::vector<TrackState> savitzkyGolayTrack(std::span<const TrackSample> samples, const TrackOptions& o) {
  const double h = evenStep(samples, o.evenTolerance);
  std::vector<TrackState> out(samples.size());
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> x(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
      x[i] = samples[i].position[axis];
    }
    const std::vector<double> p = SavitzkyGolay(o.halfWidth, o.order, 0).filter(x, h);
    const std::vector<double> v = SavitzkyGolay(o.halfWidth, o.order, 1).filter(x, h);
    const std::vector<double> a = SavitzkyGolay(o.halfWidth, o.order, 2).filter(x, h);
    for (std::size_t i = 0; i < samples.size(); ++i) {
      out[i].time = samples[i].time;
      out[i].position[axis] = p[i];
      out[i].velocity[axis] = v[i];
      out[i].acceleration[axis] = a[i];
    }
  }
  return out;
}

} // namespace

std::vector<TrackState> differentiateTrack(std::span<const TrackSample> samples, const TrackOptions& options) {
  requireOptions(options);
  if (options.method == TrackMethod::savitzkyGolay) {
    requireSamples(samples, static_cast<std::size_t>(2 * options.halfWidth + 1));
    return savitzkyGolayTrack(samples, options);
  }
  requireSamples(samples, 3);
  const std::size_t n = samples.size();
  std::vector<TrackState> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    out[i].time = samples[i].time;
    out[i].position = samples[i].position;
  }
  const auto x = [&](std::size_t i) -> const Vec3d& { return samples[i].position; };
  const auto step = [&](std::size_t i) { return samples[i].time - samples[i - 1].time; };
  if (options.method == TrackMethod::backward) {
    for (std::size_t i = 1; i < n; ++i) {
      out[i].velocity = backwardDifference(x(i - 1), x(i), step(i));
      if (i >= 2) {
        // The second difference of the last three, taken as the newest sample's acceleration
        // (it is the middle one's: one sample of lag, what real time allows).
        out[i].acceleration = secondDifferenceUneven(x(i - 2), x(i - 1), x(i), step(i - 1), step(i));
      }
    }
    return out;
  }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    out[i].velocity = centralDifferenceUneven(x(i - 1), x(i), x(i + 1), step(i), step(i + 1));
    out[i].acceleration = secondDifferenceUneven(x(i - 1), x(i), x(i + 1), step(i), step(i + 1));
  }
  // Ends: the derivative at the end point of the parabola through the three end samples
  // (second-order one-sided formulas); the acceleration is that parabola's, constant.
  {
    const double h1 = step(1);
    const double h2 = step(2);
    // v_0 = -(2 h1 + h2)/(h1 (h1 + h2)) x0 + (h1 + h2)/(h1 h2) x1 - h1/(h2 (h1 + h2)) x2
    out[0].velocity =
        x(0) * (-(2.0 * h1 + h2) / (h1 * (h1 + h2))) + x(1) * ((h1 + h2) / (h1 * h2)) - x(2) * (h1 / (h2 * (h1 + h2)));
    out[0].acceleration = out[1].acceleration;
  }
  {
    const double h1 = step(n - 2);
    const double h2 = step(n - 1);
    // v_n = h2/(h1 (h1 + h2)) x_{n-3} - (h1 + h2)/(h1 h2) x_{n-2} + (h1 + 2 h2)/(h2 (h1 + h2)) x_{n-1}
    out[n - 1].velocity = x(n - 3) * (h2 / (h1 * (h1 + h2))) - x(n - 2) * ((h1 + h2) / (h1 * h2)) +
                          x(n - 1) * ((h1 + 2.0 * h2) / (h2 * (h1 + h2)));
    out[n - 1].acceleration = out[n - 2].acceleration;
  }
  return out;
}

TrackState releaseState(std::span<const TrackSample> samples, const TrackOptions& options) {
  requireOptions(options);
  if (options.method == TrackMethod::savitzkyGolay) {
    const auto n = static_cast<std::size_t>(2 * options.halfWidth + 1);
    requireSamples(samples, n);
    const std::span<const TrackSample> last = samples.subspan(samples.size() - n);
    const double h = evenStep(last, options.evenTolerance);
    TrackState s;
    s.time = last.back().time;
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> x(n);
      for (std::size_t i = 0; i < n; ++i) {
        x[i] = last[i].position[axis];
      }
      s.position[axis] = SavitzkyGolay(options.halfWidth, options.order, 0).applyLatest(x, h);
      s.velocity[axis] = SavitzkyGolay(options.halfWidth, options.order, 1).applyLatest(x, h);
      s.acceleration[axis] = SavitzkyGolay(options.halfWidth, options.order, 2).applyLatest(x, h);
    }
    return s;
  }
  requireSamples(samples, 3);
  const std::span<const TrackSample> last = samples.subspan(samples.size() - 3);
  TrackOptions backward = options;
  backward.method = TrackMethod::backward;
  return differentiateTrack(last, backward).back();
}

double depthFromDisparity(double focalPixels, double baseline, double disparity) {
  requirePositive(focalPixels, "focalPixels");
  requirePositive(baseline, "baseline");
  requirePositive(disparity, "disparity");
  return focalPixels * baseline / disparity;
}

} // namespace impetus::sensors
