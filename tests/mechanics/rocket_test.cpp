// The vertical rocket against RK4 integration of m dv/dt = mdot u - m g with m(t) = m0 - mdot t
// (the same physics, solved numerically), the rocket equation, the ballistic coast, the
// launch-pad hold, and bad input.
#include <impetus/error.hpp>
#include <impetus/integrate/rk4.hpp>
#include <impetus/mechanics/rocket.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace impetus {
namespace {

struct State {
  double y, v, m;
  State operator+(const State& o) const { return {y + o.y, v + o.v, m + o.m}; }
  State operator*(double k) const { return {y * k, v * k, m * k}; }
};

/// Integrates the rocket from `t0` to `t1` with RK4: thrust mdot u while burning, gravity, and
/// (when `pad`) the pad's normal force keeping v >= 0 at the start altitude. The burn-out instant
/// is hit exactly (the step is cut there) so that the discontinuity in thrust does not cost
/// accuracy.
State integrate(const VerticalRocket& r, double t1, double h) {
  const double tb = r.propellantMass / r.burnRate;
  bool burning = true; // per step, not per stage: a stage landing exactly on t_b still burns
  const auto f = [&](double, const State& s) {
    const double thrust = burning ? r.burnRate * r.exhaustVelocity : 0.0;
    return State{s.v, thrust / s.m - r.gravity, burning ? -r.burnRate : 0.0};
  };
  State s{r.initialAltitude, r.initialVelocity, r.initialMass};
  double t = 0.0;
  const bool onPad = r.initialVelocity == 0.0;
  while (t < t1) {
    double step = std::min(h, t1 - t);
    if (t < tb && t + step > tb) {
      step = tb - t;
    }
    burning = t < tb;
    s = rk4Step(f, t, s, step);
    t += step;
    if (onPad && s.y <= r.initialAltitude && s.v <= 0.0) { // held by the pad
      s.y = r.initialAltitude;
      s.v = 0.0;
    }
  }
  return s;
}

VerticalRocket sounding() {
  // A small sounding rocket: 500 kg with 350 kg of propellant burnt at 10 kg/s, u = 2200 m/s,
  // thrust 22 kN, T/W = 4.5 at lift-off.
  return {500.0, 350.0, 10.0, 2200.0, 9.81, 0.0, 0.0};
}

TEST(Rocket, equation_and_thrust) {
  EXPECT_NEAR(rocketDeltaV(2200.0, 500.0, 150.0), 2200.0 * std::log(500.0 / 150.0), 1e-12);
  EXPECT_EQ(rocketDeltaV(2200.0, 500.0, 500.0), 0.0);
  EXPECT_EQ(rocketThrust(10.0, 2200.0), 22000.0);
}

TEST(Rocket, burn_matches_rk4_integration) {
  const VerticalRocket r = sounding();
  for (const double t : {0.5, 7.0, 20.0, 34.9, 35.0}) {
    const RocketState s = verticalRocketStateAt(r, t);
    const State n = integrate(r, t, 1e-3);
    // RK4 at 1 ms on a smooth burn: error ~h^4 * (d^5 y/dt^5) * t, far below 1e-7 m here.
    EXPECT_NEAR(s.altitude, n.y, 1e-7 * std::max(1.0, n.y)) << t;
    EXPECT_NEAR(s.velocity, n.v, 1e-9 * std::max(1.0, n.v)) << t;
    EXPECT_NEAR(s.mass, n.m, 1e-9) << t;
    EXPECT_TRUE(s.burning == (t < 35.0)) << t;
  }
}

TEST(Rocket, burnout_and_coast_match_rk4_and_the_ballistic_formulas) {
  const VerticalRocket r = sounding();
  const RocketFlight f = verticalRocketFlight(r);
  EXPECT_NEAR(f.burnoutTime, 35.0, 1e-12);
  EXPECT_NEAR(f.burnoutMass, 150.0, 1e-12);
  EXPECT_NEAR(f.thrust, 22000.0, 1e-9);
  EXPECT_NEAR(f.liftoffThrustToWeight, 22000.0 / (500.0 * 9.81), 1e-12);
  EXPECT_TRUE(f.liftsOff);
  EXPECT_EQ(f.liftoffTime, 0.0);
  // Burn-out speed: the rocket equation less the gravity loss g t_b.
  EXPECT_NEAR(f.idealDeltaV, 2200.0 * std::log(500.0 / 150.0), 1e-9);
  EXPECT_NEAR(f.burnoutVelocity, f.idealDeltaV - 9.81 * 35.0, 1e-9);
  const State atBurnout = integrate(r, f.burnoutTime, 1e-3);
  EXPECT_NEAR(f.burnoutAltitude, atBurnout.y, 1e-7 * atBurnout.y);
  EXPECT_NEAR(f.burnoutVelocity, atBurnout.v, 1e-9 * atBurnout.v);
  // Coast: peak at t_b + v_b/g, y_b + v_b^2/(2 g); checked against the integrated flight there.
  EXPECT_NEAR(f.peakTime, f.burnoutTime + f.burnoutVelocity / 9.81, 1e-9);
  EXPECT_NEAR(f.peakAltitude, f.burnoutAltitude + f.burnoutVelocity * f.burnoutVelocity / (2 * 9.81), 1e-6);
  const State atPeak = integrate(r, f.peakTime, 1e-3);
  EXPECT_NEAR(atPeak.v, 0.0, 1e-7);
  EXPECT_NEAR(atPeak.y, f.peakAltitude, 1e-7 * f.peakAltitude);
  const RocketState later = verticalRocketStateAt(r, f.peakTime + 10.0);
  EXPECT_NEAR(later.altitude, f.peakAltitude - 0.5 * 9.81 * 100.0, 1e-6);
  EXPECT_EQ(later.acceleration, -9.81);
}

TEST(Rocket, stays_on_the_pad_until_thrust_exceeds_weight) {
  // T = 10 kg/s * 2200 m/s = 22 kN; weight at ignition 3000 kg * 9.81 = 29.4 kN: it sits on the
  // pad until m = T/g = 2242.6 kg, i.e. 75.7 s into a 250 s burn.
  const VerticalRocket r{3000.0, 2500.0, 10.0, 2200.0, 9.81, 0.0, 0.0};
  const RocketFlight f = verticalRocketFlight(r);
  EXPECT_TRUE(f.liftsOff);
  EXPECT_NEAR(f.liftoffTime, (3000.0 - 22000.0 / 9.81) / 10.0, 1e-9);
  EXPECT_LT(f.liftoffThrustToWeight, 1.0);
  const RocketState held = verticalRocketStateAt(r, 50.0);
  EXPECT_EQ(held.velocity, 0.0);
  EXPECT_EQ(held.altitude, 0.0);
  for (const double t : {100.0, 200.0, 250.0, 300.0}) {
    const State n = integrate(r, t, 1e-3);
    const RocketState s = verticalRocketStateAt(r, t);
    // The pad clamp in the reference costs O(h) at lift-off only when it engages late: the
    // reference holds to ~1e-9 m/s before lift-off, so a few 1e-6 of relative slack.
    EXPECT_NEAR(s.velocity, n.v, 1e-6 * std::max(1.0, std::abs(n.v))) << t;
    EXPECT_NEAR(s.altitude, n.y, 1e-6 * std::max(1.0, std::abs(n.y))) << t;
  }
}

TEST(Rocket, that_never_lifts_off_is_reported_not_flown) {
  // Even empty (500 kg, 4.9 kN) it outweighs its 4 kN thrust.
  const VerticalRocket r{3000.0, 2500.0, 2.0, 2000.0, 9.81, 0.0, 5.0};
  const RocketFlight f = verticalRocketFlight(r);
  EXPECT_FALSE(f.liftsOff);
  EXPECT_EQ(f.peakAltitude, 5.0);
  EXPECT_EQ(f.burnoutVelocity, 0.0);
  const RocketState s = verticalRocketStateAt(r, 1000.0);
  EXPECT_EQ(s.altitude, 5.0);
  EXPECT_EQ(s.velocity, 0.0);
}

TEST(Rocket, already_climbing_with_low_thrust_peaks_during_the_burn) {
  // An upper stage coasting up at 50 m/s lights a motor weaker than its weight (6 kN against
  // 9.8 kN): it decelerates and tops out ~14 s into the burn; thrust only exceeds the weight at
  // 194 s, too late to climb back before burn-out at 300 s, so the peak is inside the burn.
  const VerticalRocket r{1000.0, 600.0, 2.0, 3000.0, 9.81, 50.0, 1000.0};
  const RocketFlight f = verticalRocketFlight(r);
  // Reference: RK4 integration up to the reported peak time must find v = 0 there, and no
  // sampled point of the flight may be higher.
  const double h = 1e-2;
  double bestT = 0.0;
  double bestY = -1e300;
  for (double t = 0.0; t <= 400.0; t += 0.5) {
    const double y = verticalRocketStateAt(r, t).altitude;
    if (y > bestY) {
      bestY = y;
      bestT = t;
    }
  }
  const State n = integrate(r, f.peakTime, h);
  EXPECT_NEAR(n.v, 0.0, 1e-8);
  EXPECT_NEAR(n.y, f.peakAltitude, 1e-8 * f.peakAltitude);
  EXPECT_GE(f.peakAltitude, bestY);
  EXPECT_NEAR(f.peakTime, bestT, 0.5);
  EXPECT_LT(f.peakTime, f.burnoutTime);
}

TEST(Rocket, bad_input_names_the_parameter) {
  VerticalRocket r = sounding();
  r.burnRate = 0.0;
  expectErrorField([&] { (void)verticalRocketFlight(r); }, "burnRate");
  r = sounding();
  r.propellantMass = 500.0;
  expectErrorField([&] { (void)verticalRocketFlight(r); }, "propellantMass");
  r = sounding();
  r.initialMass = -1.0;
  expectErrorField([&] { (void)verticalRocketFlight(r); }, "initialMass");
  r = sounding();
  r.exhaustVelocity = NAN;
  expectErrorField([&] { (void)verticalRocketFlight(r); }, "exhaustVelocity");
  r = sounding();
  r.gravity = 0.0;
  expectErrorField([&] { (void)verticalRocketFlight(r); }, "gravity");
  expectErrorField([] { (void)verticalRocketStateAt(sounding(), -1.0); }, "time");
  expectErrorField([] { (void)rocketDeltaV(2000.0, 100.0, 200.0); }, "finalMass");
  expectErrorField([] { (void)rocketDeltaV(2000.0, 100.0, 0.0); }, "finalMass");
}

} // namespace
} // namespace impetus
