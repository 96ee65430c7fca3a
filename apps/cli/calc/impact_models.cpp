// `impetus calc` entries for chapter 5 (collisions): impulse and average force, the coefficient
// of restitution, 1D and 2D particle impacts, the book's billiard and bat examples, and the
// rigid-body impulse with friction in the plane.
#include "calc/calc.hpp"
#include "calc/values.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/mechanics/impact.hpp>

#include <fmt/core.h>

#include <cmath>
#include <string>

namespace impetus::cli {
namespace {

constexpr const char* topic = "collisions (ch. 5)";

Param required(std::string name, std::string unit, std::string help) {
  return {std::move(name), std::move(unit), std::move(help), std::nullopt};
}
Param withDefault(std::string name, std::string unit, std::string help, std::string value) {
  return {std::move(name), std::move(unit), std::move(help), std::move(value)};
}

/// A finite number parameter. Errors name the parameter as typed (kebab-case fields are passed
/// through by the framework).
double finite(const Args& a, const std::string& name) { return requireFinite(a.number(name), name); }

/// A mass or moment of inertia that may be `inf` (an immovable body): returns its inverse.
double inverseOf(const Args& a, const std::string& name) {
  const double value = a.number(name);
  if (!(value > 0.0) || std::isnan(value)) {
    throwInvalid(name, value, "must be positive (inf for an immovable body)");
  }
  return std::isinf(value) ? 0.0 : 1.0 / value;
}

/// Unit vector at `angleDeg` degrees from +x, counter-clockwise.
Vec2d direction(const Args& a, const std::string& name) {
  const double angle = degToRad(finite(a, name));
  return {std::cos(angle), std::sin(angle)};
}

Vector toVector2(const Vec2d& v) { return {v.x, v.y}; }

Result impulse(const Args& a) {
  const double mass = a.number("mass");
  const double before = a.number("velocity-before");
  const double after = a.number("velocity-after");
  const double duration = a.number("duration");
  const double distance = requireNonNegative(a.number("distance"), "distance");
  const double j = linearImpulse(mass, finite(a, "velocity-after") - finite(a, "velocity-before"));
  Result r;
  r.add("impulse", j, "N s", "J = m (v+ - v-), the change of momentum");
  r.add("momentum_before", mass * before, "kg m/s");
  r.add("momentum_after", mass * after, "kg m/s");
  r.add("average_force", averageImpactForce(j, duration), "N", "J / dt");
  if (distance > 0.0) {
    const double average = distance / duration;
    r.add("average_speed", average, "m/s", "distance / duration");
    const double sum = before + after;
    if (sum > 0.0) {
      r.add("uniform_acceleration_duration", 2.0 * distance / sum, "s",
            "time to cover the distance at constant force: 2 d / (v- + v+)");
    }
    if (average > std::fmax(std::abs(before), std::abs(after))) {
      r.notes.emplace_back(fmt::format(
          "inconsistent inputs: covering {} m in {} s needs an average speed of {:.6g} m/s, faster than both the "
          "initial and the final speed, which no push that only accelerates can do (the book's bullet, Ex 5.1, "
          "has this flaw; its 0.150 kg mass is also implausible: 150 grains = 9.72 g)",
          distance, duration, average));
    }
  }
  return r;
}

Result restitution(const Args& a) {
  const double e = coefficientOfRestitution(a.number("v1-before"), a.number("v2-before"), a.number("v1-after"),
                                            a.number("v2-after"));
  Result r;
  r.add("restitution", e, "", "e = -(v1+ - v2+) / (v1- - v2-)");
  r.add("relative_energy_kept", e * e, "", "fraction of the kinetic energy of relative normal motion kept: e^2");
  if (e > 1.0) {
    r.notes.emplace_back("e > 1: the bodies separate faster than they met; energy was added (not a passive impact)");
  }
  return r;
}

Result restitutionBounce(const Args& a) {
  Result r;
  r.add("restitution", restitutionFromBounce(a.number("drop-height"), a.number("bounce-height")), "",
        "e = sqrt(h_bounce / h_drop)");
  return r;
}

Result impact1D(const Args& a) {
  const double m1 = a.number("mass1");
  const double m2 = a.number("mass2");
  const double v1 = a.number("velocity1");
  const double v2 = a.number("velocity2");
  const Impact1DResult i = resolveImpact1D(m1, v1, m2, v2, a.number("restitution"));
  Result r;
  r.add("velocity1_after", i.velocity1, "m/s");
  r.add("velocity2_after", i.velocity2, "m/s");
  r.add("impulse", i.impulse, "N s", "on body 2 along +x; body 1 gets the opposite");
  r.add("kinetic_energy_lost", i.kineticEnergyLost, "J", "1/2 mu_red (1 - e^2)(v1 - v2)^2");
  if (std::isfinite(m1) && std::isfinite(m2)) {
    r.add("momentum", m1 * v1 + m2 * v2, "kg m/s", "the same before and after");
    r.add("kinetic_energy_before", 0.5 * (m1 * v1 * v1 + m2 * v2 * v2), "J");
    r.add("kinetic_energy_after", 0.5 * (m1 * i.velocity1 * i.velocity1 + m2 * i.velocity2 * i.velocity2), "J");
  }
  if (i.impulse == 0.0) {
    r.notes.emplace_back("no impact: body 1 (behind) is not faster than body 2 (ahead), so they do not close");
  }
  return r;
}

Result impactSpheres2D(const Args& a) {
  const ImpactParticle2D b1{inverseOf(a, "mass1"), {finite(a, "velocity1-x"), finite(a, "velocity1-y")}};
  const ImpactParticle2D b2{inverseOf(a, "mass2"), {finite(a, "velocity2-x"), finite(a, "velocity2-y")}};
  if (b1.inverseMass == 0.0 && b2.inverseMass == 0.0) {
    throwInvalid("mass2", a.number("mass2"), "both bodies are immovable");
  }
  const ParticleImpactResult2D i =
      resolveParticleImpact(b1, b2, direction(a, "normal-angle-deg"), a.number("restitution"));
  Result r;
  r.add("velocity1_after", toVector2(i.velocity1), "m/s");
  r.add("velocity2_after", toVector2(i.velocity2), "m/s");
  r.add("speed1_after", length(i.velocity1), "m/s");
  r.add("speed2_after", length(i.velocity2), "m/s");
  r.add("impulse", i.impulse, "N s", "along n on body 1, -n on body 2");
  r.add("kinetic_energy_lost", i.kineticEnergyLost, "J");
  if (i.impulse == 0.0) {
    r.notes.emplace_back("no impact: the bodies are not approaching along the normal");
  }
  return r;
}

/// Two equal solid balls; ball 1 moves along +x into ball 2 at rest, the line of centres at
/// `angle-deg` from x. With friction, the tangential impulse makes both balls spin about z.
Result billiards(const Args& a) {
  const double diameter = requirePositive(a.number("diameter"), "diameter");
  const double mass = requirePositive(a.number("mass"), "mass");
  const double speed = requireNonNegative(a.number("speed"), "speed");
  const double angleDeg = finite(a, "angle-deg");
  if (std::abs(angleDeg) > 90.0) {
    throwInvalid("angle-deg", angleDeg, "must be between -90 and 90 (the line of centres must face ball 1's motion)");
  }
  const double angle = degToRad(angleDeg);
  const double radius = 0.5 * diameter;
  const Vec3d line{std::cos(angle), std::sin(angle), 0.0}; // centre of ball 1 to centre of ball 2
  ImpactBody ball1;
  ball1.inverseMass = 1.0 / mass;
  ball1.inverseInertiaWorld = Mat33d::identity() * (2.5 / (mass * radius * radius)); // I = 2/5 m r^2
  ball1.velocity = {speed, 0.0, 0.0};
  ball1.offset = line * radius;
  ImpactBody ball2 = ball1;
  ball2.velocity = {};
  ball2.offset = -line * radius;
  const ImpactResult i = resolveImpact(ball1, ball2, -line, a.number("restitution"), a.number("friction"));
  const double normal1 = dot(i.velocity1, line);
  const double tangential1 = i.velocity1.y * line.x - i.velocity1.x * line.y;
  const auto degrees = [](const Vec3d& v) { return radToDeg(std::atan2(v.y, v.x)); };
  Result r;
  r.add("impulse", i.normalImpulse, "N s", "J = (1 + e) m v cos(theta) / 2");
  r.add("impact_parameter", diameter * std::sin(angle), "m", "offset of ball 2's centre from ball 1's path");
  r.add("ball1_velocity", toVector(i.velocity1), "m/s");
  r.add("ball1_normal_speed", normal1, "m/s", "along the line of centres: (1 - e)/2 v cos(theta)");
  r.add("ball1_tangential_speed", std::abs(tangential1), "m/s", "across it: v sin(theta) without friction");
  r.add("ball1_speed", length(i.velocity1), "m/s");
  r.add("ball1_direction_deg", degrees(i.velocity1), "deg", "from +x");
  r.add("ball2_velocity", toVector(i.velocity2), "m/s");
  r.add("ball2_speed", length(i.velocity2), "m/s",
        "along the line of centres without friction: (1 + e)/2 v cos(theta)");
  r.add("ball2_direction_deg", degrees(i.velocity2), "deg", "from +x");
  r.add("kinetic_energy_before", 0.5 * mass * speed * speed, "J");
  r.add("kinetic_energy_lost", i.kineticEnergyLost, "J");
  if (i.frictionImpulse > 0.0) {
    r.add("friction_impulse", i.frictionImpulse, "N s", "min(mu J, the impulse that stops the slip)");
    r.add("ball1_spin", i.angularVelocity1.z, "rad/s", "about the vertical axis z");
    r.add("ball2_spin", i.angularVelocity2.z, "rad/s", "about the vertical axis z");
  }
  return r;
}

/// Ball (body 1) along +x from the pitcher, bat (body 2) along -x; the bat lies along y and is hit
/// at `impact-offset` from its centre of mass, translating without rotation at the instant of
/// impact (with offset 0 it is the book's free particle).
Result batBall(const Args& a) {
  const double ballMass = requirePositive(a.number("ball-mass"), "ball-mass");
  const double batMass = requirePositive(a.number("bat-mass"), "bat-mass");
  const double ballSpeed = finite(a, "ball-speed");
  const double batSpeed = finite(a, "bat-speed");
  const double offset = requireNonNegative(a.number("impact-offset"), "impact-offset");
  const double batInertia = requirePositive(a.number("bat-inertia"), "bat-inertia");
  const ImpactBody2D ball{1.0 / ballMass, 0.0, {ballSpeed, 0.0}, 0.0, {}};
  const ImpactBody2D bat{1.0 / batMass, 1.0 / batInertia, {-batSpeed, 0.0}, 0.0, {0.0, offset}};
  const ImpactResult2D i = resolveImpact(ball, bat, {-1.0, 0.0}, a.number("restitution"));
  const double before = 0.5 * (ballMass * ballSpeed * ballSpeed + batMass * batSpeed * batSpeed);
  const double after = 0.5 * (ballMass * lengthSquared(i.velocity1) + batMass * lengthSquared(i.velocity2) +
                              batInertia * i.angularVelocity2 * i.angularVelocity2);
  Result r;
  r.add("ball_speed_after", -i.velocity1.x, "m/s", "back toward the pitcher");
  r.add("bat_speed_after", -i.velocity2.x, "m/s", "of the bat's centre of mass, along the swing");
  r.add("bat_angular_velocity", i.angularVelocity2, "rad/s", "spin the impact gives the bat");
  r.add("impulse", i.normalImpulse, "N s");
  r.add("effective_bat_mass", 1.0 / (1.0 / batMass + offset * offset / batInertia), "kg",
        "1 / (1/m + d^2 / I): what the ball feels at the impact point");
  r.add("kinetic_energy_before", before, "J");
  r.add("kinetic_energy_after", after, "J");
  r.add("kinetic_energy_lost", i.kineticEnergyLost, "J");
  return r;
}

Result rigidImpact2D(const Args& a) {
  const ImpactBody2D b1{inverseOf(a, "mass1"),
                        inverseOf(a, "inertia1"),
                        {finite(a, "velocity1-x"), finite(a, "velocity1-y")},
                        finite(a, "angular-velocity1"),
                        {finite(a, "offset1-x"), finite(a, "offset1-y")}};
  const ImpactBody2D b2{inverseOf(a, "mass2"),
                        inverseOf(a, "inertia2"),
                        {finite(a, "velocity2-x"), finite(a, "velocity2-y")},
                        finite(a, "angular-velocity2"),
                        {finite(a, "offset2-x"), finite(a, "offset2-y")}};
  if (b1.inverseMass == 0.0 && b1.inverseInertia == 0.0 && b2.inverseMass == 0.0 && b2.inverseInertia == 0.0) {
    throwInvalid("mass2", a.number("mass2"), "both bodies are immovable");
  }
  const Vec2d n = direction(a, "normal-angle-deg");
  const ImpactResult2D i = resolveImpact(b1, b2, n, a.number("restitution"), a.number("friction"));
  const auto contactVelocity = [](const Vec2d& v, double w, const Vec2d& offset) { return v + cross(w, offset); };
  const Vec2d before = contactVelocity(b1.velocity, b1.angularVelocity, b1.offset) -
                       contactVelocity(b2.velocity, b2.angularVelocity, b2.offset);
  const Vec2d after = contactVelocity(i.velocity1, i.angularVelocity1, b1.offset) -
                      contactVelocity(i.velocity2, i.angularVelocity2, b2.offset);
  Result r;
  r.add("velocity1_after", toVector2(i.velocity1), "m/s");
  r.add("angular_velocity1_after", i.angularVelocity1, "rad/s");
  r.add("velocity2_after", toVector2(i.velocity2), "m/s");
  r.add("angular_velocity2_after", i.angularVelocity2, "rad/s");
  r.add("normal_impulse", i.normalImpulse, "N s", "J = -(1+e) v_rn / (1/m1 + 1/m2 + (r1 x n)^2/I1 + (r2 x n)^2/I2)");
  r.add("friction_impulse", i.frictionImpulse, "N s", "min(mu J, the impulse that stops the slip)");
  r.add("impulse", toVector2(i.impulse), "N s", "total on body 1; body 2 gets the opposite");
  r.add("sticking", i.sticking, "", "friction stopped the tangential slip");
  r.add("normal_velocity_before", dot(before, n), "m/s", "relative, at the contact point (< 0: approaching)");
  r.add("normal_velocity_after", dot(after, n), "m/s");
  r.add("tangential_velocity_before", cross(n, before), "m/s", "relative slip along n rotated +90 deg");
  r.add("tangential_velocity_after", cross(n, after), "m/s");
  r.add("kinetic_energy_lost", i.kineticEnergyLost, "J");
  if (i.normalImpulse == 0.0) {
    r.notes.emplace_back("no impact: the contact points are not approaching along the normal");
  }
  return r;
}

} // namespace

void registerImpactModels(Registry& registry) {
  registry.add(
      {"impulse",
       topic,
       "impulse and average force: J = m (v+ - v-), F = J / dt",
       {required("mass", "kg", "mass of the body"), withDefault("velocity-before", "m/s", "velocity before", "0"),
        required("velocity-after", "m/s", "velocity after"), required("duration", "s", "time the impulse acts"),
        withDefault("distance", "m",
                    "distance covered meanwhile (e.g. a barrel), checked for consistency; 0: not given", "0")},
       impulse});
  registry.add({"restitution",
                topic,
                "coefficient of restitution from normal velocities: e = -(v1+ - v2+) / (v1- - v2-)",
                {required("v1-before", "m/s", "body 1 along the line of action, before"),
                 required("v2-before", "m/s", "body 2 along the line of action, before"),
                 required("v1-after", "m/s", "body 1 along the line of action, after"),
                 required("v2-after", "m/s", "body 2 along the line of action, after")},
                restitution});
  registry.add({"restitution-bounce",
                topic,
                "coefficient of restitution from a drop on a fixed floor: e = sqrt(h_bounce / h_drop)",
                {required("drop-height", "m", "height the ball is dropped from"),
                 required("bounce-height", "m", "height it bounces back to")},
                restitutionBounce});
  registry.add({"impact-1d",
                topic,
                "direct central impact on a line, body 1 behind body 2: J = (1+e)(v1-v2) / (1/m1 + 1/m2)",
                {required("mass1", "kg", "body 1 (behind); inf for an immovable body"),
                 required("velocity1", "m/s", "body 1, along +x"),
                 required("mass2", "kg", "body 2 (ahead); inf for an immovable body"),
                 required("velocity2", "m/s", "body 2, along +x"),
                 required("restitution", "", "coefficient of restitution e, 0 (plastic) to 1 (elastic)")},
                impact1D});
  registry.add(
      {"impact-spheres-2d",
       topic,
       "frictionless particles or spheres along a normal n: J = -(1+e)(v_r . n) / (1/m1 + 1/m2)",
       {required("mass1", "kg", "body 1; inf for an immovable body"),
        required("velocity1-x", "m/s", "body 1 velocity, x"), required("velocity1-y", "m/s", "body 1 velocity, y"),
        required("mass2", "kg", "body 2; inf for an immovable body"),
        withDefault("velocity2-x", "m/s", "body 2 velocity, x", "0"),
        withDefault("velocity2-y", "m/s", "body 2 velocity, y", "0"),
        required("normal-angle-deg", "deg", "direction of n, from body 2 toward body 1, from +x"),
        required("restitution", "", "coefficient of restitution e, 0 to 1")},
       impactSpheres2D});
  registry.add(
      {"billiards",
       topic,
       "the book's billiard shot (Ex 5.2): ball 1 into ball 2 at rest, line of centres at an angle",
       {withDefault("diameter", "m", "ball diameter", "0.057"), withDefault("mass", "kg", "mass of each ball", "0.156"),
        withDefault("restitution", "", "coefficient of restitution e", "0.9"),
        withDefault("speed", "m/s", "speed of ball 1 (along +x)", "6"),
        withDefault("angle-deg", "deg", "line of centres from ball 1's path, 0 = head-on", "30"),
        withDefault("friction", "", "ball-ball friction coefficient (0 as in the book); solid balls spin", "0")},
       billiards});
  registry.add(
      {"bat-ball",
       topic,
       "the book's baseball hitting a bat (Ex 5.3), head-on; effective bat mass 1/(1/m + d^2/I) off its centre",
       {withDefault("ball-mass", "kg", "baseball mass", "0.15"),
        withDefault("ball-speed", "m/s", "pitch speed toward the bat", "40"),
        withDefault("bat-mass", "kg", "bat mass (the book's 'weight of 1.02 kg')", "1.02"),
        withDefault("bat-speed", "m/s", "bat speed at the impact point, toward the pitcher", "31"),
        withDefault("restitution", "", "coefficient of restitution e", "0.46"),
        withDefault("impact-offset", "m", "distance along the bat from its centre of mass to the impact point", "0"),
        withDefault("bat-inertia", "kg m^2", "bat's moment of inertia about its centre of mass (used with an offset)",
                    "0.05")},
       batBall});
  registry.add({"rigid-impact-2d",
                topic,
                "planar rigid bodies with friction: linear + angular impulse, friction capped so slip never reverses",
                {required("mass1", "kg", "body 1; inf for an immovable body"),
                 required("inertia1", "kg m^2", "body 1 about its centre of mass; inf for no rotation"),
                 required("velocity1-x", "m/s", "body 1 centre-of-mass velocity, x"),
                 required("velocity1-y", "m/s", "body 1 centre-of-mass velocity, y"),
                 withDefault("angular-velocity1", "rad/s", "body 1 spin, counter-clockwise", "0"),
                 required("offset1-x", "m", "body 1: contact point minus centre of mass, x"),
                 required("offset1-y", "m", "body 1: contact point minus centre of mass, y"),
                 required("mass2", "kg", "body 2; inf for an immovable body"),
                 required("inertia2", "kg m^2", "body 2 about its centre of mass; inf for no rotation"),
                 withDefault("velocity2-x", "m/s", "body 2 centre-of-mass velocity, x", "0"),
                 withDefault("velocity2-y", "m/s", "body 2 centre-of-mass velocity, y", "0"),
                 withDefault("angular-velocity2", "rad/s", "body 2 spin, counter-clockwise", "0"),
                 required("offset2-x", "m", "body 2: contact point minus centre of mass, x"),
                 required("offset2-y", "m", "body 2: contact point minus centre of mass, y"),
                 required("normal-angle-deg", "deg", "direction of n, from body 2 toward body 1, from +x"),
                 required("restitution", "", "coefficient of restitution e, 0 to 1"),
                 withDefault("friction", "", "Coulomb friction coefficient mu during the impact", "0")},
                rigidImpact2D});
}

} // namespace impetus::cli
