// `impetus calc` entries for chapter 6 (projectiles): vacuum trajectories with a launch and a
// target height, terminal velocity, the Reynolds number and the smooth-sphere drag coefficient,
// the Magnus force, a ball flight with drag and Magnus lift, and the vertical rocket.
#include "calc/calc.hpp"
#include "calc/values.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/mechanics/aerodynamics.hpp>
#include <impetus/mechanics/projectile.hpp>
#include <impetus/mechanics/rocket.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace impetus::cli {
namespace {

constexpr const char* topic = "projectiles (ch. 6)";
constexpr const char* gravityDefault = "9.80665";
constexpr const char* airDensityDefault = "1.225";
constexpr double rpm = 2.0 * pi<double> / 60.0; // rad/s per rev/min

Param required(std::string name, std::string unit, std::string help) {
  return {std::move(name), std::move(unit), std::move(help), std::nullopt};
}
Param optional(std::string name, std::string unit, std::string help, std::string def) {
  return {std::move(name), std::move(unit), std::move(help), std::move(def)};
}
Param gravityParam() {
  return optional("gravity", "m/s^2", "gravitational acceleration (the book's ch. 6 uses 9.8)", gravityDefault);
}
Param airDensityParam() {
  return optional("air-density", "kg/m^3", "air density (1.225: sea level, 15 C)", airDensityDefault);
}

/// A `-deg` parameter in radians, within [-90, 90] degrees (named as the CLI spells it).
double degrees(const Args& a, const std::string& name) {
  const double d = a.number(name);
  if (!(std::abs(d) <= 90.0)) {
    throw Error(name, "--" + name + " = " + formatValue(d) + ": must be within [-90, 90] degrees");
  }
  return degToRad(d);
}

Result projectile(const Args& a) {
  const VacuumLaunch launch{a.number("speed"), degrees(a, "angle-deg"), a.number("launch-height"), a.number("gravity")};
  const double target = a.number("target-height");
  const VacuumFlight f = vacuumFlight(launch, target);
  Result r;
  r.add("time_of_flight", f.timeOfFlight, "s", "until the descending path reaches the target height");
  r.add("range", f.range, "m", "horizontal distance to the target-height crossing");
  r.add("apex_height", f.apexHeight, "m", "highest point, same reference as the heights given");
  r.add("apex_time", f.apexTime, "s");
  r.add("impact_speed", f.impactSpeed, "m/s");
  r.add("impact_angle_deg", radToDeg(f.impactAngle), "deg", "below the horizontal");
  if (launch.speed > 0.0) {
    const double best = maximumRangeAngle(launch.speed, launch.launchHeight, target, launch.gravity);
    r.add("best_angle_deg", radToDeg(best), "deg", "launch angle of the longest range to this target height");
    r.add("max_range", vacuumFlight({launch.speed, best, launch.launchHeight, launch.gravity}, target).range, "m");
  }
  r.notes.emplace_back("vacuum, flat ground, constant g (the book's tables 6-1 to 6-4); "
                       "a drop from a vehicle is --angle-deg 0 with --launch-height");
  return r;
}

Result terminalVelocity(const Args& a) {
  const double v = terminalVelocityQuadratic(a.number("weight"), a.number("drag-coefficient"),
                                             a.number("fluid-density"), a.number("area"));
  Result r;
  r.add("terminal_velocity", v, "m/s", "sqrt(2 W / (Cd rho A))");
  r.add("terminal_velocity_kmh", v * 3.6, "km/h");
  r.notes.emplace_back("the book's Table 6-5 skydiver rows agree with this; its baseball, golf-ball and raindrop rows "
                       "do not follow from its own inputs (golf ball: 116 km/h printed, 122.9 computed)");
  return r;
}

Result reynolds(const Args& a) {
  const double re =
      reynoldsNumber(a.number("speed"), a.number("length"), a.number("density"), a.number("dynamic-viscosity"));
  Result r;
  r.add("reynolds_number", re);
  r.add("kinematic_viscosity", a.number("dynamic-viscosity") / a.number("density"), "m^2/s");
  if (re > 0.0) {
    r.add("sphere_drag_coefficient", sphereDragCoefficient(re), "", "of a smooth sphere of that diameter");
  }
  return r;
}

std::string dragRegime(double re) {
  if (re < 1.0) {
    return "Stokes (creeping flow, Cd ~ 24/Re)";
  }
  if (re < 1e3) {
    return "intermediate";
  }
  if (re < 2e5) {
    return "Newton plateau (laminar boundary layer)";
  }
  if (re < 5e5) {
    return "drag crisis (boundary layer turning turbulent)";
  }
  return "supercritical";
}

Result sphereDrag(const Args& a) {
  const double re = a.number("reynolds");
  Result r;
  r.add("drag_coefficient", sphereDragCoefficient(re), "", "smooth sphere, Morrison (2013) correlation");
  r.add("regime", dragRegime(re));
  if (re > sphereDragCorrelationLimit) {
    r.notes.emplace_back("above Re = 1e6 the correlation is not fitted: Cd is held at its value at 1e6");
  }
  return r;
}

Result magnus(const Args& a) {
  const double speed = a.number("speed");
  const double radius = a.number("radius");
  const double rho = a.number("air-density");
  // In rev/min and under its own name: the library would see rad/s and name spinRate.
  const double w = requireFinite(a.number("spin-rpm"), "spin-rpm") * rpm;
  requirePositive(speed, "speed");
  const double weight = requirePositive(a.number("mass"), "mass") * requirePositive(a.number("gravity"), "gravity");
  const Vec3d v{speed, 0.0, 0.0};
  const Vec3d spin{0.0, 0.0, w}; // backspin for a ball moving along +x: lift along +y
  const double s = spinRatio(radius, std::abs(w), speed);
  const double fit = length(magnusForce(v, spin, radius, rho, LiftModel::sawicki2003));
  const double ideal = length(magnusForce(v, spin, radius, rho, LiftModel::idealizedSphere));
  Result r;
  r.add("spin_rate", w, "rad/s");
  r.add("spin_ratio", s, "", "S = r w / v");
  r.add("lift_coefficient", liftCoefficientSawicki2003(s), "", "Sawicki, Hubbard & Stronge (2003) baseball fit");
  r.add("magnus_force", fit, "N", "1/2 rho v^2 A C_L, perpendicular to v and the spin axis");
  r.add("weight_fraction", fit / weight);
  r.add("magnus_force_idealized", ideal, "N", "the book's pi^2 rho r^3 w v");
  r.add("idealized_weight_fraction", ideal / weight);
  r.notes.emplace_back("the book's idealized formula overpredicts: for its 45 m/s, 30 rev/s pitch it gives 3.5x the "
                       "ball's weight where the book quotes up to 33 %");
  return r;
}

DragModel parseDragModel(const std::string& text) {
  if (text == "constant") {
    return DragModel::constantCoefficient;
  }
  if (text == "smooth-sphere") {
    return DragModel::smoothSphere;
  }
  if (text == "none") {
    return DragModel::none;
  }
  throw Error("dragModel", "--drag-model = '" + text + "': expected constant, smooth-sphere or none");
}

LiftModel parseLiftModel(const std::string& text) {
  if (text == "sawicki2003") {
    return LiftModel::sawicki2003;
  }
  if (text == "constant") {
    return LiftModel::constantCoefficient;
  }
  if (text == "idealized") {
    return LiftModel::idealizedSphere;
  }
  if (text == "none") {
    return LiftModel::none;
  }
  throw Error("liftModel", "--lift-model = '" + text + "': expected sawicki2003, constant, idealized or none");
}

Result ballFlight(const Args& a) {
  BallProperties ball;
  ball.mass = a.number("mass");
  ball.radius = a.number("radius");
  ball.dragModel = parseDragModel(a.text("drag-model"));
  ball.dragCoefficient = a.number("drag-coefficient");
  ball.liftModel = parseLiftModel(a.text("lift-model"));
  ball.liftCoefficient = a.number("lift-coefficient");
  FlightConditions c;
  c.airDensity = a.number("air-density");
  c.gravity = a.number("gravity");
  // The shot goes along +x with y up, so +z is to the shooter's right. Backspin is +z spin;
  // spin about +y (counterclockwise seen from above) curves the ball left, so a positive
  // (rightward) sidespin is -y.
  // Checked under the parameters' names: the library would name spin.y, spin.z, wind.x, wind.z.
  for (const char* name : {"sidespin-rpm", "backspin-rpm", "tail-wind", "cross-wind", "launch-height"}) {
    requireFinite(a.number(name), name);
  }
  c.spin = Vec3d{0.0, -a.number("sidespin-rpm"), a.number("backspin-rpm")} * rpm;
  c.wind = {a.number("tail-wind"), 0.0, a.number("cross-wind")};
  const double speed = a.number("speed");
  requireNonNegative(speed, "speed");
  const double angle = degrees(a, "angle-deg");
  const double height = a.number("launch-height");
  const Vec3d v0{speed * std::cos(angle), speed * std::sin(angle), 0.0};
  const BallFlight f = simulateBallFlight(ball, c, {0.0, height, 0.0}, v0, {a.number("time-step"), 60.0});
  Result r;
  r.add("landed", f.landed);
  r.add("range", f.range, "m", "along the launch direction");
  r.add("flight_time", f.flightTime, "s");
  r.add("max_height", f.maxHeight, "m");
  r.add("apex_time", f.apexTime, "s");
  r.add("landing_point", toVector(f.landingPoint), "m", "x downrange, y up, z to the right");
  r.add("lateral_deflection", f.lateralDeflection, "m", "+ to the right");
  r.add("landing_speed", length(f.landingVelocity), "m/s");
  if (c.gravity > 0.0) {
    r.add("vacuum_range", vacuumFlight({speed, angle, height, c.gravity}, 0.0).range, "m", "no air, for comparison");
  }
  if (!f.landed) {
    r.notes.emplace_back("still in the air after 60 s");
  }
  if (ball.liftModel == LiftModel::idealizedSphere) {
    r.notes.emplace_back("the idealized (book) lift overpredicts about 10x: expect loops at high spin");
  }
  return r;
}

Result rocket(const Args& a) {
  VerticalRocket v;
  v.initialMass = a.number("initial-mass");
  v.propellantMass = a.number("propellant-mass");
  v.burnRate = a.number("burn-rate");
  v.exhaustVelocity = a.number("exhaust-velocity");
  v.gravity = a.number("gravity");
  v.initialVelocity = a.number("initial-velocity");
  v.initialAltitude = a.number("initial-altitude");
  const RocketFlight f = verticalRocketFlight(v);
  Result r;
  r.add("thrust", f.thrust, "N", "mdot u");
  r.add("thrust_to_weight", f.liftoffThrustToWeight, "", "at ignition");
  r.add("ideal_delta_v", f.idealDeltaV, "m/s", "u ln(m0/m1), no gravity");
  r.add("lifts_off", f.liftsOff);
  if (f.liftsOff) {
    r.add("liftoff_time", f.liftoffTime, "s");
  } else {
    r.notes.emplace_back("the thrust never exceeds the weight before burn-out: the rocket stays on the pad");
  }
  r.add("burnout_time", f.burnoutTime, "s");
  r.add("burnout_mass", f.burnoutMass, "kg");
  r.add("burnout_velocity", f.burnoutVelocity, "m/s");
  r.add("burnout_altitude", f.burnoutAltitude, "m");
  r.add("peak_altitude", f.peakAltitude, "m");
  r.add("peak_time", f.peakTime, "s");
  r.notes.emplace_back("vertical flight, constant g, no air resistance (the book's assumptions)");
  return r;
}

} // namespace

void registerProjectileModels(Registry& registry) {
  registry.add({"projectile",
                topic,
                "vacuum trajectory to a target height: T, R = v0 cos(phi) T, apex v0^2 sin^2(phi)/(2g)",
                {required("speed", "m/s", "launch speed v0"),
                 required("angle-deg", "deg", "launch angle above the horizontal, -90 to 90"),
                 optional("launch-height", "m", "height of the launch point", "0"),
                 optional("target-height", "m", "height where the flight ends (on the way down)", "0"), gravityParam()},
                projectile});
  registry.add({"terminal-velocity",
                topic,
                "quadratic-drag terminal velocity v_t = sqrt(2 W / (Cd rho A))",
                {required("weight", "N", "weight W = m g"), required("area", "m^2", "projected frontal area A"),
                 optional("drag-coefficient", "", "Cd (the book's Table 6-5 uses 0.5)", "0.5"),
                 optional("fluid-density", "kg/m^3", "density of the fluid", airDensityDefault)},
                terminalVelocity});
  registry.add(
      {"reynolds-number",
       topic,
       "Rn = rho v L / mu (and the smooth-sphere Cd at that Rn)",
       {required("speed", "m/s", "speed relative to the fluid"),
        required("length", "m", "characteristic length (a sphere's diameter)"),
        optional("density", "kg/m^3", "fluid density", airDensityDefault),
        optional("dynamic-viscosity", "Pa s", "mu (air at 15 C: Sutherland, US Std Atmosphere 1976)", "1.7894e-5")},
       reynolds});
  registry.add({"sphere-drag-coefficient",
                topic,
                "smooth-sphere Cd(Re), Morrison (2013) correlation with the drag crisis",
                {required("reynolds", "", "Reynolds number, > 0")},
                sphereDrag});
  registry.add({"magnus-force",
                topic,
                "Magnus lift 1/2 rho v^2 A C_L(S), S = r w / v, and the book's pi^2 rho r^3 w v",
                {required("speed", "m/s", "air speed"), required("spin-rpm", "rev/min", "spin rate (1 rev/s = 60)"),
                 optional("radius", "m", "ball radius (baseball)", "0.0366"),
                 optional("mass", "kg", "ball mass, for the weight fraction (baseball)", "0.145"), airDensityParam(),
                 gravityParam()},
                magnus});
  registry.add(
      {"ball-flight",
       topic,
       "ball flight with gravity, quadratic drag (relative to the air) and Magnus lift, RK4",
       {required("speed", "m/s", "launch speed"),
        required("angle-deg", "deg", "launch angle above the horizontal"),
        optional("launch-height", "m", "height of the launch point above the ground", "1"),
        optional("backspin-rpm", "rev/min", "spin about the horizontal axis across the shot (+ backspin)", "0"),
        optional("sidespin-rpm", "rev/min", "spin about the vertical axis (+ curves the ball to the right)", "0"),
        optional("mass", "kg", "ball mass (default: baseball)", "0.145"),
        optional("radius", "m", "ball radius (default: baseball)", "0.0366"),
        {"drag-model", "", "constant, smooth-sphere (Cd(Re)) or none", std::string("constant"), ParamKind::text},
        optional("drag-coefficient", "", "Cd for --drag-model constant", "0.35"),
        {"lift-model", "", "sawicki2003 (baseball C_L(S)), constant, idealized (the book's) or none",
         std::string("sawicki2003"), ParamKind::text},
        optional("lift-coefficient", "", "C_L for --lift-model constant", "0.2"),
        optional("tail-wind", "m/s", "wind along the shot (negative: head wind)", "0"),
        optional("cross-wind", "m/s", "wind across the shot, + blowing to the right", "0"),
        airDensityParam(),
        gravityParam(),
        optional("time-step", "s", "RK4 step", "0.001")},
       ballFlight});
  registry.add(
      {"rocket",
       topic,
       "vertical rocket, constant burn rate: v = v0 + u ln(m0/m) - g t, burn-out, coast to the peak",
       {required("initial-mass", "kg", "total mass at ignition m0"),
        required("propellant-mass", "kg", "propellant burnt, less than the initial mass"),
        required("burn-rate", "kg/s", "mdot"), required("exhaust-velocity", "m/s", "u, relative to the rocket"),
        gravityParam(), optional("initial-velocity", "m/s", "0: on a launch pad until thrust exceeds weight", "0"),
        optional("initial-altitude", "m", "altitude at ignition", "0")},
       rocket});
}

} // namespace impetus::cli
