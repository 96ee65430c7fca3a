// The fixed-step integrators: the book's ship table (ch. 7), order of accuracy, and energy
// behaviour on the undamped oscillator and a Kepler orbit.
#include <impetus/integrate/integrate.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/vec3.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace impetus {
namespace {

// ---------------------------------------------------------------------------------------------
// The book's ship (ch. 4 and 7): m dv/dt = T - C v, ds/dt = v, from rest.

constexpr double kThrust = 20000.0; // N
constexpr double kMass = 10000.0;   // kg
constexpr double kDrag = 1000.0;    // N s/m

double shipAcceleration(double v) { return (kThrust - kDrag * v) / kMass; }
double exactShipVelocity(double t) { return 20.0 * -std::expm1(-0.1 * t); }
double exactShipPosition(double t) { return 20.0 * t - 200.0 * -std::expm1(-0.1 * t); }

/// (s, v) as one first-order state.
struct Ship {
  double s = 0.0; // m
  double v = 0.0; // m/s
  Ship operator+(const Ship& o) const { return {s + o.s, v + o.v}; }
  Ship operator*(double k) const { return {s * k, v * k}; }
};

Ship shipRate(double /*t*/, const Ship& x) { return {x.v, shipAcceleration(x.v)}; }
double shipVelocityRate(double /*t*/, double v) { return shipAcceleration(v); }
double shipAccel(double /*t*/, double /*s*/, double v) { return shipAcceleration(v); }

using Phase = PhaseState<double>;

/// Integrates from t = 0 to n h with a step function (state, t) -> state.
template <typename State, typename Step> State run(State x, double h, int n, Step step) {
  for (int i = 0; i < n; ++i) {
    x = step(x, i * h);
  }
  return x;
}

/// The book's listings: the method advances the velocity only, then Snew = S + Vnew dt.
template <typename Stepper> std::vector<Ship> booksShip(Stepper stepper, double h, int n) {
  std::vector<Ship> rows{{0.0, 0.0}};
  for (int i = 0; i < n; ++i) {
    const double v = stepper(shipVelocityRate, i * h, rows.back().v, h);
    rows.push_back({rows.back().s + v * h, v});
  }
  return rows;
}

/// The book's table 7-1: dt = 0.5 s. Euler (the book's, semi-implicit) is
/// v_n = 20 (1 - 0.95^n); Heun 20 (1 - 0.95125^n); RK4 20 (1 - g^n) with g the 4th-order Taylor
/// polynomial of e^-0.05 (spec ch. 7 notes, 5.1).
TEST(Integrators, books_ship_table_matches_the_closed_forms) {
  const double h = 0.5;
  const int n = 40; // to t = 20 s
  const double g = 1.0 - 0.05 + 0.05 * 0.05 / 2 - 0.05 * 0.05 * 0.05 / 6 + 0.05 * 0.05 * 0.05 * 0.05 / 24;
  EXPECT_NEAR(g, 0.9512294271, 1e-10);
  // The book's Euler is semi-implicit Euler on (s, v); its velocity is the same as explicit Euler's.
  Phase euler{0.0, 0.0};
  const std::vector<Ship> heun = booksShip(Heun{}, h, n);
  const std::vector<Ship> rk4 = booksShip(RungeKutta4{}, h, n);
  for (int i = 1; i <= n; ++i) {
    euler = semiImplicitEulerStep(shipAccel, (i - 1) * h, euler, h);
    EXPECT_NEAR(euler.velocity, 20.0 * (1.0 - std::pow(0.95, i)), 1e-12) << i;
    EXPECT_NEAR(heun[i].v, 20.0 * (1.0 - std::pow(0.95125, i)), 1e-12) << i;
    EXPECT_NEAR(rk4[i].v, 20.0 * (1.0 - std::pow(g, i)), 1e-12) << i;
  }
}

TEST(Integrators, books_ship_rows_and_mean_errors) {
  const auto euler = [](double h, int n) {
    std::vector<double> v{0.0};
    Phase x{0.0, 0.0};
    for (int i = 0; i < n; ++i) {
      x = semiImplicitEulerStep(shipAccel, i * h, x, h);
      v.push_back(x.velocity);
    }
    return v;
  };
  const auto velocities = [](const std::vector<Ship>& rows) {
    std::vector<double> v;
    v.reserve(rows.size());
    for (const Ship& r : rows) {
      v.push_back(r.v);
    }
    return v;
  };
  const double h = 0.5;
  const std::vector<double> e = euler(h, 20);
  const std::vector<double> ie = velocities(booksShip(Heun{}, h, 20));
  const std::vector<double> rk = velocities(booksShip(RungeKutta4{}, h, 20));
  // I-1..I-6: exact and Euler at 6.5 ... 8.5 s (rows 13..17).
  const std::array<double, 5> exact{9.559084, 10.068294, 10.552669, 11.013421, 11.451701};
  const std::array<double, 5> book{9.733158, 10.246500, 10.734175, 11.197467, 11.637593};
  const std::array<double, 5> improved{9.556148, 10.065286, 10.549603, 11.010310, 11.448557}; // I-8
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(exactShipVelocity(6.5 + 0.5 * k), exact[k], 5e-7);
    EXPECT_NEAR(e[13 + k], book[k], 5e-7);
    EXPECT_NEAR(ie[13 + k], improved[k], 5e-7);
  }
  EXPECT_NEAR(rk[13], 9.559084, 5e-7); // I-9
  EXPECT_NEAR(rk[17], 11.451701, 5e-7);
  // I-10: the first two steps.
  EXPECT_NEAR(e[1], 1.0, 1e-15);
  EXPECT_NEAR(e[2], 1.95, 1e-15);
  EXPECT_NEAR(ie[1], 0.975, 1e-15);
  EXPECT_NEAR(ie[2], 1.902469, 5e-7);
  EXPECT_NEAR(rk[1], 0.975411, 5e-7);
  EXPECT_NEAR(rk[2], 1.903252, 5e-7);
  // I-11: v(10).
  EXPECT_NEAR(e[20], 12.830282, 5e-7);
  EXPECT_NEAR(ie[20], 12.639228, 5e-7);
  EXPECT_NEAR(rk[20], 12.642411, 5e-7);
  EXPECT_NEAR(exactShipVelocity(10.0), 12.642411, 5e-7);

  // I-7 and I-13: mean |relative error| over 6.5 ... 8.5 s, in %, at dt = 0.5 and 0.25.
  const auto meanError = [](const std::vector<double>& v, double step) {
    double sum = 0.0;
    for (int k = 0; k < 5; ++k) {
      const double t = 6.5 + 0.5 * k;
      const auto i = static_cast<std::size_t>(std::lround(t / step));
      sum += std::abs(v[i] - exactShipVelocity(t)) / exactShipVelocity(t);
    }
    return 100.0 * sum / 5.0;
  };
  EXPECT_NEAR(meanError(e, h), 1.7211, 5e-5);
  EXPECT_NEAR(meanError(ie, h), 0.02907, 5e-6);
  EXPECT_NEAR(meanError(rk, h), 3.648e-6, 5e-9);
  const std::vector<double> e4 = euler(0.25, 40);
  const std::vector<double> ie4 = velocities(booksShip(Heun{}, 0.25, 40));
  const std::vector<double> rk4 = velocities(booksShip(RungeKutta4{}, 0.25, 40));
  EXPECT_NEAR(meanError(e4, 0.25), 0.8500, 5e-5);
  EXPECT_NEAR(meanError(ie4, 0.25), 0.00713, 5e-6);
  EXPECT_NEAR(meanError(rk4, 0.25), 2.23e-7, 5e-10);
}

// The book's RK4 listing integrates the velocity only and then moves the ship by
// S + Vnew dt, which is first order: at t = 10 s, dt = 0.5 s, the velocity is right to 1e-7 but
// the position is 76.710 m against an exact 73.576 m (4.3 %). RK4 on the whole state (s, v) with
// the force re-evaluated at every stage is right to 4e-6 m.
TEST(Integrators, books_velocity_only_rk4_against_whole_state_rk4) {
  const double h = 0.5;
  const std::vector<Ship> book = booksShip(RungeKutta4{}, h, 20);
  const Ship whole = run(Ship{}, h, 20, [&](const Ship& x, double t) { return rk4Step(shipRate, t, x, h); });
  const double exactS = exactShipPosition(10.0);
  EXPECT_NEAR(exactS, 73.575888, 5e-7);
  EXPECT_NEAR(book.back().s, 76.710151, 5e-7);
  EXPECT_NEAR((book.back().s - exactS) / exactS, 0.0426, 5e-4);
  EXPECT_NEAR(whole.s, exactS, 5e-6);
  EXPECT_NEAR(whole.v, exactShipVelocity(10.0), 1e-6);
  // The book's Euler and improved Euler positions (I-12).
  EXPECT_NEAR(booksShip(Heun{}, h, 20).back().s, 76.686511, 5e-7);
  const Phase euler =
      run(Phase{}, h, 20, [&](const Phase& x, double t) { return semiImplicitEulerStep(shipAccel, t, x, h); });
  EXPECT_NEAR(euler.position, 78.112325, 5e-7);
}

// ---------------------------------------------------------------------------------------------
// Order of accuracy: halving the step divides the global error by 2^p (within 15%).

struct Method {
  std::string name;
  int order;
  /// One step of the method on a second-order system x'' = a(t, x, v).
  std::function<Phase(const std::function<double(double, double, double)>&, double, const Phase&, double)> step;
};

std::vector<Method> allMethods() {
  using Accel = std::function<double(double, double, double)>;
  const auto whole = [](auto stepper) {
    return
        [stepper](const Accel& a, double t, const Phase& x, double h) { return stepper(firstOrderRate(a), t, x, h); };
  };
  return {
      {"explicit Euler", 1, whole(ExplicitEuler{})},
      {"Heun", 2, whole(Heun{})},
      {"midpoint", 2, whole(Midpoint{})},
      {"RK4", 4, whole(RungeKutta4{})},
      {"explicit Euler (2nd-order form)", 1,
       [](const Accel& a, double t, const Phase& x, double h) { return explicitEulerStep2(a, t, x, h); }},
      {"semi-implicit Euler", 1,
       [](const Accel& a, double t, const Phase& x, double h) { return semiImplicitEulerStep(a, t, x, h); }},
      {"velocity Verlet", 2,
       [](const Accel& a, double t, const Phase& x, double h) { return velocityVerletStep(a, t, x, h); }},
  };
}

/// Global error max(|x - x_exact|, |v - v_exact|) at time T after n steps.
double globalError(const Method& m, const std::function<double(double, double, double)>& a, const Phase& start,
                   const Phase& exact, double time, int n) {
  const double h = time / n;
  const Phase end = run(start, h, n, [&](const Phase& x, double t) { return m.step(a, t, x, h); });
  return std::max(std::abs(end.position - exact.position), std::abs(end.velocity - exact.velocity));
}

void expectOrder(const Method& m, const std::function<double(double, double, double)>& a, const Phase& start,
                 const Phase& exact, double time, int n) {
  const double expected = std::pow(2.0, m.order);
  double previous = globalError(m, a, start, exact, time, n);
  for (int k = 1; k <= 2; ++k) {
    const double error = globalError(m, a, start, exact, time, n << k);
    const double ratio = previous / error;
    EXPECT_NEAR(ratio, expected, 0.15 * expected) << m.name << ", " << (n << (k - 1)) << " -> " << (n << k) << " steps";
    previous = error;
  }
}

TEST(Integrators, halving_the_step_divides_the_ship_error_by_2_to_the_order) {
  const Phase exact{exactShipPosition(10.0), exactShipVelocity(10.0)};
  for (const Method& m : allMethods()) {
    expectOrder(m, shipAccel, Phase{0.0, 0.0}, exact, 10.0, 20); // dt = 0.5, 0.25, 0.125 s
  }
}

TEST(Integrators, halving_the_step_divides_the_oscillator_error_by_2_to_the_order) {
  // x'' = -x from (1, 0): x = cos t, v = -sin t, to t = 5 (not a whole period, so no
  // cancellation hides the error).
  const auto spring = [](double, double x, double) { return -x; };
  const Phase exact{std::cos(5.0), -std::sin(5.0)};
  for (const Method& m : allMethods()) {
    expectOrder(m, spring, Phase{1.0, 0.0}, exact, 5.0, m.order == 1 ? 400 : 50);
  }
}

// A damped, driven oscillator x'' = -4x - 0.5v + cos t: velocity-dependent forces (Verlet's
// predicted velocity) and time-dependent ones (every stage at its own time).
TEST(Integrators, order_holds_with_velocity_and_time_dependent_forces) {
  const auto force = [](double t, double x, double v) { return -4.0 * x - 0.5 * v + std::cos(t); };
  // Reference: RK4 with 2^16 steps (error ~1e-16).
  const std::vector<Method> methods = allMethods();
  const Method& rk4 = methods[3];
  const int fine = 1 << 16;
  const double h = 4.0 / fine;
  const Phase exact = run(Phase{1.0, 0.0}, h, fine, [&](const Phase& x, double t) { return rk4.step(force, t, x, h); });
  for (const Method& m : methods) {
    expectOrder(m, force, Phase{1.0, 0.0}, exact, 4.0, m.order == 1 ? 400 : 40);
  }
}

// ---------------------------------------------------------------------------------------------
// Energy on the undamped oscillator x'' = -x (w = 1, so z = h): E = (x^2 + v^2)/2.

double energy(const Phase& s) { return 0.5 * (s.position * s.position + s.velocity * s.velocity); }
double spring(double, double x, double) { return -x; }

/// The spec's table (ch. 7 notes, 1.4), to its printed digits.
TEST(Integrators, amplification_table_matches_the_spec) {
  struct Row {
    double z, explicitEuler, semiImplicit, heun, rk4;
  };
  const std::array<Row, 6> rows{{{0.1, 1.004988, 1.0, 1.0000125, 0.99999999},
                                 {0.5, 1.118034, 1.0, 1.007782, 0.999895},
                                 {1.0, 1.414214, 1.0, 1.118034, 0.993905},
                                 {2.0, 2.236068, 1.0, 2.236068, 0.745356},
                                 {2.5, 2.692582, 4.0, 3.281101, 0.508186},
                                 {3.0, 3.162278, 6.854, 4.609772, 1.505}}};
  for (const Row& r : rows) {
    EXPECT_NEAR(oscillatorAmplification(Integrator::explicitEuler, r.z), r.explicitEuler, 5e-7);
    EXPECT_NEAR(oscillatorAmplification(Integrator::semiImplicitEuler, r.z), r.semiImplicit, 5e-4);
    EXPECT_NEAR(oscillatorAmplification(Integrator::velocityVerlet, r.z), r.semiImplicit, 5e-4);
    EXPECT_NEAR(oscillatorAmplification(Integrator::heun, r.z), r.heun, 5e-7);
    EXPECT_NEAR(oscillatorAmplification(Integrator::midpoint, r.z), r.heun, 5e-7);
    EXPECT_NEAR(oscillatorAmplification(Integrator::rk4, r.z), r.rk4, 5e-4);
  }
  EXPECT_NEAR(oscillatorAmplification(Integrator::rk4, oscillatorStabilityLimit(Integrator::rk4)), 1.0, 1e-12);
  EXPECT_GT(oscillatorAmplification(Integrator::rk4, 2.83), 1.0);
  EXPECT_LT(oscillatorAmplification(Integrator::rk4, 2.82), 1.0);
  for (Integrator m : {Integrator::explicitEuler, Integrator::semiImplicitEuler, Integrator::heun, Integrator::midpoint,
                       Integrator::rk4, Integrator::velocityVerlet}) {
    EXPECT_EQ(parseIntegrator(integratorName(m)), m);
  }
  EXPECT_FALSE(parseIntegrator("euler").has_value());
}

/// Each method's measured per-step growth on the oscillator equals its tabled amplification:
/// exactly for the Runge-Kutta family (one step is |R| times a rotation), asymptotically for the
/// symplectic ones above z = 2 (the growing eigenvector takes over).
TEST(Integrators, measured_growth_per_step_matches_the_amplification) {
  const std::vector<Method> methods = allMethods();
  const std::array<Integrator, 7> kinds{Integrator::explicitEuler, Integrator::heun,
                                        Integrator::midpoint,      Integrator::rk4,
                                        Integrator::explicitEuler, Integrator::semiImplicitEuler,
                                        Integrator::velocityVerlet};
  for (std::size_t i = 0; i < methods.size(); ++i) {
    for (double z : {0.1, 0.5, 1.0, 2.5, 3.0}) {
      const bool symplectic = kinds[i] == Integrator::semiImplicitEuler || kinds[i] == Integrator::velocityVerlet;
      if (symplectic && z < 2.0) {
        continue; // bounded: the next tests
      }
      const int n = symplectic ? 60 : 10;
      Phase s{1.0, 0.0};
      Phase before = s;
      for (int k = 0; k < n; ++k) {
        before = s;
        s = methods[i].step(spring, k * z, s, z);
      }
      const double growth = std::sqrt(energy(s) / energy(before));
      EXPECT_NEAR(growth, oscillatorAmplification(kinds[i], z), 1e-9 * growth) << methods[i].name << " z = " << z;
    }
  }
}

TEST(Integrators, explicit_euler_energy_grows_as_1_plus_z_squared_per_step) {
  const double z = 0.1;
  Phase s{1.0, 0.0};
  for (int k = 0; k < 1000; ++k) {
    s = explicitEulerStep2(spring, k * z, s, z);
  }
  const double expected = std::pow(1.0 + z * z, 1000); // (1.004988^2)^1000 = 2.1e4
  EXPECT_NEAR(energy(s) / 0.5, expected, 1e-10 * expected);
  EXPECT_GT(energy(s) / 0.5, 2e4);
}

TEST(Integrators, semi_implicit_euler_energy_stays_bounded_below_z_2_and_blows_up_above) {
  // z = 0.1 over 10^4 periods (628,319 steps): the energy oscillates by O(z) and never drifts.
  {
    const double z = 0.1;
    Phase s{1.0, 0.0};
    double lo = 1.0;
    double hi = 1.0;
    const long n = std::lround(1e4 * 2.0 * pi<double> / z);
    for (long k = 0; k < n; ++k) {
      s = semiImplicitEulerStep(spring, 0.0, s, z);
      const double ratio = energy(s) / 0.5;
      lo = std::min(lo, ratio);
      hi = std::max(hi, ratio);
    }
    // The shadow energy v^2 + x^2 - z x v is exactly conserved, so E/E0 stays in
    // [1/(1 + z/2), 1/(1 - z/2)] = [0.952, 1.053].
    EXPECT_GT(lo, 1.0 / (1.0 + z / 2) - 1e-9);
    EXPECT_LT(hi, 1.0 / (1.0 - z / 2) + 1e-9);
    EXPECT_LT(hi - lo, 1.1 * z);
  }
  // Just below the limit: bounded (by 1/(1 - z/2) = 20 at z = 1.9) over 10^4 steps.
  {
    const double z = 1.9;
    Phase s{1.0, 0.0};
    double hi = 1.0;
    for (int k = 0; k < 10000; ++k) {
      s = semiImplicitEulerStep(spring, 0.0, s, z);
      hi = std::max(hi, energy(s) / 0.5);
    }
    EXPECT_LT(hi, 1.0 / (1.0 - z / 2) + 1e-6);
  }
  // Just above: amplification 1.877 per step, the energy passes 1e50 within 100 steps.
  {
    const double z = 2.1;
    Phase s{1.0, 0.0};
    for (int k = 0; k < 100; ++k) {
      s = semiImplicitEulerStep(spring, 0.0, s, z);
    }
    EXPECT_GT(energy(s), 1e50);
  }
}

TEST(Integrators, heun_grows_slowly_and_rk4_decays_slightly) {
  const double z = 0.1;
  const int n = 10000;
  Phase heun{1.0, 0.0};
  Phase rk4{1.0, 0.0};
  for (int k = 0; k < n; ++k) {
    heun = heunStep(firstOrderRate(spring), k * z, heun, z);
    rk4 = rk4Step(firstOrderRate(spring), k * z, rk4, z);
  }
  // Amplitude after N steps = |R|^N: Heun (1 + z^4/4)^(N/2) = e^0.125 = 1.133, RK4 0.99993.
  const double heunAmplitude = std::sqrt(energy(heun) / 0.5);
  const double rk4Amplitude = std::sqrt(energy(rk4) / 0.5);
  EXPECT_NEAR(heunAmplitude, std::pow(oscillatorAmplification(Integrator::heun, z), n), 1e-10);
  EXPECT_NEAR(heunAmplitude, 1.133, 5e-4);
  EXPECT_NEAR(rk4Amplitude, std::pow(oscillatorAmplification(Integrator::rk4, z), n), 1e-12);
  EXPECT_NEAR(rk4Amplitude, 0.99993, 5e-6);
  EXPECT_LT(rk4Amplitude, 1.0);
}

TEST(Integrators, velocity_verlet_keeps_oscillator_energy_over_ten_thousand_periods) {
  const int perPeriod = 128; // z = 0.049: the energy oscillates by z^2/4 = 6e-4 (shadow energy)
  const double h = 2.0 * pi<double> / perPeriod;
  Phase s{1.0, 0.0};
  double a = spring(0.0, s.position, s.velocity);
  double worst = 0.0;
  for (long k = 0; k < 10000L * perPeriod; ++k) {
    s = velocityVerletStep(spring, 0.0, s, h, a);
    worst = std::max(worst, std::abs(energy(s) / 0.5 - 1.0));
  }
  EXPECT_LT(worst, 1e-3);
  // No drift: after whole periods the state is back near its start (phase error only).
  EXPECT_NEAR(energy(s) / 0.5, 1.0, 1e-3);
}

// ---------------------------------------------------------------------------------------------
// Kepler orbit: r'' = -GM r / |r|^3 with GM = 1, semi-major axis 1 (period 2 pi), eccentricity
// 0.5, from periapsis r = a (1 - e) = 0.5 at speed sqrt(GM (1 + e) / (a (1 - e))) = sqrt(3).

Vec3d gravity(double, const Vec3d& r, const Vec3d&) {
  const double d = length(r);
  return r * (-1.0 / (d * d * d));
}

double orbitEnergy(const PhaseState<Vec3d>& s) { return 0.5 * lengthSquared(s.velocity) - 1.0 / length(s.position); }

TEST(Integrators, velocity_verlet_keeps_kepler_energy_over_a_hundred_orbits) {
  PhaseState<Vec3d> s{{0.5, 0.0, 0.0}, {0.0, std::sqrt(3.0), 0.0}};
  const double e0 = orbitEnergy(s);
  EXPECT_NEAR(e0, -0.5, 1e-15); // -GM / (2a)
  const Vec3d l0 = cross(s.position, s.velocity);
  const int perOrbit = 1000;
  const double h = 2.0 * pi<double> / perOrbit;
  Vec3d a = gravity(0.0, s.position, s.velocity);
  double worst = 0.0;
  for (long k = 0; k < 100L * perOrbit; ++k) {
    s = velocityVerletStep(gravity, 0.0, s, h, a);
    worst = std::max(worst, std::abs(orbitEnergy(s) / e0 - 1.0));
  }
  EXPECT_LT(worst, 1e-3);
  // A central force: Verlet conserves the angular momentum to round-off.
  EXPECT_NEAR(cross(s.position, s.velocity).z, l0.z, 1e-12);
  // Explicit Euler at the same step spirals out: the energy climbs by far more.
  PhaseState<Vec3d> euler{{0.5, 0.0, 0.0}, {0.0, std::sqrt(3.0), 0.0}};
  for (int k = 0; k < perOrbit; ++k) {
    euler = explicitEulerStep2(gravity, 0.0, euler, h);
  }
  EXPECT_LT(orbitEnergy(euler) / e0, 0.95); // E rose from -0.5 to -0.45 in one orbit
}

} // namespace
} // namespace impetus
