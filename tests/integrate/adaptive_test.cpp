// The adaptive drivers: the book's step-doubling oracle and its flaws fixed, Dormand-Prince
// against fixed-step RK4, and bad input.
#include <impetus/integrate/integrate.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/vec3.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace impetus {
namespace {

// The book's ship (ch. 4, 7): m dv/dt = T - C v with T = 20000 N, m = 10000 kg, C = 1000 N s/m.
double shipVelocityRate(double /*t*/, double v) { return (20000.0 - 1000.0 * v) / 10000.0; }
double exactShipVelocity(double t) { return 20.0 * -std::expm1(-0.1 * t); }
double exactShipPosition(double t) { return 20.0 * t - 200.0 * -std::expm1(-0.1 * t); }

using Phase = PhaseState<double>;
Phase shipRate(double /*t*/, const Phase& x) { return {x.velocity, shipVelocityRate(0.0, x.velocity)}; }
Phase oscillatorRate(double /*t*/, const Phase& x) { return {x.velocity, -x.position}; }

AdaptiveSettings absolute(double tolerance) {
  AdaptiveSettings s;
  s.absoluteTolerance = tolerance;
  s.relativeTolerance = 0.0;
  return s;
}

// ---------------------------------------------------------------------------------------------
// Step doubling.

// Spec ch. 7 notes 1.5 / I-14: from rest with dt = 0.5, one Euler step gives v1 = 1.0, two half
// steps v2 = 0.9875, error 0.0125; the book's h_new = h (tol/err)^(1/2) (safety 1).
TEST(StepDoubling, books_adaptive_step_oracle) {
  struct Case {
    double tolerance, step;
    bool accepted;
  };
  for (const Case& c : {Case{0.01, 0.44721, false}, Case{0.001, 0.14142, false}, Case{0.025, 0.70711, true}}) {
    AdaptiveSettings book = absolute(c.tolerance);
    book.safety = 1.0;
    const StepDoublingTrial<double> trial = stepDoublingTrial(ExplicitEuler{}, shipVelocityRate, 0.0, 0.0, 0.5, book);
    EXPECT_DOUBLE_EQ(trial.single, 1.0);
    EXPECT_DOUBLE_EQ(trial.doubled, 0.9875);
    EXPECT_NEAR(trial.error, 0.0125, 1e-15);
    EXPECT_NEAR(trial.proposedStep, c.step, 5e-6) << c.tolerance;
    EXPECT_EQ(trial.accepted, c.accepted) << c.tolerance;
    // With the safety factor the proposal is 0.9 times the book's.
    const StepDoublingTrial<double> safe =
        stepDoublingTrial(ExplicitEuler{}, shipVelocityRate, 0.0, 0.0, 0.5, absolute(c.tolerance));
    EXPECT_NEAR(safe.proposedStep, 0.9 * trial.proposedStep, 1e-12);
  }
  // The book keeps v1; the Richardson extrapolate 2 v2 - v1 = 0.975 is ~100x closer to the exact
  // 0.975412 than v1 = 1.0 (and 30x closer than v2).
  const StepDoublingTrial<double> trial = stepDoublingTrial(ExplicitEuler{}, shipVelocityRate, 0.0, 0.0, 0.5);
  EXPECT_NEAR(trial.extrapolated, 0.975, 1e-15);
  const double exact = exactShipVelocity(0.5);
  EXPECT_LT(std::abs(trial.extrapolated - exact) * 50.0, std::abs(trial.single - exact));
}

// Euler is exact for y' = 1, so the two estimates agree: the book's formula divides by zero.
// Here the step grows by maxScale per step up to maxStep, and the end is hit exactly.
TEST(StepDoubling, zero_error_grows_the_step_without_dividing_by_zero) {
  AdaptiveSettings s;
  s.initialStep = 0.01;
  s.maxStep = 10.0;
  const auto constant = [](double, double) { return 1.0; };
  const StepDoublingTrial<double> trial = stepDoublingTrial(ExplicitEuler{}, constant, 0.0, 0.0, 0.01, s);
  EXPECT_EQ(trial.error, 0.0);
  EXPECT_DOUBLE_EQ(trial.proposedStep, 0.05);
  const AdaptiveResult<double> r = integrateStepDoubling(ExplicitEuler{}, constant, 0.0, 0.0, 100.0, s);
  EXPECT_EQ(r.time, 100.0);
  EXPECT_NEAR(r.state, 100.0, 1e-12);
  EXPECT_EQ(r.stats.rejected, 0);
  EXPECT_EQ(r.stats.largestStep, 10.0);
  EXPECT_LT(r.stats.accepted, 16); // 0.01, 0.05, 0.25, 1.25, 6.25, then 10s
}

// From a step far too large the first retry (at most minScale = 0.2 smaller) still fails; the
// book would accept it unchecked. Here every retry is a full trial, and the first step taken
// meets the tolerance.
TEST(StepDoubling, rejected_retry_is_checked_again) {
  AdaptiveSettings s = absolute(1e-6);
  s.initialStep = 10.0;
  std::vector<double> times;
  const AdaptiveResult<Phase> r =
      integrateStepDoubling(ExplicitEuler{}, oscillatorRate, 0.0, Phase{1.0, 0.0}, 1.0, s, StateNorm{},
                            [&](double t, const Phase&) { times.push_back(t); });
  ASSERT_FALSE(times.empty());
  EXPECT_GE(r.stats.rejected, 3);
  const double first = times.front();
  EXPECT_LT(first, 0.01);
  EXPECT_TRUE(stepDoublingTrial(ExplicitEuler{}, oscillatorRate, 0.0, Phase{1.0, 0.0}, first, s).accepted);
  EXPECT_EQ(r.time, 1.0);
  EXPECT_EQ(times.back(), 1.0);
  EXPECT_NEAR(r.state.position, std::cos(1.0), 1e-4);
}

// Each stepper, on the whole ship state (s, v): reaches t = 10 exactly and is accurate to
// about the tolerance per step; higher orders need far fewer evaluations.
TEST(StepDoubling, integrates_the_ship_with_each_stepper) {
  const double tolerance = 1e-7;
  const auto check = [&](const auto& stepper, long maxEvaluations) {
    const AdaptiveResult<Phase> r = integrateStepDoubling(stepper, shipRate, 0.0, Phase{}, 10.0, absolute(tolerance));
    EXPECT_EQ(r.time, 10.0);
    EXPECT_NEAR(r.state.position, exactShipPosition(10.0), 20 * tolerance);
    EXPECT_NEAR(r.state.velocity, exactShipVelocity(10.0), 20 * tolerance);
    // 3 stepper calls per trial, plus 2 evaluations to choose the first step.
    using Stepper = std::remove_cvref_t<decltype(stepper)>;
    EXPECT_EQ(r.stats.evaluations, 3 * Stepper::evaluations * (r.stats.accepted + r.stats.rejected) + 2);
    EXPECT_LT(r.stats.evaluations, maxEvaluations);
    return r.stats.evaluations;
  };
  const long euler = check(ExplicitEuler{}, 100000);
  const long heun = check(Heun{}, 5000);
  const long midpoint = check(Midpoint{}, 5000);
  const long rk4 = check(RungeKutta4{}, 1000);
  EXPECT_LT(heun * 5, euler);
  EXPECT_LT(midpoint * 5, euler);
  EXPECT_LT(rk4 * 2, heun);
}

// ---------------------------------------------------------------------------------------------
// Dormand-Prince.

/// Fixed-step RK4 from (t0, y0) over `span` in n steps.
template <typename State, typename F> State fixedRk4(F f, const State& y0, double span, long n) {
  State y = y0;
  const double h = span / static_cast<double>(n);
  for (long i = 0; i < n; ++i) {
    y = rk4Step(f, static_cast<double>(i) * h, y, h);
  }
  return y;
}

/// The evaluations of fixed-step RK4 with the fewest steps that meet `target` (error falls
/// monotonically with the step count here: doubling, then bisection).
template <typename State, typename F, typename Error>
long rk4EvaluationsFor(double target, F f, const State& y0, double span, Error error) {
  const auto meets = [&](long n) { return error(fixedRk4(f, y0, span, n)) < target; };
  long hi = 64;
  while (!meets(hi)) {
    hi *= 2;
  }
  long lo = hi / 2;
  while (hi - lo > 1) {
    const long mid = (lo + hi) / 2;
    (meets(mid) ? hi : lo) = mid;
  }
  return 4 * hi;
}

// x'' = -x over 10 periods: back to (1, 0). Dormand-Prince meets 1e-10 (8e-11) in ~17,500
// evaluations; fixed RK4 needs ~16,900 steps, ~67,600 evaluations.
TEST(DormandPrince, oscillator_to_1e_10_with_far_fewer_evaluations_than_rk4) {
  const double span = 20.0 * pi<double>;
  const auto error = [](const Phase& y) { return std::max(std::abs(y.position - 1.0), std::abs(y.velocity)); };
  AdaptiveSettings s;
  s.absoluteTolerance = 4e-12;
  s.relativeTolerance = 4e-12;
  const AdaptiveResult<Phase> r = integrateDormandPrince(oscillatorRate, 0.0, Phase{1.0, 0.0}, span, s);
  EXPECT_EQ(r.time, span);
  EXPECT_LT(error(r.state), 1e-10);
  const long rk4 = rk4EvaluationsFor(1e-10, oscillatorRate, Phase{1.0, 0.0}, span, error);
  EXPECT_LT(3 * r.stats.evaluations, rk4) << "Dormand-Prince " << r.stats.evaluations << ", RK4 " << rk4;
  // 6 per trial (FSAL), 1 for f(t0, y0), 1 for choosing the first step.
  EXPECT_EQ(r.stats.evaluations, 6 * (r.stats.accepted + r.stats.rejected) + 2);
}

// The e = 0.5 Kepler orbit over 3 periods: the adaptive step shrinks at periapsis (speed sqrt(3))
// and grows at apoapsis (speed 1/sqrt(3)), where fixed RK4 must use the periapsis step throughout.
// Dormand-Prince meets 1e-10 (6e-11) in ~13,300 evaluations with steps from 0.0007 to 0.017;
// fixed RK4 needs ~20,600 steps, ~82,400 evaluations.
TEST(DormandPrince, kepler_orbit_to_1e_10_with_far_fewer_evaluations_than_rk4) {
  using Orbit = PhaseState<Vec3d>;
  const auto gravity = [](double, const Vec3d& r, const Vec3d&) {
    const double d = length(r);
    return r * (-1.0 / (d * d * d));
  };
  const auto rate = firstOrderRate(gravity);
  const Orbit start{{0.5, 0.0, 0.0}, {0.0, std::sqrt(3.0), 0.0}};
  const double span = 3.0 * 2.0 * pi<double>;
  const auto error = [&](const Orbit& y) {
    return std::max(length(y.position - start.position), length(y.velocity - start.velocity));
  };
  AdaptiveSettings s;
  s.absoluteTolerance = 1e-13;
  s.relativeTolerance = 1e-13;
  std::vector<double> steps;
  double last = 0.0;
  const AdaptiveResult<Orbit> r =
      integrateDormandPrince(rate, 0.0, start, span, s, StateNorm{}, [&](double t, const Orbit&) {
        steps.push_back(t - last);
        last = t;
      });
  EXPECT_EQ(r.time, span);
  EXPECT_LT(error(r.state), 1e-10);
  EXPECT_GT(r.stats.largestStep, 10.0 * r.stats.smallestStep);
  const long rk4 = rk4EvaluationsFor(1e-10, rate, start, span, error);
  EXPECT_LT(5 * r.stats.evaluations, rk4) << "Dormand-Prince " << r.stats.evaluations << ", RK4 " << rk4;
  EXPECT_EQ(static_cast<long>(steps.size()), r.stats.accepted);
}

TEST(DormandPrince, ends_exactly_at_the_end_time_and_continues_from_there) {
  AdaptiveSettings s = absolute(1e-9);
  std::vector<double> times;
  const AdaptiveResult<Phase> first = integrateDormandPrince(shipRate, 0.0, Phase{}, 3.7, s, StateNorm{},
                                                             [&](double t, const Phase&) { times.push_back(t); });
  EXPECT_EQ(first.time, 3.7);
  ASSERT_FALSE(times.empty());
  EXPECT_EQ(times.back(), 3.7);
  for (std::size_t i = 1; i < times.size(); ++i) {
    EXPECT_LT(times[i - 1], times[i]);
  }
  EXPECT_GT(first.nextStep, 0.0);
  s.initialStep = first.nextStep;
  const AdaptiveResult<Phase> second = integrateDormandPrince(shipRate, first.time, first.state, 10.0, s);
  EXPECT_EQ(second.time, 10.0);
  EXPECT_NEAR(second.state.position, exactShipPosition(10.0), 1e-8);
  EXPECT_NEAR(second.state.velocity, exactShipVelocity(10.0), 1e-9);
  EXPECT_EQ(second.stats.evaluations, 6 * (second.stats.accepted + second.stats.rejected) + 1);
  // Nothing to do: no evaluation, the state back unchanged.
  const AdaptiveResult<Phase> none = integrateDormandPrince(shipRate, 2.0, Phase{1.0, 2.0}, 2.0);
  EXPECT_EQ(none.stats.evaluations, 0);
  EXPECT_EQ(none.state.velocity, 2.0);
}

// Tolerance proportionality: tightening the tolerance 1000x cuts the error by about 1000x (a
// well-behaved controller), and a scalar state works as well as a struct.
TEST(DormandPrince, error_follows_the_tolerance) {
  const auto decay = [](double t, double y) { return -y + std::sin(t); };
  // y' = -y + sin t, y(0) = 1: y = 1.5 e^-t + (sin t - cos t)/2.
  const double exact = 1.5 * std::exp(-5.0) + (std::sin(5.0) - std::cos(5.0)) / 2.0;
  const double loose = std::abs(integrateDormandPrince(decay, 0.0, 1.0, 5.0, absolute(1e-5)).state - exact);
  const double tight = std::abs(integrateDormandPrince(decay, 0.0, 1.0, 5.0, absolute(1e-8)).state - exact);
  EXPECT_LT(loose, 1e-5);
  EXPECT_LT(tight, 1e-8);
  EXPECT_GT(loose / tight, 100.0);
}

// ---------------------------------------------------------------------------------------------
// Bad input.

TEST(Adaptive, bad_input_names_the_field) {
  const auto withDp = [](AdaptiveSettings s) {
    return [s] { (void)integrateDormandPrince(shipVelocityRate, 0.0, 0.0, 1.0, s); };
  };
  const auto withDoubling = [](AdaptiveSettings s) {
    return [s] { (void)integrateStepDoubling(Heun{}, shipVelocityRate, 0.0, 0.0, 1.0, s); };
  };
  const auto both = [&](AdaptiveSettings s, const std::string& field) {
    expectErrorField(withDp(s), field);
    expectErrorField(withDoubling(s), field);
  };
  AdaptiveSettings s;
  s.absoluteTolerance = -1e-6;
  both(s, "absoluteTolerance");
  s = {};
  s.relativeTolerance = std::nan("");
  both(s, "relativeTolerance");
  s = {};
  s.absoluteTolerance = 0.0;
  s.relativeTolerance = 0.0;
  both(s, "absoluteTolerance");
  s = {};
  s.minStep = 0.0;
  both(s, "minStep");
  s = {};
  s.maxStep = 1e-13;
  both(s, "maxStep");
  s = {};
  s.initialStep = -0.1;
  both(s, "initialStep");
  s = {};
  s.safety = 1.5;
  both(s, "safety");
  s = {};
  s.minScale = 1.0;
  both(s, "minScale");
  s = {};
  s.maxScale = 1.0;
  both(s, "maxScale");
  s = {};
  s.maxSteps = 0;
  both(s, "maxSteps");
  s = absolute(1e-12);
  s.maxSteps = 5; // far too few for 1e-12 over 10 s
  expectErrorField([&] { (void)integrateDormandPrince(shipRate, 0.0, Phase{}, 10.0, s); }, "maxSteps");
  expectErrorField([&] { (void)integrateStepDoubling(Heun{}, shipRate, 0.0, Phase{}, 10.0, s); }, "maxSteps");

  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectErrorField([&] { (void)integrateDormandPrince(shipVelocityRate, 0.0, nan, 1.0); }, "initialState");
  expectErrorField([&] { (void)integrateStepDoubling(Heun{}, shipRate, 0.0, Phase{0.0, nan}, 1.0); }, "initialState");
  expectErrorField([&] { (void)integrateDormandPrince(shipVelocityRate, 0.0, 0.0, -1.0); }, "endTime");
  expectErrorField([&] { (void)integrateDormandPrince(shipVelocityRate, nan, 0.0, 1.0); }, "startTime");
  expectErrorField([&] { (void)integrateStepDoubling(Heun{}, shipVelocityRate, 0.0, 0.0, nan); }, "endTime");
  const auto nanRate = [](double, double) { return std::numeric_limits<double>::quiet_NaN(); };
  expectErrorField([&] { (void)integrateDormandPrince(nanRate, 0.0, 0.0, 1.0); }, "derivative");
  expectErrorField([&] { (void)integrateStepDoubling(Heun{}, nanRate, 0.0, 0.0, 1.0); }, "derivative");
  expectErrorField([&] { (void)stepDoublingTrial(Heun{}, shipVelocityRate, 0.0, 0.0, 0.0); }, "step");
  expectErrorField([&] { (void)stepDoublingTrial(Heun{}, shipVelocityRate, nan, 0.0, 0.1); }, "time");
}

// y' = y^2 from y(0) = 1 is 1/(1 - t): it blows up at t = 1. Integrating past it must stop with
// a step underflow naming minStep, not loop or return infinity. So must a force that turns NaN.
TEST(Adaptive, singularity_and_nan_force_end_in_step_underflow) {
  const auto blowUp = [](double, double y) { return y * y; };
  AdaptiveSettings s;
  s.minStep = 1e-10;
  expectErrorField([&] { (void)integrateDormandPrince(blowUp, 0.0, 1.0, 2.0, s); }, "minStep");
  expectErrorField([&] { (void)integrateStepDoubling(RungeKutta4{}, blowUp, 0.0, 1.0, 2.0, s); }, "minStep");
  const auto turnsNan = [](double t, double y) { return t < 0.5 ? -y : std::numeric_limits<double>::quiet_NaN(); };
  expectErrorField([&] { (void)integrateDormandPrince(turnsNan, 0.0, 1.0, 1.0, s); }, "minStep");
  expectErrorField([&] { (void)integrateStepDoubling(Midpoint{}, turnsNan, 0.0, 1.0, 1.0, s); }, "minStep");
  // Up to the singularity it is accurate: y(0.9) = 10.
  EXPECT_NEAR(integrateDormandPrince(blowUp, 0.0, 1.0, 0.9, s).state, 10.0, 1e-4);
  // The message says where: at the pole.
  try {
    (void)integrateDormandPrince(blowUp, 0.0, 1.0, 2.0, s);
  } catch (const Error& e) {
    const std::string what = e.what();
    const std::string key = "step underflow at t = ";
    ASSERT_NE(what.find(key), std::string::npos) << what;
    EXPECT_NEAR(std::stod(what.substr(what.find(key) + key.size())), 1.0, 1e-4) << what;
  }
}

} // namespace
} // namespace impetus
