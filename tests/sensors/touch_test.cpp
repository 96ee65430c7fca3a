// Touch screens (ch. 20) against references the library did not produce: the resistive panels'
// voltages computed here from the circuit by Ohm's law, hand-computed corner currents, an affine
// map chosen here, Gaussian finger profiles sampled on a grid, and the book's Table 20-1.
#include <impetus/sensors/touch_calibration.hpp>
#include <impetus/sensors/touch_capacitive.hpp>
#include <impetus/sensors/touch_grid.hpp>
#include <impetus/sensors/touch_resistive.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace impetus::sensors {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// ---- Resistive ----------------------------------------------------------------------------------

TEST(ResistiveTouch, four_wire_position_and_contact_resistance_from_the_circuit) {
  // A 0.20 x 0.15 m panel, X sheet 600 ohm and Y sheet 400 ohm end to end, V_ref = 3.3 V, and a
  // press of 350 ohm at (0.05, 0.12) m. Ohm's law through the circuit, written out here:
  const double width = 0.20, height = 0.15, rx = 600.0, ry = 400.0, vref = 3.3, rTouch = 350.0;
  const double x = 0.05, y = 0.12;
  // Read X: the X sheet is a divider; the Y sheet probes without current.
  const double vx = vref * x / width;
  const double vy = vref * y / height;
  // Z: Y+ (at y = height) -> Y sheet down to the touch -> contact -> X sheet to X- (x = 0).
  const double current = vref / (ry * (1.0 - y / height) + rTouch + rx * x / width);
  const double z1 = current * rx * x / width;            // X+ sees the X sheet's touch point
  const double z2 = current * (rTouch + rx * x / width); // Y- sees the Y sheet's touch point
  FourWirePanel panel;
  panel.x = {width, 0.0, vref};
  panel.y = {height, 0.0, vref};
  panel.xPlateOhms = rx;
  panel.referenceVolts = vref;
  const TouchPoint p = readFourWire(panel, {vx, vy, z1, z2});
  EXPECT_NEAR(p.position.x, x, 1e-15);
  EXPECT_NEAR(p.position.y, y, 1e-15);
  ASSERT_TRUE(p.touchOhms.has_value());
  EXPECT_NEAR(*p.touchOhms, rTouch, 1e-9 * rTouch);
  // A harder press, half the resistance, reads twice the force with the same calibration.
  EXPECT_NEAR(touchForce(175.0, 350.0 * 1.5) / touchForce(350.0, 350.0 * 1.5), 2.0, 1e-15);
  // No contact: Z1 = 0.
  EXPECT_FALSE(readFourWire(panel, {vx, vy, 0.0, 0.0}).touchOhms.has_value());
}

TEST(ResistiveTouch, calibrated_voltage_range_maps_linearly) {
  // An ADC that reads 0.2 V at the left edge and 3.0 V at the right (bus-bar drops).
  const AxisRange axis{480.0, 0.2, 3.0};
  EXPECT_NEAR(positionFromVoltage(0.2, axis), 0.0, 1e-12);
  EXPECT_NEAR(positionFromVoltage(1.6, axis), 240.0, 1e-12);
  EXPECT_NEAR(positionFromVoltage(3.0, axis), 480.0, 1e-12);
  expectErrorField([] { (void)positionFromVoltage(1.0, {480.0, 1.0, 1.0}); }, "maxVoltage");
  expectErrorField([] { (void)positionFromVoltage(nan, {}); }, "voltage");
  expectErrorField([] { (void)positionFromVoltage(1.0, {0.0, 0.0, 3.3}); }, "length");
  expectErrorField([] { (void)fourWireTouchResistance(500.0, 0.5, 1.0, 0.9); }, "z2");
  expectErrorField([] { (void)fourWireTouchResistance(500.0, 0.5, -1.0, 0.9); }, "z1");
}

TEST(ResistiveTouch, five_wire_position_and_contact_resistance_from_the_divider) {
  // Bottom sheet driven corner to corner: the wiper reads V_ref x / W. Pressure: the wiper pulled
  // up through 47 kohm over a 1.2 kohm contact to the grounded corners.
  const double vref = 5.0, pullup = 47'000.0, rc = 1'200.0;
  FiveWirePanel panel;
  panel.x = {800.0, 0.0, vref};
  panel.y = {600.0, 0.0, vref};
  panel.pullupOhms = pullup;
  panel.referenceVolts = vref;
  const double wiper = vref * rc / (rc + pullup);
  const TouchPoint p = readFiveWire(panel, {vref * 0.3, vref * 0.75, wiper});
  EXPECT_NEAR(p.position.x, 240.0, 1e-12);
  EXPECT_NEAR(p.position.y, 450.0, 1e-12);
  ASSERT_TRUE(p.touchOhms.has_value());
  EXPECT_NEAR(*p.touchOhms, rc, 1e-9 * rc);
  EXPECT_FALSE(readFiveWire(panel, {1.0, 1.0, vref}).touchOhms.has_value()); // pulled fully up: no touch
  expectErrorField([&] { (void)readFiveWire(panel, {1.0, 1.0, -0.1}); }, "wiper");
}

TEST(ResistiveTouch, four_wire_pin_roles_are_the_books_table_20_1) {
  using enum PinRole;
  EXPECT_EQ(fourWirePins(FourWireState::waitForTouch), (std::array{open, open, pulledUpInput, ground}));
  EXPECT_EQ(fourWirePins(FourWireState::readX), (std::array{voltageProbe, ground, voltageSource, open}));
  EXPECT_EQ(fourWirePins(FourWireState::readY), (std::array{voltageSource, open, voltageProbe, ground}));
}

// ---- Calibration ----------------------------------------------------------------------------------

TEST(TouchCalibration, three_touches_recover_a_rotated_scaled_offset_panel) {
  // A 12-bit panel on an 800 x 480 display, turned 1.5 degrees, with its own scale and offset.
  const double c = std::cos(0.0261799), s = std::sin(0.0261799);
  const auto truth = [&](const Vec2d& r) {
    return Vec2d{0.2 * (c * r.x - s * r.y) + 12.0, 0.12 * (s * r.x + c * r.y) - 7.5};
  };
  const std::array<Vec2d, 3> raw{{{400.0, 350.0}, {3700.0, 2000.0}, {1900.0, 3800.0}}};
  std::array<Vec2d, 3> screen{};
  for (std::size_t i = 0; i < raw.size(); ++i) {
    screen[i] = truth(raw[i]);
  }
  const TouchCalibration cal = TouchCalibration::fit(raw, screen);
  for (const Vec2d r : {Vec2d{0.0, 0.0}, Vec2d{4095.0, 4095.0}, Vec2d{2048.0, 100.0}}) {
    EXPECT_NEAR(cal.apply(r).x, truth(r).x, 1e-9);
    EXPECT_NEAR(cal.apply(r).y, truth(r).y, 1e-9);
  }
  // Five noisy touches (+-1 px) fit by least squares land within a pixel everywhere.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  std::vector<Vec2d> raw5{{300, 300}, {3800, 300}, {3800, 3800}, {300, 3800}, {2048, 2048}};
  std::vector<Vec2d> screen5;
  for (const Vec2d& r : raw5) {
    screen5.push_back(truth(r) + Vec2d{noise(rng), noise(rng)});
  }
  const TouchCalibration fit5 = TouchCalibration::fit(raw5, screen5);
  EXPECT_LT(distance(fit5.apply({2500.0, 1200.0}), truth({2500.0, 1200.0})), 1.0);
}

TEST(TouchCalibration, collinear_or_too_few_touches_are_refused) {
  const std::array<Vec2d, 3> line{{{0, 0}, {1, 1}, {2, 2}}};
  expectErrorField([&] { (void)TouchCalibration::fit(line, line); }, "raw");
  const std::array<Vec2d, 2> two{{{0, 0}, {1, 0}}};
  expectErrorField([&] { (void)TouchCalibration::fit(two, two); }, "points");
  const std::array<Vec2d, 3> three{{{0, 0}, {1, 0}, {0, 1}}};
  expectErrorField([&] { (void)TouchCalibration::fit(three, two); }, "points");
}

// ---- Surface capacitive -----------------------------------------------------------------------

TEST(SurfaceCapacitive, position_from_hand_computed_corner_currents) {
  // Right corners carry 6 of 8 units, upper corners 4 of 8: three quarters across, half up.
  const auto p = surfaceCapacitivePosition({1.0, 3.0, 1.0, 3.0}, 0.30, 0.20);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->x, 0.225, 1e-15);
  EXPECT_NEAR(p->y, 0.10, 1e-15);
  // A finger at (0.06, 0.15) m drawing 20 uA, through the separable split and back.
  const CornerCurrents i = surfaceCapacitiveCurrents({0.06, 0.15}, 0.30, 0.20, 20e-6);
  EXPECT_NEAR(i.upperLeft + i.upperRight + i.lowerLeft + i.lowerRight, 20e-6, 1e-20);
  EXPECT_NEAR(i.upperRight, 20e-6 * 0.2 * 0.75, 1e-20);
  const auto q = surfaceCapacitivePosition(i, 0.30, 0.20);
  EXPECT_NEAR(q->x, 0.06, 1e-15);
  EXPECT_NEAR(q->y, 0.15, 1e-15);
  EXPECT_FALSE(surfaceCapacitivePosition({}, 0.3, 0.2).has_value());
  EXPECT_FALSE(surfaceCapacitivePosition({1e-9, 1e-9, 1e-9, 1e-9}, 0.3, 0.2, 1e-8).has_value());
  expectErrorField([] { (void)surfaceCapacitivePosition({1.0, 1.0, -1.0, 1.0}, 0.3, 0.2); }, "lowerLeft");
  expectErrorField([] { (void)surfaceCapacitivePosition({1.0, 1.0, 1.0, 1.0}, 0.0, 0.2); }, "width");
}

// ---- Projected capacitive grid --------------------------------------------------------------------

TEST(CapacitiveGrid, centred_finger_is_found_exactly) {
  GridGeometry g;
  g.rows = 12;
  g.columns = 8;
  g.pitchX = g.pitchY = 5e-3;
  const Vec2d centre = g.cellCentre(5, 3);
  const std::array<Vec2d, 1> fingers{centre};
  const std::vector<double> scan = simulateGridScan(g, fingers, 100.0, 4e-3);
  const std::vector<GridTouch> touches = findGridTouches(scan, g, 5.0);
  ASSERT_EQ(touches.size(), 1U);
  // The blob is symmetric about the cell centre: the centroid is exact to rounding.
  EXPECT_NEAR(touches[0].position.x, centre.x, 1e-15);
  EXPECT_NEAR(touches[0].position.y, centre.y, 1e-15);
  EXPECT_EQ(touches[0].row, 5);
  EXPECT_EQ(touches[0].column, 3);
}

TEST(CapacitiveGrid, centroid_resolves_positions_between_the_electrodes) {
  // A fingertip profile of sigma 5 mm (one pitch) at sub-cell offsets on a 5 mm grid: the centroid
  // lands within 1 % of a pitch (0.05 mm), where the peak cell alone is off by up to half a pitch.
  // (Weighted by DeltaC itself, without taking off the threshold, it is off by 2.2 %.)
  GridGeometry g;
  g.rows = 16;
  g.columns = 10;
  g.pitchX = g.pitchY = 5e-3;
  double worst = 0.0;
  for (const double fx : {0.0, 0.1, 0.25, 0.4, 0.5}) {
    for (const double fy : {0.0, 0.2, 0.45}) {
      const Vec2d truth = g.cellCentre(7, 4) + Vec2d{fx * g.pitchX, fy * g.pitchY};
      const std::array<Vec2d, 1> fingers{truth};
      const std::vector<double> scan = simulateGridScan(g, fingers, 80.0, 5e-3);
      const std::vector<GridTouch> touches = findGridTouches(scan, g, 2.0);
      ASSERT_EQ(touches.size(), 1U) << fx << " " << fy;
      worst = std::max(worst, distance(touches[0].position, truth));
    }
  }
  EXPECT_LT(worst, 0.01 * g.pitchX);
}

TEST(CapacitiveGrid, two_fingers_give_two_touches_even_when_their_blobs_touch) {
  GridGeometry g;
  g.rows = 10;
  g.columns = 16;
  g.pitchX = g.pitchY = 4e-3;
  // 3.5 pitches apart: their above-threshold cells form one connected region, with a dip between.
  const std::array<Vec2d, 2> fingers{
      {g.cellCentre(4, 4) + Vec2d{1e-3, 0.5e-3}, g.cellCentre(4, 7) + Vec2d{3e-3, 0.5e-3}}};
  const std::vector<double> scan = simulateGridScan(g, fingers, 50.0, 4e-3);
  const std::vector<GridTouch> touches = findGridTouches(scan, g, 1.0);
  ASSERT_EQ(touches.size(), 2U);
  const bool firstIsLeft = touches[0].position.x < touches[1].position.x;
  const GridTouch& left = firstIsLeft ? touches[0] : touches[1];
  const GridTouch& right = firstIsLeft ? touches[1] : touches[0];
  // Each blob is cut at the dip, so each centroid is pulled a little away from the other finger
  // (its neighbour's tail is gone): within a fifth of a pitch.
  EXPECT_LT(distance(left.position, fingers[0]), 0.2 * g.pitchX);
  EXPECT_LT(distance(right.position, fingers[1]), 0.2 * g.pitchX);
}

TEST(CapacitiveGrid, bad_scans_are_refused) {
  GridGeometry g;
  g.rows = 2;
  g.columns = 2;
  const std::vector<double> three(3, 0.0);
  expectErrorField([&] { (void)findGridTouches(three, g, 0.0); }, "deltas");
  const std::vector<double> four{0.0, nan, 0.0, 0.0};
  expectErrorField([&] { (void)findGridTouches(four, g, 0.0); }, "deltas");
  const std::vector<double> zeros(4, 0.0);
  expectErrorField([&] { (void)findGridTouches(zeros, g, -1.0); }, "threshold");
  g.rows = 0;
  expectErrorField([&] { (void)findGridTouches(zeros, g, 0.0); }, "rows");
  g.rows = 2;
  EXPECT_TRUE(findGridTouches(zeros, g, 0.0).empty());
}

} // namespace
} // namespace impetus::sensors
