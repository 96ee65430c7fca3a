#include <impetus/error.hpp>
#include <impetus/integrate/rk4.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/mechanics/aiming.hpp>
#include <impetus/mechanics/cannon.hpp>

#include <gtest/gtest.h>

namespace impetus {
namespace {

constexpr double kDeg = pi<double> / 180.0;

/// Position and velocity, for integrating the same equations the closed forms solve.
struct PointState {
  Vec3d p;
  Vec3d v;
  PointState operator+(const PointState& o) const { return {p + o.p, v + o.v}; }
  PointState operator*(double s) const { return {p * s, v * s}; }
};

void expectNear(const Vec3d& a, const Vec3d& b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

/// Integrates m dv/dt = -C v + F with classic RK4 at `steps` steps to time t.
PointState integrate(const CannonSetup& cannon, double mass, double drag, const Vec3d& force, double t, int steps) {
  PointState s{muzzlePosition(cannon), muzzleVelocity(cannon)};
  const auto f = [&](double, const PointState& x) { return PointState{x.v, (force - x.v * drag) / mass}; };
  const double h = t / steps;
  for (int i = 0; i < steps; ++i) {
    s = rk4Step(f, i * h, s, h);
  }
  return s;
}

TEST(Cannon, direction_cosines_follow_the_books_angles) {
  expectNear(barrelDirection(0.0, 1.0), {0.0, 1.0, 0.0}, 1e-15);       // alpha = 0: straight up
  expectNear(barrelDirection(90 * kDeg, 0.0), {1.0, 0.0, 0.0}, 1e-15); // level, along +x
  expectNear(barrelDirection(90 * kDeg, 90 * kDeg), {0.0, 0.0, 1.0}, 1e-15);
  const Vec3d d = barrelDirection(30 * kDeg, 40 * kDeg);
  EXPECT_NEAR(length(d), 1.0, 1e-15);
  // Book: b = L cos(90 - alpha) is the barrel's projection on the x-z plane.
  EXPECT_NEAR(std::hypot(d.x, d.z), std::cos((90 - 30) * kDeg), 1e-15);
}

TEST(Cannon, muzzle_is_at_the_barrel_tip_above_the_base) {
  const CannonSetup c{100.0, 60 * kDeg, 20 * kDeg, 5.0, 3.0};
  const Vec3d tip = muzzlePosition(c);
  EXPECT_NEAR(tip.x, 5.0 * std::sin(60 * kDeg) * std::cos(20 * kDeg), 1e-14);
  EXPECT_NEAR(tip.y, 3.0 + 5.0 * std::cos(60 * kDeg), 1e-14);
  EXPECT_NEAR(tip.z, 5.0 * std::sin(60 * kDeg) * std::sin(20 * kDeg), 1e-14);
  EXPECT_NEAR(length(muzzleVelocity(c)), 100.0, 1e-12);
}

TEST(Cannon, vacuum_flight_is_the_constant_acceleration_parabola) {
  const CannonSetup c{80.0, 50 * kDeg, 30 * kDeg, 4.0, 1.0};
  const ShellFlight flight(c, 10.0, Atmosphere{});
  for (double t : {0.0, 0.5, 3.0, 9.0}) {
    const ShellState s = flight.at(t);
    const Vec3d expected = muzzlePosition(c) + muzzleVelocity(c) * t + Vec3d{0.0, -0.5 * 9.81 * t * t, 0.0};
    expectNear(s.position, expected, 1e-11);
    expectNear(s.velocity, muzzleVelocity(c) + Vec3d{0.0, -9.81 * t, 0.0}, 1e-12);
  }
}

// The closed forms against RK4 on the same ODE: RK4's global error at h = 1 ms over 6 s is
// ~h^4 * t * (k^4 v) ~ 1e-12 m here, so 1e-8 m is a comfortable but meaningful bound.
TEST(Cannon, drag_with_moving_air_matches_integrated_ode) {
  const CannonSetup c{90.0, 40 * kDeg, 10 * kDeg, 3.0, 0.0};
  Atmosphere air;
  air.dragCoefficient = 2.5;
  air.windSpeed = 12.0;
  air.windDirection = 30 * kDeg;
  const double mass = 20.0;
  const ShellFlight flight(c, mass, air);
  // Air moves along -(cos gw, 0, sin gw); the drag acts on the velocity relative to it.
  const Vec3d wind = Vec3d{std::cos(air.windDirection), 0.0, std::sin(air.windDirection)} * -air.windSpeed;
  const Vec3d force = Vec3d{0.0, -mass * air.gravity, 0.0} + wind * air.dragCoefficient;
  const PointState reference = integrate(c, mass, air.dragCoefficient, force, 6.0, 6000);
  const ShellState s = flight.at(6.0);
  expectNear(s.position, reference.p, 1e-8);
  expectNear(s.velocity, reference.v, 1e-9);
  // Long after firing the shell drifts with the air horizontally.
  const Vec3d terminal = flight.terminalVelocity();
  EXPECT_NEAR(terminal.x, wind.x, 1e-12);
  EXPECT_NEAR(terminal.z, wind.z, 1e-12);
  EXPECT_NEAR(terminal.y, -mass * air.gravity / air.dragCoefficient, 1e-12);
}

TEST(Cannon, books_constant_wind_force_matches_integrated_ode) {
  const CannonSetup c{90.0, 40 * kDeg, 10 * kDeg, 3.0, 0.0};
  Atmosphere air;
  air.dragCoefficient = 2.5;
  air.windSpeed = 12.0;
  air.windDirection = 0.0;
  air.windCoefficient = 4.0;
  air.windModel = WindModel::bookConstantForce;
  const double mass = 20.0;
  const ShellFlight flight(c, mass, air);
  const Vec3d force{-air.windCoefficient * air.windSpeed, -mass * air.gravity, 0.0};
  expectNear(flight.constantForce(), force, 1e-12);
  const PointState reference = integrate(c, mass, air.dragCoefficient, force, 6.0, 6000);
  expectNear(flight.at(6.0).position, reference.p, 1e-8);
}

// The book's Cannon2 divides by Cd; ours tends continuously to the vacuum parabola.
TEST(Cannon, vanishing_drag_tends_to_vacuum_without_cancellation) {
  const CannonSetup c{80.0, 50 * kDeg, 0.0, 4.0, 1.0};
  Atmosphere tiny;
  tiny.dragCoefficient = 1e-13;
  const ShellState vacuum = ShellFlight(c, 10.0, Atmosphere{}).at(5.0);
  const ShellState almost = ShellFlight(c, 10.0, tiny).at(5.0);
  // The physical difference is ~k t * x ~ 1e-14 * 5 * 250 m ~ 1e-11 m.
  expectNear(almost.position, vacuum.position, 1e-10);
  // A small but real drag (k t = 5e-5, the series branch) against RK4 on the same ODE.
  Atmosphere small;
  small.dragCoefficient = 1e-4;
  const Vec3d gravity{0.0, -10.0 * small.gravity, 0.0};
  const PointState reference = integrate(c, 10.0, small.dragCoefficient, gravity, 5.0, 5000);
  expectNear(ShellFlight(c, 10.0, small).at(5.0).position, reference.p, 1e-9);
  EXPECT_LT(ShellFlight(c, 10.0, small).at(5.0).position.x, vacuum.position.x - 1e-3); // drag is felt
}

TEST(Cannon, shot_aimed_with_launch_angles_hits_the_target) {
  // A level barrel pivot at the origin with no barrel length, so the aim is from the origin.
  const double speed = 60.0;
  const TargetBox target{{200.0, 5.0, 0.0}, {4.0, 4.0, 4.0}};
  const std::optional<AimSolutions> aim = launchAngles(200.0, 5.0, speed);
  ASSERT_TRUE(aim.has_value());
  for (double elevation : {aim->low.angle, aim->high.angle}) {
    const CannonSetup c{speed, pi<double> / 2 - elevation, 0.0, 0.0, 0.0};
    const ShotResult r = fireAtTarget(ShellFlight(c, 1.0, Atmosphere{}), target, 0.01);
    ASSERT_EQ(r.outcome, ShotOutcome::hit);
    EXPECT_LE(std::abs(r.position.x - 200.0), 2.0 + 1e-9);
    EXPECT_LE(std::abs(r.position.y - 5.0), 2.0 + 1e-9);
  }
}

TEST(Cannon, ground_impact_time_matches_the_vacuum_root) {
  const CannonSetup c{50.0, 45 * kDeg, 0.0, 0.0, 10.0};
  const ShotResult r = fireAtTarget(ShellFlight(c, 1.0, Atmosphere{}), TargetBox{{-100.0, 0.0, 0.0}, {1.0, 1.0, 1.0}});
  ASSERT_EQ(r.outcome, ShotOutcome::ground);
  // 10 + vy t - g t^2 / 2 = 0.
  const double vy = 50.0 * std::cos(45 * kDeg);
  const double t = (vy + std::sqrt(vy * vy + 2 * 9.81 * 10.0)) / 9.81;
  EXPECT_NEAR(r.time, t, 1e-8);
  EXPECT_NEAR(r.position.x, 50.0 * std::sin(45 * kDeg) * t, 1e-6);
  EXPECT_EQ(r.trajectory.back().time, r.time);
}

// The book tests the point at each step against the box; a fast shell passes through a thin
// target between two steps. The chord test does not.
TEST(Cannon, thin_target_is_not_tunnelled_through) {
  const CannonSetup c{400.0, 90 * kDeg, 0.0, 0.0, 50.0}; // level, 400 m/s, 50 m up
  const TargetBox wall{{100.0, 50.0, 0.0}, {0.05, 10.0, 10.0}};
  const ShotResult r = fireAtTarget(ShellFlight(c, 1.0, Atmosphere{}), wall, 0.1); // 40 m per step
  ASSERT_EQ(r.outcome, ShotOutcome::hit);
  EXPECT_NEAR(r.position.x, 99.975, 1e-9);
  // No sample before the hit lies inside the wall: a point test would have missed it.
  for (std::size_t i = 0; i + 1 < r.trajectory.size(); ++i) {
    EXPECT_GT(std::abs(r.trajectory[i].position.x - 100.0), 0.025);
  }
}

TEST(Cannon, times_out_when_the_shell_never_lands) {
  const CannonSetup c{50.0, 0.0, 0.0, 0.0, 0.0};
  Atmosphere space;
  space.gravity = 0.0;
  const ShotResult r =
      fireAtTarget(ShellFlight(c, 1.0, space), TargetBox{{0.0, -50.0, 0.0}, {1.0, 1.0, 1.0}}, 0.5, 10.0);
  EXPECT_EQ(r.outcome, ShotOutcome::timeout);
  EXPECT_DOUBLE_EQ(r.time, 10.0);
}

// Ex 2.2: 500 m at 800 m/s takes 0.625 s and drops 1.916 m with g = 9.81.
TEST(Rifle, books_horizontal_shot) {
  const RifleShot shot = rifleShot(500.0, 800.0, 9.81);
  EXPECT_DOUBLE_EQ(shot.time, 0.625);
  EXPECT_NEAR(shot.drop, 1.916, 5e-4);
  EXPECT_NEAR(rifleShot(500.0, 800.0, 9.8).drop, 1.914, 5e-4);
}

TEST(Cannon, bad_input_names_the_field) {
  const auto field = [](auto&& make) {
    try {
      make();
    } catch (const Error& e) {
      return e.field();
    }
    return std::string("no error");
  };
  const CannonSetup ok{};
  EXPECT_EQ(field([&] { (void)ShellFlight(ok, -1.0, Atmosphere{}); }), "mass");
  EXPECT_EQ(field([&] { (void)ShellFlight(CannonSetup{50.0, 4.0, 0.0, 1.0, 0.0}, 1.0, Atmosphere{}); }), "altitude");
  EXPECT_EQ(field([&] { (void)ShellFlight(CannonSetup{-5.0, 1.0, 0.0, 1.0, 0.0}, 1.0, Atmosphere{}); }), "muzzleSpeed");
  Atmosphere air;
  air.dragCoefficient = std::nan("");
  EXPECT_EQ(field([&] { (void)ShellFlight(ok, 1.0, air); }), "dragCoefficient");
  const ShellFlight flight(ok, 1.0, Atmosphere{});
  EXPECT_EQ(field([&] { (void)fireAtTarget(flight, TargetBox{}, 0.0); }), "timeStep");
  EXPECT_EQ(field([&] { (void)fireAtTarget(flight, TargetBox{{}, {-1.0, 1.0, 1.0}}); }), "target.size.x");
  EXPECT_EQ(field([&] { (void)rifleShot(100.0, 0.0); }), "muzzleSpeed");
}

} // namespace
} // namespace impetus
