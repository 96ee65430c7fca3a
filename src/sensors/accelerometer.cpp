#include <impetus/error.hpp>
#include <impetus/sensors/accelerometer.hpp>

#include <algorithm>
#include <cmath>

namespace impetus::sensors {

double proofMassReading(double deflection, double stiffness, double proofMass, double gravity) {
  requireFinite(deflection, "deflection");
  requirePositive(stiffness, "stiffness");
  requirePositive(proofMass, "proofMass");
  requirePositive(gravity, "gravity");
  return stiffness * deflection / (proofMass * gravity);
}

double clipReading(double trueG, double range) {
  requirePositive(range, "range");
  if (std::isnan(trueG)) {
    throwInvalid("trueG", trueG, "must not be NaN");
  }
  return std::clamp(trueG, -range, range);
}

bool isClipped(double value, double range, double tolerance) {
  // +-infinity is a (very) clipped reading; NaN is no reading and compared false.
  if (std::isnan(value)) {
    throwInvalid("value", value, "must not be NaN");
  }
  requirePositive(range, "range");
  requireNonNegative(tolerance, "tolerance");
  return std::abs(value) >= range - tolerance;
}

std::vector<double> fillClippedGaps(std::span<const double> samples, double range, double tolerance) {
  requirePositive(range, "range");
  requireNonNegative(tolerance, "tolerance");
  for (const double s : samples) {
    requireFinite(s, "samples");
  }
  std::vector<double> out(samples.begin(), samples.end());
  const std::size_t n = samples.size();
  std::size_t i = 0;
  while (i < n) {
    if (!isClipped(samples[i], range, tolerance)) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < n && isClipped(samples[end], range, tolerance)) {
      ++end;
    }
    // Run [i, end). Needs a good sample on both sides, and two for the slopes.
    if (i >= 2 && end + 1 < n) {
      const std::size_t a = i - 1;               // last good before
      const std::size_t b = end;                 // first good after
      const auto h = static_cast<double>(b - a); // in samples
      const double slopeA = samples[a] - samples[a - 1];
      const double slopeB = samples[b + 1] - samples[b];
      for (std::size_t k = i; k < end; ++k) {
        const double t = static_cast<double>(k - a) / h;
        const double t2 = t * t;
        const double t3 = t2 * t;
        const double h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
        const double h10 = t3 - 2.0 * t2 + t;
        const double h01 = -2.0 * t3 + 3.0 * t2;
        const double h11 = t3 - t2;
        double v = h00 * samples[a] + h10 * h * slopeA + h01 * samples[b] + h11 * h * slopeB;
        // The truth was at least the limit, on the clipped side.
        v = samples[k] > 0.0 ? std::max(v, samples[k]) : std::min(v, samples[k]);
        out[k] = v;
      }
    }
    i = end;
  }
  return out;
}

AxisCalibration AxisCalibration::fromFlip(double readingUp, double readingDown) {
  requireFinite(readingUp, "readingUp");
  requireFinite(readingDown, "readingDown");
  if (!(readingUp > readingDown)) {
    throwInvalid("readingUp", readingUp, "must exceed readingDown (+1 g must read more than -1 g)");
  }
  return {(readingUp + readingDown) * 0.5, (readingUp - readingDown) * 0.5};
}

} // namespace impetus::sensors
