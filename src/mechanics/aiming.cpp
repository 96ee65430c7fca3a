#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/mechanics/aiming.hpp>

namespace impetus {
namespace {

void validate(double distance, double height, double gravity) {
  requireNonNegative(distance, "distance");
  requireFinite(height, "height");
  requirePositive(gravity, "gravity");
}

} // namespace

std::optional<AimSolutions> launchAngles(double distance, double height, double speed, double gravity) {
  validate(distance, height, gravity);
  requirePositive(speed, "speed");
  const double v2 = speed * speed;
  if (distance == 0.0) {
    // Straight up reaches heights up to v^2 / (2g); straight down reaches everything below.
    if (height > 0.0 && height > v2 / (2.0 * gravity)) {
      return std::nullopt;
    }
    const double angle = height >= 0.0 ? pi<double> / 2.0 : -pi<double> / 2.0;
    // |height| = v t -/+ g t^2 / 2: the first root.
    const double vertical = height >= 0.0 ? speed : -speed;
    const double root = std::sqrt(std::fmax(0.0, v2 - 2.0 * gravity * height));
    const double t = height == 0.0 ? 0.0 : (vertical - std::copysign(root, vertical)) / gravity;
    const LaunchSolution s{angle, std::abs(t)};
    return AimSolutions{s, s};
  }
  const double discriminant = v2 * v2 - gravity * (gravity * distance * distance + 2.0 * height * v2);
  if (discriminant < 0.0) {
    return std::nullopt;
  }
  const double root = std::sqrt(discriminant);
  const double gx = gravity * distance;
  // atan2 keeps both angles in (-pi/2, pi/2] without dividing by a small gx.
  const double low = std::atan2(v2 - root, gx);
  const double high = std::atan2(v2 + root, gx);
  const auto time = [&](double angle) { return distance / (speed * std::cos(angle)); };
  return AimSolutions{{low, time(low)}, {high, time(high)}};
}

MinimumSpeed minimumLaunchSpeed(double distance, double height, double gravity) {
  validate(distance, height, gravity);
  const double r = std::hypot(distance, height);
  if (r == 0.0) {
    return {0.0, 0.0};
  }
  // Straight-line cases (distance 0): up needs sqrt(2 g h), down needs nothing.
  const double speed = std::sqrt(gravity * (height + r));
  return {speed, std::atan2(height + r, distance)};
}

std::optional<Aim3> aimAt(const Vec3d& from, const Vec3d& to, double speed, double gravity) {
  requireFinite(from, "from");
  requireFinite(to, "to");
  const Vec3d d = to - from;
  const double horizontal = std::hypot(d.x, d.z);
  const std::optional<AimSolutions> angles = launchAngles(horizontal, d.y, speed, gravity);
  if (!angles) {
    return std::nullopt;
  }
  const double heading = std::atan2(d.z, d.x);
  const auto direction = [&](double elevation) {
    return Vec3d{std::cos(elevation) * std::cos(heading), std::sin(elevation), std::cos(elevation) * std::sin(heading)};
  };
  return Aim3{direction(angles->low.angle), direction(angles->high.angle), angles->low.timeOfFlight,
              angles->high.timeOfFlight};
}

} // namespace impetus
