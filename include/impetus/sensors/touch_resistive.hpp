// Resistive touch screens (ch. 20): position and touch pressure from the controller's voltages.
//
// A resistive panel is two sheets coated with a resistive film (ITO) held apart by spacer dots.
// Pressing brings them into contact at one point. A uniform film of length L has R = rho_e L / A,
// so along a film driven with V_ref across it the voltage grows linearly with distance: the
// contact point, probed through the other sheet (which then carries no current), sits at
//   x = L (V_x - V_min) / (V_max - V_min)        (ideally V_min = 0, V_max = V_ref: x = L V_x / V_ref).
//
// 4-wire: each sheet has a bus bar on two opposite edges (X sheet: left/right, Y sheet:
// top/bottom). Read X: drive the X sheet, probe with the Y sheet; read Y: the reverse (the book's
// Table 20-1 state machine, `fourWirePins`). Pressure: drive current from Y+ through the contact
// to X- and read Z1 (at X+) and Z2 (at Y-). Z1 = I R_x x/L and Z2 = I (R_touch + R_x x/L), so
//   R_touch = R_x-plate (x / L) (Z2 / Z1 - 1)                    (TI ADS7846 data sheet, eq. 1).
// A harder press makes a larger contact patch, so R_touch falls: pressure is read as 1/R_touch.
//
// 5-wire: the four corners of the bottom sheet are electrodes and the top sheet is only a probe
// (the fifth wire, the "wiper"). Read X: upper- and lower-right corners at V_ref, left corners
// grounded; read Y: upper corners at V_ref, lower corners grounded. The top sheet carries no
// current, so flexing it (the 4-wire's weakness: micro-cracks) does not change the reading.
// Pressure: ground the four corners and pull the wiper up to V_ref through R_pullup; the wiper
// then reads V_w = V_ref R_c / (R_c + R_pullup), R_c = R_touch + the spreading resistance of the
// bottom sheet, so R_c = R_pullup V_w / (V_ref - V_w).
//
// Real panels are not perfectly uniform: an affine calibration from three reference touches
// (touch_calibration.hpp) takes out offset, scale and rotation.
#pragma once

#include <impetus/math/vec2.hpp>

#include <array>
#include <optional>

namespace impetus::sensors {

/// One axis of the panel: the voltages at the two ends of the calibrated range.
struct AxisRange {
  double length = 1.0;     ///< active length along the axis, m (or pixels: the result has this unit)
  double minVoltage = 0.0; ///< V read at position 0 (0 for an ideal panel)
  double maxVoltage = 3.3; ///< V read at position `length` (V_ref for an ideal panel)
};

/// x = length (V - V_min) / (V_max - V_min), in the unit of `length`. V outside [V_min, V_max]
/// (noise near the edges) extrapolates; it is not clamped. Throws impetus::Error (field
/// "voltage" or "minVoltage"/"maxVoltage"/"length") for non-finite input, length <= 0 or
/// V_max == V_min.
[[nodiscard]] double positionFromVoltage(double voltage, const AxisRange& axis);

/// A 4-wire panel: X and Y sheets and their end-to-end resistances.
struct FourWirePanel {
  AxisRange x{};               ///< read X: the X sheet is driven, the Y sheet probes
  AxisRange y{};               ///< read Y: the Y sheet is driven, the X sheet probes
  double xPlateOhms = 500.0;   ///< end-to-end resistance of the X sheet, ohm (> 0)
  double referenceVolts = 3.3; ///< V_ref of the Z measurement, V (> 0)
};

/// A full 4-wire reading: positions from V_x and V_y, pressure from Z1 and Z2.
struct FourWireReading {
  double voltageX = 0.0; ///< V at the Y sheet while the X sheet is driven
  double voltageY = 0.0; ///< V at the X sheet while the Y sheet is driven
  double z1 = 0.0;       ///< V at X+ with Y+ driven and X- grounded
  double z2 = 0.0;       ///< V at Y- with Y+ driven and X- grounded
};

struct TouchPoint {
  Vec2d position;                  ///< in the unit of the axis lengths
  std::optional<double> touchOhms; ///< contact resistance, ohm; none when not measured
};

/// Position and contact resistance. z1 <= 0 means no contact: touchOhms is then empty. Throws
/// impetus::Error naming the field for non-finite voltages or a bad panel ("voltageX",
/// "y.maxVoltage", ...).
[[nodiscard]] TouchPoint readFourWire(const FourWirePanel& panel, const FourWireReading& reading);

/// R_touch = R_x-plate (x / L) (Z2 / Z1 - 1), ohm, x measured from the X- (grounded) bar. Z1 > 0
/// and Z2 >= Z1 are required (field "z1" or "z2").
[[nodiscard]] double fourWireTouchResistance(double xPlateOhms, double xFraction, double z1, double z2);

/// A 5-wire panel: the bottom sheet's corners are driven, the top sheet probes.
struct FiveWirePanel {
  AxisRange x{};                ///< read X: right corners at V_ref, left corners grounded
  AxisRange y{};                ///< read Y: upper corners at V_ref, lower corners grounded
  double pullupOhms = 50'000.0; ///< pull-up from the wiper to V_ref for the pressure reading, ohm
  double referenceVolts = 3.3;  ///< V_ref, V
};

struct FiveWireReading {
  double voltageX = 0.0; ///< wiper voltage, X gradient applied, V
  double voltageY = 0.0; ///< wiper voltage, Y gradient applied, V
  double wiper = 3.3;    ///< wiper voltage with the corners grounded and the pull-up on, V (V_ref: no touch)
};

/// Position and contact resistance R_c = R_pullup V_w / (V_ref - V_w) (empty when V_w >= V_ref:
/// nothing touches). Throws impetus::Error naming the field for non-finite input.
[[nodiscard]] TouchPoint readFiveWire(const FiveWirePanel& panel, const FiveWireReading& reading);

/// A press read as force from the contact resistance: the contact patch (and so the contact
/// conductance) grows about linearly with the force, F = k / R_touch. `newtonOhms` is k, from one
/// calibration press (k = F_cal R_cal), N ohm (> 0).
[[nodiscard]] double touchForce(double touchOhms, double newtonOhms);

/// The 4-wire controller's states and pin roles (the book's Table 20-1). Pins 2 (ground) and 3
/// (source) are the bus bars of the sheet driven to read X, pins 1 (source) and 4 (ground) those
/// of the sheet driven to read Y. While waiting, pin 3 is pulled up and pin 4 grounded: a touch
/// joins the sheets and pulls pin 3 low, and the controller reads X, then Y (about 500 times/s).
enum class FourWireState { waitForTouch, readX, readY };
enum class PinRole { open, ground, voltageSource, voltageProbe, pulledUpInput };

[[nodiscard]] std::array<PinRole, 4> fourWirePins(FourWireState state) noexcept;

} // namespace impetus::sensors
