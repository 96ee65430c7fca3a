// The input validation audit of the mechanics models (docs/reliability.md, "Input validation"):
// every function of chapters 2-6 refuses a NaN or an infinity in any of its number parameters
// with an impetus::Error naming that parameter, and the values that make no physical sense
// (negative masses, zero lengths, restitution above 1, ...) likewise.
#include "support/validation_table.hpp"

#include <impetus/mechanics/mechanics.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace impetus {
namespace {

using impetus::testing::expectRejected;
using impetus::testing::infd;
using impetus::testing::nand;
using impetus::testing::Rejection;

/// Rows for a function of N doubles: for each parameter, NaN and +infinity (unless listed in
/// `infinityAllowed`) with the other parameters at their valid values, each expected to be
/// refused naming the parameter. The valid call itself must succeed.
template <std::size_t N, class F> std::vector<Rejection> everyParameter(F f, const double (&validValues)[N],
                                                                        const char* const (&names)[N],
                                                                        std::set<std::size_t> infinityAllowed = {}) {
  const std::array<double, N> valid = std::to_array(validValues);
  EXPECT_NO_THROW((void)std::apply(f, valid)) << names[0];
  std::vector<Rejection> rows;
  for (std::size_t i = 0; i < N; ++i) {
    for (const double bad : {nand, infd}) {
      if (bad == infd && infinityAllowed.contains(i)) {
        continue;
      }
      std::array<double, N> args = valid;
      args[i] = bad;
      rows.push_back({names[i], formatValue(bad), [f, args] { (void)std::apply(f, args); }});
    }
  }
  return rows;
}

/// Concatenates row lists.
std::vector<Rejection> operator+(std::vector<Rejection> a, const std::vector<Rejection>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(MechanicsValidation, kinematics) {
  expectRejected(
      everyParameter([](double v, double a, double t) { return finalVelocityAfterTime(v, a, t); }, {1, 2, 3},
                     {"initialVelocity", "acceleration", "time"}) +
      everyParameter([](double v, double a, double s) { return finalVelocityAfterDisplacement(v, a, s); }, {1, 2, 3},
                     {"initialVelocity", "acceleration", "displacement"}) +
      everyParameter([](double v, double a, double t) { return displacementAfterTime(v, a, t); }, {1, 2, 3},
                     {"initialVelocity", "acceleration", "time"}) +
      everyParameter([](double v1, double v2, double a) { return displacementBetweenVelocities(v1, v2, a); }, {1, 2, 3},
                     {"initialVelocity", "finalVelocity", "acceleration"}) +
      everyParameter([](double v1, double v2, double t) { return displacementFromMeanVelocity(v1, v2, t); }, {1, 2, 3},
                     {"initialVelocity", "finalVelocity", "time"}) +
      everyParameter([](double v1, double v2, double a) { return timeBetweenVelocities(v1, v2, a); }, {1, 2, 3},
                     {"initialVelocity", "finalVelocity", "acceleration"}) +
      everyParameter([](double v, double a, double s) { return timeToDisplacement(v, a, s); }, {1, 2, 3},
                     {"initialVelocity", "acceleration", "displacement"}) +
      everyParameter([](double v1, double v2, double t) { return accelerationFromVelocityChange(v1, v2, t); },
                     {1, 2, 3}, {"initialVelocity", "finalVelocity", "time"}) +
      everyParameter([](double v1, double v2, double s) { return accelerationOverDisplacement(v1, v2, s); }, {1, 2, 3},
                     {"initialVelocity", "finalVelocity", "displacement"}) +
      everyParameter([](double v, double a, double t) { return initialVelocityBeforeTime(v, a, t); }, {5, 1, 2},
                     {"finalVelocity", "acceleration", "time"}) +
      everyParameter([](double v, double a, double s) { return initialVelocityBeforeDisplacement(v, a, s); }, {5, 1, 2},
                     {"finalVelocity", "acceleration", "displacement"}) +
      everyParameter([](double s, double v, double k, double t) { return quadraticDragMotion(s, v, k, t); },
                     {0, 10, 0.1, 2}, {"initialPosition", "initialVelocity", "dragPerUnitMass", "time"}) +
      everyParameter([](double s, double v, double k, double p) { return quadraticDragVelocityAt(s, v, k, p); },
                     {0, 10, 0.1, 2}, {"initialPosition", "initialVelocity", "dragPerUnitMass", "position"}) +
      everyParameter([](double s, double v, double k, double p) { return quadraticDragTimeTo(s, v, k, p); },
                     {0, 10, 0.1, 2}, {"initialPosition", "initialVelocity", "dragPerUnitMass", "position"}) +
      everyParameter([](double q, double w, double a, double t) { return angularMotionAfterTime(q, w, a, t); },
                     {0, 1, 2, 3}, {"angle", "angularVelocity", "angularAcceleration", "time"}) +
      everyParameter([](double w, double a, double q) { return angularVelocityAfterRotation(w, a, q); }, {1, 2, 3},
                     {"angularVelocity", "angularAcceleration", "rotation"}) +
      everyParameter([](double r, double w, double a) { return circularMotion(r, w, a); }, {1, 2, 3},
                     {"radius", "angularVelocity", "angularAcceleration"}) +
      std::vector<Rejection>{
          {"time", "-1", [] { (void)finalVelocityAfterTime(1, 2, -1); }},
          {"time", "-1", [] { (void)quadraticDragMotion(0, 1, 0.1, -1); }},
          {"dragPerUnitMass", "-1", [] { (void)quadraticDragMotion(0, 1, -1, 1); }},
          {"radius", "-1", [] { (void)circularMotion(-1, 1, 0); }},
          {"knowns", "2",
           [] {
             (void)solveConstantAcceleration({1.0, 2.0, {}, {}, {}});
           }},
          {"time", "nan",
           [] {
             (void)solveConstantAcceleration({1.0, 2.0, {}, nand, {}});
           }},
          {"offset.x", "nan",
           [] {
             (void)pointOnRotatingBody(PlanarBodyMotion{}, Vec2d{nand, 0});
           }},
          {"angularVelocity.z", "inf",
           [] {
             (void)pointOnRotatingBody(BodyMotion{{}, {}, {0, 0, infd}, {}}, Vec3d{1, 0, 0});
           }},
      });
}

TEST(MechanicsValidation, forces_and_friction) {
  expectRejected(
      everyParameter([](double m1, double m2, double r) { return gravitationalForce(m1, m2, r); }, {1, 2, 3},
                     {"mass1", "mass2", "distance"}) +
      everyParameter([](double m, double g) { return weight(m, g); }, {1, 9.81}, {"mass", "gravity"}) +
      everyParameter([](double h, double m, double r) { return gravityAtAltitude(h, m, r); }, {100, 6e24, 6.4e6},
                     {"altitude", "bodyMass", "bodyRadius"}) +
      everyParameter([](double rho, double a, double cd) { return quadraticDragConstant(rho, a, cd); },
                     {1.2, 0.5, 0.47}, {"density", "area", "dragCoefficient"}) +
      everyParameter([](double p, double a) { return pressureForce(p, a); }, {1e5, 2}, {"pressure", "area"}) +
      everyParameter([](double rho, double h, double g, double p0) { return hydrostaticPressure(rho, h, g, p0); },
                     {1000, 2, 9.81, 1e5}, {"density", "depth", "gravity", "surfacePressure"}) +
      everyParameter([](double rho, double v, double g) { return buoyantForce(rho, v, g); }, {1000, 0.1, 9.81},
                     {"fluidDensity", "displacedVolume", "gravity"}) +
      everyParameter([](double rb, double rf, double v, double g) { return immersedBody(rb, rf, v, g); },
                     {500, 1000, 0.1, 9.81}, {"bodyDensity", "fluidDensity", "volume", "gravity"}) +
      everyParameter([](double f, double n, double s, double k) { return frictionAtRest(f, n, s, k); },
                     {10, 100, 0.5, 0.4}, {"appliedForce", "normalForce", "staticCoefficient", "kineticCoefficient"}) +
      everyParameter([](double v, double n, double k) { return kineticFrictionForce(v, n, k); }, {1, 100, 0.4},
                     {"velocity", "normalForce", "kineticCoefficient"}) +
      everyParameter([](double m, double f, double s, double k, double g) { return pushBlock(m, f, s, k, g); },
                     {10, 20, 0.5, 0.4, 9.81},
                     {"mass", "pushForce", "staticCoefficient", "kineticCoefficient", "gravity"}) +
      everyParameter([](double s) { return angleOfRepose(s); }, {0.5}, {"staticCoefficient"}) +
      everyParameter([](double m, double a, double s, double k, double g) { return blockOnIncline(m, a, s, k, g); },
                     {10, 0.3, 0.5, 0.4, 9.81},
                     {"mass", "inclineAngle", "staticCoefficient", "kineticCoefficient", "gravity"}) +
      std::vector<Rejection>{
          {"mass1", "-1", [] { (void)gravitationalForce(-1, 1, 1); }},
          {"distance", "0", [] { (void)gravitationalForce(1, 1, 0); }},
          {"mass", "-1", [] { (void)weight(-1); }},
          {"bodyRadius", "0", [] { (void)gravityAtAltitude(0, 1, 0); }},
          {"area", "-1", [] { (void)quadraticDragConstant(1, -1, 1); }},
          {"dragConstant", "-1",
           [] {
             (void)linearDragForce({1, 0, 0}, -1);
           }},
          {"velocity.x", "nan",
           [] {
             (void)quadraticDragForce({nand, 0, 0}, 1);
           }},
          {"fluidVelocity.z", "inf",
           [] {
             (void)fluidDragForce({}, 1, 1, 1, {0, 0, infd});
           }},
          {"density", "-1", [] { (void)hydrostaticPressure(-1, 1); }},
          {"fluidDensity", "0", [] { (void)immersedBody(1, 0, 1); }},
          {"stiffness", "-1",
           [] {
             (void)springDamperForce(SpringDamper{-1, 0, 1}, Vec3d{}, {}, {1, 0, 0}, {});
           }},
          {"restLength", "nan",
           [] {
             (void)springDamperForce(SpringDamper{1, 0, nand}, Vec2d{}, {}, Vec2d{1, 0}, {});
           }},
          {"position2.x", "inf",
           [] {
             (void)springDamperForce(SpringDamper{1, 0, 1}, Vec3d{}, {}, {infd, 0, 0}, {});
           }},
          {"arm.x", "nan",
           [] {
             (void)torque(Vec3d{nand, 0, 0}, Vec3d{});
           }},
          {"force.y", "inf",
           [] {
             (void)torque(Vec2d{}, Vec2d{0, infd});
           }},
          {"normalForce", "-1", [] { (void)frictionAtRest(1, -1, 0.5, 0.4); }},
          {"kineticCoefficient", "0.6", [] { (void)frictionAtRest(1, 10, 0.5, 0.6); }},
          {"staticCoefficient", "-1", [] { (void)angleOfRepose(-1); }},
          {"mass", "0", [] { (void)pushBlock(0, 1, 0.5, 0.4); }},
      });
}

TEST(MechanicsValidation, projectiles_aiming_and_cannon) {
  const auto launch = [](auto change) {
    return [change] {
      VacuumLaunch l{20, 0.5, 0, 9.81};
      change(l);
      (void)vacuumFlight(l);
    };
  };
  expectRejected(
      everyParameter([](double v, double h, double g) { return vehicleDrop(v, h, g); }, {20, 10, 9.81},
                     {"speed", "height", "gravity"}) +
      everyParameter([](double v, double h0, double h1, double g) { return maximumRangeAngle(v, h0, h1, g); },
                     {20, 1, 0, 9.81}, {"speed", "launchHeight", "targetHeight", "gravity"}) +
      everyParameter([](double w, double cd, double rho, double a) { return terminalVelocityQuadratic(w, cd, rho, a); },
                     {700, 1, 1.2, 0.7}, {"weight", "dragCoefficient", "fluidDensity", "area"}) +
      everyParameter([](double w, double c) { return terminalVelocityLinear(w, c); }, {700, 10},
                     {"weight", "linearDragCoefficient"}) +
      everyParameter([](double d, double h, double v, double g) { return launchAngles(d, h, v, g); }, {10, 1, 20, 9.81},
                     {"distance", "height", "speed", "gravity"}) +
      everyParameter([](double d, double h, double g) { return minimumLaunchSpeed(d, h, g); }, {10, 1, 9.81},
                     {"distance", "height", "gravity"}) +
      everyParameter([](double a, double z) { return barrelDirection(a, z); }, {0.5, 0.2}, {"altitude", "azimuth"}) +
      everyParameter([](double d, double v, double g) { return rifleShot(d, v, g); }, {100, 800, 9.81},
                     {"distance", "muzzleSpeed", "gravity"}) +
      std::vector<Rejection>{
          {"speed", "-1", launch([](VacuumLaunch& l) { l.speed = -1; })},
          {"angle", "2", launch([](VacuumLaunch& l) { l.angle = 2; })},
          {"launchHeight", "nan", launch([](VacuumLaunch& l) { l.launchHeight = nand; })},
          {"gravity", "0", launch([](VacuumLaunch& l) { l.gravity = 0; })},
          {"time", "-1",
           [] {
             (void)vacuumPointAt(VacuumLaunch{20, 0.5, 0, 9.81}, -1);
           }},
          {"targetHeight", "inf",
           [] {
             (void)vacuumFlight(VacuumLaunch{20, 0.5, 0, 9.81}, infd);
           }},
          {"gravity", "0", [] { (void)launchAngles(10, 0, 20, 0); }},
          {"speed", "-1", [] { (void)launchAngles(10, 0, -1); }},
          {"from.x", "nan",
           [] {
             (void)aimAt({nand, 0, 0}, {10, 0, 0}, 20);
           }},
          {"to.y", "inf",
           [] {
             (void)aimAt({}, {10, infd, 0}, 20);
           }},
          {"speed", "nan",
           [] {
             (void)aimAt({}, {10, 0, 0}, nand);
           }},
          {"muzzleSpeed", "-1",
           [] {
             (void)muzzleVelocity(CannonSetup{-1.0, 0.7, 0, 2, 0});
           }},
          {"altitude", "4",
           [] {
             (void)muzzlePosition(CannonSetup{50, 4.0, 0, 2, 0});
           }},
          {"barrelLength", "-1",
           [] {
             (void)muzzlePosition(CannonSetup{50, 0.7, 0, -1, 0});
           }},
          {"baseHeight", "inf",
           [] {
             (void)muzzlePosition(CannonSetup{50, 0.7, 0, 2, infd});
           }},
          {"mass", "0", [] { ShellFlight f({}, 0.0, {}); }},
          {"dragCoefficient", "-1",
           [] {
             ShellFlight f({}, 1.0, Atmosphere{9.81, -1.0, 0, 0, 0});
           }},
          {"windSpeed", "nan",
           [] {
             ShellFlight f({}, 1.0, Atmosphere{9.81, 0.0, nand, 0, 0});
           }},
          {"time", "-1", [] { (void)ShellFlight({}, 1.0, {}).at(-1); }},
          {"timeStep", "0",
           [] {
             (void)fireAtTarget(ShellFlight({}, 1.0, {}), TargetBox{{10, 0, 0}, {1, 1, 1}}, 0.0);
           }},
          {"target.size.x", "-1",
           [] {
             (void)fireAtTarget(ShellFlight({}, 1.0, {}), TargetBox{{10, 0, 0}, {-1, 1, 1}});
           }},
          {"distance", "-1", [] { (void)rifleShot(-1, 800); }},
      });
}

TEST(MechanicsValidation, impact_and_kinetics) {
  const PushedBox box{10, 1, 2, 1, 0.5, 0.4, 9.81};
  const auto pushed = [box](auto change) {
    return [box, change] {
      PushedBox b = box;
      change(b);
      (void)boxTipping(b);
    };
  };
  expectRejected(
      everyParameter([](double m, double dv) { return linearImpulse(m, dv); }, {2, 3}, {"mass", "velocityChange"}) +
      everyParameter([](double j, double t) { return averageImpactForce(j, t); }, {2, 0.1}, {"impulse", "duration"}) +
      everyParameter([](double a, double b, double c, double d) { return coefficientOfRestitution(a, b, c, d); },
                     {2, 0, 0, 1}, {"v1Before", "v2Before", "v1After", "v2After"}) +
      everyParameter([](double h0, double h1) { return restitutionFromBounce(h0, h1); }, {2, 1},
                     {"dropHeight", "bounceHeight"}) +
      everyParameter([](double m1, double m2, double v, double e) { return impactEnergyLoss(m1, m2, v, e); },
                     {1, 2, 3, 0.5}, {"mass1", "mass2", "normalClosingSpeed", "restitution"},
                     {0, 1}) + // an infinite mass is an immovable body
      everyParameter(
          [](double m1, double v1, double m2, double v2, double e) { return resolveImpact1D(m1, v1, m2, v2, e); },
          {1, 2, 3, -1, 0.5}, {"mass1", "velocity1", "mass2", "velocity2", "restitution"},
          {0, 2}) + // an infinite mass is an immovable body
      everyParameter([](double f, double m, double c, double t, double v) { return shipMotion(f, m, c, t, v); },
                     {1000, 500, 10, 5, 0}, {"thrust", "mass", "resistanceCoefficient", "time", "initialSpeed"}) +
      everyParameter([](double f, double c) { return shipTerminalSpeed(f, c); }, {1000, 10},
                     {"thrust", "resistanceCoefficient"}) +
      everyParameter([](double m, double c) { return shipTimeConstant(m, c); }, {500, 10},
                     {"mass", "resistanceCoefficient"}) +
      std::vector<Rejection>{
          {"mass", "-1", [] { (void)linearImpulse(-1, 1); }},
          {"duration", "0", [] { (void)averageImpactForce(1, 0); }},
          {"dropHeight", "0", [] { (void)restitutionFromBounce(0, 0); }},
          {"bounceHeight", "3", [] { (void)restitutionFromBounce(2, 3); }},
          {"restitution", "1.5", [] { (void)resolveImpact1D(1, 1, 1, 0, 1.5); }},
          {"restitution", "-0.5", [] { (void)impactEnergyLoss(1, 1, 1, -0.5); }},
          {"mass1", "0", [] { (void)resolveImpact1D(0, 1, 1, 0, 0.5); }},
          {"body1.inverseMass", "-1",
           [] {
             (void)resolveParticleImpact(ImpactParticle{-1, {}}, ImpactParticle{1, {}}, Vec3d{1, 0, 0}, 0.5);
           }},
          {"normal", "0",
           [] {
             (void)resolveParticleImpact(ImpactParticle2D{1, {}}, ImpactParticle2D{1, {}}, Vec2d{}, 0.5);
           }},
          {"body2.velocity.y", "nan",
           [] {
             (void)resolveParticleImpact(ImpactParticle{1, {}}, ImpactParticle{1, {0, nand, 0}}, Vec3d{1, 0, 0}, 0.5);
           }},
          {"friction", "-1",
           [] {
             (void)resolveImpact(ImpactBody2D{1, 1, {1, 0}, 0, {}}, ImpactBody2D{1, 1, {}, 0, {}}, Vec2d{1, 0}, 0.5,
                                 -1);
           }},
          {"body1.inverseInertia", "nan",
           [] {
             (void)resolveImpact(ImpactBody2D{1, nand, {}, 0, {}}, ImpactBody2D{1, 1, {}, 0, {}}, Vec2d{1, 0}, 0.5);
           }},
          {"body2.offset.z", "inf",
           [] {
             ImpactBody b;
             b.inverseMass = 1;
             ImpactBody c = b;
             c.offset = {0, 0, infd};
             (void)resolveImpact(b, c, Vec3d{1, 0, 0}, 0.5);
           }},
          {"mass", "0", [] { (void)shipMotion(1, 0, 1, 1); }},
          {"time", "-1", [] { (void)shipMotion(1, 1, 1, -1); }},
          {"resistanceCoefficient", "-1", [] { (void)shipTimeConstant(1, -1); }},
          {"mass", "0", pushed([](PushedBox& b) { b.mass = 0; })},
          {"width", "nan", pushed([](PushedBox& b) { b.width = nand; })},
          {"height", "-1", pushed([](PushedBox& b) { b.height = -1; })},
          {"pushHeight", "3", pushed([](PushedBox& b) { b.pushHeight = 3; })},
          {"staticCoefficient", "inf", pushed([](PushedBox& b) { b.staticCoefficient = infd; })},
          {"kineticCoefficient", "0.6", pushed([](PushedBox& b) { b.kineticCoefficient = 0.6; })},
          {"gravity", "-1", pushed([](PushedBox& b) { b.gravity = -1; })},
          {"pushForce", "nan", [box] { (void)pushBoxAtRest(box, nand); }},
          {"pushForce", "inf", [box] { (void)boxSupportReactions(box, infd, false); }},
      });
}

TEST(MechanicsValidation, aerodynamics_relativity_rocket_explosion) {
  const auto ball = [](auto change) {
    return [change] {
      BallProperties b = baseball();
      change(b);
      (void)ballAcceleration(b, {}, {40, 0, 0});
    };
  };
  const auto conditions = [](auto change) {
    return [change] {
      FlightConditions c;
      change(c);
      (void)ballAcceleration(baseball(), c, {40, 0, 0});
    };
  };
  const auto rocket = [](auto change) {
    return [change] {
      VerticalRocket r{1000, 800, 10, 3000, 9.81, 0};
      change(r);
      (void)verticalRocketFlight(r);
    };
  };
  const auto gps = [](auto change) {
    return [change] {
      GpsClockInputs g;
      change(g);
      (void)gpsClockDrift(g);
    };
  };
  const auto explosion = [](auto change) {
    return [change] {
      ExplosionSettings s;
      change(s);
      KinematicExplosion e(s);
    };
  };
  expectRejected(
      everyParameter([](double v, double l, double rho, double mu) { return reynoldsNumber(v, l, rho, mu); },
                     {10, 0.1, 1.2, 1.8e-5}, {"speed", "length", "density", "dynamicViscosity"}) +
      everyParameter([](double v, double l, double nu) { return reynoldsNumberKinematic(v, l, nu); }, {10, 0.1, 1.5e-5},
                     {"speed", "length", "kinematicViscosity"}) +
      everyParameter([](double re) { return sphereDragCoefficient(re); }, {1e5}, {"reynolds"}) +
      everyParameter([](double r, double w, double v) { return spinRatio(r, w, v); }, {0.04, 200, 40},
                     {"radius", "spinRate", "speed"}) +
      everyParameter([](double s) { return liftCoefficientSawicki2003(s); }, {0.2}, {"spinRatio"}) +
      everyParameter([](double rho, double r, double w) { return idealMagnusCoefficient(rho, r, w); }, {1.2, 0.04, 200},
                     {"airDensity", "radius", "spinRate"}) +
      everyParameter([](double v, double c) { return lorentzFactor(v, c); }, {1e7, 3e8}, {"speed", "speedOfLight"}) +
      everyParameter([](double t, double v, double c) { return dilatedTime(t, v, c); }, {1, 1e7, 3e8},
                     {"properTime", "speed", "speedOfLight"}) +
      everyParameter([](double v, double c) { return specialRelativisticRate(v, c); }, {1e4, 3e8},
                     {"speed", "speedOfLight"}) +
      everyParameter([](double v, double c) { return specialRelativisticRateExact(v, c); }, {1e4, 3e8},
                     {"speed", "speedOfLight"}) +
      everyParameter([](double gm, double r1, double r2, double c) { return gravitationalRate(gm, r1, r2, c); },
                     {4e14, 6.4e6, 2.6e7, 3e8},
                     {"gravitationalParameter", "lowerRadius", "upperRadius", "speedOfLight"}) +
      everyParameter([](double u, double m0, double m1) { return rocketDeltaV(u, m0, m1); }, {3000, 1000, 200},
                     {"exhaustVelocity", "initialMass", "finalMass"}) +
      everyParameter([](double mdot, double u) { return rocketThrust(mdot, u); }, {10, 3000},
                     {"burnRate", "exhaustVelocity"}) +
      std::vector<Rejection>{
          {"length", "0", [] { (void)reynoldsNumber(10, 0); }},
          {"dynamicViscosity", "0", [] { (void)reynoldsNumber(10, 1, 1.2, 0); }},
          {"reynolds", "-1", [] { (void)sphereDragCoefficient(-1); }},
          {"airDensity", "-1",
           [] {
             (void)dragForce({1, 0, 0}, -1, 1, 1);
           }},
          {"relativeVelocity.x", "nan",
           [] {
             (void)dragForce({nand, 0, 0}, 1, 1, 1);
           }},
          {"radius", "0", [] { (void)spinRatio(0, 1, 1); }},
          {"spin.y", "inf",
           [] {
             (void)magnusForce({1, 0, 0}, {0, infd, 0}, 0.04, 1.2, LiftModel::sawicki2003);
           }},
          {"mass", "0",
           [] {
             (void)magnusClosedForm(MagnusPlaneLaunch{{}, {10, 0}, 0.0, 0.1, 9.81}, 1);
           }},
          {"time", "-1",
           [] {
             (void)magnusClosedForm(MagnusPlaneLaunch{{}, {10, 0}, 1.0, 0.1, 9.81}, -1);
           }},
          {"velocity.y", "nan",
           [] {
             (void)bookMagnusFormula(MagnusPlaneLaunch{{}, {10, nand}, 1.0, 0.1, 9.81}, 1);
           }},
          {"gravity", "-1",
           [] {
             (void)bookMagnusSingularTime(MagnusPlaneLaunch{{}, {10, 0}, 1.0, 0.1, -1});
           }},
          {"mass", "0", ball([](BallProperties& b) { b.mass = 0; })},
          {"radius", "nan", ball([](BallProperties& b) { b.radius = nand; })},
          {"dragCoefficient", "-1", ball([](BallProperties& b) { b.dragCoefficient = -1; })},
          {"airDensity", "-1", conditions([](FlightConditions& c) { c.airDensity = -1; })},
          {"dynamicViscosity", "0", conditions([](FlightConditions& c) { c.dynamicViscosity = 0; })},
          {"wind.x", "inf", conditions([](FlightConditions& c) { c.wind.x = infd; })},
          {"spin.z", "nan", conditions([](FlightConditions& c) { c.spin.z = nand; })},
          {"velocity.z", "nan",
           [] {
             (void)ballAcceleration(baseball(), {}, {0, 0, nand});
           }},
          {"timeStep", "0",
           [] {
             (void)simulateBallFlight(baseball(), {}, {}, {40, 10, 0}, FlightSettings{0.0, 10.0});
           }},
          {"maxTime", "inf",
           [] {
             (void)simulateBallFlight(baseball(), {}, {}, {40, 10, 0}, FlightSettings{1e-3, infd});
           }},
          {"launchVelocity.x", "nan",
           [] {
             (void)simulateBallFlight(baseball(), {}, {}, {nand, 10, 0});
           }},
          {"speed", "3e+08", [] { (void)lorentzFactor(3e8, 3e8); }},
          {"speedOfLight", "0", [] { (void)lorentzFactor(1, 0); }},
          {"lowerRadius", "0", [] { (void)gravitationalRate(4e14, 0, 1e7); }},
          {"orbitRadius", "1", gps([](GpsClockInputs& g) { g.orbitRadius = 1; })},
          {"groundRadius", "nan", gps([](GpsClockInputs& g) { g.groundRadius = nand; })},
          {"orbitalSpeed", "-1", gps([](GpsClockInputs& g) { g.orbitalSpeed = -1; })},
          {"nominalFrequency", "0", gps([](GpsClockInputs& g) { g.nominalFrequency = 0; })},
          {"finalMass", "2000", [] { (void)rocketDeltaV(3000, 1000, 2000); }},
          {"finalMass", "0", [] { (void)rocketDeltaV(3000, 1000, 0); }},
          {"burnRate", "-1", [] { (void)rocketThrust(-1, 3000); }},
          {"initialMass", "0", rocket([](VerticalRocket& r) { r.initialMass = 0; })},
          {"propellantMass", "1000", rocket([](VerticalRocket& r) { r.propellantMass = 1000; })},
          {"burnRate", "nan", rocket([](VerticalRocket& r) { r.burnRate = nand; })},
          {"exhaustVelocity", "-1", rocket([](VerticalRocket& r) { r.exhaustVelocity = -1; })},
          {"gravity", "0", rocket([](VerticalRocket& r) { r.gravity = 0; })},
          {"initialAltitude", "inf", rocket([](VerticalRocket& r) { r.initialAltitude = infd; })},
          {"time", "-1",
           [] {
             (void)verticalRocketStateAt(VerticalRocket{1000, 800, 10, 3000, 9.81, 0}, -1);
           }},
          {"origin.x", "nan", explosion([](ExplosionSettings& s) { s.origin.x = nand; })},
          {"speed", "-1", explosion([](ExplosionSettings& s) { s.speed = -1; })},
          {"life", "0", explosion([](ExplosionSettings& s) { s.life = 0; })},
          {"gravity", "inf", explosion([](ExplosionSettings& s) { s.gravity = infd; })},
          {"direction", "nan", explosion([](ExplosionSettings& s) { s.direction = nand; })},
          {"spread", "-1", explosion([](ExplosionSettings& s) { s.spread = -1; })},
          {"count", "-1", explosion([](ExplosionSettings& s) { s.count = -1; })},
          {"time", "nan", [] { (void)KinematicExplosion({}).particleAt(0, nand); }},
      });
}

} // namespace
} // namespace impetus
