#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/mechanics/aiming.hpp>

#include <gtest/gtest.h>

namespace impetus {
namespace {

constexpr double g = 9.81;

/// Height of a vacuum trajectory at horizontal distance x: the reference the aim must satisfy.
double heightAt(double x, double speed, double angle) {
  const double t = x / (speed * std::cos(angle));
  return speed * std::sin(angle) * t - 0.5 * g * t * t;
}

TEST(Aiming, both_solutions_pass_through_the_target) {
  for (const auto& [x, y, v] : {std::tuple{100.0, 0.0, 40.0}, {250.0, 30.0, 60.0}, {80.0, -40.0, 25.0}}) {
    const std::optional<AimSolutions> aim = launchAngles(x, y, v, g);
    ASSERT_TRUE(aim.has_value());
    EXPECT_LT(aim->low.angle, aim->high.angle);
    for (const LaunchSolution& s : {aim->low, aim->high}) {
      EXPECT_NEAR(heightAt(x, v, s.angle), y, 1e-9 * (1 + std::abs(y)));
      EXPECT_NEAR(s.timeOfFlight, x / (v * std::cos(s.angle)), 1e-12);
    }
  }
}

// On level ground the two angles are complementary and the range is v^2 sin(2 theta) / g.
TEST(Aiming, level_ground_angles_are_complementary) {
  const std::optional<AimSolutions> aim = launchAngles(120.0, 0.0, 50.0, g);
  ASSERT_TRUE(aim.has_value());
  EXPECT_NEAR(aim->low.angle + aim->high.angle, pi<double> / 2, 1e-12);
  EXPECT_NEAR(50.0 * 50.0 * std::sin(2 * aim->low.angle) / g, 120.0, 1e-9);
}

TEST(Aiming, minimum_speed_is_the_edge_of_reach) {
  const double x = 150.0;
  const double y = 20.0;
  const MinimumSpeed least = minimumLaunchSpeed(x, y, g);
  // At the edge the two solutions merge into the minimum-speed angle.
  const std::optional<AimSolutions> edge = launchAngles(x, y, least.speed * (1 + 1e-12), g);
  ASSERT_TRUE(edge.has_value());
  EXPECT_NEAR(edge->low.angle, least.angle, 1e-5);
  EXPECT_NEAR(edge->high.angle, least.angle, 1e-5);
  EXPECT_NEAR(heightAt(x, least.speed, least.angle), y, 1e-8);
  EXPECT_FALSE(launchAngles(x, y, least.speed * 0.999, g).has_value());
  // Level ground: the least speed is sqrt(g x), at 45 degrees.
  const MinimumSpeed level = minimumLaunchSpeed(100.0, 0.0, g);
  EXPECT_NEAR(level.speed, std::sqrt(g * 100.0), 1e-12);
  EXPECT_NEAR(level.angle, pi<double> / 4, 1e-12);
}

TEST(Aiming, straight_up_and_down) {
  const std::optional<AimSolutions> up = launchAngles(0.0, 10.0, 20.0, g);
  ASSERT_TRUE(up.has_value());
  EXPECT_DOUBLE_EQ(up->low.angle, pi<double> / 2);
  // 10 = 20 t - g t^2 / 2, first root.
  EXPECT_NEAR(up->low.timeOfFlight, (20.0 - std::sqrt(400.0 - 2 * g * 10.0)) / g, 1e-12);
  EXPECT_FALSE(launchAngles(0.0, 30.0, 20.0, g).has_value()); // apex 20.4 m
  const std::optional<AimSolutions> down = launchAngles(0.0, -10.0, 5.0, g);
  ASSERT_TRUE(down.has_value());
  EXPECT_DOUBLE_EQ(down->low.angle, -pi<double> / 2);
  EXPECT_NEAR(5.0 * down->low.timeOfFlight + 0.5 * g * std::pow(down->low.timeOfFlight, 2), 10.0, 1e-12);
}

TEST(Aiming, aim_in_3d_reaches_the_point) {
  const Vec3d from{1.0, 2.0, 3.0};
  const Vec3d to{60.0, 12.0, -45.0};
  const double v = 45.0;
  const std::optional<Aim3> aim = aimAt(from, to, v, g);
  ASSERT_TRUE(aim.has_value());
  for (const auto& [dir, t] : {std::pair{aim->lowDirection, aim->lowTime}, {aim->highDirection, aim->highTime}}) {
    EXPECT_NEAR(length(dir), 1.0, 1e-14);
    const Vec3d p = from + dir * (v * t) + Vec3d{0.0, -0.5 * g * t * t, 0.0};
    EXPECT_NEAR(distance(p, to), 0.0, 1e-9);
  }
  EXPECT_FALSE(aimAt(from, {5000.0, 0.0, 0.0}, v, g).has_value());
}

TEST(Aiming, bad_input_names_the_field) {
  EXPECT_THROW((void)launchAngles(-1.0, 0.0, 10.0), Error);
  EXPECT_THROW((void)launchAngles(10.0, std::nan(""), 10.0), Error);
  EXPECT_THROW((void)launchAngles(10.0, 0.0, 0.0), Error);
  EXPECT_THROW((void)minimumLaunchSpeed(10.0, 0.0, 0.0), Error);
  try {
    (void)launchAngles(10.0, 0.0, -3.0);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "speed");
  }
}

} // namespace
} // namespace impetus
