// GPS clock and range helpers: c dt (1 us is 299.79 m, not the book's "over 900 miles"), time
// of flight, and the relativistic drift's range error (about 11.6 km a day, the book says 10).
#include <impetus/geo/gps_clock.hpp>
#include <impetus/mechanics/relativity.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

namespace impetus::geo {
namespace {

TEST(GpsClock, a_microsecond_is_three_hundred_metres_not_nine_hundred_miles) {
  EXPECT_NEAR(rangeErrorFromClockError(1e-6), 299.792458, 1e-9);
  EXPECT_NEAR(rangeErrorFromClockError(1e-6) / 0.3048, 983.571, 1e-3); // feet: the book's 900 "miles"
  EXPECT_NEAR(clockErrorFromRangeError(299.792458), 1e-6, 1e-18);
  EXPECT_NEAR(rangeFromTimeOfFlight(0.0, 0.07), 0.07 * 299792458.0, 1e-6); // ~21,000 km, a GPS range
}

TEST(GpsClock, the_relativistic_drift_would_cost_about_eleven_kilometres_a_day) {
  // The book's net 38,640 ns/day: c x 38.64 us = 11.58 km (the book says "about 10 km").
  EXPECT_NEAR(accumulatedRangeError(38640e-9 / 86400.0, 86400.0), 11584.0, 1.0);
  const GpsClockDrift d = gpsClockDrift();
  EXPECT_NEAR(accumulatedRangeError(d.netRate, 86400.0), d.rangeErrorPerDay, 1e-6);
}

TEST(GpsClock, bad_input_is_rejected) {
  expectErrorField([] { (void)rangeFromTimeOfFlight(1.0, 0.5); }, "receiveTime");
  expectErrorField([] { (void)rangeFromTimeOfFlight(NAN, 0.5); }, "transmitTime");
  expectErrorField([] { (void)rangeErrorFromClockError(INFINITY); }, "clockError");
  expectErrorField([] { (void)accumulatedRangeError(1e-10, -1.0); }, "duration");
  expectErrorField([] { (void)rangeErrorFromClockError(1e-6, 0.0); }, "speedOfLight");
}

} // namespace
} // namespace impetus::geo
