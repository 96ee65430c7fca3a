#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/mechanics/forces.hpp>

#include <cmath>
#include <string_view>

namespace impetus {
namespace {

void requireSpring(const SpringDamper& s) {
  requireNonNegative(s.stiffness, "stiffness");
  requireNonNegative(s.damping, "damping");
  requireNonNegative(s.restLength, "restLength");
}

} // namespace

// ---- Gravitation --------------------------------------------------------------------------------

double gravitationalForce(double mass1, double mass2, double distance, double gravitationalConstant) {
  requireNonNegative(mass1, "mass1");
  requireNonNegative(mass2, "mass2");
  const double r = requirePositive(distance, "distance");
  requirePositive(gravitationalConstant, "gravitationalConstant");
  const double f = gravitationalConstant * mass1 * mass2 / (r * r);
  if (!std::isfinite(f)) {
    throwInvalid("distance", r, "too small: the force overflows");
  }
  return f;
}

Vec3d gravitationalForce(double mass1, const Vec3d& position1, double mass2, const Vec3d& position2,
                         double gravitationalConstant) {
  requireNonNegative(mass1, "mass1");
  requireNonNegative(mass2, "mass2");
  requireFinite(position1, "position1");
  requireFinite(position2, "position2");
  requirePositive(gravitationalConstant, "gravitationalConstant");
  const Vec3d d = position2 - position1;
  const double r = length(d);
  if (!(r > 0.0)) {
    throwInvalid("position2", position2.x, "coincides with position1: gravitation is singular at r = 0");
  }
  const Vec3d f = d * (gravitationalConstant * mass1 * mass2 / (r * r * r));
  if (!isFinite(f)) {
    throwInvalid("position2", position2.x, "too close to position1: the force overflows");
  }
  return f;
}

double weight(double mass, double gravity) {
  return requireNonNegative(mass, "mass") * requireNonNegative(gravity, "gravity");
}

double gravityAtAltitude(double altitude, double bodyMass, double bodyRadius, double gravitationalConstant) {
  requireFinite(altitude, "altitude");
  requirePositive(bodyMass, "bodyMass");
  requirePositive(bodyRadius, "bodyRadius");
  requirePositive(gravitationalConstant, "gravitationalConstant");
  const double r = bodyRadius + altitude;
  if (!(r > 0.0)) {
    throwInvalid("altitude", altitude, "must be above the centre of the body (bodyRadius + altitude > 0)");
  }
  return gravitationalConstant * bodyMass / (r * r);
}

// ---- Drag -----------------------------------------------------------------------------------------

Vec3d linearDragForce(const Vec3d& velocity, double dragConstant, const Vec3d& fluidVelocity) {
  requireFinite(velocity, "velocity");
  requireNonNegative(dragConstant, "dragConstant");
  requireFinite(fluidVelocity, "fluidVelocity");
  return (velocity - fluidVelocity) * -dragConstant;
}

Vec3d quadraticDragForce(const Vec3d& velocity, double dragConstant, const Vec3d& fluidVelocity) {
  requireFinite(velocity, "velocity");
  requireNonNegative(dragConstant, "dragConstant");
  requireFinite(fluidVelocity, "fluidVelocity");
  const Vec3d relative = velocity - fluidVelocity;
  return relative * (-dragConstant * length(relative));
}

double quadraticDragConstant(double density, double area, double dragCoefficient) {
  requireNonNegative(density, "density");
  requirePositive(area, "area");
  requireNonNegative(dragCoefficient, "dragCoefficient");
  return 0.5 * density * area * dragCoefficient;
}

Vec3d fluidDragForce(const Vec3d& velocity, double density, double area, double dragCoefficient,
                     const Vec3d& fluidVelocity) {
  return quadraticDragForce(velocity, quadraticDragConstant(density, area, dragCoefficient), fluidVelocity);
}

// ---- Pressure and buoyancy --------------------------------------------------------------------------

double pressureForce(double pressure, double area) {
  return requireFinite(pressure, "pressure") * requirePositive(area, "area");
}

double hydrostaticPressure(double density, double depth, double gravity, double surfacePressure) {
  requireNonNegative(density, "density");
  requireNonNegative(depth, "depth");
  requireNonNegative(gravity, "gravity");
  requireFinite(surfacePressure, "surfacePressure");
  return surfacePressure + density * gravity * depth;
}

double buoyantForce(double fluidDensity, double displacedVolume, double gravity) {
  requireNonNegative(fluidDensity, "fluidDensity");
  requireNonNegative(displacedVolume, "displacedVolume");
  requireNonNegative(gravity, "gravity");
  return fluidDensity * gravity * displacedVolume;
}

ImmersedBody immersedBody(double bodyDensity, double fluidDensity, double volume, double gravity) {
  requireNonNegative(bodyDensity, "bodyDensity");
  requirePositive(fluidDensity, "fluidDensity");
  requireNonNegative(volume, "volume");
  requireNonNegative(gravity, "gravity");
  ImmersedBody b{};
  b.weight = bodyDensity * gravity * volume;
  b.buoyantForce = fluidDensity * gravity * volume;
  b.netForce = b.buoyantForce - b.weight;
  if (bodyDensity < fluidDensity) {
    b.flotation = Flotation::floats;
    b.submergedFraction = bodyDensity / fluidDensity;
  } else {
    b.flotation = bodyDensity == fluidDensity ? Flotation::neutral : Flotation::sinks;
    b.submergedFraction = 1.0;
  }
  return b;
}

// ---- Spring-damper ----------------------------------------------------------------------------------

namespace {

template <class V> V springDamperForceImpl(const SpringDamper& s, const V& p1, const V& v1, const V& p2, const V& v2) {
  requireSpring(s);
  requireFinite(p1, "position1");
  requireFinite(v1, "velocity1");
  requireFinite(p2, "position2");
  requireFinite(v2, "velocity2");
  const V separation = p1 - p2;
  const double len = length(separation);
  const V direction = normalize(separation); // zero vector when the points coincide
  if (direction == V{}) {
    return V{};
  }
  const double stretch = len - s.restLength;
  const double rate = dot(v1 - v2, direction); // d|L|/dt
  return direction * -(s.stiffness * stretch + s.damping * rate);
}

} // namespace

Vec3d springDamperForce(const SpringDamper& spring, const Vec3d& position1, const Vec3d& velocity1,
                        const Vec3d& position2, const Vec3d& velocity2) {
  return springDamperForceImpl(spring, position1, velocity1, position2, velocity2);
}

Vec2d springDamperForce(const SpringDamper& spring, const Vec2d& position1, const Vec2d& velocity1,
                        const Vec2d& position2, const Vec2d& velocity2) {
  return springDamperForceImpl(spring, position1, velocity1, position2, velocity2);
}

// ---- Torque -------------------------------------------------------------------------------------------

Vec3d torque(const Vec3d& arm, const Vec3d& force) {
  requireFinite(arm, "arm");
  requireFinite(force, "force");
  return cross(arm, force);
}

double torque(const Vec2d& arm, const Vec2d& force) {
  requireFinite(arm, "arm");
  requireFinite(force, "force");
  return cross(arm, force);
}

ForceResultant resultant(std::span<const AppliedForce> forces, const Vec3d& about) {
  requireFinite(about, "about");
  ForceResultant r{};
  for (const AppliedForce& f : forces) {
    requireFinite(f.point, "point");
    r.force += f.force;
    r.torque += torque(f.point - about, f.force);
  }
  return r;
}

ForceResultant2 resultant(std::span<const AppliedForce2> forces, const Vec2d& about) {
  requireFinite(about, "about");
  ForceResultant2 r{};
  for (const AppliedForce2& f : forces) {
    requireFinite(f.point, "point");
    r.force += f.force;
    r.torque += torque(f.point - about, f.force);
  }
  return r;
}

} // namespace impetus
