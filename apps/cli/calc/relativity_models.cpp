// `impetus calc` entries for relativistic time (ch. 1 and ch. 22): the Lorentz factor and time
// dilation, and the GPS satellite clock.
#include "calc/calc.hpp"

#include <impetus/core/constants.hpp>
#include <impetus/mechanics/relativity.hpp>

#include <fmt/core.h>

#include <string>

namespace impetus::cli {
namespace {

constexpr const char* topic = "relativity (ch. 1, 22)";

Result lorentz(const Args& a) {
  const double v = a.number("speed");
  const double t0 = a.number("proper-time");
  Result r;
  const double gamma = lorentzFactor(v);
  r.add("beta", v / constants::speedOfLight, "", "v / c");
  r.add("lorentz_factor", gamma, "", "1/sqrt(1 - v^2/c^2)");
  r.add("dilated_time", dilatedTime(t0, v), "s", "gamma t0: the moving clock's tick seen from rest");
  r.add("clock_rate", specialRelativisticRateExact(v), "", "1/gamma - 1: fractional rate of the moving clock");
  r.add("clock_rate_first_order", specialRelativisticRate(v), "", "-v^2/(2 c^2)");
  return r;
}

Result gps(const Args& a) {
  GpsClockInputs in;
  in.orbitRadius = a.number("orbit-radius");
  in.groundRadius = a.number("ground-radius");
  in.gravitationalParameter = a.number("gravitational-parameter");
  in.orbitalSpeed = a.number("orbital-speed");
  in.nominalFrequency = a.number("nominal-frequency");
  const double w0 = a.number("ground-potential");
  if (w0 != 0.0) {
    in.groundPotential = w0;
  }
  const GpsClockDrift d = gpsClockDrift(in);
  Result r;
  r.add("orbital_speed", d.orbitalSpeed, "m/s");
  r.add("special_ns_per_day", d.specialNanosecondsPerDay, "ns/day", "-v^2/(2 c^2): the moving clock loses");
  r.add("gravitational_ns_per_day", d.gravitationalNanosecondsPerDay, "ns/day",
        "(GM/c^2)(1/R - 1/r): the higher clock gains");
  r.add("net_ns_per_day", d.netNanosecondsPerDay, "ns/day");
  r.add("net_rate", d.netRate, "", "fractional, satellite relative to ground");
  r.add("corrected_frequency", d.correctedFrequency, "Hz", "to set on the satellite so the ground sees nominal");
  r.add("corrected_frequency_mhz", d.correctedFrequency * 1e-6, "MHz", "the same in MHz (the book gives 11 decimals)");
  r.add("frequency_offset", d.correctedFrequency - in.nominalFrequency, "Hz", "corrected minus nominal");
  r.add("range_error_per_day", d.rangeErrorPerDay, "m", "c times the uncorrected drift over a day");
  r.notes.emplace_back("the book's net '+38,640 ns/day' is 45,850 - 7,214 = 38,636 ns/day; the spec's radii give "
                       "45,718 - 7,214 = 38,505; --orbit-radius 2.656175e7 --ground-potential 62636856 (the rotating "
                       "geoid) gives the GPS factor 4.4647e-10 = 38,575 ns/day and 10.22999999543 MHz");
  return r;
}

} // namespace

void registerRelativityModels(Registry& registry) {
  registry.add({"lorentz-factor",
                topic,
                "gamma = 1/sqrt(1 - v^2/c^2) and time dilation t = gamma t0 (v < c)",
                {{"speed", "m/s", "speed of the moving clock, below c = 299792458", std::nullopt},
                 {"proper-time", "s", "tick t0 of the moving clock in its own frame", std::string("1")}},
                lorentz});
  registry.add(
      {"gps-clock",
       topic,
       "GPS satellite clock: special (-7.2 us/day) and gravitational (+45.7 us/day) rates, corrected frequency",
       {{"orbit-radius", "m", "orbit radius r", std::string("2.656e7")},
        {"ground-radius", "m", "radius R of the ground clock", std::string("6.371e6")},
        {"gravitational-parameter", "m^3/s^2", "Earth's GM (WGS 84)", std::string("3.986004418e14")},
        {"orbital-speed", "m/s", "0: circular orbit, sqrt(GM/r)", std::string("0")},
        {"nominal-frequency", "Hz", "the clock frequency wanted on the ground", std::string("10.23e6")},
        {"ground-potential", "m^2/s^2", "0: use GM/R; else the ground clock's potential (geoid W0 = 62636856)",
         std::string("0")}},
       gps});
}

} // namespace impetus::cli
