// One step of the classic fourth-order Runge-Kutta method for any state that supports
// state + state and state * scalar (a vector, a struct of vectors...). Forces are re-evaluated
// at every stage, on the whole state (the book's RK4 integrates velocity only). Local error
// O(h^5), global O(h^4); four derivative evaluations per step.
//
// The integrators issue builds the full `integrate` layer (Euler, Heun, Verlet, adaptive
// steppers) around this; the closed-form models of the mechanics layer use it where a model has
// no closed form.
#pragma once

#include <concepts>

namespace impetus {

/// x(t + h) from x(t), where dx/dt = f(t, x).
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

} // namespace impetus
