// The input validation audit of the sensors layer (docs/reliability.md, "Input validation"):
// accelerometers, buttons, the balance board, barometers and pressure, load cells, filters and
// finite differences, tracking, tilt and the touch screens refuse NaN, infinity, negative or
// zero values where none is meaningful (a zero sensor range, a cut-off at or above Nyquist),
// values out of range and degenerate geometry with an impetus::Error naming the field and
// showing the value.
#include "support/validation_table.hpp"

#include <impetus/sensors/accelerometer.hpp>
#include <impetus/sensors/analog_button.hpp>
#include <impetus/sensors/balance_board.hpp>
#include <impetus/sensors/barometer.hpp>
#include <impetus/sensors/depth_pressure.hpp>
#include <impetus/sensors/finite_difference.hpp>
#include <impetus/sensors/gestures.hpp>
#include <impetus/sensors/load_cell.hpp>
#include <impetus/sensors/moving_average.hpp>
#include <impetus/sensors/optical_tracking.hpp>
#include <impetus/sensors/savitzky_golay.hpp>
#include <impetus/sensors/sensor_filters.hpp>
#include <impetus/sensors/tilt.hpp>
#include <impetus/sensors/tilt_sprite.hpp>
#include <impetus/sensors/touch_calibration.hpp>
#include <impetus/sensors/touch_capacitive.hpp>
#include <impetus/sensors/touch_explosion.hpp>
#include <impetus/sensors/touch_grid.hpp>
#include <impetus/sensors/touch_recording.hpp>
#include <impetus/sensors/touch_resistive.hpp>
#include <impetus/sensors/touch_tracker.hpp>

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

namespace impetus::sensors {
namespace {

using impetus::testing::expectAccepted;
using impetus::testing::expectRejected;
using impetus::testing::infd;
using impetus::testing::nand;

TEST(SensorsValidation, accelerometer_buttons_and_balance_board) {
  const std::array<Vec2d, 4> cells = normalizedBoardCells();
  expectRejected({
      {"deflection", "nan", [] { (void)proofMassReading(nand, 1.0, 1e-9); }},
      {"stiffness", "0", [] { (void)proofMassReading(1e-9, 0.0, 1e-9); }},
      {"proofMass", "-1", [] { (void)proofMassReading(1e-9, 1.0, -1.0); }},
      {"gravity", "inf", [] { (void)proofMassReading(1e-9, 1.0, 1e-9, infd); }},
      {"range", "0", [] { (void)clipReading(1.0, 0.0); }},
      {"range", "nan", [] { (void)clipReading(1.0, nand); }},
      {"trueG", "nan", [] { (void)clipReading(nand, 2.0); }},
      {"value", "nan", [] { (void)isClipped(nand, 2.0); }},
      {"range", "-2", [] { (void)isClipped(1.0, -2.0); }},
      {"tolerance", "-1", [] { (void)isClipped(1.0, 2.0, -1.0); }},
      {"samples", "nan",
       [] {
         (void)fillClippedGaps(std::vector<double>{0.0, nand, 0.0}, 2.0);
       }},
      {"range", "0", [] { (void)fillClippedGaps(std::vector<double>{0.0}, 0.0); }},
      {"readingUp", "nan", [] { (void)AxisCalibration::fromFlip(nand, -1.0); }},
      {"readingDown", "-inf", [] { (void)AxisCalibration::fromFlip(1.0, -infd); }},
      {"readingUp", "0.5", [] { (void)AxisCalibration::fromFlip(0.5, 1.0); }},
      {"raw", "256", [] { (void)buttonDepression(256); }},
      {"raw", "-1", [] { (void)buttonZone(-1); }},
      {"maxCurrent", "0", [] { (void)depressionFromCurrent(0.0, 0.0); }},
      {"current", "-1", [] { (void)depressionFromCurrent(-1.0, 1.0); }},
      {"current", "2", [] { (void)depressionFromCurrent(2.0, 1.0); }},
      {"depression", "1.5", [] { (void)ButtonDome{}.force(1.5); }},
      {"depression", "nan", [] { (void)ButtonDome{}.fingertipPressure(nand); }},
      {"stiffness", "-1", [] { (void)ButtonDome{-1.0}.force(0.5); }},
      {"travel", "inf",
       [] {
         (void)ButtonDome{2000.0, infd}.force(0.5);
       }},
      {"contactArea", "0",
       [] {
         (void)ButtonDome{2000.0, 1e-3, 0.0}.fingertipPressure(0.5);
       }},
      {"window", "0", [] { ButtonMash m(0.0); }},
      {"pressLevel", "1.5", [] { ButtonMash m(1.0, 1.5); }},
      {"releaseLevel", "-0.1", [] { ButtonMash m(1.0, 0.6, -0.1); }},
      {"releaseLevel", "0.7", [] { ButtonMash m(1.0, 0.6, 0.7); }},
      {"time", "nan", [] { ButtonMash().update(nand, 0.5); }},
      {"depression", "2", [] { ButtonMash().update(0.0, 2.0); }},
      {"time", "0.5",
       [] {
         ButtonMash m;
         (void)m.update(1.0, 0.0);
         (void)m.update(0.5, 0.0);
       }},
      {"loads", "2",
       [&] {
         (void)centreOfGravity(cells, std::vector<double>{1.0, 2.0});
       }},
      {"loads", "0", [] { (void)centreOfGravity({}, {}); }},
      {"loads", "nan",
       [] {
         (void)boardCentreOfGravity({30.0, nand, 20.0, 35.0});
       }},
      {"positions.y", "inf",
       [] {
         (void)centreOfGravity(std::vector<Vec2d>{{0.0, infd}}, std::vector<double>{1.0});
       }},
      {"minimumTotal", "nan",
       [] {
         (void)boardCentreOfGravity({30.0, 15.0, 20.0, 35.0}, nand);
       }},
      {"loadRatio", "nan", [] { (void)classifyMotion(nand, 0.0); }},
      {"cogX", "inf", [] { (void)classifyMotion(1.0, infd); }},
  });
  expectAccepted({
      {"an infinite reading clips", [] { EXPECT_EQ(clipReading(infd, 2.0), 2.0); }},
      {"an infinite value is clipped", [] { EXPECT_TRUE(isClipped(-infd, 2.0)); }},
      {"raw 0 and 255", [] { (void)(buttonDepression(0) + buttonDepression(255)); }},
      {"slightly negative loads (tare noise)",
       [] {
         (void)boardCentreOfGravity({-0.1, 0.0, 0.0, 0.0});
       }},
  });
}

TEST(SensorsValidation, barometer_depth_and_load_cells) {
  const auto cell = [](auto change, double volts = 0.005) {
    return [change, volts] {
      LoadCell c;
      change(c);
      (void)c.force(volts);
    };
  };
  expectRejected({
      {"pressure", "0", [] { (void)barometricAltitude(0.0); }},
      {"pressure", "nan", [] { (void)barometricAltitude(nand); }},
      // Above 20 km in the standard atmosphere (5474.9 Pa there).
      {"pressure", "1000", [] { (void)barometricAltitude(1000.0); }},
      {"seaLevelPressure", "0", [] { (void)barometricAltitude(90'000.0, 0.0); }},
      {"altitude", "25000", [] { (void)pressureAtAltitude(25'000.0); }},
      {"altitude", "-6000", [] { (void)pressureAtAltitude(-6000.0); }},
      {"altitude", "nan", [] { (void)pressureAtAltitude(nand); }},
      {"seaLevelPressure", "inf", [] { (void)pressureAtAltitude(100.0, infd); }},
      {"seaLevelPressure", "-1013.25", [] { (void)androidAltitude(-1013.25, 900.0); }},
      {"pressure", "nan", [] { (void)androidAltitude(1013.25, nand); }},
      {"pressure1", "0", [] { (void)altitudeDifference(0.0, 90'000.0); }},
      {"pressure2", "inf", [] { (void)altitudeDifference(90'000.0, infd); }},
      {"depth", "-1", [] { (void)depthPressure(-1.0); }},
      {"density", "nan", [] { (void)depthPressure(10.0, nand); }},
      {"gravity", "-9.81", [] { (void)depthPressure(10.0, 1025.0, -9.81); }},
      {"surfacePressure", "inf", [] { (void)depthPressure(10.0, 1025.0, 9.81, infd); }},
      {"internalPressure", "-1", [] { (void)depthPressure(10.0, 1025.0, 9.81, 101'325.0, -1.0); }},
      {"gauge", "-1", [] { (void)depthForPressure(-1.0); }},
      {"density", "0", [] { (void)depthForPressure(1e5, 0.0); }},
      {"gravity", "0", [] { (void)depthForPressure(1e5, 1025.0, 0.0); }},
      {"strain", "nan", [] { (void)bridgeOutputRatio(nand, 2.0, BridgeKind::full); }},
      {"gaugeFactor", "0", [] { (void)bridgeOutputRatio(1e-3, 0.0, BridgeKind::full); }},
      // |GF strain| = 1.2: beyond any gauge.
      {"strain", "0.6", [] { (void)bridgeOutputRatio(0.6, 2.0, BridgeKind::half); }},
      {"kind", "7", [] { (void)bridgeOutputRatio(1e-3, 2.0, static_cast<BridgeKind>(7)); }},
      {"outputRatio", "inf", [] { (void)strainFromBridge(infd, 2.0, BridgeKind::full); }},
      {"outputRatio", "0.5", [] { (void)strainFromBridge(0.5, 2.0, BridgeKind::quarter); }},
      {"gaugeFactor", "nan", [] { (void)strainFromBridge(1e-3, nand, BridgeKind::half); }},
      {"kind", "-1", [] { (void)strainFromBridge(1e-3, 2.0, static_cast<BridgeKind>(-1)); }},
      {"youngsModulus", "0", [] { (void)forceFromStrain(1e-3, 0.0, 1e-4); }},
      {"area", "-1e-04", [] { (void)forceFromStrain(1e-3, 2e11, -1e-4); }},
      {"strain", "inf", [] { (void)forceFromStrain(infd, 2e11, 1e-4); }},
      {"capacity", "0", cell([](LoadCell& c) { c.capacity = 0.0; })},
      {"ratedOutput", "-0.002", cell([](LoadCell& c) { c.ratedOutput = -0.002; })},
      {"excitation", "nan", cell([](LoadCell& c) { c.excitation = nand; })},
      {"zeroBalance", "inf", cell([](LoadCell& c) { c.zeroBalance = infd; })},
      {"outputVolts", "nan", cell([](LoadCell&) {}, nand)},
      {"force", "inf", [] { (void)LoadCell{}.outputVolts(infd); }},
  });
  expectAccepted({
      {"below sea level", [] { (void)barometricAltitude(105'000.0); }},
      {"20 km exactly", [] { (void)pressureAtAltitude(20'000.0); }},
      {"the surface, no fluid, no gravity", [] { (void)depthPressure(0.0, 0.0, 0.0, 0.0, 0.0); }},
      {"zero strain", [] { (void)bridgeOutputRatio(0.0, 2.0, BridgeKind::quarter); }},
      {"a negative force (tension)", [] { (void)LoadCell{}.outputVolts(-100.0); }},
  });
}

TEST(SensorsValidation, filters_differences_and_tracking) {
  const std::vector<TrackSample> three{{0.0, {}}, {0.1, {1.0, 0.0, 0.0}}, {0.2, {2.0, 0.0, 0.0}}};
  const auto track = [](const std::vector<TrackSample>& samples, auto change) {
    return [samples, change] {
      TrackOptions o;
      change(o);
      (void)differentiateTrack(samples, o);
    };
  };
  const auto same = [](TrackOptions&) {};
  const auto golay = [](TrackOptions& o) {
    o.method = TrackMethod::savitzkyGolay;
    o.halfWidth = 1;
  };
  const SavitzkyGolay sg(2, 2);
  expectRejected({
      {"cutoffHz", "0", [] { LowPassFilter f(0.0, 100.0); }},
      // At or above Nyquist (50 Hz at 100 Hz sampling) a first-order RC filter is no filter.
      {"cutoffHz", "60", [] { LowPassFilter f(60.0, 100.0); }},
      {"cutoffHz", "50", [] { HighPassFilter f(50.0, 100.0); }},
      {"sampleRateHz", "nan", [] { LowPassFilter f(1.0, nand); }},
      {"sampleRateHz", "-100", [] { HighPassFilter f(1.0, -100.0); }},
      {"x", "nan", [] { (void)LowPassFilter(1.0, 100.0).update(nand); }},
      {"dt", "0", [] { (void)HighPassFilter(1.0, 100.0).update(1.0, 0.0); }},
      {"dt", "inf", [] { (void)LowPassFilter(1.0, 100.0).update(1.0, infd); }},
      {"weights", "0", [] { WeightedMovingAverage a(std::vector<double>{}); }},
      {"weights", "-1",
       [] {
         WeightedMovingAverage a({1.0, -1.0});
       }},
      {"weights", "nan", [] { WeightedMovingAverage a({nand}); }},
      {"weights", "0",
       [] {
         WeightedMovingAverage a({0.0, 0.0});
       }},
      // Each weight finite, their sum not: every average would be inf / inf.
      {"weights", "inf",
       [] {
         WeightedMovingAverage a({1e308, 1e308});
       }},
      {"length", "0", [] { (void)WeightedMovingAverage::simple(0); }},
      {"length", "100001", [] { (void)WeightedMovingAverage::linear(100001); }},
      {"x", "inf", [] { (void)WeightedMovingAverage::simple(3).update(infd); }},
      {"h", "0", [] { (void)backwardDifference(0.0, 1.0, 0.0); }},
      {"h", "nan", [] { (void)centralDifference(0.0, 1.0, nand); }},
      {"h1", "-0.1", [] { (void)centralDifferenceUneven(0.0, 1.0, 2.0, -0.1, 0.1); }},
      {"h2", "inf", [] { (void)secondDifferenceUneven(0.0, 1.0, 2.0, 0.1, infd); }},
      {"x", "nan", [] { (void)forwardDifference(nand, 1.0, 0.1); }},
      {"x.y", "inf",
       [] {
         (void)secondDifference(Vec2d{}, Vec2d{0.0, infd}, Vec2d{}, 0.1);
       }},
      {"x.z", "nan",
       [] {
         (void)centralDifference(Vec3d{}, Vec3d{0.0, 0.0, nand}, 0.1);
       }},
      {"halfWidth", "0", [] { SavitzkyGolay s(0, 0); }},
      {"halfWidth", "101", [] { SavitzkyGolay s(101, 2); }},
      {"order", "3", [] { SavitzkyGolay s(1, 3); }},
      {"order", "11", [] { SavitzkyGolay s(10, 11); }},
      {"derivative", "3", [] { SavitzkyGolay s(2, 2, 3); }},
      {"offset", "3", [&] { (void)sg.atOffset(3); }},
      {"window", "3",
       [&] {
         (void)sg.apply(std::vector<double>{1.0, 2.0, 3.0}, 0.1);
       }},
      {"window", "nan",
       [&] {
         (void)sg.apply(std::vector<double>{1.0, 2.0, nand, 4.0, 5.0}, 0.1);
       }},
      {"h", "0",
       [&] {
         (void)sg.applyLatest(std::vector<double>{1.0, 2.0, 3.0, 4.0, 5.0}, 0.0);
       }},
      {"series", "4",
       [&] {
         (void)sg.filter(std::vector<double>{1.0, 2.0, 3.0, 4.0}, 0.1);
       }},
      {"samples", "2", track({three[0], three[1]}, same)},
      {"samples", "nan", track({three[0], {nand, {}}, three[2]}, same)},
      {"samples.z", "inf", track({three[0], three[1], {0.2, {0.0, 0.0, infd}}}, same)},
      {"samples", "0.1", track({three[0], three[1], {0.1, {}}}, same)},
      // Savitzky-Golay needs even steps: 0.1 and 0.2 s against their mean 0.15 s.
      {"samples", "0.1", track({three[0], three[1], {0.3, {}}}, golay)},
      {"order", "1",
       track(three,
             [](TrackOptions& o) {
               o.method = TrackMethod::savitzkyGolay;
               o.order = 1;
             })},
      {"halfWidth", "0",
       track(three,
             [](TrackOptions& o) {
               o.method = TrackMethod::savitzkyGolay;
               o.halfWidth = 0;
             })},
      {"evenTolerance", "-1", track(three, [](TrackOptions& o) { o.evenTolerance = -1.0; })},
      {"samples", "1", [&] { (void)releaseState(std::span(three).first(1)); }},
      {"focalPixels", "0", [] { (void)depthFromDisparity(0.0, 0.1, 10.0); }},
      {"baseline", "nan", [] { (void)depthFromDisparity(500.0, nand, 10.0); }},
      {"disparity", "-1", [] { (void)depthFromDisparity(500.0, 0.1, -1.0); }},
  });
  expectAccepted({
      {"a cut-off just below Nyquist", [] { LowPassFilter f(49.9, 100.0); }},
      {"zero weights among positive ones",
       [] {
         WeightedMovingAverage a({1.0, 0.0});
       }},
      {"uneven steps for central differences", track({three[0], three[1], {0.3, {}}}, same)},
      {"Savitzky-Golay at its minimum window", track(three, golay)},
  });
}

TEST(SensorsValidation, tilt_and_gestures) {
  const auto sprite = [](auto change) {
    return [change] {
      TiltSpriteSettings s;
      change(s);
      TiltSprite t(s);
    };
  };
  const auto gestures = [](auto change) {
    return [change] {
      GestureSettings s;
      change(s);
      GestureRecognizer g(s);
    };
  };
  expectRejected({
      {"ax", "nan", [] { (void)tiltAngle(nand, 1.0); }},
      {"ay", "inf", [] { (void)tiltAngle(0.0, infd); }},
      // Lying flat: no gravity in the screen's plane, no angle.
      {"ay", "0", [] { (void)tiltAngle(0.0, 0.0); }},
      {"ay", "0", [] { (void)angle360(0.0, 0.0); }},
      {"ax", "-inf", [] { (void)angle360(-infd, 1.0); }},
      {"reading.y", "nan",
       [] {
         (void)tiltFromGravity({0.0, nand, 1.0});
       }},
      {"reading", "0", [] { (void)tiltFromGravity({}); }},
      {"pitch", "nan",
       [] {
         (void)gravityReading({nand, 0.0});
       }},
      {"roll", "inf",
       [] {
         (void)gravityReading({0.0, infd});
       }},
      {"reading.z", "inf",
       [] {
         (void)grossOrientation({0.0, 0.0, infd}, AccelConvention::specificForce);
       }},
      {"deadBand", "-0.1",
       [] {
         (void)grossOrientation({0.0, 0.0, 1.0}, AccelConvention::specificForce, -0.1);
       }},
      {"worldSize.x", "0", sprite([](TiltSpriteSettings& s) { s.worldSize.x = 0.0; })},
      {"spriteSize.y", "nan", sprite([](TiltSpriteSettings& s) { s.spriteSize.y = nand; })},
      {"spriteSize.x", "1", sprite([](TiltSpriteSettings& s) { s.spriteSize.x = 1.0; })},
      {"gravity", "-9.8", sprite([](TiltSpriteSettings& s) { s.gravity = -9.8; })},
      {"staticFriction", "nan", sprite([](TiltSpriteSettings& s) { s.staticFriction = nand; })},
      {"kineticFriction", "0.3", sprite([](TiltSpriteSettings& s) {
         s.staticFriction = 0.2;
         s.kineticFriction = 0.3;
       })},
      {"drag", "-1", sprite([](TiltSpriteSettings& s) { s.drag = -1.0; })},
      {"restitution", "1.5", sprite([](TiltSpriteSettings& s) { s.restitution = 1.5; })},
      {"restitution", "-0.1", sprite([](TiltSpriteSettings& s) { s.restitution = -0.1; })},
      {"timestamp", "nan", [] { (void)TiltSprite({}).update({}, nand); }},
      {"reading.x", "nan",
       [] {
         TiltSprite t({});
         (void)t.update({}, 0.0);
         (void)t.update({nand, 0.0, 0.0}, 0.1);
       }},
      {"timestamp", "0.5",
       [] {
         TiltSprite t({});
         (void)t.update({}, 1.0);
         (void)t.update({}, 0.5);
       }},
      {"dt", "-0.1", [] { TiltSprite({}).step({}, -0.1); }},
      {"reading.z", "inf",
       [] {
         TiltSprite({}).step({0.0, 0.0, infd}, 0.1);
       }},
      {"position.x", "-1",
       [] {
         TiltSprite({}).setState({-1.0, 0.1}, {});
       }},
      {"velocity.y", "nan",
       [] {
         TiltSprite({}).setState({0.1, 0.1}, {0.0, nand});
       }},
      {"tapMaxDuration", "0", gestures([](GestureSettings& s) { s.tapMaxDuration = 0.0; })},
      {"slop", "-1", gestures([](GestureSettings& s) { s.slop = -1.0; })},
      {"pinchThreshold", "nan", gestures([](GestureSettings& s) { s.pinchThreshold = nand; })},
      {"rotateThreshold", "inf", gestures([](GestureSettings& s) { s.rotateThreshold = infd; })},
      {"time", "nan", [] { (void)GestureRecognizer().update(nand, {}); }},
  });
  expectAccepted({
      {"sprite as large as the world", sprite([](TiltSpriteSettings& s) { s.spriteSize = s.worldSize; })},
      {"restitution 0 and 1", sprite([](TiltSpriteSettings& s) { s.restitution = 1.0; })},
      {"zero slop and thresholds", gestures([](GestureSettings& s) {
         s.slop = 0.0;
         s.pinchThreshold = 0.0;
         s.rotateThreshold = 0.0;
       })},
      {"a zero step",
       [] {
         TiltSprite({}).step({0.0, -1.0, 0.0}, 0.0);
       }},
  });
}

TEST(SensorsValidation, touch_screens) {
  const std::vector<Vec2d> rawPoints{{100.0, 100.0}, {900.0, 120.0}, {500.0, 900.0}};
  const std::vector<Vec2d> screenPoints{{0.0, 0.0}, {320.0, 0.0}, {160.0, 480.0}};
  const auto explosions = [](auto change) {
    return [change] {
      TouchExplosionSettings s;
      change(s);
      TouchExplosions e(s);
    };
  };
  const auto grid = [](auto change) {
    return [change] {
      GridGeometry g{2, 2};
      change(g);
      (void)findGridTouches(std::vector<double>(4, 0.0), g, 0.1);
    };
  };
  const auto fourWire = [](auto change) {
    return [change] {
      FourWirePanel panel;
      FourWireReading reading{1.0, 1.0, 1.0, 2.0};
      change(panel, reading);
      (void)readFourWire(panel, reading);
    };
  };
  const auto fiveWire = [](auto change) {
    return [change] {
      FiveWirePanel panel;
      FiveWireReading reading{1.0, 1.0, 1.0};
      change(panel, reading);
      (void)readFiveWire(panel, reading);
    };
  };
  expectRejected({
      {"points", "2", [&] { (void)TouchCalibration::fit(rawPoints, std::span(screenPoints).first(2)); }},
      {"points", "2",
       [&] { (void)TouchCalibration::fit(std::span(rawPoints).first(2), std::span(screenPoints).first(2)); }},
      {"raw.x", "nan",
       [&] {
         std::vector<Vec2d> raw = rawPoints;
         raw[1].x = nand;
         (void)TouchCalibration::fit(raw, screenPoints);
       }},
      {"screen.y", "inf",
       [&] {
         std::vector<Vec2d> screen = screenPoints;
         screen[2].y = infd;
         (void)TouchCalibration::fit(rawPoints, screen);
       }},
      // Collinear reference touches: the determinant of the normal equations is 0.
      {"raw", "0",
       [&] {
         (void)TouchCalibration::fit(std::vector<Vec2d>{{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}}, screenPoints);
       }},
      {"upperLeft", "-1",
       [] {
         (void)surfaceCapacitivePosition({-1.0, 1.0, 1.0, 1.0}, 1.0, 1.0);
       }},
      {"lowerRight", "nan",
       [] {
         (void)surfaceCapacitivePosition({1.0, 1.0, 1.0, nand}, 1.0, 1.0);
       }},
      {"width", "0",
       [] {
         (void)surfaceCapacitivePosition({1.0, 1.0, 1.0, 1.0}, 0.0, 1.0);
       }},
      {"height", "inf",
       [] {
         (void)surfaceCapacitivePosition({1.0, 1.0, 1.0, 1.0}, 1.0, infd);
       }},
      {"minimumTotal", "-1",
       [] {
         (void)surfaceCapacitivePosition({1.0, 1.0, 1.0, 1.0}, 1.0, 1.0, -1.0);
       }},
      {"position.x", "nan",
       [] {
         (void)surfaceCapacitiveCurrents({nand, 0.5}, 1.0, 1.0, 1.0);
       }},
      {"position.x", "2",
       [] {
         (void)surfaceCapacitiveCurrents({2.0, 0.5}, 1.0, 1.0, 1.0);
       }},
      {"total", "-1",
       [] {
         (void)surfaceCapacitiveCurrents({0.5, 0.5}, 1.0, 1.0, -1.0);
       }},
      {"screenHeight", "0", explosions([](TouchExplosionSettings& s) { s.screen.screenHeight = 0.0; })},
      {"pixelsPerMetre", "nan", explosions([](TouchExplosionSettings& s) { s.screen.pixelsPerMetre = nand; })},
      {"maxJump", "0", explosions([](TouchExplosionSettings& s) { s.maxJump = 0.0; })},
      {"maxExplosions", "0", explosions([](TouchExplosionSettings& s) { s.maxExplosions = 0; })},
      {"speed", "-1", explosions([](TouchExplosionSettings& s) { s.explosion.speed = -1.0; })},
      {"time", "nan",
       [] {
         TouchExplosions e({});
         (void)e.update(nand, {});
       }},
      {"rows", "0", grid([](GridGeometry& g) { g.rows = 0; })},
      {"columns", "5000", grid([](GridGeometry& g) { g.columns = 5000; })},
      {"pitchX", "0", grid([](GridGeometry& g) { g.pitchX = 0.0; })},
      {"pitchY", "nan", grid([](GridGeometry& g) { g.pitchY = nand; })},
      {"origin.x", "inf", grid([](GridGeometry& g) { g.origin.x = infd; })},
      {"deltas", "4", [] { (void)findGridTouches(std::vector<double>(4, 0.0), GridGeometry{}, 0.1); }},
      {"deltas", "nan",
       [] {
         (void)findGridTouches(std::vector<double>{0.0, nand, 0.0, 0.0}, GridGeometry{2, 2}, 0.1);
       }},
      {"threshold", "-1",
       [] {
         (void)findGridTouches(std::vector<double>(4, 0.0), GridGeometry{2, 2}, -1.0);
       }},
      {"amplitude", "-1", [] { (void)simulateGridScan(GridGeometry{}, {}, -1.0, 4e-3); }},
      {"sigma", "0", [] { (void)simulateGridScan(GridGeometry{}, {}, 1.0, 0.0); }},
      {"centres.y", "nan",
       [] {
         (void)simulateGridScan(GridGeometry{}, std::vector<Vec2d>{{0.0, nand}}, 1.0, 4e-3);
       }},
      {"voltage", "nan", [] { (void)positionFromVoltage(nand, {}); }},
      {"length", "0",
       [] {
         (void)positionFromVoltage(1.0, {0.0, 0.0, 3.3});
       }},
      {"minVoltage", "inf",
       [] {
         (void)positionFromVoltage(1.0, {1.0, infd, 3.3});
       }},
      {"maxVoltage", "1",
       [] {
         (void)positionFromVoltage(1.0, {1.0, 1.0, 1.0});
       }},
      {"xPlateOhms", "0", [] { (void)fourWireTouchResistance(0.0, 0.5, 1.0, 2.0); }},
      {"xFraction", "nan", [] { (void)fourWireTouchResistance(500.0, nand, 1.0, 2.0); }},
      {"z1", "0", [] { (void)fourWireTouchResistance(500.0, 0.5, 0.0, 2.0); }},
      {"z2", "0.5", [] { (void)fourWireTouchResistance(500.0, 0.5, 1.0, 0.5); }},
      {"xPlateOhms", "-1", fourWire([](FourWirePanel& p, FourWireReading&) { p.xPlateOhms = -1.0; })},
      {"referenceVolts", "0", fourWire([](FourWirePanel& p, FourWireReading&) { p.referenceVolts = 0.0; })},
      {"z1", "nan", fourWire([](FourWirePanel&, FourWireReading& r) { r.z1 = nand; })},
      {"voltageX", "nan", fourWire([](FourWirePanel&, FourWireReading& r) { r.voltageX = nand; })},
      {"voltageY", "inf", fourWire([](FourWirePanel&, FourWireReading& r) { r.voltageY = infd; })},
      {"y.length", "0", fourWire([](FourWirePanel& p, FourWireReading&) { p.y.length = 0.0; })},
      {"x.maxVoltage", "0", fourWire([](FourWirePanel& p, FourWireReading&) { p.x.maxVoltage = 0.0; })},
      {"pullupOhms", "0", fiveWire([](FiveWirePanel& p, FiveWireReading&) { p.pullupOhms = 0.0; })},
      {"referenceVolts", "nan", fiveWire([](FiveWirePanel& p, FiveWireReading&) { p.referenceVolts = nand; })},
      {"wiper", "-1", fiveWire([](FiveWirePanel&, FiveWireReading& r) { r.wiper = -1.0; })},
      {"voltageY", "nan", fiveWire([](FiveWirePanel&, FiveWireReading& r) { r.voltageY = nand; })},
      {"x.minVoltage", "inf", fiveWire([](FiveWirePanel& p, FiveWireReading&) { p.x.minVoltage = infd; })},
      {"touchOhms", "0", [] { (void)touchForce(0.0, 100.0); }},
      {"newtonOhms", "nan", [] { (void)touchForce(100.0, nand); }},
      {"maxJump", "0", [] { TouchTracker t(0.0); }},
      {"maxJump", "nan", [] { TouchTracker t(nand); }},
      {"time", "inf", [] { (void)TouchTracker(10.0).update(infd, {}); }},
      {"time", "0.5",
       [] {
         TouchTracker t(10.0);
         (void)t.update(1.0, {});
         (void)t.update(0.5, {});
       }},
      {"points.y", "nan",
       [] {
         (void)TouchTracker(10.0).update(0.0, std::vector<Vec2d>{{1.0, nand}});
       }},
  });
  expectAccepted({
      {"no current: no touch", [] { EXPECT_FALSE(surfaceCapacitivePosition({}, 1.0, 1.0).has_value()); }},
      {"a touch on the panel's corner",
       [] {
         (void)surfaceCapacitiveCurrents({1.0, 0.0}, 1.0, 1.0, 1.0);
       }},
      {"z1 = 0: no contact", fourWire([](FourWirePanel&, FourWireReading& r) { r.z1 = 0.0; })},
      {"wiper at V_ref: no touch", fiveWire([](FiveWirePanel&, FiveWireReading& r) { r.wiper = 3.3; })},
      {"a zero threshold",
       [] {
         (void)findGridTouches(std::vector<double>(4, 0.0), GridGeometry{2, 2}, 0.0);
       }},
  });
}

// The text form's errors name "recording" and the frame at fault (the value here is text, not a
// number, so the message reads "recording: frame N: ...").
TEST(SensorsValidation, touch_recordings) {
  struct Row {
    const char* text;
    const char* shown;
  };
  for (const Row& row :
       {Row{"0.0: 1,2\nabc: 1,2", "frame 2: 'abc' is not a number"}, Row{"nan: 1,2", "frame 1: 'nan' is not finite"},
        Row{"1.0:\n0.5:", "frame 2: time 0.5 goes back"}, Row{"0: 1/2", "frame 1: point '1/2' is not X,Y"},
        Row{"0: 1,inf", "frame 1: 'inf' is not finite"}, Row{"12 3,4", "frame 1: '12 3,4' has no 'TIME:'"}}) {
    SCOPED_TRACE(row.text);
    try {
      (void)parseTouchRecording(row.text);
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.field(), "recording");
      EXPECT_NE(std::string(e.what()).find(row.shown), std::string::npos) << e.what();
    }
  }
}

} // namespace
} // namespace impetus::sensors
