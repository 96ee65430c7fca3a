// `impetus calc` entries for chapter 2 (kinematics): the constant-acceleration relations,
// straight-line motion with quadratic drag, rotation with constant angular acceleration, a point
// on a circle and a point on a rotating rigid body.
#include "calc/calc.hpp"
#include "calc/values.hpp"

#include <impetus/error.hpp>
#include <impetus/mechanics/kinematics.hpp>

#include <algorithm>
#include <charconv>
#include <optional>
#include <string>

namespace impetus::cli {
namespace {

constexpr const char* topic = "kinematics (ch. 2)";

Result constantAcceleration(const Args& a) {
  ConstantAccelerationKnowns k;
  k.initialVelocity = optionalNumber(a, "initial-velocity");
  k.finalVelocity = optionalNumber(a, "final-velocity");
  k.acceleration = optionalNumber(a, "acceleration");
  k.time = optionalNumber(a, "time");
  k.displacement = optionalNumber(a, "displacement");
  const int given = int(k.initialVelocity.has_value()) + int(k.finalVelocity.has_value()) +
                    int(k.acceleration.has_value()) + int(k.time.has_value()) + int(k.displacement.has_value());
  if (given != 3) {
    throw Error("knowns", "give exactly three of --initial-velocity, --final-velocity, --acceleration, --time, "
                          "--displacement (" +
                              std::to_string(given) + " given)");
  }
  const ConstantAccelerationMotion m = solveConstantAcceleration(k);
  Result r;
  r.add("initial_velocity", m.initialVelocity, "m/s", "v1");
  r.add("final_velocity", m.finalVelocity, "m/s", "v2");
  r.add("acceleration", m.acceleration, "m/s^2", "a");
  r.add("time", m.time, "s", "t");
  r.add("displacement", m.displacement, "m", "s2 - s1");
  r.notes.emplace_back("where a square root leaves the sign open, the motion that reaches its end first is taken");
  return r;
}

Result quadraticDrag(const Args& a) {
  const double s1 = a.number("initial-position");
  const double v1 = a.number("initial-velocity");
  const double k = a.number("drag-per-unit-mass");
  const LinearState state = quadraticDragMotion(s1, v1, k, a.number("time"));
  Result r;
  r.add("position", state.position, "m", "at --time");
  r.add("velocity", state.velocity, "m/s", "at --time");
  if (const std::optional<double> target = optionalNumber(a, "position")) {
    r.add("velocity_at_position", quadraticDragVelocityAt(s1, v1, k, *target), "m/s", "when passing --position");
    r.add("time_to_position", quadraticDragTimeTo(s1, v1, k, *target), "s", "to reach --position");
  }
  if (v1 < 0.0 && k > 0.0) {
    r.notes.emplace_back("the book's v1/(1 + k v1 t) and ln(1 + k v1 t)/k hold for v1 >= 0 only; these use |v1| "
                         "(drag a = -k|v|v)");
  }
  return r;
}

Result angularMotion(const Args& a) {
  const AngularState s = angularMotionAfterTime(a.number("angle"), a.number("angular-velocity"),
                                                a.number("angular-acceleration"), a.number("time"));
  Result r;
  r.add("angle", s.angle, "rad", "Omega2 = Omega1 + omega1 t + 1/2 alpha t^2");
  r.add("angular_velocity", s.angularVelocity, "rad/s", "omega2 = omega1 + alpha t");
  return r;
}

Result circle(const Args& a) {
  const CircularMotion c =
      circularMotion(a.number("radius"), a.number("angular-velocity"), a.number("angular-acceleration"));
  Result r;
  r.add("tangential_speed", c.tangentialSpeed, "m/s", "r omega");
  r.add("tangential_acceleration", c.tangentialAcceleration, "m/s^2", "r alpha");
  r.add("centripetal_acceleration", c.centripetalAcceleration, "m/s^2", "r omega^2, toward the axis");
  r.add("acceleration", c.acceleration, "m/s^2", "magnitude");
  return r;
}

Result pointOnBody(const Args& a) {
  BodyMotion body;
  body.velocity = vector3(a, "velocity");
  body.acceleration = vector3(a, "acceleration");
  body.angularVelocity = vector3(a, "angular-velocity");
  body.angularAcceleration = vector3(a, "angular-acceleration");
  const PointMotion p = pointOnRotatingBody(body, vector3(a, "offset"));
  Result r;
  r.add("velocity", toVector(p.velocity), "m/s", "v_cg + omega x r");
  r.add("acceleration", toVector(p.acceleration), "m/s^2", "a_cg + alpha x r + omega x (omega x r)");
  r.add("tangential_acceleration", toVector(p.tangentialAcceleration), "m/s^2", "alpha x r");
  r.add("centripetal_acceleration", toVector(p.centripetalAcceleration), "m/s^2", "omega x (omega x r)");
  return r;
}

} // namespace

void registerKinematicsModels(Registry& registry) {
  registry.add({"constant-acceleration",
                topic,
                "any two of v1, v2, a, t, s from the other three: v2 = v1 + a t, s = v1 t + a t^2/2, "
                "v2^2 = v1^2 + 2 a s",
                {optionalParam("initial-velocity", "m/s", "v1"), optionalParam("final-velocity", "m/s", "v2"),
                 optionalParam("acceleration", "m/s^2", "a"), optionalParam("time", "s", "elapsed time t >= 0"),
                 optionalParam("displacement", "m", "s2 - s1")},
                constantAcceleration});
  registry.add({"quadratic-drag-motion",
                topic,
                "straight line, a = -k|v|v: v = v1/(1 + k|v1|t), s = s1 + sgn(v1) ln(1 + k|v1|t)/k",
                {{"initial-position", "m", "s1", "0"},
                 {"initial-velocity", "m/s", "v1 (either sign)", std::nullopt},
                 {"drag-per-unit-mass", "1/m", "k = C/m = rho Cd A / (2 m) >= 0", std::nullopt},
                 {"time", "s", "elapsed time >= 0", std::nullopt},
                 optionalParam("position", "m", "a position ahead: the velocity there and the time to reach it")},
                quadraticDrag});
  registry.add({"angular-motion",
                topic,
                "constant angular acceleration: omega2 = omega1 + alpha t, Omega2 = Omega1 + omega1 t + alpha t^2/2",
                {{"angle", "rad", "initial angle Omega1", "0"},
                 {"angular-velocity", "rad/s", "initial angular velocity omega1", "0"},
                 {"angular-acceleration", "rad/s^2", "alpha", std::nullopt},
                 {"time", "s", "elapsed time >= 0", std::nullopt}},
                angularMotion});
  registry.add({"circular-motion",
                topic,
                "point at radius r: v = r omega, a_t = r alpha, a_n = r omega^2",
                {{"radius", "m", "distance from the axis", std::nullopt},
                 {"angular-velocity", "rad/s", "omega", std::nullopt},
                 {"angular-acceleration", "rad/s^2", "alpha", "0"}},
                circle});
  registry.add({"point-on-rotating-body",
                topic,
                "v_P = v_cg + omega x r, a_P = a_cg + alpha x r + omega x (omega x r) (plane: use z components)",
                {vectorParam("velocity", "m/s", "velocity of the centre of gravity", "0,0,0"),
                 vectorParam("acceleration", "m/s^2", "acceleration of the centre of gravity", "0,0,0"),
                 vectorParam("angular-velocity", "rad/s", "omega", std::nullopt),
                 vectorParam("angular-acceleration", "rad/s^2", "alpha", "0,0,0"),
                 vectorParam("offset", "m", "r, from the centre of gravity to the point, world axes", std::nullopt)},
                pointOnBody});
}

} // namespace impetus::cli
