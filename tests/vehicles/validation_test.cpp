// The input validation audit of the hovercraft (docs/reliability.md, "Input validation"): its
// parameters, placement, thrust and time step refuse NaN, infinity, negative and degenerate
// values with an impetus::Error naming the field and showing the value.
#include "support/validation_table.hpp"

#include <impetus/vehicles/hovercraft.hpp>

#include <gtest/gtest.h>

namespace impetus::vehicles {
namespace {

using impetus::testing::expectAccepted;
using impetus::testing::expectRejected;
using impetus::testing::inff;
using impetus::testing::nanf;

TEST(VehiclesValidation, hovercraft) {
  const auto params = [](auto change) {
    return [change] {
      rigid2d::World world;
      HovercraftParams p;
      change(p);
      Hovercraft craft(world, p, {}, 0.0f);
    };
  };
  const auto running = [](auto use) {
    return [use] {
      rigid2d::World world;
      Hovercraft craft(world, {}, {}, 0.0f);
      use(craft);
    };
  };
  expectRejected({
      {"mass", "0", params([](HovercraftParams& p) { p.mass = 0.0f; })},
      {"mass", "nan", params([](HovercraftParams& p) { p.mass = nanf; })},
      {"inertia", "-1", params([](HovercraftParams& p) { p.inertia = -1.0f; })},
      {"length", "inf", params([](HovercraftParams& p) { p.length = inff; })},
      {"width", "0", params([](HovercraftParams& p) { p.width = 0.0f; })},
      {"height", "-1", params([](HovercraftParams& p) { p.height = -1.0f; })},
      {"steeringForce", "-1", params([](HovercraftParams& p) { p.steeringForce = -1.0f; })},
      {"dragCoefficient", "nan", params([](HovercraftParams& p) { p.dragCoefficient = nanf; })},
      {"airDensity", "-1", params([](HovercraftParams& p) { p.airDensity = -1.0f; })},
      {"thrustRate", "inf", params([](HovercraftParams& p) { p.thrustRate = inff; })},
      {"minThrust", "nan", params([](HovercraftParams& p) { p.minThrust = nanf; })},
      {"maxThrust", "inf", params([](HovercraftParams& p) { p.maxThrust = inff; })},
      {"minThrust", "20", params([](HovercraftParams& p) { p.minThrust = 20.0f; })},
      {"restitution", "1.5", params([](HovercraftParams& p) { p.restitution = 1.5f; })},
      {"centreOfDrag.x", "nan", params([](HovercraftParams& p) { p.centreOfDrag.x = nanf; })},
      {"portThrusterPoint.y", "inf", params([](HovercraftParams& p) { p.portThrusterPoint.y = inff; })},
      {"starboardThrusterPoint.x", "nan", params([](HovercraftParams& p) { p.starboardThrusterPoint.x = nanf; })},
      {"position.x", "nan",
       [] {
         rigid2d::World world;
         Hovercraft craft(world, {}, {nanf, 0.0f}, 0.0f);
       }},
      {"angle", "inf",
       [] {
         rigid2d::World world;
         Hovercraft craft(world, {}, {}, inff);
       }},
      {"initialThrust", "nan",
       [] {
         rigid2d::World world;
         Hovercraft craft(world, {}, {}, 0.0f, nanf);
       }},
      {"thrust", "inf", running([](Hovercraft& c) { c.setThrust(inff); })},
      {"dt", "0", running([](Hovercraft& c) { (void)c.applyLoads({}, 0.0f); })},
      {"dt", "nan", running([](Hovercraft& c) { (void)c.applyLoads({}, nanf); })},
  });
  expectAccepted({
      {"no drag, no steering, equal thrust limits",
       [] {
         rigid2d::World world;
         HovercraftParams p;
         p.dragCoefficient = p.airDensity = p.steeringForce = p.thrustRate = 0.0f;
         p.minThrust = p.maxThrust = 5.0f;
         Hovercraft craft(world, p, {}, 0.0f);
         (void)craft.applyLoads({1, true, true}, 1.0f / 60.0f);
       }},
  });
}

} // namespace
} // namespace impetus::vehicles
