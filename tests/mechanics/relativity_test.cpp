// Relativistic time against the spec's oracles (Ex 1.2: Lorentz factors computed for the notes,
// the GPS figures of ch. 22 and their checks), the light-clock derivation itself, and the GPS
// interface's 10.22999999543 MHz.
#include <impetus/core/constants.hpp>
#include <impetus/error.hpp>
#include <impetus/mechanics/relativity.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace impetus {
namespace {

constexpr double c = constants::speedOfLight;

TEST(Relativity, lorentz_factor_matches_the_spec_oracles) {
  // Ex 1.2 [C], given to 8 significant digits: +-5e-8.
  EXPECT_NEAR(lorentzFactor(0.1 * c), 1.0050378, 5e-8);
  EXPECT_NEAR(lorentzFactor(0.5 * c), 1.1547005, 5e-8);
  EXPECT_NEAR(lorentzFactor(0.8 * c), 1.6666667, 5e-8);
  EXPECT_NEAR(lorentzFactor(0.9 * c), 2.2941573, 5e-8);
  EXPECT_NEAR(lorentzFactor(0.99 * c), 7.0888121, 5e-8);
  EXPECT_EQ(lorentzFactor(0.0), 1.0);
}

TEST(Relativity, speed_of_light_or_more_is_an_error_not_infinity) {
  expectErrorField([] { (void)lorentzFactor(c); }, "speed");
  expectErrorField([] { (void)lorentzFactor(2.0 * c); }, "speed");
  expectErrorField([] { (void)lorentzFactor(-1.0); }, "speed");
  expectErrorField([] { (void)lorentzFactor(NAN); }, "speed");
  expectErrorField([] { (void)dilatedTime(1.0, c); }, "speed");
  expectErrorField([] { (void)dilatedTime(-1.0, 0.5 * c); }, "properTime");
  // Just below c it is large and finite: 1/sqrt((1-b)(1+b)) with 1 - b = 2^-53 ~ 1.1e-16.
  const double almost = std::nextafter(c, 0.0);
  EXPECT_TRUE(std::isfinite(lorentzFactor(almost)));
  EXPECT_GT(lorentzFactor(almost), 1e7);
}

TEST(Relativity, dilated_time_is_the_light_clock_tick) {
  // The book's light clock: mirrors L apart; moving at v the light runs the hypotenuse
  // H = sqrt(L^2 + (v t/2)^2) each half tick, so the tick t satisfies t = 2 H / c.
  const double l = 1.5;
  const double t0 = 2.0 * l / c;
  for (const double b : {0.1, 0.6, 0.95}) {
    const double t = dilatedTime(t0, b * c);
    const double hyp = std::hypot(l, b * c * t / 2.0);
    EXPECT_NEAR(2.0 * hyp / c, t, 1e-15 * t) << b;
  }
}

TEST(Relativity, special_relativistic_rate_exact_and_first_order_agree_where_they_should) {
  // At 3874 m/s: v^2/(2 c^2) * 86400 s = 7,214 ns/day (Ex 1.2, the book's ch. 22 figure).
  EXPECT_NEAR(-specialRelativisticRate(3874.0) * 86400e9, 7214.0, 0.5);
  // Exact minus first order is -b^4/8 + ...: relative difference ~b^2/4.
  const double b = 3874.0 / c;
  EXPECT_NEAR(specialRelativisticRateExact(3874.0) / specialRelativisticRate(3874.0) - 1.0, b * b / 4.0, 1e-15);
  // At 1 m/s the exact form does not cancel to 0: -b^2/2 = -5.56e-18.
  EXPECT_NEAR(specialRelativisticRateExact(1.0), -0.5 / (c * c), 1e-15 * 0.5 / (c * c));
  // At 0.6 c exactly: 1/gamma - 1 = 0.8 - 1.
  EXPECT_NEAR(specialRelativisticRateExact(0.6 * c), -0.2, 1e-15);
}

TEST(Relativity, gps_clock_drift_with_the_spec_radii) {
  const GpsClockDrift d = gpsClockDrift(); // r = 2.656e7 m, R = 6.371e6 m, circular orbit
  EXPECT_NEAR(d.orbitalSpeed, 3874.0, 0.1);
  EXPECT_NEAR(d.specialNanosecondsPerDay, -7214.0, 1.0);
  // (GM/c^2)(1/R - 1/r) 86400 s ~ 45,720 ns/day (Ex 1.2); the book's 45,850 used other radii.
  EXPECT_NEAR(d.gravitationalNanosecondsPerDay, 45720.0, 5.0);
  EXPECT_NEAR(d.gravitationalRate, gravitationalRate(constants::earthGravitationalParameter, 6.371e6, 2.656e7), 1e-24);
  // Net ~38.5 us/day with these radii (the book: 45,850 - 7,214 = 38,636, printed as 38,640).
  EXPECT_NEAR(d.netNanosecondsPerDay, 38504.6, 0.5);
  EXPECT_NEAR(d.netNanosecondsPerDay, d.gravitationalNanosecondsPerDay + d.specialNanosecondsPerDay, 1e-9);
  // It still sets the oscillator to the book's 10.22999999543 MHz within 1.1e-5 Hz.
  EXPECT_NEAR(d.correctedFrequency, 10'229'999.99543, 1.2e-5);
  // About 11.5 km of range error per day uncorrected (the book says "about 10 km").
  EXPECT_NEAR(d.rangeErrorPerDay, c * d.netNanosecondsPerDay * 1e-9, 1e-6);
  EXPECT_NEAR(d.rangeErrorPerDay, 11'543.0, 1.0);
}

TEST(Relativity, gps_clock_referred_to_the_geoid_gives_the_systems_factor) {
  // What GPS corrects for: the ground clock sits on the rotating geoid (potential
  // W0 = 62,636,856.0 m^2/s^2, gravity plus rotation) and the orbit's semi-major axis is
  // 26,561.75 km. The net rate is the 4.4647e-10 of the GPS interface specification (IS-GPS-200),
  // 38.6 us/day, and the oscillator is set to exactly the book's 10.22999999543 MHz.
  GpsClockInputs in;
  in.orbitRadius = 26'561.75e3;
  in.groundPotential = 62'636'856.0;
  const GpsClockDrift d = gpsClockDrift(in);
  EXPECT_NEAR(d.netRate, 4.4647e-10, 0.00005e-10);
  EXPECT_NEAR(d.netNanosecondsPerDay * 1e-3, 38.6, 0.05);
  EXPECT_NEAR(d.correctedFrequency, 10'229'999.99543, 0.5e-5); // the book's last digit is 1e-5 Hz
  EXPECT_NEAR(d.rangeErrorPerDay, 11'600.0, 100.0);            // the spec's "38.64 us x c = 11.6 km"
  // The spec's frequency check: (10.23 - 10.22999999543)/10.23 MHz = 4.467e-10, 38.6 us/day.
  EXPECT_NEAR((10.23e6 - 10'229'999.99543) / 10.23e6 * 86400e6, 38.6, 0.05);
}

TEST(Relativity, bad_gps_inputs_name_the_parameter) {
  GpsClockInputs in;
  in.orbitRadius = 6.0e6; // below the ground
  expectErrorField([&] { (void)gpsClockDrift(in); }, "orbitRadius");
  in = {};
  in.groundRadius = 0.0;
  expectErrorField([&] { (void)gpsClockDrift(in); }, "groundRadius");
  in = {};
  in.orbitalSpeed = 2.0 * c;
  expectErrorField([&] { (void)gpsClockDrift(in); }, "orbitalSpeed");
  in = {};
  in.nominalFrequency = -1.0;
  expectErrorField([&] { (void)gpsClockDrift(in); }, "nominalFrequency");
  expectErrorField([] { (void)gravitationalRate(3.986e14, 0.0, 2.6e7); }, "lowerRadius");
}

} // namespace
} // namespace impetus
