// Adaptive step-size control (ch. 7): the book's step doubling with its flaws fixed, and an
// embedded Dormand-Prince RK5(4) with a PI controller. Both integrate dy/dt = f(t, y) from t0 to
// exactly t1 (the last step is clipped), for any state with state + state and state * double,
// and measure the error on the whole state through a norm (StateNorm by default).
//
// Error control, per step: with e the local error estimate and y, y' the states before and after,
//   tolerance = absoluteTolerance + relativeTolerance * max(||y||, ||y'||),
// the step is accepted when ||e|| <= tolerance, and the next step is
//   h' = h * clamp(safety * (tolerance / ||e||)^(1/(p+1)), minScale, maxScale)
// (p + 1 the order of the local error estimate), clamped to [minStep, maxStep]. A zero error
// grows the step by maxScale; a non-finite one (the state blew up) shrinks it by minScale. A
// step rejected at minStep throws impetus::Error naming "minStep" (step underflow), so a
// singularity or a NaN force never loops forever.
//
// The book's step doubling (ch. 7) took one step h and two steps h/2, estimated the error as
// |v1 - v2| and set h_new = h (tol/err)^(1/2). As printed it divides by zero when the two agree,
// keeps v1 (the less accurate of the two), never checks the retried step, has no safety factor,
// clamps or growth limit, measures velocity only and leaves the caller to track the time
// actually stepped. integrateStepDoubling fixes each: zero error handled, safety 0.9, min/max
// clamps and a growth limit, the Richardson extrapolate accepted, every retry re-checked by the
// same test, the norm of the whole state, and the driver owns the time and ends exactly at t1.
#pragma once

#include <impetus/error.hpp>
#include <impetus/integrate/steppers.hpp>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <limits>
#include <string>
#include <type_traits>

namespace impetus {

/// Tolerances and step limits of the adaptive drivers (times in the problem's unit, usually s).
struct AdaptiveSettings {
  double absoluteTolerance = 1e-6; ///< >= 0, in the state's norm unit
  double relativeTolerance = 1e-6; ///< >= 0; not both tolerances 0
  double initialStep = 0.0;        ///< first trial step, > 0; 0 = chosen automatically from f(t0, y0)
  double minStep = 1e-12;          ///< > 0: a step rejected at this size throws (step underflow)
  double maxStep = std::numeric_limits<double>::infinity(); ///< >= minStep
  double safety = 0.9;                                      ///< in (0, 1]: aim below the tolerance
  double minScale = 0.2;                                    ///< in (0, 1): the most a step may shrink per trial
  double maxScale = 5.0;                                    ///< > 1: the most a step may grow per accepted step
  long maxSteps = 10'000'000;                               ///< > 0: accepted plus rejected trials before giving up
};

/// What an adaptive integration did.
struct AdaptiveStats {
  long accepted = 0;                                             ///< steps kept
  long rejected = 0;                                             ///< trials thrown away and retried smaller
  long evaluations = 0;                                          ///< calls of f
  double smallestStep = std::numeric_limits<double>::infinity(); ///< of the accepted steps
  double largestStep = 0.0;                                      ///< of the accepted steps
};

template <typename State> struct AdaptiveResult {
  State state;         ///< y(t1)
  double time = 0.0;   ///< t1, exactly
  double nextStep = 0; ///< the step the controller would try next: pass it as initialStep to go on
  AdaptiveStats stats;
};

/// The default norm: |x| for a number, length(x) for a vector (Vec2, Vec3), the larger of the
/// members' norms for a PhaseState. Any other state needs its own norm (a callable
/// state -> double), which is also how to weight position against velocity. NaN propagates, so
/// the norm doubles as the finiteness check.
struct StateNorm {
  template <typename T> [[nodiscard]] double operator()(const T& x) const {
    if constexpr (std::is_arithmetic_v<T>) {
      return std::abs(static_cast<double>(x));
    } else if constexpr (requires {
                           x.position;
                           x.velocity;
                         }) {
      const double a = (*this)(x.position);
      const double b = (*this)(x.velocity);
      return (a >= b || std::isnan(a)) ? a : b;
    } else {
      return static_cast<double>(length(x));
    }
  }
};

/// An observer that does nothing. An observer is called as observe(t, y) after every accepted
/// step (not at t0), e.g. to record a trajectory.
struct NoObserver {
  template <typename State> void operator()(double, const State&) const noexcept {}
};

namespace detail {

inline void validateAdaptive(const AdaptiveSettings& s) {
  requireNonNegative(s.absoluteTolerance, "absoluteTolerance");
  requireNonNegative(s.relativeTolerance, "relativeTolerance");
  if (s.absoluteTolerance == 0.0 && s.relativeTolerance == 0.0) {
    throwInvalid("absoluteTolerance", 0.0, "must be positive when relativeTolerance is 0");
  }
  requireNonNegative(s.initialStep, "initialStep");
  requirePositive(s.minStep, "minStep");
  if (!(s.maxStep >= s.minStep)) {
    throwInvalid("maxStep", s.maxStep, "must be >= minStep = " + formatValue(s.minStep));
  }
  if (!(s.safety > 0.0 && s.safety <= 1.0)) {
    throwInvalid("safety", s.safety, "must be in (0, 1]");
  }
  if (!(s.minScale > 0.0 && s.minScale < 1.0)) {
    throwInvalid("minScale", s.minScale, "must be in (0, 1)");
  }
  if (!(s.maxScale > 1.0 && std::isfinite(s.maxScale))) {
    throwInvalid("maxScale", s.maxScale, "must be finite and > 1");
  }
  if (s.maxSteps <= 0) {
    throwInvalid("maxSteps", static_cast<double>(s.maxSteps), "must be positive");
  }
}

inline void validateSpan(double t0, double t1) {
  requireFinite(t0, "startTime");
  requireFinite(t1, "endTime");
  if (t1 < t0) {
    throwInvalid("endTime", t1, "must be >= startTime = " + formatValue(t0));
  }
}

/// atol + rtol * max(||y||, ||y'||).
inline double tolerance(const AdaptiveSettings& s, double norm0, double norm1) {
  return s.absoluteTolerance + s.relativeTolerance * std::max(norm0, norm1);
}

/// safety * (tolerance/error)^exponent clamped to [minScale, maxScale]; maxScale for a zero
/// error, minScale for a non-finite one.
inline double stepScale(const AdaptiveSettings& s, double error, double tol, double exponent) {
  if (!std::isfinite(error)) {
    return s.minScale;
  }
  if (error == 0.0) {
    return s.maxScale;
  }
  return std::clamp(s.safety * std::pow(tol / error, exponent), s.minScale, s.maxScale);
}

[[noreturn]] inline void throwUnderflow(const AdaptiveSettings& s, double t, double ratio) {
  throwInvalid("minStep", s.minStep,
               "step underflow at t = " + formatValue(t) + ": the local error is still " + formatValue(ratio) +
                   " times the tolerance (a singularity, a discontinuity or a non-finite derivative?)");
}

/// A first step from f(t0, y0) (Hairer, Norsett & Wanner, Solving ODEs I, II.4): the step for
/// which an Euler step changes y by 1% of the tolerance scale, refined by the change in f over
/// it so that the local error of an order-p method is near the tolerance. One evaluation of f.
template <typename State, typename Derivative, typename Norm>
double initialStep(Derivative& f, double t0, const State& y0, const State& f0, double span, int order,
                   const AdaptiveSettings& s, Norm& norm) {
  double scale = tolerance(s, norm(y0), 0.0);
  if (scale == 0.0) { // purely relative control from y0 = 0: take the scale of |y| ~ 1
    scale = s.relativeTolerance;
  }
  const double d0 = norm(y0) / scale;
  const double d1 = norm(f0) / scale;
  double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
  h0 = std::min({h0, span, s.maxStep});
  const State f1 = f(t0 + h0, y0 + f0 * h0);
  const double d2 = norm(f1 + f0 * -1.0) / scale / h0;
  const double d = std::max(d1, d2);
  const double h1 = d <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / d, 1.0 / (order + 1));
  return std::clamp(std::min(100.0 * h0, h1), s.minStep, s.maxStep);
}

/// Checks the settings, the time span and the initial state of an adaptive run, and starts its
/// result at (t0, y0) with the first step to try.
template <typename State, typename Norm>
AdaptiveResult<State> startAdaptive(const AdaptiveSettings& s, double t0, const State& y0, double t1, Norm& norm) {
  validateAdaptive(s);
  validateSpan(t0, t1);
  requireFinite(norm(y0), "initialState");
  return {y0, t0, s.initialStep, {}};
}

} // namespace detail

// ---------------------------------------------------------------------------------------------
// Step doubling.

/// One trial of step doubling.
template <typename State> struct StepDoublingTrial {
  State single;              ///< one step of h (the book's v1)
  State doubled;             ///< two steps of h/2 (the book's v2)
  State extrapolated;        ///< Richardson: doubled + (doubled - single)/(2^p - 1), order p + 1
  double error = 0.0;        ///< ||doubled - single||: the book's epsilon_t
  double tolerance = 0.0;    ///< atol + rtol * max(||y||, ||doubled||)
  double proposedStep = 0.0; ///< h * clamp(safety (tolerance/error)^(1/(p+1))), in [minStep, maxStep]
  bool accepted = false;     ///< error <= tolerance (and finite)
};

namespace detail {

template <typename Stepper, typename State, typename Derivative, typename Norm>
StepDoublingTrial<State> stepDoublingTrialUnchecked(const Stepper& stepper, Derivative& f, double t, const State& y,
                                                    double h, const AdaptiveSettings& s, Norm& norm) {
  constexpr int p = Stepper::order;
  const double half = h / 2.0;
  StepDoublingTrial<State> r{stepper(f, t, y, h), stepper(f, t + half, stepper(f, t, y, half), half), y};
  const State difference = r.doubled + r.single * -1.0;
  r.extrapolated = r.doubled + difference * (1.0 / static_cast<double>((1 << p) - 1));
  r.error = norm(difference);
  r.tolerance = tolerance(s, norm(y), norm(r.doubled));
  r.accepted = r.error <= r.tolerance && std::isfinite(norm(r.extrapolated));
  double scale = stepScale(s, r.error, r.tolerance, 1.0 / (p + 1));
  if (!r.accepted) {
    scale = std::min(scale, std::isfinite(r.error) ? 1.0 : s.minScale);
  }
  r.proposedStep = std::clamp(h * scale, s.minStep, s.maxStep);
  return r;
}

} // namespace detail

/// One step-doubling trial of `stepper` (ExplicitEuler, Heun, Midpoint, RungeKutta4 or any
/// object with a static `order` and a call (f, t, y, h) -> y) from (t, y) with step h > 0.
/// The error of one step of an order-p method is C h^(p+1); two half steps leave 2 C (h/2)^(p+1),
/// so single - doubled estimates it, and h (tol/err)^(1/(p+1)) is the step that would meet the
/// tolerance. With safety = 1 and relativeTolerance = 0 this is the book's formula exactly.
/// Costs 3 steps of the stepper (3, 6, 6 or 12 evaluations for the four methods).
template <typename Stepper, typename State, typename Derivative, typename Norm = StateNorm>
requires std::invocable<Derivative&, double, const State&>
[[nodiscard]] StepDoublingTrial<State> stepDoublingTrial(const Stepper& stepper, Derivative&& f, double t,
                                                         const State& y, double h,
                                                         const AdaptiveSettings& settings = {}, Norm norm = {}) {
  detail::validateAdaptive(settings);
  requireFinite(t, "time");
  requirePositive(h, "step");
  return detail::stepDoublingTrialUnchecked(stepper, f, t, y, h, settings, norm);
}

/// Integrates dy/dt = f(t, y) from (t0, y0) to t1 >= t0 with step doubling around `stepper`,
/// accepting the Richardson extrapolate of each step (one order higher than the stepper; the
/// error control is conservative for it). Throws impetus::Error for bad settings, a non-finite
/// y0 ("initialState") or f(t0, y0) ("derivative"), a step underflow ("minStep") or too many
/// steps ("maxSteps").
template <typename Stepper, typename State, typename Derivative, typename Norm = StateNorm,
          typename Observer = NoObserver>
requires std::invocable<Derivative&, double, const State&>
[[nodiscard]] AdaptiveResult<State> integrateStepDoubling(const Stepper& stepper, Derivative&& f, double t0,
                                                          const State& y0, double t1,
                                                          const AdaptiveSettings& settings = {}, Norm norm = {},
                                                          Observer observe = {}) {
  const AdaptiveSettings& s = settings;
  AdaptiveResult<State> r = detail::startAdaptive(s, t0, y0, t1, norm);
  auto counted = [&](double t, const State& y) -> State {
    ++r.stats.evaluations;
    return f(t, y);
  };
  if (t1 == t0) {
    return r;
  }
  double h = s.initialStep;
  if (h == 0.0) {
    const State f0 = counted(t0, y0);
    requireFinite(norm(f0), "derivative");
    h = detail::initialStep(counted, t0, y0, f0, t1 - t0, Stepper::order, s, norm);
  }
  h = std::clamp(h, s.minStep, s.maxStep);
  bool afterRejection = false;
  while (r.time < t1) {
    if (r.stats.accepted + r.stats.rejected >= s.maxSteps) {
      throwInvalid("maxSteps", static_cast<double>(s.maxSteps),
                   "reached at t = " + formatValue(r.time) + " before endTime = " + formatValue(t1));
    }
    const bool last = h >= t1 - r.time;
    const double step = last ? t1 - r.time : h;
    if (r.time + step == r.time) {
      detail::throwUnderflow(s, r.time, 1.0);
    }
    const StepDoublingTrial<State> trial =
        detail::stepDoublingTrialUnchecked(stepper, counted, r.time, r.state, step, s, norm);
    if (trial.accepted) {
      r.time = last ? t1 : r.time + step;
      r.state = trial.extrapolated;
      ++r.stats.accepted;
      r.stats.smallestStep = std::min(r.stats.smallestStep, step);
      r.stats.largestStep = std::max(r.stats.largestStep, step);
      observe(r.time, r.state);
      // No growth straight after a rejection (the estimate just proved optimistic); a clipped
      // last step says nothing about the step the solution allows.
      const double next = afterRejection ? std::min(trial.proposedStep, step) : trial.proposedStep;
      h = last ? std::max(next, h) : next;
      afterRejection = false;
    } else {
      ++r.stats.rejected;
      if (step <= s.minStep) {
        detail::throwUnderflow(s, r.time, trial.error / trial.tolerance);
      }
      h = trial.proposedStep; // the retry is a full trial again: re-checked, never accepted blind
      afterRejection = true;
    }
  }
  r.nextStep = h;
  return r;
}

// ---------------------------------------------------------------------------------------------
// Dormand-Prince RK5(4).

/// Integrates dy/dt = f(t, y) from (t0, y0) to t1 >= t0 with the embedded Runge-Kutta pair of
/// Dormand and Prince (1980), the method of MATLAB's ode45 and SciPy's RK45: 7 stages, the 5th
/// order solution propagated (local extrapolation), the embedded 4th order one giving the error
/// estimate, and the last stage reused as the next step's first (FSAL), so 6 evaluations per
/// trial step. Step control: Gustafsson's PI controller as in Hairer's DOPRI5,
///   h' = h * safety * ratio^(-0.17) * previousRatio^(0.04),   ratio = ||e|| / tolerance,
/// clamped to [minScale, maxScale], with no growth straight after a rejection. The PI term damps
/// the step-size oscillation a plain controller shows where stability, not accuracy, limits h.
/// The last step is clipped so the result is at t1 exactly. Throws as integrateStepDoubling.
template <typename State, typename Derivative, typename Norm = StateNorm, typename Observer = NoObserver>
requires std::invocable<Derivative&, double, const State&>
[[nodiscard]] AdaptiveResult<State> integrateDormandPrince(Derivative&& f, double t0, const State& y0, double t1,
                                                           const AdaptiveSettings& settings = {}, Norm norm = {},
                                                           Observer observe = {}) {
  // Butcher tableau (c, a), 5th-order weights b (= the last row of a, hence FSAL) and the error
  // weights e = b - b*, b* the embedded 4th-order weights.
  constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
  constexpr double a21 = 1.0 / 5;
  constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
  constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
  constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
  constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                   a65 = -5103.0 / 18656;
  constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
  constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200, e6 = 22.0 / 525,
                   e7 = -1.0 / 40;
  constexpr double beta = 0.04;               // PI controller: weight of the previous error
  constexpr double alpha = 0.2 - 0.75 * beta; // and of the current one (1/5 for a plain controller)

  const AdaptiveSettings& s = settings;
  AdaptiveResult<State> r = detail::startAdaptive(s, t0, y0, t1, norm);
  auto counted = [&](double t, const State& y) -> State {
    ++r.stats.evaluations;
    return f(t, y);
  };
  if (t1 == t0) {
    return r;
  }
  State k1 = counted(t0, y0);
  requireFinite(norm(k1), "derivative");
  double h = s.initialStep > 0.0 ? s.initialStep : detail::initialStep(counted, t0, y0, k1, t1 - t0, 4, s, norm);
  h = std::clamp(h, s.minStep, s.maxStep);
  double previousRatio = 1e-4;
  bool afterRejection = false;
  while (r.time < t1) {
    if (r.stats.accepted + r.stats.rejected >= s.maxSteps) {
      throwInvalid("maxSteps", static_cast<double>(s.maxSteps),
                   "reached at t = " + formatValue(r.time) + " before endTime = " + formatValue(t1));
    }
    const bool last = h >= t1 - r.time;
    const double step = last ? t1 - r.time : h;
    const double t = r.time;
    const State& y = r.state;
    if (t + step == t) {
      detail::throwUnderflow(s, t, 1.0);
    }
    const State k2 = counted(t + c2 * step, y + k1 * (a21 * step));
    const State k3 = counted(t + c3 * step, y + (k1 * a31 + k2 * a32) * step);
    const State k4 = counted(t + c4 * step, y + (k1 * a41 + k2 * a42 + k3 * a43) * step);
    const State k5 = counted(t + c5 * step, y + (k1 * a51 + k2 * a52 + k3 * a53 + k4 * a54) * step);
    const State k6 = counted(t + step, y + (k1 * a61 + k2 * a62 + k3 * a63 + k4 * a64 + k5 * a65) * step);
    const State next = y + (k1 * b1 + k3 * b3 + k4 * b4 + k5 * b5 + k6 * b6) * step;
    const State k7 = counted(t + step, next);
    const State error = (k1 * e1 + k3 * e3 + k4 * e4 + k5 * e5 + k6 * e6 + k7 * e7) * step;
    const double nextNorm = norm(next);
    const double ratio = norm(error) / detail::tolerance(s, norm(y), nextNorm);
    if (ratio <= 1.0 && std::isfinite(nextNorm) && std::isfinite(norm(k7))) {
      double scale = s.maxScale;
      if (ratio > 0.0) {
        scale = std::clamp(s.safety * std::pow(ratio, -alpha) * std::pow(previousRatio, beta), s.minScale, s.maxScale);
      }
      if (afterRejection) {
        scale = std::min(scale, 1.0);
      }
      previousRatio = std::max(ratio, 1e-4);
      r.time = last ? t1 : t + step;
      r.state = next;
      k1 = k7;
      ++r.stats.accepted;
      r.stats.smallestStep = std::min(r.stats.smallestStep, step);
      r.stats.largestStep = std::max(r.stats.largestStep, step);
      observe(r.time, r.state);
      const double proposed = std::clamp(step * scale, s.minStep, s.maxStep);
      h = last ? std::max(proposed, h) : proposed;
      afterRejection = false;
    } else {
      ++r.stats.rejected;
      if (step <= s.minStep) {
        detail::throwUnderflow(s, t, ratio);
      }
      const double scale =
          std::isfinite(ratio) ? std::clamp(s.safety * std::pow(ratio, -alpha), s.minScale, 1.0) : s.minScale;
      h = std::max(step * scale, s.minStep);
      afterRejection = true;
    }
  }
  r.nextStep = h;
  return r;
}

} // namespace impetus
