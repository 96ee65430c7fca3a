#include <impetus/error.hpp>
#include <impetus/sensors/touch_resistive.hpp>

#include <string>

namespace impetus::sensors {
namespace {

/// `prefix` names the panel's axis ("x.") when the range is part of a panel.
void requireAxis(const AxisRange& axis, const std::string& prefix = {}) {
  requirePositive(axis.length, prefix + "length");
  requireFinite(axis.minVoltage, prefix + "minVoltage");
  requireFinite(axis.maxVoltage, prefix + "maxVoltage");
  if (axis.maxVoltage == axis.minVoltage) {
    throwInvalid(prefix + "maxVoltage", axis.maxVoltage, "must differ from minVoltage (no voltage gradient)");
  }
}

/// A panel's two axes and readings under their own names ("y.length", "voltageX"), before
/// positionFromVoltage would name them "length" and "voltage".
void requirePanelAxes(const AxisRange& x, const AxisRange& y, double voltageX, double voltageY) {
  requireAxis(x, "x.");
  requireAxis(y, "y.");
  requireFinite(voltageX, "voltageX");
  requireFinite(voltageY, "voltageY");
}

} // namespace

double positionFromVoltage(double voltage, const AxisRange& axis) {
  requireFinite(voltage, "voltage");
  requireAxis(axis);
  return axis.length * (voltage - axis.minVoltage) / (axis.maxVoltage - axis.minVoltage);
}

double fourWireTouchResistance(double xPlateOhms, double xFraction, double z1, double z2) {
  requirePositive(xPlateOhms, "xPlateOhms");
  requireFinite(xFraction, "xFraction");
  requirePositive(z1, "z1");
  requireFinite(z2, "z2");
  // Z2 is Z1 plus the drop across the contact, so Z2 < Z1 is a wiring or noise fault.
  if (z2 < z1) {
    throwInvalid("z2", z2, "must be at least z1 (the contact adds a drop)");
  }
  return xPlateOhms * xFraction * (z2 / z1 - 1.0);
}

TouchPoint readFourWire(const FourWirePanel& panel, const FourWireReading& reading) {
  requirePositive(panel.xPlateOhms, "xPlateOhms");
  requirePositive(panel.referenceVolts, "referenceVolts");
  requireFinite(reading.z1, "z1");
  requireFinite(reading.z2, "z2");
  requirePanelAxes(panel.x, panel.y, reading.voltageX, reading.voltageY);
  TouchPoint p;
  p.position = {positionFromVoltage(reading.voltageX, panel.x), positionFromVoltage(reading.voltageY, panel.y)};
  if (reading.z1 > 0.0) {
    p.touchOhms = fourWireTouchResistance(panel.xPlateOhms, p.position.x / panel.x.length, reading.z1, reading.z2);
  }
  return p;
}

TouchPoint readFiveWire(const FiveWirePanel& panel, const FiveWireReading& reading) {
  requirePositive(panel.pullupOhms, "pullupOhms");
  requirePositive(panel.referenceVolts, "referenceVolts");
  requireNonNegative(reading.wiper, "wiper");
  requirePanelAxes(panel.x, panel.y, reading.voltageX, reading.voltageY);
  TouchPoint p;
  p.position = {positionFromVoltage(reading.voltageX, panel.x), positionFromVoltage(reading.voltageY, panel.y)};
  // Divider R_pullup over R_c: V_w = V_ref R_c / (R_c + R_pullup).
  if (reading.wiper < panel.referenceVolts) {
    p.touchOhms = panel.pullupOhms * reading.wiper / (panel.referenceVolts - reading.wiper);
  }
  return p;
}

double touchForce(double touchOhms, double newtonOhms) {
  requirePositive(touchOhms, "touchOhms");
  requirePositive(newtonOhms, "newtonOhms");
  return newtonOhms / touchOhms;
}

std::array<PinRole, 4> fourWirePins(FourWireState state) noexcept {
  switch (state) {
  case FourWireState::readX:
    return {PinRole::voltageProbe, PinRole::ground, PinRole::voltageSource, PinRole::open};
  case FourWireState::readY:
    return {PinRole::voltageSource, PinRole::open, PinRole::voltageProbe, PinRole::ground};
  case FourWireState::waitForTouch:
    break;
  }
  return {PinRole::open, PinRole::open, PinRole::pulledUpInput, PinRole::ground};
}

} // namespace impetus::sensors
