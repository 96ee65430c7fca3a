// The book's ch. 9 hovercraft and ch. 10 bumper cars, headless, on the 2D engine.
//
// hovercraft: full thrust from rest along +x, then 20 s with the port thruster (a right turn),
// then 20 s with the starboard thruster (a left turn): the turns are "soft" (the book), the
// craft keeps sliding along its old heading for a while because only air drag removes sideways
// velocity. bumper-cars: the player's craft rams craft 2 (heading down the screen at thrust 5)
// side on, restitution 0.5, once with the book's single-impulse response and once with the soft
// step: the impulse is the same physics, so both conserve momentum and lose kinetic energy alike.
#include "demos/demos.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/vehicles/hovercraft.hpp>

#include <fmt/core.h>

#include <cmath>
#include <vector>

namespace impetus::cli {
namespace {

constexpr float dt = 1.0f / 60.0f;

rigid2d::WorldDef flatWorld(rigid2d::SolverKind solver) {
  rigid2d::WorldDef def;
  def.gravity = {};
  def.solver = solver;
  return def;
}

float degrees(float rad) { return radToDeg(rad); }

} // namespace

int demoHovercraft(const DemoOptions& options) {
  rigid2d::World world(flatWorld(rigid2d::SolverKind::softStep));
  vehicles::Hovercraft craft(world, {}, {0.0f, 0.0f}, 0.0f, 10.0f);
  std::vector<std::vector<double>> rows;
  fmt::print("the book's ch. 9 hovercraft: 100 kg, 20 m x 10 m, full thrust 10 N, drag at 5 m aft of the CG\n");
  for (int i = 0; i <= 100 * 60; ++i) {
    const float t = static_cast<float>(i) * dt;
    vehicles::HovercraftControls controls;
    controls.portThruster = t >= 60.0f && t < 80.0f;
    controls.starboardThruster = t >= 80.0f && t < 100.0f;
    if (i % 60 == 0) {
      const Vec2f p = world.position(craft.body());
      const Vec2f v = world.linearVelocity(craft.body());
      const float heading = world.angle(craft.body());
      const float track = std::atan2(v.y, v.x);
      rows.push_back({t, p.x, p.y, heading, v.x, v.y, world.angularVelocity(craft.body()), craft.thrust()});
      if (i % (20 * 60) == 0) {
        fmt::print("  t = {:5.1f} s  x = {:8.2f} m  y = {:7.2f} m  speed = {:5.2f} m/s  heading = {:7.2f} deg  "
                   "sideslip = {:6.2f} deg\n",
                   t, p.x, p.y, length(v), degrees(heading),
                   degrees(std::remainder(heading - track, 2.0f * pi<float>)));
      }
    }
    craft.applyLoads(controls, dt);
    world.step(dt);
  }
  fmt::print("port thruster from 60 s: right turn (heading falls); starboard from 80 s: left turn\n");
  writeCsv(options, "hovercraft.csv", "t,x,y,heading,vx,vy,w,thrust", rows);
  return 0;
}

int demoBumperCars(const DemoOptions& options) {
  fmt::print("the book's ch. 10 bumper cars: craft 1 rams craft 2 side on, e = 0.5\n");
  for (const auto solver : {rigid2d::SolverKind::bookImpulse, rigid2d::SolverKind::softStep}) {
    const bool book = solver == rigid2d::SolverKind::bookImpulse;
    rigid2d::World world(flatWorld(solver));
    vehicles::Hovercraft player(world, {}, {-40.0f, 4.0f}, 0.0f, 10.0f);
    vehicles::Hovercraft other(world, {}, {0.0f, 30.0f}, -0.5f * pi<float>, 5.0f);
    world.setLinearVelocity(player.body(), {8.0f, 0.0f});
    world.setLinearVelocity(other.body(), {0.0f, -2.0f});
    std::vector<std::vector<double>> rows;
    const auto momentum = [&] {
      return world.linearVelocity(player.body()) * world.mass(player.body()) +
             world.linearVelocity(other.body()) * world.mass(other.body());
    };
    const auto energy = [&] {
      float e = 0.0f;
      for (const rigid2d::BodyId b : {player.body(), other.body()}) {
        e += 0.5f * world.mass(b) * lengthSquared(world.linearVelocity(b)) +
             0.5f * world.rotationalInertia(b) * world.angularVelocity(b) * world.angularVelocity(b);
      }
      return e;
    };
    bool reported = false;
    for (int i = 0; i <= 20 * 60; ++i) {
      const Vec2f before = momentum();
      const float energyBefore = energy();
      player.applyLoads({}, dt);
      other.applyLoads({}, dt);
      world.step(dt);
      const Vec2f p1 = world.position(player.body());
      const Vec2f p2 = world.position(other.body());
      rows.push_back(
          {static_cast<double>(i) * dt, p1.x, p1.y, world.angle(player.body()), p2.x, p2.y, world.angle(other.body())});
      if (!reported && !world.contactEvents().hits.empty()) {
        reported = true;
        const rigid2d::ContactHitEvent& hit = world.contactEvents().hits.front();
        fmt::print("  {:<11} hit at t = {:5.2f} s, {:4.2f} m/s: momentum ({:7.2f}, {:7.2f}) -> ({:7.2f}, {:7.2f}) "
                   "kg m/s, kinetic energy {:7.1f} -> {:7.1f} J; spins {:+6.3f} and {:+6.3f} rad/s\n",
                   book ? "book:" : "soft step:", static_cast<float>(i) * dt, hit.approachSpeed, before.x, before.y,
                   momentum().x, momentum().y, energyBefore, energy(), world.angularVelocity(player.body()),
                   world.angularVelocity(other.body()));
      }
    }
    writeCsv(options, book ? "bumper-cars-book.csv" : "bumper-cars-soft.csv", "t,x1,y1,angle1,x2,y2,angle2", rows);
  }
  return 0;
}

} // namespace impetus::cli
