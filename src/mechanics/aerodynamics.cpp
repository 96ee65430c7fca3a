#include <impetus/error.hpp>
#include <impetus/integrate/rk4.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/mechanics/aerodynamics.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace impetus {
namespace {

/// sin(x)/x, 1 at 0.
double sinc(double x) {
  if (std::abs(x) < 1e-4) {
    return 1.0 - x * x / 6.0; // next term x^4/120 < 1e-18
  }
  return std::sin(x) / x;
}

/// (1 - cos x)/x = sin(x/2) sinc(x/2): no cancellation.
double oneMinusCosOverX(double x) { return std::sin(0.5 * x) * sinc(0.5 * x); }

/// (1 - cos x)/x^2 = sinc^2(x/2)/2.
double oneMinusCosOverX2(double x) {
  const double s = sinc(0.5 * x);
  return 0.5 * s * s;
}

/// (x - sin x)/x^2: the series sum_k (-1)^(k+1) x^(2k-1)/(2k+1)! below |x| = 1 (where the direct
/// form loses digits to cancellation); ten terms leave an error below 1/23! there.
double xMinusSinOverX2(double x) {
  if (std::abs(x) >= 1.0) {
    return (x - std::sin(x)) / (x * x);
  }
  double term = x / 6.0; // x/3!
  double sum = term;
  const double x2 = x * x;
  for (int k = 2; k <= 10; ++k) {
    term *= -x2 / static_cast<double>((2 * k) * (2 * k + 1));
    sum += term;
  }
  return sum;
}

void validate(const MagnusPlaneLaunch& launch, double time) {
  requireFinite(launch.position, "position");
  requireFinite(launch.velocity, "velocity");
  requirePositive(launch.mass, "mass");
  requireFinite(launch.magnusCoefficient, "magnusCoefficient");
  requireNonNegative(launch.gravity, "gravity");
  requireNonNegative(time, "time");
}

void validate(const BallProperties& ball) {
  requirePositive(ball.mass, "mass");
  requirePositive(ball.radius, "radius");
  requireNonNegative(ball.dragCoefficient, "dragCoefficient");
  requireFinite(ball.liftCoefficient, "liftCoefficient");
}

void validate(const FlightConditions& c) {
  requireNonNegative(c.airDensity, "airDensity");
  requirePositive(c.dynamicViscosity, "dynamicViscosity");
  requireNonNegative(c.gravity, "gravity");
  requireFinite(c.wind, "wind");
  requireFinite(c.spin, "spin");
  requireFinite(c.groundHeight, "groundHeight");
}

double morrison(double re) {
  const double a = re / 5.0;
  const double b = re / 263000.0;
  return 24.0 / re + 2.6 * a / (1.0 + std::pow(a, 1.52)) + 0.411 * std::pow(b, -7.94) / (1.0 + std::pow(b, -8.0)) +
         std::pow(re, 0.8) / 461000.0;
}

Vec3d dragUnchecked(const Vec3d& relativeVelocity, double airDensity, double area, double dragCoefficient) {
  return relativeVelocity * (-0.5 * airDensity * length(relativeVelocity) * area * dragCoefficient);
}

Vec3d magnusUnchecked(const Vec3d& v, const Vec3d& spin, double radius, double airDensity, LiftModel model,
                      double liftCoefficient) {
  const double speed = length(v);
  const double w = length(spin);
  if (model == LiftModel::none || speed == 0.0 || w == 0.0 || airDensity == 0.0) {
    return {};
  }
  if (model == LiftModel::idealizedSphere) {
    return cross(spin, v) * (pi<double> * pi<double> * airDensity * radius * radius * radius);
  }
  const double cl = model == LiftModel::sawicki2003 ? liftCoefficientSawicki2003(radius * w / speed) : liftCoefficient;
  // 1/2 rho v^2 A C_L (w_hat x v_hat) = 1/2 rho A C_L (v/w) (w x v)
  return cross(spin, v) * (0.5 * airDensity * pi<double> * radius * radius * cl * speed / w);
}

Vec3d accelerationUnchecked(const BallProperties& ball, const FlightConditions& c, const Vec3d& velocity) {
  const Vec3d rel = velocity - c.wind;
  Vec3d force{};
  if (ball.dragModel != DragModel::none && c.airDensity > 0.0) {
    const double speed = length(rel);
    if (speed > 0.0) {
      double cd = ball.dragCoefficient;
      if (ball.dragModel == DragModel::smoothSphere) {
        cd = sphereDragCoefficient(c.airDensity * speed * 2.0 * ball.radius / c.dynamicViscosity);
      }
      force += dragUnchecked(rel, c.airDensity, pi<double> * ball.radius * ball.radius, cd);
    }
  }
  force += magnusUnchecked(rel, c.spin, ball.radius, c.airDensity, ball.liftModel, ball.liftCoefficient);
  return force / ball.mass - Vec3d{0.0, c.gravity, 0.0};
}

struct FlightState {
  Vec3d position;
  Vec3d velocity;
};
FlightState operator+(const FlightState& a, const FlightState& b) {
  return {a.position + b.position, a.velocity + b.velocity};
}
FlightState operator*(const FlightState& a, double s) { return {a.position * s, a.velocity * s}; }

/// The root in (0, h] of f(tau), with f(0) >= 0 > f(h) (or f(h) <= 0), where f and f' are
/// evaluated on the RK4 sub-step of length tau: safeguarded Newton (bisection when a Newton step
/// leaves the bracket). Converges to rounding in a handful of iterations for smooth flights.
double findCrossing(const std::function<double(double)>& f, const std::function<double(double)>& fPrime, double h) {
  double lo = 0.0;
  double hi = h;
  const double f0 = f(0.0);
  const double fh = f(h);
  double tau = f0 - fh != 0.0 ? h * f0 / (f0 - fh) : h; // secant first guess
  for (int i = 0; i < 60; ++i) {
    const double value = f(tau);
    if (value == 0.0) {
      return tau;
    }
    if (value > 0.0) {
      lo = tau;
    } else {
      hi = tau;
    }
    const double slope = fPrime(tau);
    double next = slope != 0.0 ? tau - value / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) {
      next = 0.5 * (lo + hi);
    }
    if (std::abs(next - tau) <= 1e-15 * h) {
      return next;
    }
    tau = next;
  }
  return tau;
}

} // namespace

double reynoldsNumber(double speed, double length, double density, double dynamicViscosity) {
  requireNonNegative(speed, "speed");
  requirePositive(length, "length");
  requirePositive(density, "density");
  requirePositive(dynamicViscosity, "dynamicViscosity");
  return density * speed * length / dynamicViscosity;
}

double reynoldsNumberKinematic(double speed, double length, double kinematicViscosity) {
  requireNonNegative(speed, "speed");
  requirePositive(length, "length");
  requirePositive(kinematicViscosity, "kinematicViscosity");
  return speed * length / kinematicViscosity;
}

double sphereDragCoefficient(double reynolds) {
  requirePositive(reynolds, "reynolds");
  return morrison(std::fmin(reynolds, sphereDragCorrelationLimit));
}

Vec3d dragForce(const Vec3d& relativeVelocity, double airDensity, double area, double dragCoefficient) {
  requireFinite(relativeVelocity, "relativeVelocity");
  requireNonNegative(airDensity, "airDensity");
  requirePositive(area, "area");
  requireNonNegative(dragCoefficient, "dragCoefficient");
  return dragUnchecked(relativeVelocity, airDensity, area, dragCoefficient);
}

double spinRatio(double radius, double spinRate, double speed) {
  requirePositive(radius, "radius");
  requireNonNegative(spinRate, "spinRate");
  requirePositive(speed, "speed");
  return radius * spinRate / speed;
}

double liftCoefficientSawicki2003(double spinRatio) {
  requireNonNegative(spinRatio, "spinRatio");
  return spinRatio <= 0.1 ? 1.5 * spinRatio : 0.09 + 0.6 * spinRatio;
}

double idealMagnusCoefficient(double airDensity, double radius, double spinRate) {
  requireNonNegative(airDensity, "airDensity");
  requirePositive(radius, "radius");
  requireFinite(spinRate, "spinRate");
  return pi<double> * pi<double> * airDensity * radius * radius * radius * spinRate;
}

Vec3d magnusForce(const Vec3d& relativeVelocity, const Vec3d& spin, double radius, double airDensity, LiftModel model,
                  double liftCoefficient) {
  requireFinite(relativeVelocity, "relativeVelocity");
  requireFinite(spin, "spin");
  requirePositive(radius, "radius");
  requireNonNegative(airDensity, "airDensity");
  requireFinite(liftCoefficient, "liftCoefficient");
  return magnusUnchecked(relativeVelocity, spin, radius, airDensity, model, liftCoefficient);
}

MagnusPlaneState magnusClosedForm(const MagnusPlaneLaunch& launch, double time) {
  validate(launch, time);
  const double t = time;
  const double theta = launch.magnusCoefficient / launch.mass * t; // Omega t, rad
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  const double s1 = sinc(theta);              // sin(theta)/theta
  const double c1 = oneMinusCosOverX(theta);  // (1 - cos)/theta
  const double c2 = oneMinusCosOverX2(theta); // (1 - cos)/theta^2
  const double c3 = xMinusSinOverX2(theta);   // (theta - sin)/theta^2
  const double g = launch.gravity;
  const Vec2d v0 = launch.velocity;
  MagnusPlaneState out;
  out.time = t;
  out.velocity = {v0.x * c - v0.y * s + g * t * c1, v0.x * s + v0.y * c - g * t * s1};
  out.position = {launch.position.x + t * (v0.x * s1 - v0.y * c1) + g * t * t * c3,
                  launch.position.y + t * (v0.x * c1 + v0.y * s1) - g * t * t * c2};
  return out;
}

double bookMagnusSingularTime(const MagnusPlaneLaunch& launch) {
  validate(launch, 0.0);
  if (launch.magnusCoefficient == 0.0) {
    return std::numeric_limits<double>::infinity();
  }
  return launch.mass / std::abs(launch.magnusCoefficient);
}

MagnusPlaneState bookMagnusFormula(const MagnusPlaneLaunch& launch, double time) {
  validate(launch, time);
  const double m = launch.mass;
  const double cc = launch.magnusCoefficient;
  const double g = launch.gravity;
  const double t = time;
  const double k = cc * t / m; // the book's (t/m) C
  const double denominator = 1.0 - k * k;
  if (std::abs(denominator) <= 1e-12) {
    throwInvalid("time", time, "the book's Magnus formula divides by zero at t = m/C");
  }
  const Vec2d v0 = launch.velocity;
  MagnusPlaneState out;
  out.time = t;
  out.velocity.x = (v0.x + k * v0.y - cc * g * t * t / m) / denominator;
  out.velocity.y = v0.y + k * out.velocity.x - g * t;
  out.position.x = launch.position.x + v0.x * t + 0.5 * (cc / m * out.velocity.y) * t * t;
  out.position.y = launch.position.y + v0.y * t + 0.5 * ((cc * out.velocity.x - m * g) / m) * t * t;
  return out;
}

BallProperties baseball() { return {0.145, 0.0366, DragModel::constantCoefficient, 0.35, LiftModel::sawicki2003, 0.0}; }

BallProperties golfBall() {
  return {0.04593, 0.021335, DragModel::constantCoefficient, 0.25, LiftModel::constantCoefficient, 0.2};
}

Vec3d ballAcceleration(const BallProperties& ball, const FlightConditions& conditions, const Vec3d& velocity) {
  validate(ball);
  validate(conditions);
  requireFinite(velocity, "velocity");
  return accelerationUnchecked(ball, conditions, velocity);
}

BallFlight simulateBallFlight(const BallProperties& ball, const FlightConditions& conditions,
                              const Vec3d& launchPosition, const Vec3d& launchVelocity,
                              const FlightSettings& settings) {
  validate(ball);
  validate(conditions);
  requireFinite(launchPosition, "launchPosition");
  requireFinite(launchVelocity, "launchVelocity");
  requirePositive(settings.timeStep, "timeStep");
  requirePositive(settings.maxTime, "maxTime");
  if (launchPosition.y < conditions.groundHeight) {
    throwInvalid("launchPosition", launchPosition.y, "must not be below the ground");
  }
  const double steps = std::ceil(settings.maxTime / settings.timeStep);
  if (steps > 1e7) {
    throwInvalid("timeStep", settings.timeStep, "too small for maxTime: more than 1e7 steps");
  }
  const auto rate = [&](double /*t*/, const FlightState& s) {
    return FlightState{s.velocity, accelerationUnchecked(ball, conditions, s.velocity)};
  };
  const double ground = conditions.groundHeight;

  BallFlight flight;
  flight.samples.reserve(static_cast<std::size_t>(steps) + 2);
  FlightState state{launchPosition, launchVelocity};
  double t = 0.0;
  flight.samples.push_back({t, state.position, state.velocity});
  flight.maxHeight = launchPosition.y;
  const auto count = static_cast<long>(steps);
  for (long i = 0; i < count; ++i) {
    const double h = std::fmin(settings.timeStep, settings.maxTime - t);
    if (!(h > 0.0)) {
      break;
    }
    const FlightState next = rk4Step(rate, t, state, h);
    const FlightState from = state;
    const double t0 = t;
    const auto subStep = [&](double tau) { return rk4Step(rate, t0, from, tau); };
    if (from.velocity.y > 0.0 && next.velocity.y <= 0.0) { // the apex is inside this step
      const double tau = findCrossing([&](double x) { return subStep(x).velocity.y; },
                                      [&](double x) { return rate(t0 + x, subStep(x)).velocity.y; }, h);
      const FlightState apex = subStep(tau);
      if (apex.position.y > flight.maxHeight) {
        flight.maxHeight = apex.position.y;
        flight.apexTime = t0 + tau;
      }
    }
    if (next.position.y < ground) { // came down through the ground inside this step
      const double tau = findCrossing([&](double x) { return subStep(x).position.y - ground; },
                                      [&](double x) { return subStep(x).velocity.y; }, h);
      state = subStep(tau);
      state.position.y = ground; // exact to rounding; pin it
      t = t0 + tau;
      flight.landed = true;
      flight.samples.push_back({t, state.position, state.velocity});
      break;
    }
    state = next;
    t = t0 + h;
    flight.samples.push_back({t, state.position, state.velocity});
    if (state.position.y > flight.maxHeight) {
      flight.maxHeight = state.position.y;
      flight.apexTime = t;
    }
  }
  flight.flightTime = t;
  flight.landingPoint = state.position;
  flight.landingVelocity = state.velocity;
  Vec3d direction = normalize(Vec3d{launchVelocity.x, 0.0, launchVelocity.z});
  if (lengthSquared(direction) == 0.0) {
    direction = Vec3d::unitX(); // launched straight up or down: measure along x
  }
  const Vec3d right = cross(direction, Vec3d::unitY());
  const Vec3d travelled = state.position - launchPosition;
  flight.range = dot(travelled, direction);
  flight.lateralDeflection = dot(travelled, right);
  return flight;
}

} // namespace impetus
