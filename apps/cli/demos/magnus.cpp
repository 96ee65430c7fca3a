// The book's Magnus demo (ch. 6, Fig. 6-13), corrected. The book flies a spinning ball with
// gravity and the idealized Magnus force C (w_hat x v), C = pi^2 rho r^3 w, evaluating a
// whole-flight formula at each time. That formula has the x force's sign wrong and divides by
// zero at t = m/C (spec 4.4). This demo prints the book's formula next to the exact solution
// (velocity circling the drift velocity g/Omega), shows where the book's blows up, and then flies
// the same pitch the way a library should: quadratic drag plus an empirical lift coefficient.
//
// CSV files (with --out DIR):
//   magnus.csv         the exact solution of the book's model (for 60 s: with this much lift
//                      it never lands), and the no-spin parabola at the same times (continued
//                      below the ground)
//   magnus-book.csv    the book's formula and the exact solution up to 97 % of t = m/C
//   magnus-flight.csv  drag + Sawicki lift, no spin and backspin (a landed flight keeps its
//                      landing point)
#include "demos/demos.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/mechanics/aerodynamics.hpp>
#include <impetus/mechanics/projectile.hpp>

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace impetus::cli {
namespace {

constexpr double g = 9.8;      // the book's chapter-6 value
constexpr double rho = 1.225;  // the book's RHO
constexpr double mass = 0.145; // baseball, kg
constexpr double radius = 0.0366;
constexpr double spinRpm = 1800.0; // 30 rev/s of backspin
constexpr double launchHeight = 1.0;
const Vec2d launchVelocity{40.0, 5.0};

double energy(const MagnusPlaneState& s) {
  return 0.5 * mass * (s.velocity.x * s.velocity.x + s.velocity.y * s.velocity.y) + mass * g * s.position.y;
}

} // namespace

int demoMagnus(const DemoOptions& options) {
  const double omega = spinRpm * 2.0 * pi<double> / 60.0;
  const double c = idealMagnusCoefficient(rho, radius, omega);
  const MagnusPlaneLaunch launch{{0.0, launchHeight}, launchVelocity, mass, c, g};
  const double singular = bookMagnusSingularTime(launch);
  const double e0 = energy(magnusClosedForm(launch, 0.0));

  fmt::print("Magnus demo (ch. 6): baseball {} kg, r = {} m, {} rpm backspin, v0 = ({}, {}) m/s from y = {} m\n", mass,
             radius, spinRpm, launchVelocity.x, launchVelocity.y, launchHeight);
  fmt::print("the book's model: gravity + F = C (w_hat x v), C = pi^2 rho r^3 w = {:.5f} N s/m, no drag\n", c);
  fmt::print("lift at launch: {:.2f} N = {:.1f} x the weight (the book itself quotes up to 33 %)\n\n",
             c * length(launchVelocity), c * length(launchVelocity) / (mass * g));

  fmt::print("the book's formula against the exact solution (energy should stay {:.2f} J):\n", e0);
  fmt::print("{:>6} {:>10} {:>10} {:>12} {:>10} {:>10} {:>12}\n", "t s", "x exact", "y exact", "E exact J", "x book",
             "y book", "E book J");
  for (const double t : {0.0, 0.25, 0.5, 0.75, 1.0, 1.2, 1.28, 1.295}) {
    const MagnusPlaneState exact = magnusClosedForm(launch, t);
    const MagnusPlaneState book = bookMagnusFormula(launch, t);
    fmt::print("{:>6.3f} {:>10.2f} {:>10.2f} {:>12.2f} {:>10.4g} {:>10.4g} {:>12.4g}\n", t, exact.position.x,
               exact.position.y, energy(exact), book.position.x, book.position.y, energy(book));
  }
  fmt::print("the book's formula divides by zero at t = m/C = {:.3f} s; its x force is +C vy where it must be "
             "-C vy, so its 'lift' does work\n\n",
             singular);

  // The exact solution of the book's model until it lands (the integrator with the idealized
  // lift and no drag follows it to 1e-9 m: tests/mechanics/aerodynamics_test.cpp).
  BallProperties ideal{mass, radius, DragModel::none, 0.0, LiftModel::idealizedSphere, 0.0};
  FlightConditions conditions;
  conditions.airDensity = rho;
  conditions.gravity = g;
  conditions.spin = {0.0, 0.0, omega};
  const Vec3d v0{launchVelocity.x, launchVelocity.y, 0.0};
  const BallFlight idealFlight = simulateBallFlight(ideal, conditions, {0.0, launchHeight, 0.0}, v0);
  const VacuumFlight vacuum =
      vacuumFlight({length(launchVelocity), std::atan2(launchVelocity.y, launchVelocity.x), launchHeight, g}, 0.0);
  double minVx = launchVelocity.x;
  double lowest = idealFlight.maxHeight; // lowest point after the first apex
  for (const FlightSample& s : idealFlight.samples) {
    minVx = std::min(minVx, s.velocity.x);
    if (s.time > idealFlight.apexTime) {
      lowest = std::min(lowest, s.position.y);
    }
  }
  if (idealFlight.landed) {
    fmt::print("exact solution of the book's model: lands after {:.3f} s at x = {:.2f} m, peak {:.2f} m;\n",
               idealFlight.flightTime, idealFlight.range, idealFlight.maxHeight);
  } else {
    fmt::print("exact solution of the book's model: the ball never comes down. It loops (a trochoid) between "
               "{:.2f} m and {:.2f} m\n  and after {:.0f} s it is {:.0f} m downrange;\n",
               lowest, idealFlight.maxHeight, idealFlight.flightTime, idealFlight.range);
  }
  fmt::print("  its velocity circles the drift velocity (g/Omega, 0) = ({:.2f}, 0) m/s: vx goes down to {:.2f} m/s\n",
             g * mass / c, minVx);
  fmt::print("  without spin (vacuum): lands after {:.3f} s at x = {:.2f} m, peak {:.2f} m\n\n", vacuum.timeOfFlight,
             vacuum.range, vacuum.apexHeight);

  // The same pitch with drag (Cd 0.35) and the empirical lift of Sawicki et al. (2003).
  const BallProperties ball = baseball();
  FlightConditions noSpin;
  noSpin.airDensity = rho;
  noSpin.gravity = g;
  FlightConditions backspin = noSpin;
  backspin.spin = conditions.spin;
  const BallFlight plain = simulateBallFlight(ball, noSpin, {0.0, launchHeight, 0.0}, v0);
  const BallFlight spun = simulateBallFlight(ball, backspin, {0.0, launchHeight, 0.0}, v0);
  const Vec3d lift = magnusForce({v0.x, v0.y, 0.0}, backspin.spin, radius, rho, LiftModel::sawicki2003);
  fmt::print("with drag (Cd {}) and the measured lift C_L(S) of Sawicki et al. (2003):\n", ball.dragCoefficient);
  fmt::print("  lift at launch {:.2f} N = {:.0f} % of the weight\n", length(lift), 100.0 * length(lift) / (mass * g));
  fmt::print("  no spin:  lands after {:.3f} s at x = {:.2f} m, peak {:.2f} m\n", plain.flightTime, plain.range,
             plain.maxHeight);
  fmt::print("  backspin: lands after {:.3f} s at x = {:.2f} m, peak {:.2f} m ({:+.2f} m of carry from the spin)\n",
             spun.flightTime, spun.range, spun.maxHeight, spun.range - plain.range);

  std::vector<std::vector<double>> rows;
  for (std::size_t i = 0; i < idealFlight.samples.size(); i += 10) { // every 10 ms
    const FlightSample& s = idealFlight.samples[i];
    const ProjectilePoint p = vacuumPointAt(
        {length(launchVelocity), std::atan2(launchVelocity.y, launchVelocity.x), launchHeight, g}, s.time);
    rows.push_back({s.time, s.position.x, s.position.y, s.velocity.x, s.velocity.y, p.position.x, p.position.y});
  }
  writeCsv(options, "magnus.csv", "t,x,y,vx,vy,x_no_spin,y_no_spin", rows);

  std::vector<std::vector<double>> bookRows;
  for (int i = 0; i * 0.005 < 0.97 * singular; ++i) {
    const double t = i * 0.005;
    const MagnusPlaneState book = bookMagnusFormula(launch, t);
    const MagnusPlaneState exact = magnusClosedForm(launch, t);
    bookRows.push_back({t, book.position.x, book.position.y, exact.position.x, exact.position.y});
  }
  writeCsv(options, "magnus-book.csv", "t,x_book,y_book,x_exact,y_exact", bookRows);

  std::vector<std::vector<double>> flightRows;
  const std::size_t n = std::max(plain.samples.size(), spun.samples.size());
  const auto addFlightRow = [&](std::size_t i) {
    const FlightSample& a = plain.samples[std::min(i, plain.samples.size() - 1)];
    const FlightSample& b = spun.samples[std::min(i, spun.samples.size() - 1)];
    flightRows.push_back({std::max(a.time, b.time), a.position.x, a.position.y, b.position.x, b.position.y});
  };
  for (std::size_t i = 0; i < n; i += 10) { // every 10 ms
    addFlightRow(i);
  }
  if ((n - 1) % 10 != 0) {
    addFlightRow(n - 1); // and the landing
  }
  writeCsv(options, "magnus-flight.csv", "t,x_no_spin,y_no_spin,x_backspin,y_backspin", flightRows);
  return 0;
}

} // namespace impetus::cli
