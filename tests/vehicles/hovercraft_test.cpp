// The book's ch. 9 hovercraft on the 2D engine, against its drag law and the book's claims:
// port thruster turns right, the aft centre of drag gives directional stability.
#include "support/error_field.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/vehicles/hovercraft.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace impetus::vehicles {
namespace {

constexpr float dt = 1.0f / 60.0f;

rigid2d::World flatWorld() {
  rigid2d::WorldDef def;
  def.gravity = {}; // seen from above: the skirt carries the weight
  return rigid2d::World(def);
}

// Full thrust against quadratic drag: T = 1/2 rho v^2 A Cd, so v = sqrt(2 T / (rho A Cd)),
// 9.47 m/s with the book's numbers. The time constant is m / (rho A Cd v) = 47 s: after 400 s
// the speed is within 0.1% of terminal.
TEST(Hovercraft, reaches_the_terminal_speed_of_its_drag_law) {
  rigid2d::World world = flatWorld();
  const HovercraftParams params;
  Hovercraft craft(world, params, {}, 0.0f, params.maxThrust);
  for (int i = 0; i < 400 * 60; ++i) {
    craft.applyLoads({}, dt);
    world.step(dt);
  }
  const float area = 0.5f * (params.length + params.width) * params.height;
  const float terminal = std::sqrt(2.0f * params.maxThrust / (params.airDensity * area * params.dragCoefficient));
  EXPECT_NEAR(terminal, 9.47f, 0.01f);
  EXPECT_NEAR(world.linearVelocity(craft.body()).x, terminal, 0.002f * terminal);
  EXPECT_NEAR(world.linearVelocity(craft.body()).y, 0.0f, 1e-4f);
}

// The book: the port thruster pushes the bow to starboard (a right turn, M = -(L/2) S = -30 N m
// in this +y-to-port frame); the starboard thruster turns it left.
TEST(Hovercraft, port_thruster_turns_right_and_starboard_left) {
  for (const bool port : {true, false}) {
    rigid2d::World world = flatWorld();
    Hovercraft craft(world, {}, {}, 0.0f);
    const HovercraftLoads loads = craft.applyLoads({0, port, !port}, dt);
    EXPECT_NEAR(loads.moment, port ? -30.0f : 30.0f, 1e-4f);
    for (int i = 0; i < 120; ++i) {
      world.step(dt);
      craft.applyLoads({0, port, !port}, dt);
    }
    if (port) {
      EXPECT_LT(world.angle(craft.body()), -0.1f) << "clockwise: to starboard";
    } else {
      EXPECT_GT(world.angle(craft.body()), 0.1f) << "counter-clockwise: to port";
    }
  }
}

/// Yaw rate plus sideslip left after 240 s of straight running that started with a 0.2 rad/s
/// yaw disturbance.
float yawAfterDisturbance(const Vec2f& centreOfDrag) {
  rigid2d::World world = flatWorld();
  HovercraftParams params;
  params.centreOfDrag = centreOfDrag;
  Hovercraft craft(world, params, {}, 0.0f, params.maxThrust);
  world.setLinearVelocity(craft.body(), {9.0f, 0.0f});
  world.setAngularVelocity(craft.body(), 0.2f);
  float heading = 0.0f;
  for (int i = 0; i < 240 * 60; ++i) {
    craft.applyLoads({}, dt);
    world.step(dt);
    heading = world.angle(craft.body());
  }
  // How far the bow points from the velocity (sideslip): small when the craft weathervanes.
  const Vec2f v = world.linearVelocity(craft.body());
  const float slip = std::remainder(heading - std::atan2(v.y, v.x), 2.0f * pi<float>);
  return std::abs(world.angularVelocity(craft.body())) + std::abs(slip);
}

// Drag acting aft of the centre of mass (the book's CD at -L/4) turns the bow back into the flow:
// a yaw disturbance dies out (a weathervane oscillation of about a minute's period, damped to
// 1/10 every 60 s or so) and the craft ends up tracking straight. The same drag ahead of the
// centre of mass (+L/4) does the opposite: the craft never settles nose first.
TEST(Hovercraft, aft_centre_of_drag_gives_directional_stability) {
  const float stable = yawAfterDisturbance({-5.0f, 0.0f});
  const float unstable = yawAfterDisturbance({5.0f, 0.0f});
  EXPECT_LT(stable, 0.01f);
  EXPECT_GT(unstable, 0.5f);
}

TEST(Hovercraft, bad_parameters_name_the_field) {
  rigid2d::World world = flatWorld();
  HovercraftParams params;
  params.mass = 0.0f;
  expectErrorField([&] { Hovercraft craft(world, params, {}, 0.0f); }, "mass");
  params = {};
  params.minThrust = 20.0f;
  expectErrorField([&] { Hovercraft craft(world, params, {}, 0.0f); }, "minThrust");
  params = {};
  params.restitution = 2.0f;
  expectErrorField([&] { Hovercraft craft(world, params, {}, 0.0f); }, "restitution");
  EXPECT_EQ(world.bodyCount(), 0U) << "a failed craft leaves nothing behind";
}

} // namespace
} // namespace impetus::vehicles
