// Vacuum trajectories against the book's own table formulas (6-1 to 6-4, written out here
// independently of the library's single root formula), against RK4 integration of x'' = 0,
// y'' = -g, against energy conservation and the properties the book lists (ch. 6 item 1); and
// terminal velocities against the book's Table 6-5 and against integration of the fall.
#include <impetus/error.hpp>
#include <impetus/integrate/rk4.hpp>
#include <impetus/mechanics/projectile.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace impetus {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double g = 9.8; // the book's chapter-6 value, pinned
double deg(double d) { return d * pi / 180.0; }

// Closed forms evaluate a handful of operations: 1e-12 relative is ~100 ulp of slack.
constexpr double tight = 1e-12;

TEST(VacuumProjectile, range_is_v0_squared_sin_2phi_over_g_at_launch_height) {
  for (const double a : {5.0, 20.0, 45.0, 60.0, 85.0}) {
    const VacuumFlight f = vacuumFlight({50.0, deg(a), 0.0, g}, 0.0);
    const double expected = 50.0 * 50.0 * std::sin(2.0 * deg(a)) / g;
    EXPECT_NEAR(f.range, expected, tight * expected) << a;
    // Table 6-1: T = 2 v0 sin(phi)/g, h = v0^2 sin^2(phi)/(2g).
    EXPECT_NEAR(f.timeOfFlight, 2.0 * 50.0 * std::sin(deg(a)) / g, tight * 10.0);
    EXPECT_NEAR(f.apexHeight, std::pow(50.0 * std::sin(deg(a)), 2) / (2.0 * g), tight * 200.0);
    // Same height: impact speed equals launch speed, time up equals time down.
    EXPECT_NEAR(f.impactSpeed, 50.0, tight * 50.0);
    EXPECT_NEAR(f.timeOfFlight - f.apexTime, f.apexTime, tight * 10.0);
    // The time down equals the free-fall time from the apex height.
    EXPECT_NEAR(f.timeOfFlight - f.apexTime, std::sqrt(2.0 * f.apexHeight / g), tight * 10.0);
    EXPECT_NEAR(f.impactAngle, deg(a), tight);
  }
}

TEST(VacuumProjectile, range_is_greatest_at_45_degrees_on_level_ground) {
  double bestAngle = 0.0;
  double bestRange = 0.0;
  for (int tenth = 1; tenth < 900; ++tenth) { // 0.1 degree grid
    const double a = deg(tenth / 10.0);
    const double r = vacuumFlight({30.0, a, 0.0, g}).range;
    if (r > bestRange) {
      bestRange = r;
      bestAngle = a;
    }
  }
  EXPECT_NEAR(bestAngle, deg(45.0), 1e-9); // the grid contains 45.0 exactly
  EXPECT_NEAR(maximumRangeAngle(30.0, 0.0, 0.0, g), pi / 4.0, tight);
}

TEST(VacuumProjectile, best_angle_from_a_height_matches_a_numerical_search) {
  // Launch 20 m above the target: the optimum is below 45 degrees. Golden-section search on the
  // library's range (independent of the closed form atan(v0/sqrt(v0^2 + 2 g h))).
  const double v0 = 25.0;
  const auto range = [&](double a) { return vacuumFlight({v0, a, 20.0, g}, 0.0).range; };
  double lo = 0.0;
  double hi = pi / 2.0;
  const double r = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 200; ++i) {
    const double a = hi - r * (hi - lo);
    const double b = lo + r * (hi - lo);
    if (range(a) < range(b)) {
      lo = a; // the maximum is in [a, hi]
    } else {
      hi = b; // the maximum is in [lo, b]
    }
  }
  // The range is flat at its maximum: golden section locates it to ~sqrt(eps) ~ 1e-8 rad.
  EXPECT_NEAR(maximumRangeAngle(v0, 20.0, 0.0, g), 0.5 * (lo + hi), 1e-7);
  EXPECT_LT(maximumRangeAngle(v0, 20.0, 0.0, g), pi / 4.0);
  EXPECT_GT(maximumRangeAngle(v0, 0.0, 20.0, g), pi / 4.0); // shooting uphill: steeper
}

TEST(VacuumProjectile, target_higher_matches_table_6_2) {
  const double v0 = 40.0;
  const double phi = deg(50.0);
  const double b = 12.0;
  const double h = v0 * v0 * std::sin(phi) * std::sin(phi) / (2.0 * g);
  const double T = v0 * std::sin(phi) / g + std::sqrt(2.0 * (h - b) / g); // table 6-2
  const VacuumFlight f = vacuumFlight({v0, phi, 0.0, g}, b);
  EXPECT_NEAR(f.timeOfFlight, T, tight * T);
  EXPECT_NEAR(f.range, v0 * T * std::cos(phi), tight * f.range);
  EXPECT_NEAR(f.apexHeight, h, tight * h);
  const ProjectilePoint p = vacuumPointAt({v0, phi, 0.0, g}, T);
  EXPECT_NEAR(p.position.y, b, 1e-10); // |y| ~ 60 m of cancelling terms: 1e-10 m is ~1e-12 relative
  EXPECT_NEAR(p.position.x, f.range, tight * f.range);
}

TEST(VacuumProjectile, target_lower_matches_table_6_3) {
  const double v0 = 40.0;
  const double phi = deg(30.0);
  const double b = 25.0;                                                    // target below the launch
  const double h = b + v0 * v0 * std::sin(phi) * std::sin(phi) / (2.0 * g); // above the target
  const double T = v0 * std::sin(phi) / g + std::sqrt(2.0 * h / g);         // table 6-3
  const VacuumFlight f = vacuumFlight({v0, phi, b, g}, 0.0);
  EXPECT_NEAR(f.timeOfFlight, T, tight * T);
  EXPECT_NEAR(f.apexHeight, h, tight * h);
  EXPECT_NEAR(f.impactSpeed, std::sqrt(v0 * v0 + 2.0 * g * b), tight * 50.0);
  // Launched downward at a lower target: the root formula must not cancel.
  const VacuumFlight down = vacuumFlight({40.0, deg(-60.0), 1e-6, g}, 0.0);
  const double vy = 40.0 * std::sin(deg(-60.0));
  const double tDown = (vy + std::sqrt(vy * vy + 2.0 * g * 1e-6)) / g;      // reference (cancels)
  EXPECT_NEAR(down.timeOfFlight, 1e-6 / 40.0 / std::sin(deg(60.0)), 1e-15); // small-drop limit h/|vy|
  EXPECT_NEAR(down.timeOfFlight, tDown, 1e-12);
}

TEST(VacuumProjectile, vehicle_drop_matches_table_6_4) {
  const double v0 = 60.0;
  const double h = 500.0;
  const double T = std::sqrt(2.0 * h / g); // table 6-4 (the book's "h = g t^2/2" means g T^2/2)
  const VacuumFlight f = vehicleDrop(v0, h, g);
  EXPECT_NEAR(f.timeOfFlight, T, tight * T);
  EXPECT_NEAR(f.range, v0 * T, tight * v0 * T);
  EXPECT_NEAR(f.impactSpeed, std::sqrt(v0 * v0 + g * g * T * T), tight * 200.0);
  EXPECT_NEAR(h, 0.5 * g * f.timeOfFlight * f.timeOfFlight, tight * h);
  // v0 = 0: plain free fall.
  const VacuumFlight fall = vehicleDrop(0.0, h, g);
  EXPECT_EQ(fall.range, 0.0);
  EXPECT_NEAR(fall.impactSpeed, g * T, tight * g * T);
}

TEST(VacuumProjectile, point_matches_rk4_integration_and_speed_formula) {
  const VacuumLaunch launch{35.0, deg(37.0), 3.0, g};
  struct S {
    double x, y, vx, vy;
    S operator+(const S& o) const { return {x + o.x, y + o.y, vx + o.vx, vy + o.vy}; }
    S operator*(double k) const { return {x * k, y * k, vx * k, vy * k}; }
  };
  const auto f = [](double, const S& s) { return S{s.vx, s.vy, 0.0, -g}; };
  S s{0.0, 3.0, 35.0 * std::cos(deg(37.0)), 35.0 * std::sin(deg(37.0))};
  const double h = 0.003;
  double t = 0.0;
  for (int i = 0; i < 1000; ++i) {
    s = rk4Step(f, t, s, h);
    t += h;
  }
  const ProjectilePoint p = vacuumPointAt(launch, t);
  // RK4 is exact for a quadratic path; what remains is rounding over 1000 steps (~1e-12 m).
  EXPECT_NEAR(p.position.x, s.x, 1e-9);
  EXPECT_NEAR(p.position.y, s.y, 1e-9);
  EXPECT_NEAR(p.velocity.y, s.vy, 1e-10);
  const double v0 = 35.0;
  const double book = std::sqrt(v0 * v0 - 2.0 * g * t * v0 * std::sin(deg(37.0)) + g * g * t * t);
  EXPECT_NEAR(p.speed, book, tight * book);
}

TEST(VacuumProjectile, unreachable_target_is_an_error) {
  // Apex of a 20 m/s vertical shot is 20.4 m: a 25 m target is never reached.
  expectErrorField([] { (void)vacuumFlight({20.0, deg(90.0), 0.0, g}, 25.0); }, "targetHeight");
  // Launched downward at a target above: never reached.
  expectErrorField([] { (void)vacuumFlight({20.0, deg(-10.0), 0.0, g}, 1.0); }, "targetHeight");
  expectErrorField([] { (void)maximumRangeAngle(10.0, 0.0, 100.0, g); }, "targetHeight");
}

TEST(VacuumProjectile, bad_input_names_the_parameter) {
  expectErrorField([] { (void)vacuumFlight({-1.0, 0.3, 0.0, g}); }, "speed");
  expectErrorField([] { (void)vacuumFlight({10.0, 2.0, 0.0, g}); }, "angle");
  expectErrorField([] { (void)vacuumFlight({10.0, NAN, 0.0, g}); }, "angle");
  expectErrorField([] { (void)vacuumFlight({10.0, 0.3, INFINITY, g}); }, "launchHeight");
  expectErrorField([] { (void)vacuumFlight({10.0, 0.3, 0.0, 0.0}); }, "gravity");
  expectErrorField([] { (void)vacuumPointAt({10.0, 0.3, 0.0, g}, -1.0); }, "time");
  expectErrorField([] { (void)vehicleDrop(10.0, -5.0, g); }, "height");
  expectErrorField([] { (void)terminalVelocityQuadratic(1.0, 0.0, 1.2, 0.1); }, "dragCoefficient");
  expectErrorField([] { (void)terminalVelocityQuadratic(1.0, 0.5, -1.2, 0.1); }, "fluidDensity");
  expectErrorField([] { (void)terminalVelocityQuadratic(1.0, 0.5, 1.2, 0.0); }, "area");
  expectErrorField([] { (void)terminalVelocityQuadratic(-1.0, 0.5, 1.2, 0.1); }, "weight");
  expectErrorField([] { (void)terminalVelocityLinear(1.0, 0.0); }, "linearDragCoefficient");
}

// Table 6-5 (Ex 6.1): Cd = 0.5, rho = 1.225 kg/m^3, v_t = sqrt(2 W/(Cd rho A)).
double kmh(double metresPerSecond) { return metresPerSecond * 3.6; }

TEST(TerminalVelocity, skydiver_rows_match_table_6_5_within_1_kmh) {
  EXPECT_NEAR(kmh(terminalVelocityQuadratic(801.0, 0.5, 1.225, 0.84)), 201.0, 1.0);
  EXPECT_NEAR(kmh(terminalVelocityQuadratic(801.0, 0.5, 1.225, 21.02)), 40.0, 1.0);
}

TEST(TerminalVelocity, ball_and_raindrop_rows_match_the_recomputed_values) {
  // The book's rows are inconsistent with its own inputs (spec Ex 6.1, errata 5): baseball 121
  // km/h (ours 119.8), golf ball 116 km/h (ours 122.9: the book is ~6 % low, as if W = 0.445 N,
  // a real golf ball's weight, instead of the table's 0.5 N), raindrop 32 km/h (ours 33.1). We
  // test the physics; the spec's recomputed values are given to 4 digits (+-0.005 m/s).
  EXPECT_NEAR(terminalVelocityQuadratic(1.42, 0.5, 1.225, 4.19e-3), 33.27, 0.005);
  EXPECT_NEAR(terminalVelocityQuadratic(0.5, 0.5, 1.225, 1.40e-3), 34.15, 0.005);
  EXPECT_NEAR(terminalVelocityQuadratic(3.34e-4, 0.5, 1.225, 1.29e-5), 9.195, 0.0005);
  // The golf-ball row is off by more than rounding: 116 km/h is not what the inputs give.
  EXPECT_GT(kmh(terminalVelocityQuadratic(0.5, 0.5, 1.225, 1.40e-3)) - 116.0, 6.0);
  // ... and the weight the book's 116 km/h implies is the real golf ball's 0.445 N.
  const double implied = 0.5 * 0.5 * 1.225 * 1.40e-3 * std::pow(116.0 / 3.6, 2);
  EXPECT_NEAR(implied, 0.445, 0.001);
}

TEST(TerminalVelocity, falls_reach_the_closed_forms_when_integrated) {
  // m dv/dt = W - 1/2 rho Cd A v^2 (quadratic) and m dv/dt = W - C v (linear), from rest, RK4.
  const double m = 80.0;
  const double w = m * g;
  const double vq = terminalVelocityQuadratic(w, 0.5, 1.225, 0.84);
  const double vl = terminalVelocityLinear(w, 20.0);
  double v1 = 0.0;
  double v2 = 0.0;
  const auto quadratic = [&](double, double v) { return (w - 0.5 * 1.225 * 0.5 * 0.84 * v * v) / m; };
  const auto linear = [&](double, double v) { return (w - 20.0 * v) / m; };
  for (int i = 0; i < 20000; ++i) { // 200 s at 10 ms: > 35 time constants for both
    v1 = rk4Step(quadratic, 0.0, v1, 0.01);
    v2 = rk4Step(linear, 0.0, v2, 0.01);
  }
  EXPECT_NEAR(v1, vq, 1e-9 * vq); // exponential approach: e^-70 left, then rounding
  EXPECT_NEAR(v2, vl, 1e-9 * vl);
}

} // namespace
} // namespace impetus
