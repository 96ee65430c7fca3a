// Pressure sensors, buttons and load cells (ch. 23) against references the library did not
// produce: rho g h by hand for the book's Mariana-trench ball, the U.S. Standard Atmosphere 1976
// tables, Android's getAltitude oracles, Wheatstone bridges solved here as voltage dividers, the
// book's balance-board example (0.30, -0.10) and Table 23-3, and moving averages on ramps.
#include <impetus/math/scalar.hpp>
#include <impetus/sensors/analog_button.hpp>
#include <impetus/sensors/balance_board.hpp>
#include <impetus/sensors/barometer.hpp>
#include <impetus/sensors/depth_pressure.hpp>
#include <impetus/sensors/load_cell.hpp>
#include <impetus/sensors/moving_average.hpp>

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

// ---- Depth -------------------------------------------------------------------------------------

TEST(DepthPressure, the_books_sealed_ball_in_the_mariana_trench) {
  // Sealed at 101,000 Pa, sunk to 10,900 m of sea water (1025 kg/m^3, g = 9.81):
  // rho g h = 1025 x 9.81 x 10,900 = 109,602,225 Pa, about 1,082 standard atmospheres.
  const DepthPressure p = depthPressure(10'900.0, 1025.0, 9.81, 101'000.0, 101'000.0);
  EXPECT_NEAR(p.gauge, 109'602'225.0, 1e-6);
  EXPECT_NEAR(p.absolute, 109'703'225.0, 1e-6);
  EXPECT_DOUBLE_EQ(p.differential, p.gauge); // the net push on the shell is exactly rho g h
  EXPECT_NEAR(p.gauge / 101'325.0, 1081.7, 0.05);
  // Fresh water, g = 9.8 (the spec's other figure): 1.068e8 Pa.
  EXPECT_NEAR(depthPressure(10'900.0, 1000.0, 9.8).gauge, 1.0682e8, 1e4);
  // An open ball (inside = outside) has no differential.
  EXPECT_DOUBLE_EQ(depthPressure(100.0, 1025.0, 9.81, 101'325.0, 101'325.0 + 1025.0 * 9.81 * 100.0).differential, 0.0);
  EXPECT_NEAR(depthForPressure(p.gauge, 1025.0, 9.81), 10'900.0, 1e-9);
  expectErrorField([] { (void)depthPressure(-1.0); }, "depth");
  expectErrorField([] { (void)depthPressure(10.0, nan); }, "density");
}

// ---- Barometer -----------------------------------------------------------------------------------

TEST(Barometer, isa_pressures_match_the_us_standard_atmosphere_1976_tables) {
  // U.S. Standard Atmosphere 1976, geopotential altitude (m) -> pressure (Pa).
  struct Row {
    double h, p;
  };
  for (const Row& r : {Row{0.0, 101'325.0}, Row{1000.0, 89'874.6}, Row{2000.0, 79'495.2}, Row{5000.0, 54'019.9},
                       Row{11'000.0, 22'632.1}, Row{15'000.0, 12'044.6}, Row{20'000.0, 5'474.89}}) {
    EXPECT_NEAR(pressureAtAltitude(r.h), r.p, 5e-6 * r.p) << r.h; // the tables' 6 digits
    EXPECT_NEAR(barometricAltitude(r.p), r.h, 0.05) << r.h;
    EXPECT_NEAR(barometricAltitude(pressureAtAltitude(r.h)), r.h, 1e-8);
  }
}

TEST(Barometer, androids_get_altitude_oracles_and_the_altitude_difference) {
  // Spec ch. 23: getAltitude(1013.25, 1000) = 110.90 m, (1013.25, 900) = 988.65 m, and 1000 -> 990
  // hPa is 84.49 m up.
  EXPECT_NEAR(androidAltitude(1013.25, 1000.0), 110.90, 0.005);
  EXPECT_NEAR(androidAltitude(1013.25, 900.0), 988.65, 0.005);
  EXPECT_NEAR(androidAltitude(1013.25, 990.0) - androidAltitude(1013.25, 1000.0), 84.49, 0.005);
  // The ISA form gives the same to 0.2 m over these heights (its constants are Android's, unrounded).
  EXPECT_NEAR(altitudeDifference(100'000.0, 99'000.0), 84.49, 0.05);
  EXPECT_NEAR(barometricAltitude(100'000.0), 110.90, 0.02);
  // The difference barely depends on p0: a 10 hPa error in p0 moves it by ~0.2 %.
  EXPECT_NEAR(altitudeDifference(100'000.0, 99'000.0, 102'325.0), 84.49, 0.9);
  // 1 m near sea level is about 0.12 hPa (the BMP180's resolution).
  EXPECT_NEAR(101'325.0 - pressureAtAltitude(1.0), 12.0, 0.1);
  expectErrorField([] { (void)barometricAltitude(0.0); }, "pressure");
  expectErrorField([] { (void)barometricAltitude(1000.0); }, "pressure"); // above 20 km
  expectErrorField([] { (void)barometricAltitude(90'000.0, -1.0); }, "seaLevelPressure");
  expectErrorField([] { (void)altitudeDifference(90'000.0, nan); }, "pressure2");
  expectErrorField([] { (void)pressureAtAltitude(25'000.0); }, "altitude");
}

// ---- Analog buttons and mashing ------------------------------------------------------------------

TEST(AnalogButton, zones_are_half_open_where_the_book_overlaps) {
  EXPECT_EQ(buttonZone(0), "raise");
  EXPECT_EQ(buttonZone(126), "raise");
  EXPECT_EQ(buttonZone(127), "shoulder"); // the book puts 127 in both
  EXPECT_EQ(buttonZone(249), "shoulder");
  EXPECT_EQ(buttonZone(250), "fire"); // and 250
  EXPECT_EQ(buttonZone(255), "fire");
  EXPECT_DOUBLE_EQ(buttonDepression(255), 1.0);
  EXPECT_DOUBLE_EQ(buttonDepression(51), 0.2);
  EXPECT_DOUBLE_EQ(depressionFromCurrent(3e-3, 12e-3), 0.25);
  expectErrorField([] { (void)buttonZone(256); }, "raw");
  expectErrorField([] { (void)buttonDepression(-1); }, "raw");
  expectErrorField([] { (void)depressionFromCurrent(2.0, 1.0); }, "current");
}

TEST(AnalogButton, dome_force_and_fingertip_pressure) {
  // 2000 N/m over 1 mm of travel, half pressed: 1 N; over a 1 cm^2 fingertip 10 kPa.
  const ButtonDome dome;
  EXPECT_DOUBLE_EQ(dome.force(0.5), 1.0);
  EXPECT_DOUBLE_EQ(dome.fingertipPressure(0.5), 1.0e4);
  expectErrorField([&] { (void)dome.force(1.5); }, "depression");
}

TEST(AnalogButton, mash_rate_counts_presses_with_hysteresis) {
  // 7 presses a second for 3 s, sampled at 500 Hz, each press a half sine to 0.9 with +-0.08 noise:
  // the noise crosses the 0.6 level several times per press, but never back below 0.4 while down.
  ButtonMash mash(1.0);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> noise(-0.08, 0.08);
  int completed = 0;
  for (int i = 0; i < 1500; ++i) {
    const double t = i / 500.0;
    const double phase = std::fmod(t * 7.0, 1.0);
    const double s = phase < 0.5 ? 0.9 * std::sin(phase * 2.0 * pi<double>) : 0.0;
    completed += mash.update(t, std::clamp(s + noise(rng), 0.0, 1.0)) ? 1 : 0;
  }
  EXPECT_EQ(completed, 21);
  EXPECT_EQ(mash.presses(), 21);
  EXPECT_NEAR(mash.rate(), 7.0, 1.0); // presses in the last second
  EXPECT_NEAR(mash.meanPeakDepression(), 0.95, 0.05);
  expectErrorField([] { ButtonMash m(1.0, 0.4, 0.6); }, "releaseLevel");
  expectErrorField([] { ButtonMash m(0.0); }, "window");
  expectErrorField([&] { (void)mash.update(0.0, 0.5); }, "time");
}

// ---- Load cells ------------------------------------------------------------------------------------

TEST(LoadCell, bridge_outputs_match_the_voltage_dividers) {
  // 350 ohm gauges, GF 2.1, strain 1e-3 (dR/R = 2.1e-3). Each bridge solved as two dividers.
  const double r = 350.0, gf = 2.1, eps = 1e-3, x = gf * eps;
  const double quarter = r * (1.0 + x) / (r * (1.0 + x) + r) - r / (r + r);
  const double half = r * (1.0 + x) / (r * (1.0 + x) + r * (1.0 - x)) - 0.5;
  const double full = r * (1.0 + x) / (r * (1.0 + x) + r * (1.0 - x)) - r * (1.0 - x) / (r * (1.0 - x) + r * (1.0 + x));
  EXPECT_NEAR(bridgeOutputRatio(eps, gf, BridgeKind::quarter), quarter, 1e-16);
  EXPECT_NEAR(bridgeOutputRatio(eps, gf, BridgeKind::half), half, 1e-16);
  EXPECT_NEAR(bridgeOutputRatio(eps, gf, BridgeKind::full), full, 1e-16);
  for (const BridgeKind k : {BridgeKind::quarter, BridgeKind::half, BridgeKind::full}) {
    EXPECT_NEAR(strainFromBridge(bridgeOutputRatio(-eps, gf, k), gf, k), -eps, 1e-16);
  }
  // A steel column, E = 200 GPa, 1 cm^2, at 1e-3 strain carries 20 kN.
  EXPECT_NEAR(forceFromStrain(1e-3, 200e9, 1e-4), 20'000.0, 1e-9);
  expectErrorField([] { (void)bridgeOutputRatio(1.0, 2.0, BridgeKind::full); }, "strain");
  expectErrorField([] { (void)bridgeOutputRatio(1e-3, 0.0, BridgeKind::full); }, "gaugeFactor");
  expectErrorField([] { (void)strainFromBridge(0.6, 2.0, BridgeKind::quarter); }, "outputRatio");
}

TEST(LoadCell, rated_output_maps_volts_to_newtons) {
  // 500 N cell, 2 mV/V, 5 V excitation: full scale 10 mV; 5 mV is 250 N.
  LoadCell cell;
  EXPECT_NEAR(cell.force(5e-3), 250.0, 1e-10);
  EXPECT_NEAR(cell.outputVolts(500.0), 10e-3, 1e-15);
  cell.zeroBalance = 0.1e-3; // tare: 0.5 mV at no load
  EXPECT_NEAR(cell.force(0.5e-3), 0.0, 1e-10);
  EXPECT_NEAR(cell.force(cell.outputVolts(123.4)), 123.4, 1e-10);
  EXPECT_TRUE(cell.overloaded(600.0));
  cell.excitation = 0.0;
  expectErrorField([&] { (void)cell.force(1e-3); }, "excitation");
}

// ---- Balance board --------------------------------------------------------------------------------

TEST(BalanceBoard, the_books_example_is_0_30_and_minus_0_10) {
  const auto cog = boardCentreOfGravity({30.0, 15.0, 20.0, 35.0});
  ASSERT_TRUE(cog.has_value());
  EXPECT_NEAR(cog->x, 0.30, 1e-15);
  EXPECT_NEAR(cog->y, -0.10, 1e-15);
  // The real board in metres (cells 433 x 238 mm apart): the same weighted mean, scaled.
  const std::array<Vec2d, 4> cells{{{0.2165, 0.119}, {-0.2165, 0.119}, {-0.2165, -0.119}, {0.2165, -0.119}}};
  const std::array<double, 4> loads{300.0, 150.0, 200.0, 350.0};
  const auto m = centreOfGravity(cells, loads);
  EXPECT_NEAR(m->x, 0.30 * 0.2165, 1e-15);
  EXPECT_NEAR(m->y, -0.10 * 0.119, 1e-15);
  EXPECT_FALSE(boardCentreOfGravity({0.0, 0.0, 0.0, 0.0}).has_value()); // nobody on it
  EXPECT_FALSE(boardCentreOfGravity({1.0, 1.0, 1.0, 1.0}, 10.0).has_value());
  const std::array<double, 3> three{1.0, 2.0, 3.0};
  expectErrorField([&] { (void)centreOfGravity(cells, three); }, "loads");
}

TEST(BalanceBoard, motions_follow_table_23_3_in_order) {
  EXPECT_EQ(classifyMotion(0.5, 0.4), "right foot on");
  EXPECT_EQ(classifyMotion(0.5, -0.4), "left foot on");
  EXPECT_EQ(classifyMotion(0.99, 0.2), "both feet on");
  EXPECT_EQ(classifyMotion(1.2, 0.2), "both feet on"); // > 95 % and central comes first
  EXPECT_EQ(classifyMotion(1.2, 0.8), "left thigh lifting");
  EXPECT_EQ(classifyMotion(1.2, -0.8), "right thigh lifting");
  EXPECT_EQ(classifyMotion(0.02, 0.0), "both feet off");
  EXPECT_EQ(classifyMotion(0.5, 0.0), ""); // one foot, centred: no rule
  EXPECT_EQ(classifyMotion(0.85, 0.5), "");
  expectErrorField([] { (void)classifyMotion(nan, 0.0); }, "loadRatio");
}

// ---- Moving averages --------------------------------------------------------------------------

TEST(MovingAverage, linear_weights_lag_a_ramp_by_n_minus_1_over_3) {
  for (const std::size_t n : {1U, 4U, 10U}) {
    WeightedMovingAverage wma = WeightedMovingAverage::linear(n);
    EXPECT_NEAR(wma.rampLag(), (static_cast<double>(n) - 1.0) / 3.0, 1e-15);
    double y = 0.0;
    for (int i = 0; i < 30; ++i) {
      y = wma.update(2.0 * i + 1.0); // slope 2 per sample
    }
    EXPECT_NEAR(y, 2.0 * 29 + 1.0 - 2.0 * (static_cast<double>(n) - 1.0) / 3.0, 1e-12) << n;
  }
  WeightedMovingAverage sma = WeightedMovingAverage::simple(5);
  EXPECT_NEAR(sma.rampLag(), 2.0, 1e-15);
  EXPECT_DOUBLE_EQ(sma.update(7.0), 7.0); // over what there is
  EXPECT_DOUBLE_EQ(sma.update(9.0), 8.0);
  WeightedMovingAverage custom({0.0, 1.0});
  EXPECT_DOUBLE_EQ(custom.update(5.0), 5.0); // the newest's weight is zero: holds it until a second arrives
  EXPECT_DOUBLE_EQ(custom.update(6.0), 5.0);
  expectErrorField([] { WeightedMovingAverage w(std::vector<double>{}); }, "weights");
  expectErrorField([] { WeightedMovingAverage w({1.0, -1.0}); }, "weights");
  expectErrorField([] { (void)WeightedMovingAverage::simple(0); }, "length");
}

TEST(MovingAverage, simple_average_divides_white_noise_variance_by_n) {
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 1.0);
  WeightedMovingAverage sma = WeightedMovingAverage::simple(16);
  double sum2 = 0.0;
  int count = 0;
  for (int i = 0; i < 40'000; ++i) {
    const double y = sma.update(noise(rng));
    if (i >= 16) {
      sum2 += y * y;
      ++count;
    }
  }
  EXPECT_NEAR(sum2 / count, 1.0 / 16.0, 0.1 / 16.0);
}

} // namespace
} // namespace impetus::sensors
