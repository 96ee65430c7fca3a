// `impetus calc` entries for the integrators (ch. 7): the book's ship integrated with any method
// and step against its closed form, each method's amplification per step on the undamped
// oscillator, and one trial of the book's step doubling.
#include "calc/calc.hpp"

#include <impetus/error.hpp>
#include <impetus/integrate/integrate.hpp>
#include <impetus/mechanics/kinetics.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <string>

namespace impetus::cli {
namespace {

constexpr const char* topic = "integrators (ch. 7)";

constexpr std::array<Integrator, 6> kMethods{Integrator::explicitEuler, Integrator::semiImplicitEuler,
                                             Integrator::heun,          Integrator::midpoint,
                                             Integrator::rk4,           Integrator::velocityVerlet};

std::string methodList() {
  std::string list;
  for (Integrator m : kMethods) {
    list += (list.empty() ? "" : ", ") + std::string(integratorName(m));
  }
  return list;
}

Integrator methodFromArgs(const Args& a) {
  const std::string& name = a.text("method");
  const std::optional<Integrator> m = parseIntegrator(name);
  if (!m) {
    throw Error("method", "method = " + name + ": must be one of " + methodList());
  }
  return *m;
}

/// "explicit-euler" -> "explicit_euler", for output names.
/// A per-method output's key: the quantity, then the method as --method spells it
/// ("amplification.explicit-euler"), so a script can look a method up by the name it passes.
std::string outputName(const char* quantity, Integrator m) {
  return std::string(quantity) + "." + std::string(integratorName(m));
}

/// The ship m dv/dt = T - C v, ds/dt = v from rest, integrated to `time` with steps of `step`
/// (the last one clipped). whole-state: the method on (s, v) together; book: the method on v
/// alone, then s += v_new h, as the book's listings do.
Result integrateShip(const Args& a) {
  const double thrust = a.number("thrust");
  const double mass = a.number("mass");
  const double drag = a.number("resistance-coefficient");
  const double time = a.number("time");
  const ShipState exact = shipMotion(thrust, mass, drag, time); // validates the four
  const double h = requirePositive(a.number("time-step"), "timeStep");
  const double stepCount = std::ceil(time / h * (1.0 - 1e-12));
  if (stepCount > 1e7) {
    throwInvalid("timeStep", h, "too small for the time: more than 1e7 steps");
  }
  const Integrator method = methodFromArgs(a);
  const std::string& scheme = a.text("scheme");
  const bool book = scheme == "book";
  if (!book && scheme != "whole-state") {
    throw Error("scheme", "scheme = " + scheme + ": must be whole-state or book");
  }
  const bool secondOrderOnly = method == Integrator::semiImplicitEuler || method == Integrator::velocityVerlet;
  if (book && secondOrderOnly) {
    throw Error("scheme", "scheme = book: applies to explicit-euler, heun, midpoint and rk4 (the book's own "
                          "position update makes any of them semi-implicit; --method semi-implicit-euler is the "
                          "book's Euler)");
  }

  long evaluations = 0;
  const auto accel = [&](double, double, double v) {
    ++evaluations;
    return (thrust - drag * v) / mass;
  };
  const auto velocityRate = [&](double t, double v) { return accel(t, 0.0, v); };
  const auto step = [&](const auto& f, double t, const auto& x, double dt) {
    switch (method) {
    case Integrator::explicitEuler:
      return explicitEulerStep(f, t, x, dt);
    case Integrator::heun:
      return heunStep(f, t, x, dt);
    case Integrator::midpoint:
      return midpointStep(f, t, x, dt);
    default:
      return rk4Step(f, t, x, dt);
    }
  };

  PhaseState<double> x{0.0, 0.0};
  double verletAcceleration = method == Integrator::velocityVerlet ? accel(0.0, 0.0, 0.0) : 0.0;
  double t = 0.0;
  const auto steps = static_cast<long>(stepCount);
  for (long i = 0; i < steps; ++i) {
    const double dt = i + 1 == steps ? time - t : h;
    if (book) {
      const double v = step(velocityRate, t, x.velocity, dt);
      x = {x.position + v * dt, v};
    } else if (method == Integrator::semiImplicitEuler) {
      x = semiImplicitEulerStep(accel, t, x, dt);
    } else if (method == Integrator::velocityVerlet) {
      x = velocityVerletStep(accel, t, x, dt, verletAcceleration);
    } else {
      x = step(firstOrderRate(accel), t, x, dt);
    }
    t = i + 1 == steps ? time : t + dt;
  }

  Result r;
  r.add("velocity", x.velocity, "m/s", "integrated v(t)");
  r.add("position", x.position, "m", "integrated s(t)");
  r.add("exact_velocity", exact.speed, "m/s", "(T/C)(1 - e^(-Ct/m))");
  r.add("exact_position", exact.distance, "m", "(T/C) t - (T m/C^2)(1 - e^(-Ct/m))");
  r.add("velocity_error", x.velocity - exact.speed, "m/s", "integrated - exact");
  r.add("position_error", x.position - exact.distance, "m", "integrated - exact");
  if (exact.speed != 0.0) {
    r.add("velocity_error_percent", 100.0 * (x.velocity - exact.speed) / std::abs(exact.speed), "%");
  }
  if (exact.distance != 0.0) {
    r.add("position_error_percent", 100.0 * (x.position - exact.distance) / std::abs(exact.distance), "%");
  }
  r.add("steps", static_cast<double>(steps));
  r.add("evaluations", static_cast<double>(evaluations), "", "force evaluations");
  r.add("global_order", static_cast<double>(book ? 1 : globalOrder(method)), "",
        "of the position error (the book's scheme is first order in s)");
  if (book) {
    r.notes.emplace_back("book's scheme: the method advances v only and s += v_new dt, so the position is "
                         "first order whatever the method (RK4 at dt = 0.5: s(10) = 76.710 m, exact 73.576 m)");
    if (method == Integrator::explicitEuler) {
      r.notes.emplace_back("explicit Euler on v with s += v_new dt is semi-implicit Euler: the book's \"Euler\"");
    }
  }
  if (method == Integrator::semiImplicitEuler) {
    r.notes.emplace_back("semi-implicit Euler (v += a dt, then s += v_new dt) is what the book calls Euler");
  }
  return r;
}

Result oscillatorStability(const Args& a) {
  const double z = requireNonNegative(a.number("omega-dt"), "omegaDt");
  const double steps = a.number("steps");
  if (!(steps >= 1.0 && steps <= 1e9) || steps != std::floor(steps)) {
    throwInvalid("steps", steps, "must be a whole number between 1 and 1e9");
  }
  Result r;
  for (Integrator m : kMethods) {
    const double g = oscillatorAmplification(m, z);
    r.add(outputName("amplification", m), g, "", "amplitude factor per step (1 = energy-neutral)");
  }
  for (Integrator m : kMethods) {
    // E_N / E_0 ~ |lambda|^(2N) (exactly so for the Runge-Kutta family, whose step is |lambda|
    // times a rotation); as a power of ten, since it overflows a double for unstable z.
    r.add(outputName("energy_log10", m), 2.0 * steps * std::log10(oscillatorAmplification(m, z)), "",
          "log10 of the energy ratio after --steps steps, 2 N log10|lambda|");
  }
  r.notes.emplace_back("explicit Euler sqrt(1+z^2), Heun and midpoint sqrt(1+z^4/4) always grow; RK4 decays "
                       "slightly up to z = 2.83; semi-implicit Euler and velocity Verlet stay bounded (1) up to z = 2");
  if (z > 0.0 && z <= 2.0) {
    r.notes.emplace_back("semi-implicit Euler and Verlet: |lambda| = 1, the energy oscillates (by O(z) and O(z^2)) "
                         "about a conserved shadow energy");
  }
  return r;
}

/// One step-doubling trial of the book's Euler on the ship's velocity (spec oracle: from rest,
/// dt = 0.5, tolerance 0.01 gives v1 = 1, v2 = 0.9875, error 0.0125, new step 0.44721 s).
Result adaptiveStep(const Args& a) {
  const double thrust = requireFinite(a.number("thrust"), "thrust");
  const double mass = requirePositive(a.number("mass"), "mass");
  const double drag = requireNonNegative(a.number("resistance-coefficient"), "resistanceCoefficient");
  const double v0 = requireFinite(a.number("speed"), "speed");
  AdaptiveSettings s;
  s.absoluteTolerance = requirePositive(a.number("tolerance"), "tolerance");
  s.relativeTolerance = 0.0;
  s.safety = a.number("safety");
  const auto rate = [&](double, double v) { return (thrust - drag * v) / mass; };
  const double h = requirePositive(a.number("time-step"), "timeStep");
  const StepDoublingTrial<double> trial = stepDoublingTrial(ExplicitEuler{}, rate, 0.0, v0, h, s);
  Result r;
  r.add("single_step", trial.single, "m/s", "v1: one step of dt");
  r.add("two_half_steps", trial.doubled, "m/s", "v2: two steps of dt/2");
  r.add("error", trial.error, "m/s", "|v1 - v2|");
  r.add("new_step", trial.proposedStep, "s", "dt * clamp(safety * (tolerance/error)^(1/2))");
  r.add("accepted", trial.accepted, "", "error <= tolerance");
  r.add("extrapolated", trial.extrapolated, "m/s", "Richardson 2 v2 - v1, kept when accepted");
  r.notes.emplace_back("the book keeps v1 and never re-checks the retried step; integrateStepDoubling keeps the "
                       "extrapolate and retries every rejected step as a full trial");
  return r;
}

} // namespace

void registerIntegratorModels(Registry& registry) {
  registry.add({"integrate-ship",
                topic,
                "the book's ship m dv/dt = T - C v integrated with a chosen method and step, against the exact v, s",
                {{"method", "", "explicit-euler, semi-implicit-euler, heun, midpoint, rk4 or velocity-verlet", "rk4",
                  ParamKind::text},
                 {"scheme", "", "whole-state (the method on s and v) or book (v only, then s += v_new dt)",
                  "whole-state", ParamKind::text},
                 {"time-step", "s", "dt (the book's table: 0.5)", "0.5"},
                 {"time", "s", "integrate to t, >= 0", "10"},
                 {"thrust", "N", "T", "20000"},
                 {"mass", "kg", "m", "10000"},
                 {"resistance-coefficient", "N s/m", "C in R = C v (>= 0)", "1000"}},
                integrateShip});
  registry.add({"oscillator-stability",
                topic,
                "amplification per step of each method on x'' = -w^2 x at z = w dt, and the energy ratio after N steps",
                {{"omega-dt", "", "z = w dt, >= 0", "0.5"},
                 {"steps", "", "N, for the energy ratio |lambda|^(2N) (as log10)", "1000"}},
                oscillatorStability});
  registry.add({"adaptive-step",
                topic,
                "one step-doubling trial of Euler on the ship's velocity: v1, v2, error and the new step",
                {{"time-step", "s", "dt tried", "0.5"},
                 {"tolerance", "m/s", "error tolerance on v", "0.01"},
                 {"safety", "", "safety factor in (0, 1] (the book: 1)", "1"},
                 {"speed", "m/s", "v at the start", "0"},
                 {"thrust", "N", "T", "20000"},
                 {"mass", "kg", "m", "10000"},
                 {"resistance-coefficient", "N s/m", "C", "1000"}},
                adaptiveStep});
}

} // namespace impetus::cli
