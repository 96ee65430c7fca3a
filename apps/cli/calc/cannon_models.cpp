// `impetus calc` entries for gunnery (ch. 2, 4): the rifle shot, the cannon and Cannon2 at a
// target box, aiming and the kinematic explosion.
#include "calc/calc.hpp"
#include "calc/values.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/mechanics/aiming.hpp>
#include <impetus/mechanics/cannon.hpp>
#include <impetus/mechanics/explosion.hpp>

namespace impetus::cli {
namespace {

constexpr const char* topic = "gunnery (ch. 2, 4)";

Param number(std::string name, std::string unit, std::string help, std::optional<std::string> value) {
  return {std::move(name), std::move(unit), std::move(help), std::move(value)};
}

double degrees(const Args& a, const std::string& name, const std::string& field, double lo, double hi) {
  const double v = a.number(name);
  if (!(v >= lo && v <= hi)) {
    throwInvalid(field, v, "must be between " + formatValue(lo) + " and " + formatValue(hi) + " degrees");
  }
  return degToRad(v);
}

const char* outcomeName(ShotOutcome o) {
  switch (o) {
  case ShotOutcome::hit:
    return "hit";
  case ShotOutcome::ground:
    return "ground";
  case ShotOutcome::timeout:
    return "timeout";
  }
  return "?";
}

/// The book's cannon dialog: gun, target, g and the time step.
std::vector<Param> cannonParams() {
  return {number("muzzle-speed", "m/s", "Vm, muzzle speed", "50"),
          number("altitude-deg", "deg", "alpha, barrel angle from the vertical (90 = level)", "45"),
          number("azimuth-deg", "deg", "gamma, barrel angle in the x-z plane from +x toward +z", "0"),
          number("barrel-length", "m", "L", "2"),
          number("base-height", "m", "Yb, height of the barrel's pivot", "0"),
          number("target-x", "m", "target centre x", "255"),
          number("target-y", "m", "target centre y", "5"),
          number("target-z", "m", "target centre z", "0"),
          number("target-length", "m", "target size along x", "10"),
          number("target-height", "m", "target size along y", "10"),
          number("target-width", "m", "target size along z", "10"),
          number("gravity", "m/s^2", "g (the book uses 9.81 here)", "9.81"),
          number("time-step", "s", "sampling step (the chord between samples is tested)", "0.01")};
}

CannonSetup cannonFromArgs(const Args& a) {
  return {a.number("muzzle-speed"), degrees(a, "altitude-deg", "altitudeDeg", 0.0, 180.0),
          degrees(a, "azimuth-deg", "azimuthDeg", -360.0, 360.0), a.number("barrel-length"), a.number("base-height")};
}

Result shotResult(const Args& a, const ShellFlight& flight, const CannonSetup& cannon) {
  // Checked under the parameters' names: the library would name target.center.x, target.size.x...
  for (const char* name : {"target-x", "target-y", "target-z"}) {
    requireFinite(a.number(name), name);
  }
  for (const char* name : {"target-length", "target-height", "target-width"}) {
    requireNonNegative(a.number(name), name);
  }
  const TargetBox target{{a.number("target-x"), a.number("target-y"), a.number("target-z")},
                         {a.number("target-length"), a.number("target-height"), a.number("target-width")}};
  const ShotResult shot = fireAtTarget(flight, target, a.number("time-step"));
  Result r;
  r.add("outcome", std::string(outcomeName(shot.outcome)), "", "hit, ground or timeout");
  r.add("time", shot.time, "s");
  r.add("position", toVector(shot.position), "m", "where the shell hit the target or the ground");
  r.add("velocity", toVector(shot.velocity), "m/s");
  r.add("direction_cosines", toVector(barrelDirection(cannon.altitude, cannon.azimuth)));
  r.add("muzzle_position", toVector(muzzlePosition(cannon)), "m");
  return r;
}

Result cannon(const Args& a) {
  const CannonSetup gun = cannonFromArgs(a);
  Atmosphere air;
  air.gravity = a.number("gravity");
  return shotResult(a, ShellFlight(gun, 1.0, air), gun);
}

Result cannon2(const Args& a) {
  const CannonSetup gun = cannonFromArgs(a);
  Atmosphere air;
  air.gravity = a.number("gravity");
  air.dragCoefficient = a.number("drag-coefficient");
  air.windSpeed = a.number("wind-speed");
  air.windDirection = degrees(a, "wind-direction-deg", "windDirectionDeg", -360.0, 360.0);
  air.windCoefficient = a.number("wind-coefficient");
  const std::string& model = a.text("wind-model");
  if (model == "book") {
    air.windModel = WindModel::bookConstantForce;
  } else if (model != "moving-air") {
    throw Error("windModel", "windModel = " + model + ": must be moving-air or book");
  }
  const ShellFlight flight(gun, a.number("mass"), air);
  Result r = shotResult(a, flight, gun);
  if (air.dragCoefficient > 0.0) {
    r.add("terminal_velocity", toVector(flight.terminalVelocity()), "m/s");
  } else {
    r.notes.emplace_back("no drag: the shell has no terminal velocity");
  }
  if (air.windModel == WindModel::bookConstantForce) {
    r.notes.emplace_back("book's wind: a constant force -Cw vw that ignores the shell's velocity; "
                         "--wind-model moving-air applies the drag to the velocity relative to the air");
  }
  return r;
}

} // namespace

void registerCannonModels(Registry& registry) {
  registry.add({"rifle-shot",
                topic,
                "level shot at a target: t = n / vm, drop = 1/2 g t^2",
                {number("distance", "m", "n, distance to the target", std::nullopt),
                 number("muzzle-speed", "m/s", "vm", std::nullopt), number("gravity", "m/s^2", "g", "9.81")},
                [](const Args& a) {
                  const RifleShot s = rifleShot(a.number("distance"), a.number("muzzle-speed"), a.number("gravity"));
                  Result r;
                  r.add("time", s.time, "s", "to reach the target");
                  r.add("drop", s.drop, "m", "below the line of the barrel");
                  return r;
                }});
  registry.add({"cannon", topic, "the book's cannon in vacuum: s(t) = s0 + vm t + 1/2 a t^2 at a target box",
                cannonParams(), cannon});
  std::vector<Param> drag = cannonParams();
  drag.push_back(number("mass", "kg", "m, shell mass", "10"));
  drag.push_back(number("drag-coefficient", "kg/s", "C, linear drag F = -C v (0 = vacuum)", "1"));
  drag.push_back(number("wind-speed", "m/s", "vw", "0"));
  drag.push_back(number("wind-direction-deg", "deg", "gw, where the wind comes from (0 blows toward -x)", "0"));
  drag.push_back(number("wind-coefficient", "kg/s", "Cw, only for --wind-model book", "0"));
  drag.push_back(
      {"wind-model", "", "moving-air (drag against the air) or book (constant force)", "moving-air", ParamKind::text});
  registry.add({"cannon2", topic, "Cannon2: linear drag -C v and wind, closed form per axis, at a target box",
                std::move(drag), cannon2});
  registry.add({"aim",
                topic,
                "launch angles through a point: tan a = (v^2 +- sqrt(v^4 - g(g x^2 + 2 y v^2)))/(g x)",
                {number("distance", "m", "horizontal distance to the target", std::nullopt),
                 number("height", "m", "target height above the launch point", "0"),
                 number("speed", "m/s", "launch speed", std::nullopt), number("gravity", "m/s^2", "g", "9.81")},
                [](const Args& a) {
                  const double x = a.number("distance");
                  const double y = a.number("height");
                  const double g = a.number("gravity");
                  const std::optional<AimSolutions> aim = launchAngles(x, y, a.number("speed"), g);
                  if (!aim) {
                    throwInvalid("speed", a.number("speed"),
                                 "the target is out of reach; the least speed that reaches it is " +
                                     formatValue(minimumLaunchSpeed(x, y, g).speed) + " m/s");
                  }
                  Result r;
                  r.add("low_angle", radToDeg(aim->low.angle), "deg", "above the horizontal");
                  r.add("low_time", aim->low.timeOfFlight, "s");
                  r.add("high_angle", radToDeg(aim->high.angle), "deg");
                  r.add("high_time", aim->high.timeOfFlight, "s");
                  return r;
                }});
  registry.add({"minimum-launch-speed",
                topic,
                "least speed through a point: v^2 = g (y + sqrt(x^2 + y^2))",
                {number("distance", "m", "horizontal distance", std::nullopt),
                 number("height", "m", "height above the launch point", "0"), number("gravity", "m/s^2", "g", "9.81")},
                [](const Args& a) {
                  const MinimumSpeed m =
                      minimumLaunchSpeed(a.number("distance"), a.number("height"), a.number("gravity"));
                  Result r;
                  r.add("speed", m.speed, "m/s");
                  r.add("angle", radToDeg(m.angle), "deg", "above the horizontal");
                  return r;
                }});
  registry.add({"explosion",
                topic,
                "kinematic particle explosion: x = v cos(a) t, y = v sin(a) t + g t^2/2",
                {number("speed", "m/s", "strength: particles leave at [speed/2, speed]", "10"),
                 number("life", "s", "duration: particles live [0.8, 1] x life", "2"),
                 number("gravity", "m/s^2", "vertical acceleration (negative = down)", "-9.81"),
                 number("count", "", "number of particles", "50"), number("seed", "", "random seed", "1")},
                [](const Args& a) {
                  ExplosionSettings s;
                  s.speed = a.number("speed");
                  s.life = a.number("life");
                  s.gravity = a.number("gravity");
                  const double count = a.number("count");
                  if (!(count >= 1.0 && count <= 100000.0) || count != std::floor(count)) {
                    throwInvalid("count", count, "must be a whole number between 1 and 100000");
                  }
                  s.count = static_cast<int>(count);
                  const double seed = a.number("seed");
                  if (!(seed >= 0.0 && seed <= 4294967295.0) || seed != std::floor(seed)) {
                    throwInvalid("seed", seed, "must be a whole number between 0 and 2^32 - 1");
                  }
                  s.seed = static_cast<std::uint32_t>(seed);
                  const KinematicExplosion e(s);
                  double farthest = 0.0;
                  for (std::size_t i = 0; i < e.particles().size(); ++i) {
                    const double t = e.particles()[i].life;
                    farthest = std::max(farthest, distance(e.particleAt(i, t).position, e.origin()));
                  }
                  Result r;
                  r.add("end_time", e.endTime(), "s", "when the last particle dies");
                  r.add("farthest", farthest, "m", "largest distance from the origin at death");
                  return r;
                }});
}

} // namespace impetus::cli
