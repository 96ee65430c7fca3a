// GPS clocks and ranges (ch. 22): ranging by time of flight, what a clock error costs in range,
// and the relativistic drift of the satellite clocks.
//
// A GPS receiver measures r = c (t_receive - t_transmit); a clock error dt becomes a range error
// c dt: 1 us is 299.79 m (984 ft; the book says "over 900 miles"). The satellites' own clocks run
// fast by about 38.6 us/day (general relativity +45.7, special -7.2: mechanics/relativity.hpp,
// gpsClockDrift, `impetus calc gps-clock`), which would grow to about 11.6 km of range a day
// (the book says 10 km) if the satellites' oscillators were not set low, to 10.22999999543 MHz
// (it is the satellites' clocks that are offset, not the receivers').
#pragma once

#include <impetus/core/constants.hpp>

namespace impetus::geo {

/// r = c (receiveTime - transmitTime), m; times in s, receiveTime >= transmitTime (finite).
/// Throws impetus::Error naming "receiveTime" when the signal would arrive before it left.
[[nodiscard]] double rangeFromTimeOfFlight(double transmitTime, double receiveTime,
                                           double speedOfLight = constants::speedOfLight);

/// The range error c dt of a clock error dt (s, finite, either sign), m.
[[nodiscard]] double rangeErrorFromClockError(double clockError, double speedOfLight = constants::speedOfLight);

/// The clock error dt = dr / c behind a range error dr (m), s.
[[nodiscard]] double clockErrorFromRangeError(double rangeError, double speedOfLight = constants::speedOfLight);

/// The range error a clock accumulates over `duration` (s, >= 0) when it runs at fractional
/// rate `rate` (e.g. GpsClockDrift::netRate, 4.46e-10): c rate duration, m.
[[nodiscard]] double accumulatedRangeError(double rate, double duration, double speedOfLight = constants::speedOfLight);

} // namespace impetus::geo
