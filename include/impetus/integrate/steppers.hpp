// Fixed-step integrators (ch. 7): one step of an ODE initial-value problem.
//
// First-order form, dx/dt = f(t, x), generic over the state: any type with state + state and
// state * scalar (a double, a Vec3, a struct of vectors...); f returns dx/dt as the same type.
//   explicitEulerStep  heunStep  midpointStep  rk4Step
// Second-order form, x'' = a(t, x, v), with separate position and velocity types (a returns an
// acceleration of the velocity's type; position + velocity * scalar must give a position):
//   explicitEulerStep2  semiImplicitEulerStep  velocityVerletStep
// PhaseState<P, V> holds (x, v) for the second-order steppers; it also has + and * so the
// first-order steppers integrate it whole through firstOrderRate(a).
//
// What each costs and how it behaves, h the step, z = w h for the undamped oscillator
// x'' = -w^2 x (amplification = |eigenvalue| of one step; energy scales by its square):
//
// | method              | global order | f evals/step | amplification per step            | stable   |
// |---------------------|--------------|--------------|-----------------------------------|----------|
// | explicit Euler      | 1            | 1            | sqrt(1 + z^2)                     | never    |
// | semi-implicit Euler | 1            | 1            | 1 for z < 2, then grows           | z < 2    |
// | Heun (impr. Euler)  | 2            | 2            | sqrt(1 + z^4/4)                   | never    |
// | midpoint (RK2)      | 2            | 2            | sqrt(1 + z^4/4)                   | never    |
// | classic RK4         | 4            | 4            | |1 - z^2/2 + z^4/24 + i(z-z^3/6)| | z < 2.83 |
// | velocity Verlet     | 2            | 1 (cached)   | 1 for z < 2, then grows           | z < 2    |
//
// The numbers (the spec's table, ch. 7 notes 1.4; oscillatorAmplification computes them):
// | z = w h | explicit Euler | semi-implicit Euler, Verlet | Heun, midpoint | RK4        |
// |---------|----------------|-----------------------------|----------------|------------|
// | 0.1     | 1.004988       | 1                           | 1.0000125      | 0.99999999 |
// | 0.5     | 1.118034       | 1                           | 1.007782       | 0.999895   |
// | 1.0     | 1.414214       | 1                           | 1.118034       | 0.993905   |
// | 2.0     | 2.236068       | 1 (marginal)                | 2.236068       | 0.745356   |
// | 2.5     | 2.692582       | 4.0                         | 3.281101       | 0.508186   |
// | 3.0     | 3.162278       | 6.854                       | 4.609772       | 1.505      |
//
// "Stable" here means the amplitude never grows. Explicit Euler and Heun always gain energy on
// an undamped oscillator (Heun only as z^4/8 per step, so it looks stable over short runs); RK4
// loses a little (|R| = 1 - z^6/144 - ...). Semi-implicit Euler and velocity Verlet are
// symplectic: their eigenvalues lie on the unit circle for z < 2 (det = 1, trace = 2 - z^2), so
// the energy oscillates about a conserved "shadow" energy (by O(z) and O(z^2) respectively) but
// never drifts; above z = 2 one eigenvalue is real with modulus (z^2 - 2 + sqrt((z^2-2)^2 - 4))/2.
//
// The book (ch. 7) calls its position update "Euler", but it advances the position with the
// *new* velocity: that is semi-implicit (symplectic) Euler, not explicit Euler. Its RK4 listing
// integrates only the velocity and then moves the position by s + v_new h (first order); rk4Step
// integrates the whole state, re-evaluating the forces at every stage.
//
// The steppers do not validate their input (they run in the step loop, which never throws);
// adaptive.hpp's drivers do.
#pragma once

#include <cmath>
#include <concepts>
#include <optional>
#include <string_view>
#include <type_traits>

namespace impetus {

// ---------------------------------------------------------------------------------------------
// First-order systems dx/dt = f(t, x).

/// Explicit (forward) Euler: x + h f(t, x). Local error O(h^2), global O(h); 1 evaluation.
/// Amplification on the oscillator sqrt(1 + z^2) > 1: always gains energy.
template <typename State, typename Scalar, typename Derivative>
requires std::invocable<Derivative&, Scalar, const State&>
[[nodiscard]] State explicitEulerStep(Derivative&& f, Scalar t, const State& x, Scalar h) { return x + f(t, x) * h; }

/// Heun's method (improved Euler, explicit trapezoid): predict with Euler, then average the
/// slopes at both ends, x + h (k1 + k2)/2 with k1 = f(t, x), k2 = f(t + h, x + h k1).
/// Local error O(h^3), global O(h^2); 2 evaluations. Amplification sqrt(1 + z^4/4): the
/// amplitude grows slowly (x1.133 after 10^4 steps at z = 0.1).
template <typename State, typename Scalar, typename Derivative>
requires std::invocable<Derivative&, Scalar, const State&>
[[nodiscard]] State heunStep(Derivative&& f, Scalar t, const State& x, Scalar h) {
  const State k1 = f(t, x);
  const State k2 = f(t + h, x + k1 * h);
  return x + (k1 + k2) * (h / Scalar(2));
}

/// Explicit midpoint (RK2): x + h f(t + h/2, x + (h/2) f(t, x)). Local error O(h^3), global
/// O(h^2); 2 evaluations. Same amplification as Heun on any linear problem, sqrt(1 + z^4/4).
template <typename State, typename Scalar, typename Derivative>
requires std::invocable<Derivative&, Scalar, const State&>
[[nodiscard]] State midpointStep(Derivative&& f, Scalar t, const State& x, Scalar h) {
  const Scalar half = h / Scalar(2);
  const State k1 = f(t, x);
  const State k2 = f(t + half, x + k1 * half);
  return x + k2 * h;
}

/// Classic fourth-order Runge-Kutta on the whole state, forces re-evaluated at every stage:
/// k1 = f(t, x), k2 = f(t + h/2, x + h k1/2), k3 = f(t + h/2, x + h k2/2), k4 = f(t + h, x + h k3),
/// x + h (k1 + 2 k2 + 2 k3 + k4)/6. Local error O(h^5), global O(h^4); 4 evaluations.
/// Amplification |1 - z^2/2 + z^4/24 + i (z - z^3/6)|: slightly below 1 (dissipative) for
/// z < 2 sqrt(2) = 2.83, unstable above.
template <typename State, typename Scalar, typename Derivative>
requires std::invocable<Derivative&, Scalar, const State&>
[[nodiscard]] State rk4Step(Derivative&& f, Scalar t, const State& x, Scalar h) {
  const Scalar half = h / Scalar(2);
  const State k1 = f(t, x);
  const State k2 = f(t + half, x + k1 * half);
  const State k3 = f(t + half, x + k2 * half);
  const State k4 = f(t + h, x + k3 * h);
  return x + (k1 + k2 * Scalar(2) + k3 * Scalar(2) + k4) * (h / Scalar(6));
}

/// The first-order steppers as objects, with their order, for the adaptive drivers
/// (adaptive.hpp: the step-doubling error exponent is 1/(order + 1)).
struct ExplicitEuler {
  static constexpr int order = 1;
  static constexpr int evaluations = 1;
  template <typename State, typename Scalar, typename Derivative>
  [[nodiscard]] State operator()(Derivative&& f, Scalar t, const State& x, Scalar h) const {
    return explicitEulerStep(f, t, x, h);
  }
};
struct Heun {
  static constexpr int order = 2;
  static constexpr int evaluations = 2;
  template <typename State, typename Scalar, typename Derivative>
  [[nodiscard]] State operator()(Derivative&& f, Scalar t, const State& x, Scalar h) const {
    return heunStep(f, t, x, h);
  }
};
struct Midpoint {
  static constexpr int order = 2;
  static constexpr int evaluations = 2;
  template <typename State, typename Scalar, typename Derivative>
  [[nodiscard]] State operator()(Derivative&& f, Scalar t, const State& x, Scalar h) const {
    return midpointStep(f, t, x, h);
  }
};
struct RungeKutta4 {
  static constexpr int order = 4;
  static constexpr int evaluations = 4;
  template <typename State, typename Scalar, typename Derivative>
  [[nodiscard]] State operator()(Derivative&& f, Scalar t, const State& x, Scalar h) const {
    return rk4Step(f, t, x, h);
  }
};

// ---------------------------------------------------------------------------------------------
// Second-order systems x'' = a(t, x, v).

/// Position x and velocity v of a second-order system (e.g. m, m/s). With + and * on both
/// members it is itself a first-order state, so rk4Step(firstOrderRate(a), t, s, h) integrates
/// x and v together.
template <typename Position, typename Velocity = Position> struct PhaseState {
  Position position{};
  Velocity velocity{};

  friend PhaseState operator+(const PhaseState& a, const PhaseState& b) {
    return {a.position + b.position, a.velocity + b.velocity};
  }
  template <typename Scalar> friend PhaseState operator*(const PhaseState& a, Scalar s) {
    return {a.position * s, a.velocity * s};
  }
};

/// The first-order form of x'' = a(t, x, v): d/dt (x, v) = (v, a(t, x, v)), for the generic
/// steppers. The velocity must convert to the position type (it is dx/dt).
template <typename Acceleration> [[nodiscard]] auto firstOrderRate(Acceleration a) {
  return [a](auto t, const auto& s) {
    using State = std::remove_cvref_t<decltype(s)>;
    return State{s.velocity, a(t, s.position, s.velocity)};
  };
}

/// Explicit Euler on a second-order system: x += v_old h, v += a(t, x, v) h. Global O(h);
/// 1 evaluation; amplification sqrt(1 + z^2) (identical to explicitEulerStep on (x, v)).
/// This is the textbook "Euler" whose spring-mass system blows up (the book's Fig. 7-5).
template <typename Position, typename Velocity, typename Scalar, typename Acceleration>
requires std::invocable<Acceleration&, Scalar, const Position&, const Velocity&>
[[nodiscard]] PhaseState<Position, Velocity> explicitEulerStep2(Acceleration&& a, Scalar t,
                                                                const PhaseState<Position, Velocity>& s, Scalar h) {
  return {s.position + s.velocity * h, s.velocity + a(t, s.position, s.velocity) * h};
}

/// Semi-implicit (symplectic) Euler: v += a(t, x, v) h, then x += v_new h. Global O(h);
/// 1 evaluation. Symplectic: on the oscillator the eigenvalues have modulus 1 for z <= 2, so the
/// energy stays within O(z) of its start forever; above z = 2 it blows up (amplification 4.0 at
/// z = 2.5). The book's "Euler" (every UpdateBodyEuler of ch. 8-10) is this method; it is what
/// game engines use.
template <typename Position, typename Velocity, typename Scalar, typename Acceleration>
requires std::invocable<Acceleration&, Scalar, const Position&, const Velocity&>
[[nodiscard]] PhaseState<Position, Velocity> semiImplicitEulerStep(Acceleration&& a, Scalar t,
                                                                   const PhaseState<Position, Velocity>& s, Scalar h) {
  const Velocity v = s.velocity + a(t, s.position, s.velocity) * h;
  return {s.position + v * h, v};
}

/// Velocity Verlet: x1 = x + v h + a0 h^2/2, a1 = a(t + h, x1, v + a0 h), v1 = v + (a0 + a1) h/2.
/// Global O(h^2). On entry `acceleration` must hold a0 = a(t, x, v); on return it holds a1, ready
/// for the next step, so a step costs 1 evaluation. For an acceleration that does not depend on
/// v this is exact velocity Verlet (symplectic, time-reversible: on the oscillator the energy
/// stays within O(z^2) forever for z < 2); with velocity-dependent forces (drag) a1 uses the
/// predicted velocity v + a0 h, which keeps second order but not symplecticity (drag dissipates
/// anyway).
template <typename Position, typename Velocity, typename Scalar, typename Acceleration>
requires std::invocable<Acceleration&, Scalar, const Position&, const Velocity&>
[[nodiscard]] PhaseState<Position, Velocity> velocityVerletStep(Acceleration&& a, Scalar t,
                                                                const PhaseState<Position, Velocity>& s, Scalar h,
                                                                Velocity& acceleration) {
  const Velocity a0 = acceleration;
  const Velocity halfKick = a0 * (h / Scalar(2));
  const Position x1 = s.position + (s.velocity + halfKick) * h;
  acceleration = a(t + h, x1, s.velocity + a0 * h);
  return {x1, s.velocity + halfKick + acceleration * (h / Scalar(2))};
}

/// Velocity Verlet without a cached acceleration: evaluates a(t, x, v) first, 2 evaluations.
template <typename Position, typename Velocity, typename Scalar, typename Acceleration>
requires std::invocable<Acceleration&, Scalar, const Position&, const Velocity&>
[[nodiscard]] PhaseState<Position, Velocity> velocityVerletStep(Acceleration&& a, Scalar t,
                                                                const PhaseState<Position, Velocity>& s, Scalar h) {
  Velocity acceleration = a(t, s.position, s.velocity);
  return velocityVerletStep(a, t, s, h, acceleration);
}

// ---------------------------------------------------------------------------------------------
// The methods by name, with their properties (for a world's integrator setting, the CLI, docs).

enum class Integrator { explicitEuler, semiImplicitEuler, heun, midpoint, rk4, velocityVerlet };

/// "explicit-euler", "semi-implicit-euler", "heun", "midpoint", "rk4", "velocity-verlet".
[[nodiscard]] constexpr std::string_view integratorName(Integrator m) noexcept {
  switch (m) {
  case Integrator::explicitEuler:
    return "explicit-euler";
  case Integrator::semiImplicitEuler:
    return "semi-implicit-euler";
  case Integrator::heun:
    return "heun";
  case Integrator::midpoint:
    return "midpoint";
  case Integrator::rk4:
    return "rk4";
  case Integrator::velocityVerlet:
    return "velocity-verlet";
  }
  return "?";
}

/// The method named by integratorName(), or none.
[[nodiscard]] constexpr std::optional<Integrator> parseIntegrator(std::string_view name) noexcept {
  for (Integrator m : {Integrator::explicitEuler, Integrator::semiImplicitEuler, Integrator::heun, Integrator::midpoint,
                       Integrator::rk4, Integrator::velocityVerlet}) {
    if (integratorName(m) == name) {
      return m;
    }
  }
  return std::nullopt;
}

/// p: the global error is O(h^p).
[[nodiscard]] constexpr int globalOrder(Integrator m) noexcept {
  switch (m) {
  case Integrator::explicitEuler:
  case Integrator::semiImplicitEuler:
    return 1;
  case Integrator::heun:
  case Integrator::midpoint:
  case Integrator::velocityVerlet:
    return 2;
  case Integrator::rk4:
    return 4;
  }
  return 0;
}

/// Derivative (force) evaluations per step; velocity Verlet with its acceleration cached.
[[nodiscard]] constexpr int evaluationsPerStep(Integrator m) noexcept {
  switch (m) {
  case Integrator::explicitEuler:
  case Integrator::semiImplicitEuler:
  case Integrator::velocityVerlet:
    return 1;
  case Integrator::heun:
  case Integrator::midpoint:
    return 2;
  case Integrator::rk4:
    return 4;
  }
  return 0;
}

/// The spectral radius of one step on the undamped oscillator x'' = -w^2 x at z = w h >= 0:
/// the factor by which the amplitude grows per step (energy: its square), the spec's table
/// (ch. 7 notes, section 1.4). For the symplectic methods the step matrix has det 1 and trace
/// 2 - z^2: modulus 1 up to z = 2, then the larger real root (z^2 - 2 + sqrt((z^2 - 2)^2 - 4))/2.
[[nodiscard]] inline double oscillatorAmplification(Integrator m, double z) noexcept {
  const double z2 = z * z;
  switch (m) {
  case Integrator::explicitEuler:
    return std::sqrt(1.0 + z2); // |1 + iz|
  case Integrator::heun:
  case Integrator::midpoint:
    return std::sqrt(1.0 + z2 * z2 / 4.0); // |1 + iz - z^2/2|
  case Integrator::rk4:
    return std::hypot(1.0 - z2 / 2.0 + z2 * z2 / 24.0, z - z2 * z / 6.0);
  case Integrator::semiImplicitEuler:
  case Integrator::velocityVerlet: {
    if (z2 <= 4.0) {
      return 1.0;
    }
    const double b = z2 - 2.0; // -trace
    return (b + std::sqrt(b * b - 4.0)) / 2.0;
  }
  }
  return 0.0;
}

/// The largest z = w h for which the amplitude never grows: 2 for semi-implicit Euler and
/// Verlet, 2 sqrt(2) for RK4, 0 for explicit Euler, Heun and midpoint (they always grow).
[[nodiscard]] inline double oscillatorStabilityLimit(Integrator m) noexcept {
  switch (m) {
  case Integrator::semiImplicitEuler:
  case Integrator::velocityVerlet:
    return 2.0;
  case Integrator::rk4:
    return 2.0 * std::sqrt(2.0);
  case Integrator::explicitEuler:
  case Integrator::heun:
  case Integrator::midpoint:
    return 0.0;
  }
  return 0.0;
}

} // namespace impetus
