#include <impetus/error.hpp>
#include <impetus/sensors/load_cell.hpp>

#include <cmath>

namespace impetus::sensors {
namespace {

void requireGaugeStrain(double strain, double gaugeFactor) {
  requireFinite(strain, "strain");
  requirePositive(gaugeFactor, "gaugeFactor");
  if (!(std::abs(gaugeFactor * strain) < 1.0)) {
    throwInvalid("strain", strain, "is beyond any gauge: |GF strain| must be below 1");
  }
}

void requireCell(const LoadCell& c) {
  requirePositive(c.capacity, "capacity");
  requirePositive(c.ratedOutput, "ratedOutput");
  requirePositive(c.excitation, "excitation");
  requireFinite(c.zeroBalance, "zeroBalance");
}

void requireKind(BridgeKind kind) {
  if (kind != BridgeKind::quarter && kind != BridgeKind::half && kind != BridgeKind::full) {
    throwInvalid("kind", static_cast<int>(kind), "is not a BridgeKind (quarter, half or full)");
  }
}

} // namespace

double bridgeOutputRatio(double strain, double gaugeFactor, BridgeKind kind) {
  requireGaugeStrain(strain, gaugeFactor);
  requireKind(kind);
  const double x = gaugeFactor * strain; // dR / R
  switch (kind) {
  case BridgeKind::quarter:
    // R(1 + x) over R against R over R: (1 + x)/(2 + x) - 1/2.
    return x / (4.0 + 2.0 * x);
  case BridgeKind::half:
    // R(1 + x) over R(1 - x): (1 + x)/2 - 1/2.
    return x / 2.0;
  case BridgeKind::full:
    return x;
  }
  return 0.0;
}

double strainFromBridge(double outputRatio, double gaugeFactor, BridgeKind kind) {
  requireFinite(outputRatio, "outputRatio");
  requirePositive(gaugeFactor, "gaugeFactor");
  requireKind(kind);
  double x = 0.0;
  switch (kind) {
  case BridgeKind::quarter:
    // r = x / (4 + 2x)  =>  x = 4r / (1 - 2r); the quarter bridge's output stays below 1/2.
    if (!(std::abs(outputRatio) < 0.5)) {
      throwInvalid("outputRatio", outputRatio, "is out of a quarter bridge's range (-1/2, 1/2)");
    }
    x = 4.0 * outputRatio / (1.0 - 2.0 * outputRatio);
    break;
  case BridgeKind::half:
    x = 2.0 * outputRatio;
    break;
  case BridgeKind::full:
    x = outputRatio;
    break;
  }
  return x / gaugeFactor;
}

double forceFromStrain(double strain, double youngsModulus, double area) {
  requireFinite(strain, "strain");
  requirePositive(youngsModulus, "youngsModulus");
  requirePositive(area, "area");
  return youngsModulus * strain * area;
}

double LoadCell::force(double volts) const {
  requireCell(*this);
  requireFinite(volts, "outputVolts");
  return capacity * (volts / excitation - zeroBalance) / ratedOutput;
}

double LoadCell::outputVolts(double f) const {
  requireCell(*this);
  requireFinite(f, "force");
  return excitation * (zeroBalance + ratedOutput * f / capacity);
}

} // namespace impetus::sensors
