#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/mechanics/projectile.hpp>

#include <cmath>

namespace impetus {
namespace {

void validate(const VacuumLaunch& launch) {
  requireNonNegative(launch.speed, "speed");
  requireFinite(launch.angle, "angle");
  if (std::abs(launch.angle) > pi<double> / 2) {
    throwInvalid("angle", launch.angle, "must be within [-pi/2, pi/2] rad (above or below the horizontal)");
  }
  requireFinite(launch.launchHeight, "launchHeight");
  requirePositive(launch.gravity, "gravity");
}

} // namespace

ProjectilePoint vacuumPointAt(const VacuumLaunch& launch, double time) {
  validate(launch);
  requireNonNegative(time, "time");
  const double vx = launch.speed * std::cos(launch.angle);
  const double vy0 = launch.speed * std::sin(launch.angle);
  ProjectilePoint p;
  p.time = time;
  p.position = {vx * time, launch.launchHeight + vy0 * time - 0.5 * launch.gravity * time * time};
  p.velocity = {vx, vy0 - launch.gravity * time};
  p.speed = std::hypot(p.velocity.x, p.velocity.y);
  return p;
}

VacuumFlight vacuumFlight(const VacuumLaunch& launch, double targetHeight) {
  validate(launch);
  requireFinite(targetHeight, "targetHeight");
  const double g = launch.gravity;
  const double vx = launch.speed * std::cos(launch.angle);
  const double b = launch.speed * std::sin(launch.angle); // initial vertical speed
  const double rise = targetHeight - launch.launchHeight; // Delta, m
  // y(t) = target  <=>  (g/2) t^2 - b t + rise = 0,  t = (b +- s)/g,  s = sqrt(b^2 - 2 g rise).
  const double discriminant = b * b - 2.0 * g * rise;
  if (discriminant < 0.0) {
    throwInvalid("targetHeight", targetHeight, "target never reached: it is above the apex of the trajectory");
  }
  const double s = std::sqrt(discriminant);
  // The later root (b + s)/g; written as 2 rise/(b - s) when b < 0 so that it does not cancel.
  const double t = b >= 0.0 ? (b + s) / g : 2.0 * rise / (b - s);
  if (t < 0.0) {
    throwInvalid("targetHeight", targetHeight, "target never reached: launched downward, away from it");
  }
  VacuumFlight f;
  f.timeOfFlight = t;
  f.range = vx * t;
  f.apexTime = b > 0.0 ? b / g : 0.0;
  f.apexHeight = launch.launchHeight + (b > 0.0 ? b * b / (2.0 * g) : 0.0);
  // Energy: v^2 = v0^2 - 2 g rise (>= b^2 - 2 g rise >= 0 here).
  f.impactSpeed = std::sqrt(std::fmax(0.0, launch.speed * launch.speed - 2.0 * g * rise));
  const double vyImpact = b - g * t;
  f.impactAngle = std::atan2(-vyImpact, vx);
  return f;
}

VacuumFlight vehicleDrop(double speed, double height, double gravity) {
  requireNonNegative(height, "height");
  return vacuumFlight(VacuumLaunch{speed, 0.0, height, gravity}, 0.0);
}

double maximumRangeAngle(double speed, double launchHeight, double targetHeight, double gravity) {
  requirePositive(speed, "speed");
  requireFinite(launchHeight, "launchHeight");
  requireFinite(targetHeight, "targetHeight");
  requirePositive(gravity, "gravity");
  const double impactSpeedSquared = speed * speed + 2.0 * gravity * (launchHeight - targetHeight);
  if (!(impactSpeedSquared > 0.0)) {
    throwInvalid("targetHeight", targetHeight, "target never reached: higher than a vertical shot goes");
  }
  return std::atan(speed / std::sqrt(impactSpeedSquared));
}

double terminalVelocityQuadratic(double weight, double dragCoefficient, double fluidDensity, double area) {
  requirePositive(weight, "weight");
  requirePositive(dragCoefficient, "dragCoefficient");
  requirePositive(fluidDensity, "fluidDensity");
  requirePositive(area, "area");
  return std::sqrt(2.0 * weight / (dragCoefficient * fluidDensity * area));
}

double terminalVelocityLinear(double weight, double linearDragCoefficient) {
  requirePositive(weight, "weight");
  requirePositive(linearDragCoefficient, "linearDragCoefficient");
  return weight / linearDragCoefficient;
}

} // namespace impetus
