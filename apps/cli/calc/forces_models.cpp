// `impetus calc` entries for chapter 3 (forces): gravitation and weight, fluid drag, pressure,
// buoyancy, the spring-damper, torque, and Coulomb friction with its table of material pairs.
#include "calc/calc.hpp"
#include "calc/values.hpp"

#include <impetus/error.hpp>
#include <impetus/mechanics/forces.hpp>
#include <impetus/mechanics/friction.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

namespace impetus::cli {
namespace {

constexpr const char* topic = "forces (ch. 3)";

Param gravityParam() { return {"gravity", "m/s^2", "gravitational acceleration g", "9.80665"}; }

// ---- Friction coefficients: from --material or given directly --------------------------------

std::vector<Param> frictionParams() {
  return {{"material", "", "a pair from the table (impetus calc friction-materials), e.g. rubber-concrete-dry",
           std::string{}, ParamKind::text},
          {"static-coefficient", "", "mu_s, instead of --material", std::string{}, ParamKind::text},
          {"kinetic-coefficient", "", "mu_k <= mu_s, instead of --material", std::string{}, ParamKind::text}};
}

struct Coefficients {
  double staticCoefficient;
  double kineticCoefficient;
};

Coefficients coefficients(const Args& a, bool kineticNeeded, Result& r) {
  const std::optional<double> mus = optionalNumber(a, "static-coefficient");
  const std::optional<double> muk = kineticNeeded ? optionalNumber(a, "kinetic-coefficient") : std::nullopt;
  const std::string& name = a.text("material");
  if (!name.empty()) {
    if (mus || muk) {
      throw Error("material", "give --material or the coefficients, not both");
    }
    const FrictionMaterial& m = frictionMaterial(name);
    r.notes.push_back(std::string(m.description) + ": typical values from " + std::string(m.source));
    return {m.staticCoefficient, m.kineticCoefficient};
  }
  if (!mus) {
    throw Error("staticCoefficient", "give --material or --static-coefficient");
  }
  if (kineticNeeded && !muk) {
    throw Error("kineticCoefficient", "give --material or --kinetic-coefficient");
  }
  return {*mus, muk.value_or(*mus)};
}

/// "rubber-concrete-dry" -> "rubber_concrete_dry".
std::string snakeCase(std::string_view name) {
  std::string s(name);
  std::replace(s.begin(), s.end(), '-', '_');
  return s;
}

// ---- Models --------------------------------------------------------------------------------------

Result gravitation(const Args& a) {
  Result r;
  r.add("force",
        gravitationalForce(a.number("mass1"), a.number("mass2"), a.number("distance"),
                           a.number("gravitational-constant")),
        "N", "G m1 m2 / r^2, attractive");
  return r;
}

Result gravityAltitude(const Args& a) {
  Result r;
  const double g = gravityAtAltitude(a.number("altitude"), a.number("body-mass"), a.number("body-radius"),
                                     a.number("gravitational-constant"));
  r.add("gravity", g, "m/s^2", "G M / (R + h)^2");
  r.notes.emplace_back("pure gravitation: the Earth's rotation lowers the measured g by up to 0.034 m/s^2");
  return r;
}

Result weightModel(const Args& a) {
  Result r;
  r.add("weight", weight(a.number("mass"), a.number("gravity")), "N", "m g");
  return r;
}

Result dragForce(const Args& a) {
  const Vec3d v = vector3(a, "velocity");
  const Vec3d wind = vector3(a, "fluid-velocity");
  const Vec3d f = fluidDragForce(v, a.number("density"), a.number("area"), a.number("drag-coefficient"), wind);
  Result r;
  r.add("force", toVector(f), "N", "-1/2 rho A Cd |v - w| (v - w)");
  r.add("magnitude", length(f), "N");
  r.add("relative_speed", length(v - wind), "m/s", "|v - w|, speed through the fluid");
  r.add("drag_constant", quadraticDragConstant(a.number("density"), a.number("area"), a.number("drag-coefficient")),
        "kg/m", "C = 1/2 rho A Cd");
  return r;
}

Result idealDrag(const Args& a) {
  const Vec3d v = vector3(a, "velocity");
  const Vec3d wind = vector3(a, "fluid-velocity");
  const std::string& law = a.text("law");
  Vec3d f;
  if (law == "linear") {
    f = linearDragForce(v, a.number("drag-constant"), wind);
  } else if (law == "quadratic") {
    f = quadraticDragForce(v, a.number("drag-constant"), wind);
  } else {
    throw Error("law", "--law = '" + law + "': expected linear or quadratic");
  }
  Result r;
  r.add("force", toVector(f), "N", law == "linear" ? "-C (v - w)" : "-C |v - w| (v - w)");
  r.add("magnitude", length(f), "N");
  return r;
}

Result pressureModel(const Args& a) {
  Result r;
  r.add("force", pressureForce(a.number("pressure"), a.number("area")), "N", "P A, normal to the area");
  return r;
}

Result hydrostatic(const Args& a) {
  const double p =
      hydrostaticPressure(a.number("density"), a.number("depth"), a.number("gravity"), a.number("surface-pressure"));
  Result r;
  r.add("pressure", p, "Pa", "P0 + rho g h");
  return r;
}

Result buoyancy(const Args& a) {
  const ImmersedBody b =
      immersedBody(a.number("body-density"), a.number("fluid-density"), a.number("volume"), a.number("gravity"));
  Result r;
  r.add("buoyant_force", b.buoyantForce, "N", "rho_fluid g V, fully submerged");
  r.add("weight", b.weight, "N", "rho_body g V");
  r.add("net_force", b.netForce, "N", "upward positive, fully submerged");
  r.add("submerged_fraction", b.submergedFraction, "", "at equilibrium (rho_body / rho_fluid when floating)");
  r.add("flotation", std::string(b.flotation == Flotation::floats    ? "floats"
                                 : b.flotation == Flotation::neutral ? "neutral"
                                                                     : "sinks"));
  return r;
}

Result springDamper(const Args& a) {
  const SpringDamper s{a.number("stiffness"), a.number("damping"), a.number("rest-length")};
  const Vec3d p1 = vector3(a, "position1");
  const Vec3d v1 = vector3(a, "velocity1");
  const Vec3d p2 = vector3(a, "position2");
  const Vec3d v2 = vector3(a, "velocity2");
  const Vec3d f = springDamperForce(s, p1, v1, p2, v2);
  Result r;
  r.add("force_on_1", toVector(f), "N");
  r.add("force_on_2", toVector(-f), "N", "equal and opposite");
  r.add("length", length(p1 - p2), "m", "|p1 - p2|");
  r.add("extension", length(p1 - p2) - s.restLength, "m", "length - rest length (negative: compressed)");
  r.add("power", dot(f, v1 - v2), "W", "F1 . (v1 - v2): the rate of spring energy change plus damper loss");
  if (length(p1 - p2) == 0.0) {
    r.notes.emplace_back("coincident points: the direction is undefined and taken as zero, so the force is zero");
  }
  return r;
}

Result torqueModel(const Args& a) {
  const Vec3d arm = vector3(a, "arm");
  const Vec3d force = vector3(a, "force");
  const Vec3d m = torque(arm, force);
  Result r;
  r.add("torque", toVector(m), "N m", "r x F");
  r.add("magnitude", length(m), "N m", "F d");
  const double f = length(force);
  if (f > 0.0) {
    r.add("moment_arm", length(m) / f, "m", "d, the perpendicular distance to the line of action");
  }
  return r;
}

Result friction(const Args& a) {
  Result r;
  const Coefficients c = coefficients(a, true, r);
  const PushedBlock b = pushBlock(a.number("mass"), a.number("push-force"), c.staticCoefficient, c.kineticCoefficient,
                                  a.number("gravity"));
  r.add("slides", b.slides, "", "|push| > mu_s m g");
  r.add("friction_force", b.frictionForce, "N", "opposing the push");
  r.add("normal_force", b.normalForce, "N", "m g");
  r.add("max_static_friction", c.staticCoefficient * b.normalForce, "N", "mu_s N");
  r.add("acceleration", b.acceleration, "m/s^2");
  return r;
}

Result incline(const Args& a) {
  Result r;
  const Coefficients c = coefficients(a, true, r);
  const double deg = a.number("incline-angle-deg");
  if (!(deg >= 0.0 && deg <= 90.0)) {
    throwInvalid("inclineAngleDeg", deg, "must be in [0, 90] degrees");
  }
  const BlockOnIncline b = blockOnIncline(a.number("mass"), deg * std::numbers::pi / 180.0, c.staticCoefficient,
                                          c.kineticCoefficient, a.number("gravity"));
  r.add("slides", b.slides, "", "tan(theta) > mu_s");
  r.add("acceleration", b.acceleration, "m/s^2", "down the slope: g (sin - mu_k cos)");
  r.add("normal_force", b.normalForce, "N", "m g cos(theta)");
  r.add("friction_force", b.frictionForce, "N", "up the slope");
  r.add("angle_of_repose_deg", angleOfRepose(c.staticCoefficient) * 180.0 / std::numbers::pi, "deg", "atan(mu_s)");
  return r;
}

Result repose(const Args& a) {
  Result r;
  const Coefficients c = coefficients(a, false, r);
  const double theta = angleOfRepose(c.staticCoefficient);
  r.add("angle", theta, "rad", "atan(mu_s)");
  r.add("angle_deg", theta * 180.0 / std::numbers::pi, "deg");
  return r;
}

Result materialsList(const Args&) {
  Result r;
  for (const FrictionMaterial& m : frictionMaterials()) {
    r.add(snakeCase(m.name), Vector{m.staticCoefficient, m.kineticCoefficient}, "",
          "(mu_s, mu_k) " + std::string(m.description));
  }
  r.notes.emplace_back("(mu_s, mu_k) for clean surfaces; typical textbook values that scatter by 20 % or more");
  r.notes.emplace_back("sources: Serway & Jewett, Physics for Scientists and Engineers, Table 5.1; OpenStax "
                       "College Physics (2012), Table 5.1. Not from the book, whose friction table was lost");
  return r;
}

} // namespace

void registerForceModels(Registry& registry) {
  const Param g{"gravitational-constant", "m^3/(kg s^2)", "G (CODATA 2018; the book used 6.673e-11)", "6.6743e-11"};
  registry.add({"gravitation",
                topic,
                "Newton's gravitation F = G m1 m2 / r^2",
                {{"mass1", "kg", "first mass", std::nullopt},
                 {"mass2", "kg", "second mass", std::nullopt},
                 {"distance", "m", "between the centres", std::nullopt},
                 g},
                gravitation});
  registry.add({"gravity-at-altitude",
                topic,
                "g(h) = G M / (R + h)^2 (Earth by default)",
                {{"altitude", "m", "height above the surface", "0"},
                 {"body-mass", "kg", "mass of the planet", "5.9722e24"},
                 {"body-radius", "m", "radius of the planet (Earth's mean radius by default)", "6371008.8"},
                 g},
                gravityAltitude});
  registry.add({"weight", topic, "W = m g", {{"mass", "kg", "mass", std::nullopt}, gravityParam()}, weightModel});
  registry.add({"drag-force",
                topic,
                "fluid drag F = -1/2 rho A Cd |v - w| (v - w), w the fluid's velocity",
                {vectorParam("velocity", "m/s", "velocity of the body", std::nullopt),
                 vectorParam("fluid-velocity", "m/s", "velocity of the fluid (wind, current)", "0,0,0"),
                 {"density", "kg/m^3", "fluid density (air at sea level by default)", "1.225"},
                 {"area", "m^2", "reference (frontal) area", std::nullopt},
                 {"drag-coefficient", "", "Cd", std::nullopt}},
                dragForce});
  registry.add({"ideal-drag-force",
                topic,
                "idealized drag: linear F = -C (v - w) or quadratic F = -C |v - w| (v - w)",
                {vectorParam("velocity", "m/s", "velocity of the body", std::nullopt),
                 vectorParam("fluid-velocity", "m/s", "velocity of the fluid (wind, current)", "0,0,0"),
                 {"drag-constant", "N s/m or kg/m", "C (N s/m for linear, kg/m for quadratic)", std::nullopt},
                 {"law", "", "linear or quadratic", "quadratic", ParamKind::text}},
                idealDrag});
  registry.add({"pressure-force",
                topic,
                "F = P A",
                {{"pressure", "Pa", "uniform pressure", std::nullopt}, {"area", "m^2", "flat area", std::nullopt}},
                pressureModel});
  registry.add({"hydrostatic-pressure",
                topic,
                "P = P0 + rho g h",
                {{"density", "kg/m^3", "fluid density (fresh water by default)", "999.97"},
                 {"depth", "m", "below the surface", std::nullopt},
                 gravityParam(),
                 {"surface-pressure", "Pa", "P0 (0: gauge pressure; 101325: absolute under air)", "0"}},
                hydrostatic});
  registry.add({"buoyancy",
                topic,
                "Archimedes F_B = rho_fluid g V; floating fraction rho_body / rho_fluid",
                {{"body-density", "kg/m^3", "density of the body", std::nullopt},
                 {"fluid-density", "kg/m^3", "density of the fluid (fresh water by default)", "999.97"},
                 {"volume", "m^3", "volume of the body", "1"},
                 gravityParam()},
                buoyancy});
  registry.add({"spring-damper",
                topic,
                "F1 = -[ks (L - r) + kd (v1 - v2).L/L] L/L with L = p1 - p2; F2 = -F1",
                {{"stiffness", "N/m", "ks", std::nullopt},
                 {"damping", "N s/m", "kd", "0"},
                 {"rest-length", "m", "r", std::nullopt},
                 vectorParam("position1", "m", "point 1", std::nullopt),
                 vectorParam("velocity1", "m/s", "velocity of point 1", "0,0,0"),
                 vectorParam("position2", "m", "point 2", std::nullopt),
                 vectorParam("velocity2", "m/s", "velocity of point 2", "0,0,0")},
                springDamper});
  registry.add(
      {"torque",
       topic,
       "M = r x F",
       {vectorParam("arm", "m", "r, from the axis (or centre of gravity) to the point of application", std::nullopt),
        vectorParam("force", "N", "F", std::nullopt)},
       torqueModel});
  std::vector<Param> frictionInputs{{"mass", "kg", "mass of the block", std::nullopt},
                                    {"push-force", "N", "horizontal push through the centre of gravity", std::nullopt},
                                    gravityParam()};
  for (Param& p : frictionParams()) {
    frictionInputs.push_back(std::move(p));
  }
  registry.add({"friction", topic,
                "block at rest pushed on level ground: held if |F| <= mu_s m g, else slides against mu_k m g",
                frictionInputs, friction});
  std::vector<Param> inclineInputs{
      {"mass", "kg", "mass of the block", "1"},
      {"incline-angle-deg", "deg", "slope angle above the horizontal, 0 to 90", std::nullopt},
      gravityParam()};
  for (Param& p : frictionParams()) {
    inclineInputs.push_back(std::move(p));
  }
  registry.add({"incline", topic, "block released on a slope: slides if tan(theta) > mu_s, a = g (sin - mu_k cos)",
                inclineInputs, incline});
  std::vector<Param> reposeInputs = frictionParams();
  reposeInputs.pop_back(); // no kinetic coefficient
  registry.add(
      {"angle-of-repose", topic, "steepest slope that holds a body: theta = atan(mu_s)", reposeInputs, repose});
  registry.add({"friction-materials",
                topic,
                "the table of friction coefficients (mu_s, mu_k) of material pairs",
                {},
                materialsList});
}

} // namespace impetus::cli
