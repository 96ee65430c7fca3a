#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/mechanics/kinematics.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>

namespace impetus {
namespace {

/// The first t >= 0 with v1 t + 1/2 a t^2 = s. Solved as the quadratic (a/2) t^2 + v1 t - s = 0
/// with q = -(v1 + sgn(v1) sqrt(v1^2 + 2 a s)) / 2, whose roots q / (a/2) and -s / q do not
/// suffer the cancellation of the textbook (-v1 + sqrt(...)) / a, and which stays finite for
/// a = 0 (the root -s / q = s / v1). `field` names the quantity blamed when s is never reached.
double firstTimeTo(double v1, double a, double s, std::string_view field) {
  if (s == 0.0) {
    return 0.0;
  }
  if (a == 0.0) {
    const double t = v1 != 0.0 ? s / v1 : -1.0;
    if (!(t >= 0.0) || !std::isfinite(t)) {
      throwInvalid(field, s, "never reached: with no acceleration the motion goes the other way or not at all");
    }
    return t;
  }
  double discriminant = v1 * v1 + 2.0 * a * s;
  // A grazing target (the turning point itself, e.g. v2 and s of a motion that started at rest)
  // can come out a few ulps negative from rounding alone: treat that as the tangent it is.
  if (discriminant < 0.0 &&
      -discriminant <= 8.0 * std::numeric_limits<double>::epsilon() * (v1 * v1 + std::abs(2.0 * a * s))) {
    discriminant = 0.0;
  }
  if (discriminant < 0.0) {
    throwInvalid(field, s, "never reached: the motion turns back before it (v^2 + 2 a s < 0)");
  }
  const double root = std::sqrt(discriminant);
  const double q = -0.5 * (v1 + (v1 >= 0.0 ? root : -root));
  double best = -1.0;
  const auto consider = [&best](double t) {
    if (t >= 0.0 && std::isfinite(t) && (best < 0.0 || t < best)) {
      best = t;
    }
  };
  consider(q / (0.5 * a));
  if (q != 0.0) {
    consider(-s / q);
  }
  if (best < 0.0) {
    throwInvalid(field, s, "never reached at a time t >= 0");
  }
  return best;
}

double requireTime(double t) { return requireNonNegative(t, "time"); }

} // namespace

double finalVelocityAfterTime(double initialVelocity, double acceleration, double t) {
  requireFinite(initialVelocity, "initialVelocity");
  requireFinite(acceleration, "acceleration");
  return initialVelocity + acceleration * requireTime(t);
}

double finalVelocityAfterDisplacement(double initialVelocity, double acceleration, double displacement) {
  requireFinite(initialVelocity, "initialVelocity");
  requireFinite(acceleration, "acceleration");
  requireFinite(displacement, "displacement");
  const double t = firstTimeTo(initialVelocity, acceleration, displacement, "displacement");
  if (acceleration == 0.0) {
    return initialVelocity;
  }
  // The magnitude from the energy-like relation (exact), the sign from v1 + a t.
  const double speed = std::sqrt(std::max(0.0, initialVelocity * initialVelocity + 2.0 * acceleration * displacement));
  return std::copysign(speed, initialVelocity + acceleration * t);
}

double displacementAfterTime(double initialVelocity, double acceleration, double t) {
  requireFinite(initialVelocity, "initialVelocity");
  requireFinite(acceleration, "acceleration");
  const double tt = requireTime(t);
  return initialVelocity * tt + 0.5 * acceleration * tt * tt;
}

double displacementBetweenVelocities(double initialVelocity, double finalVelocity, double acceleration) {
  const double t = timeBetweenVelocities(initialVelocity, finalVelocity, acceleration);
  return 0.5 * (initialVelocity + finalVelocity) * t; // = (v2^2 - v1^2) / (2 a), without 0/0 risk
}

double displacementFromMeanVelocity(double initialVelocity, double finalVelocity, double t) {
  requireFinite(initialVelocity, "initialVelocity");
  requireFinite(finalVelocity, "finalVelocity");
  return 0.5 * (initialVelocity + finalVelocity) * requireTime(t);
}

double timeBetweenVelocities(double initialVelocity, double finalVelocity, double acceleration) {
  requireFinite(initialVelocity, "initialVelocity");
  requireFinite(finalVelocity, "finalVelocity");
  requireFinite(acceleration, "acceleration");
  if (acceleration == 0.0) {
    throwInvalid("acceleration", acceleration,
                 initialVelocity == finalVelocity ? "must be non-zero: with a = 0 the time is not determined"
                                                  : "must be non-zero: with a = 0 the velocity never changes");
  }
  const double t = (finalVelocity - initialVelocity) / acceleration;
  if (t < 0.0) {
    throwInvalid("acceleration", acceleration, "points away from the final velocity (it was reached at t < 0)");
  }
  return t;
}

double timeToDisplacement(double initialVelocity, double acceleration, double displacement) {
  requireFinite(initialVelocity, "initialVelocity");
  requireFinite(acceleration, "acceleration");
  requireFinite(displacement, "displacement");
  return firstTimeTo(initialVelocity, acceleration, displacement, "displacement");
}

double accelerationFromVelocityChange(double initialVelocity, double finalVelocity, double t) {
  requireFinite(initialVelocity, "initialVelocity");
  requireFinite(finalVelocity, "finalVelocity");
  return (finalVelocity - initialVelocity) / requirePositive(t, "time");
}

double accelerationOverDisplacement(double initialVelocity, double finalVelocity, double displacement) {
  requireFinite(initialVelocity, "initialVelocity");
  requireFinite(finalVelocity, "finalVelocity");
  requireFinite(displacement, "displacement");
  if (displacement == 0.0) {
    throwInvalid("displacement", displacement, "must be non-zero: the acceleration is not determined");
  }
  // s = 1/2 (v1 + v2) t with t > 0: s must have the sign of v1 + v2.
  const double t = 2.0 * displacement / (initialVelocity + finalVelocity);
  if (!(t > 0.0) || !std::isfinite(t)) {
    throwInvalid("displacement", displacement,
                 "does not fit the velocities (its sign must be that of initialVelocity + finalVelocity)");
  }
  return (finalVelocity - initialVelocity) / t; // = (v2^2 - v1^2) / (2 s)
}

double initialVelocityBeforeTime(double finalVelocity, double acceleration, double t) {
  requireFinite(finalVelocity, "finalVelocity");
  requireFinite(acceleration, "acceleration");
  return finalVelocity - acceleration * requireTime(t);
}

double initialVelocityBeforeDisplacement(double finalVelocity, double acceleration, double displacement) {
  requireFinite(finalVelocity, "finalVelocity");
  requireFinite(acceleration, "acceleration");
  requireFinite(displacement, "displacement");
  // Run the motion backwards: u(tau) = -v(t - tau) starts at -v2, has the same acceleration and
  // covers -s. The shortest tau is the most recent start; then v1 = v2 - a tau.
  const double tau = firstTimeTo(-finalVelocity, acceleration, -displacement, "displacement");
  if (acceleration == 0.0) {
    return finalVelocity;
  }
  const double speed = std::sqrt(std::max(0.0, finalVelocity * finalVelocity - 2.0 * acceleration * displacement));
  return std::copysign(speed, finalVelocity - acceleration * tau);
}

ConstantAccelerationMotion solveConstantAcceleration(const ConstantAccelerationKnowns& k) {
  const int count = int(k.initialVelocity.has_value()) + int(k.finalVelocity.has_value()) +
                    int(k.acceleration.has_value()) + int(k.time.has_value()) + int(k.displacement.has_value());
  if (count != 3) {
    throwInvalid("knowns", count,
                 "give exactly three of initialVelocity, finalVelocity, acceleration, time, "
                 "displacement");
  }
  // Validate what is given; each branch below then works with plain doubles.
  if (k.initialVelocity) {
    requireFinite(*k.initialVelocity, "initialVelocity");
  }
  if (k.finalVelocity) {
    requireFinite(*k.finalVelocity, "finalVelocity");
  }
  if (k.acceleration) {
    requireFinite(*k.acceleration, "acceleration");
  }
  if (k.time) {
    requireTime(*k.time);
  }
  if (k.displacement) {
    requireFinite(*k.displacement, "displacement");
  }

  ConstantAccelerationMotion m{};
  const bool v1 = k.initialVelocity.has_value();
  const bool v2 = k.finalVelocity.has_value();
  const bool a = k.acceleration.has_value();
  const bool t = k.time.has_value();
  const bool s = k.displacement.has_value();

  if (v1 && a && t) {
    m = {*k.initialVelocity, 0.0, *k.acceleration, *k.time, 0.0};
    m.finalVelocity = finalVelocityAfterTime(m.initialVelocity, m.acceleration, m.time);
    m.displacement = displacementAfterTime(m.initialVelocity, m.acceleration, m.time);
  } else if (v1 && a && s) {
    m = {*k.initialVelocity, 0.0, *k.acceleration, 0.0, *k.displacement};
    m.time = timeToDisplacement(m.initialVelocity, m.acceleration, m.displacement);
    m.finalVelocity = finalVelocityAfterDisplacement(m.initialVelocity, m.acceleration, m.displacement);
  } else if (v1 && v2 && a) {
    m = {*k.initialVelocity, *k.finalVelocity, *k.acceleration, 0.0, 0.0};
    m.time = timeBetweenVelocities(m.initialVelocity, m.finalVelocity, m.acceleration);
    m.displacement = displacementBetweenVelocities(m.initialVelocity, m.finalVelocity, m.acceleration);
  } else if (v1 && v2 && t) {
    m = {*k.initialVelocity, *k.finalVelocity, 0.0, *k.time, 0.0};
    m.acceleration = accelerationFromVelocityChange(m.initialVelocity, m.finalVelocity, m.time);
    m.displacement = displacementFromMeanVelocity(m.initialVelocity, m.finalVelocity, m.time);
  } else if (v1 && v2 && s) {
    m = {*k.initialVelocity, *k.finalVelocity, 0.0, 0.0, *k.displacement};
    m.acceleration = accelerationOverDisplacement(m.initialVelocity, m.finalVelocity, m.displacement);
    m.time = 2.0 * m.displacement / (m.initialVelocity + m.finalVelocity);
  } else if (v1 && t && s) {
    m = {*k.initialVelocity, 0.0, 0.0, requirePositive(*k.time, "time"), *k.displacement};
    m.acceleration = 2.0 * (m.displacement - m.initialVelocity * m.time) / (m.time * m.time);
    m.finalVelocity = 2.0 * m.displacement / m.time - m.initialVelocity;
  } else if (v2 && a && t) {
    m = {0.0, *k.finalVelocity, *k.acceleration, *k.time, 0.0};
    m.initialVelocity = initialVelocityBeforeTime(m.finalVelocity, m.acceleration, m.time);
    m.displacement = m.finalVelocity * m.time - 0.5 * m.acceleration * m.time * m.time;
  } else if (v2 && a && s) {
    m = {0.0, *k.finalVelocity, *k.acceleration, 0.0, *k.displacement};
    m.time = firstTimeTo(-m.finalVelocity, m.acceleration, -m.displacement, "displacement");
    m.initialVelocity = initialVelocityBeforeDisplacement(m.finalVelocity, m.acceleration, m.displacement);
  } else if (v2 && t && s) {
    m = {0.0, *k.finalVelocity, 0.0, requirePositive(*k.time, "time"), *k.displacement};
    m.initialVelocity = 2.0 * m.displacement / m.time - m.finalVelocity;
    m.acceleration = (m.finalVelocity - m.initialVelocity) / m.time;
  } else { // a, t, s
    m = {0.0, 0.0, *k.acceleration, requirePositive(*k.time, "time"), *k.displacement};
    m.initialVelocity = m.displacement / m.time - 0.5 * m.acceleration * m.time;
    m.finalVelocity = m.initialVelocity + m.acceleration * m.time;
  }
  return m;
}

// ---- Quadratic drag ----------------------------------------------------------------------------

namespace {

void requireDragInputs(double initialPosition, double initialVelocity, double dragPerUnitMass) {
  requireFinite(initialPosition, "initialPosition");
  requireFinite(initialVelocity, "initialVelocity");
  requireNonNegative(dragPerUnitMass, "dragPerUnitMass");
}

/// |s - s1| for a position ahead of the body, or throws.
double distanceAhead(double initialPosition, double initialVelocity, double position) {
  requireFinite(position, "position");
  const double delta = position - initialPosition;
  if (delta == 0.0) {
    return 0.0;
  }
  if (initialVelocity == 0.0) {
    throwInvalid("position", position, "never reached: the body is at rest at initialPosition");
  }
  if ((delta > 0.0) != (initialVelocity > 0.0)) {
    throwInvalid("position", position, "never reached: it lies behind the moving body");
  }
  return std::abs(delta);
}

} // namespace

LinearState quadraticDragMotion(double initialPosition, double initialVelocity, double dragPerUnitMass, double t) {
  requireDragInputs(initialPosition, initialVelocity, dragPerUnitMass);
  const double tt = requireTime(t);
  const double speed = std::abs(initialVelocity);
  const double x = dragPerUnitMass * speed * tt; // k |v1| t, dimensionless
  // ln(1 + x) / k = |v1| t ln(1 + x) / x: log1p keeps full precision as k -> 0.
  const double distance = x > 0.0 ? speed * tt * (std::log1p(x) / x) : speed * tt;
  return {initialPosition + std::copysign(distance, initialVelocity), initialVelocity / (1.0 + x)};
}

double quadraticDragVelocityAt(double initialPosition, double initialVelocity, double dragPerUnitMass,
                               double position) {
  requireDragInputs(initialPosition, initialVelocity, dragPerUnitMass);
  const double d = distanceAhead(initialPosition, initialVelocity, position);
  return initialVelocity * std::exp(-dragPerUnitMass * d);
}

double quadraticDragTimeTo(double initialPosition, double initialVelocity, double dragPerUnitMass, double position) {
  requireDragInputs(initialPosition, initialVelocity, dragPerUnitMass);
  const double d = distanceAhead(initialPosition, initialVelocity, position);
  if (d == 0.0) {
    return 0.0;
  }
  const double x = dragPerUnitMass * d;
  // (e^{k d} - 1) / (k |v1|) = (d / |v1|) expm1(x) / x.
  const double t = d / std::abs(initialVelocity) * (x > 0.0 ? std::expm1(x) / x : 1.0);
  if (!std::isfinite(t)) {
    throwInvalid("position", position, "is reached only after a time too large to represent");
  }
  return t;
}

// ---- Rotation ------------------------------------------------------------------------------------

AngularState angularMotionAfterTime(double angle, double angularVelocity, double angularAcceleration, double t) {
  requireFinite(angle, "angle");
  requireFinite(angularVelocity, "angularVelocity");
  requireFinite(angularAcceleration, "angularAcceleration");
  const double tt = requireTime(t);
  return {angle + angularVelocity * tt + 0.5 * angularAcceleration * tt * tt,
          angularVelocity + angularAcceleration * tt};
}

double angularVelocityAfterRotation(double angularVelocity, double angularAcceleration, double rotation) {
  requireFinite(angularVelocity, "angularVelocity");
  requireFinite(angularAcceleration, "angularAcceleration");
  requireFinite(rotation, "rotation");
  const double t = firstTimeTo(angularVelocity, angularAcceleration, rotation, "rotation");
  if (angularAcceleration == 0.0) {
    return angularVelocity;
  }
  const double rate =
      std::sqrt(std::max(0.0, angularVelocity * angularVelocity + 2.0 * angularAcceleration * rotation));
  return std::copysign(rate, angularVelocity + angularAcceleration * t);
}

CircularMotion circularMotion(double radius, double angularVelocity, double angularAcceleration) {
  const double r = requireNonNegative(radius, "radius");
  const double w = requireFinite(angularVelocity, "angularVelocity");
  const double alpha = requireFinite(angularAcceleration, "angularAcceleration");
  CircularMotion c{};
  c.tangentialSpeed = r * w;
  c.tangentialAcceleration = r * alpha;
  c.centripetalAcceleration = r * w * w;
  c.acceleration = std::hypot(c.tangentialAcceleration, c.centripetalAcceleration);
  return c;
}

// ---- Rigid-body kinematics -------------------------------------------------------------------------

namespace {} // namespace

PlanarPointMotion pointOnRotatingBody(const PlanarBodyMotion& body, const Vec2d& offset) {
  requireFinite(body.velocity, "velocity");
  requireFinite(body.acceleration, "acceleration");
  requireFinite(body.angularVelocity, "angularVelocity");
  requireFinite(body.angularAcceleration, "angularAcceleration");
  requireFinite(offset, "offset");
  const double w = body.angularVelocity;
  PlanarPointMotion p{};
  p.velocity = body.velocity + cross(w, offset);
  p.tangentialAcceleration = cross(body.angularAcceleration, offset);
  p.centripetalAcceleration = cross(w, cross(w, offset)); // = -w^2 r
  p.acceleration = body.acceleration + p.tangentialAcceleration + p.centripetalAcceleration;
  return p;
}

PointMotion pointOnRotatingBody(const BodyMotion& body, const Vec3d& offset) {
  requireFinite(body.velocity, "velocity");
  requireFinite(body.acceleration, "acceleration");
  requireFinite(body.angularVelocity, "angularVelocity");
  requireFinite(body.angularAcceleration, "angularAcceleration");
  requireFinite(offset, "offset");
  const Vec3d& w = body.angularVelocity;
  PointMotion p{};
  p.velocity = body.velocity + cross(w, offset);
  p.tangentialAcceleration = cross(body.angularAcceleration, offset);
  p.centripetalAcceleration = cross(w, cross(w, offset));
  p.acceleration = body.acceleration + p.tangentialAcceleration + p.centripetalAcceleration;
  return p;
}

} // namespace impetus
