#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/mechanics/cannon.hpp>

#include <algorithm>
#include <limits>

namespace impetus {
namespace {

void validate(const CannonSetup& c) {
  requireNonNegative(c.muzzleSpeed, "muzzleSpeed");
  requireFinite(c.altitude, "altitude");
  if (c.altitude < 0.0 || c.altitude > pi<double>) {
    throwInvalid("altitude", c.altitude, "must be in [0, pi] rad (0 = straight up, pi/2 = level)");
  }
  requireFinite(c.azimuth, "azimuth");
  requireNonNegative(c.barrelLength, "barrelLength");
  requireFinite(c.baseHeight, "baseHeight");
}

/// (1 - e^-x) / x, -> 1 as x -> 0.
double decayFraction(double x) { return x == 0.0 ? 1.0 : -std::expm1(-x) / x; }

/// (x - (1 - e^-x)) / x^2, -> 1/2 as x -> 0; the series avoids the cancellation below 1e-4
/// (truncation error x^4/720 < 1e-18 there).
double driftFraction(double x) {
  if (x < 1e-4) {
    return 0.5 - x / 6.0 + x * x / 24.0 - x * x * x / 120.0;
  }
  return (x + std::expm1(-x)) / (x * x);
}

/// Entry fraction u in [0, 1] of the segment p0 -> p1 into the closed box [lo, hi] (slab
/// test), or a negative number when the segment misses it.
double segmentEntry(const Vec3d& p0, const Vec3d& p1, const Vec3d& lo, const Vec3d& hi) {
  double enter = 0.0;
  double leave = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double d = p1[axis] - p0[axis];
    if (d == 0.0) {
      if (p0[axis] < lo[axis] || p0[axis] > hi[axis]) {
        return -1.0;
      }
      continue;
    }
    double t0 = (lo[axis] - p0[axis]) / d;
    double t1 = (hi[axis] - p0[axis]) / d;
    if (t0 > t1) {
      std::swap(t0, t1);
    }
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave) {
      return -1.0;
    }
  }
  return enter;
}

} // namespace

Vec3d barrelDirection(double altitude, double azimuth) {
  // Public on its own too: a NaN angle would otherwise come back as a NaN direction.
  requireFinite(altitude, "altitude");
  requireFinite(azimuth, "azimuth");
  const double b = std::sin(altitude); // projection of a unit barrel on the x-z plane
  return {b * std::cos(azimuth), std::cos(altitude), b * std::sin(azimuth)};
}

Vec3d muzzlePosition(const CannonSetup& cannon) {
  validate(cannon);
  return barrelDirection(cannon.altitude, cannon.azimuth) * cannon.barrelLength + Vec3d{0.0, cannon.baseHeight, 0.0};
}

Vec3d muzzleVelocity(const CannonSetup& cannon) {
  validate(cannon);
  return barrelDirection(cannon.altitude, cannon.azimuth) * cannon.muzzleSpeed;
}

ShellFlight::ShellFlight(const CannonSetup& cannon, double mass, const Atmosphere& air)
    : start_(muzzlePosition(cannon)), launch_(muzzleVelocity(cannon)), mass_(requirePositive(mass, "mass")),
      decayRate_(requireNonNegative(air.dragCoefficient, "dragCoefficient") / mass) {
  requireNonNegative(air.gravity, "gravity");
  requireNonNegative(air.windSpeed, "windSpeed");
  requireFinite(air.windDirection, "windDirection");
  requireNonNegative(air.windCoefficient, "windCoefficient");
  // The wind comes from windDirection: it blows along -(cos gw, 0, sin gw).
  const Vec3d windward{std::cos(air.windDirection), 0.0, std::sin(air.windDirection)};
  force_ = {0.0, -mass * air.gravity, 0.0};
  if (air.windModel == WindModel::movingAir) {
    // -C (v - w) = -C v + C w: the moving air adds the constant part C w.
    force_ += windward * (-air.windSpeed * air.dragCoefficient);
  } else {
    force_ += windward * (-air.windCoefficient * air.windSpeed);
  }
}

ShellState ShellFlight::at(double time) const {
  requireNonNegative(time, "time");
  const double x = decayRate_ * time;
  const double decay = std::exp(-x);
  const double psi = decayFraction(x);
  const double phi = driftFraction(x);
  const Vec3d accel = force_ / mass_;
  ShellState s;
  s.time = time;
  s.velocity = launch_ * decay + accel * (time * psi);
  s.position = start_ + launch_ * (time * psi) + accel * (time * time * phi);
  return s;
}

Vec3d ShellFlight::terminalVelocity() const noexcept {
  const double inf = std::numeric_limits<double>::infinity();
  if (decayRate_ == 0.0) {
    const auto limit = [&](double f) { return f == 0.0 ? 0.0 : std::copysign(inf, f); };
    return {limit(force_.x), limit(force_.y), limit(force_.z)};
  }
  return force_ / (mass_ * decayRate_);
}

ShotResult fireAtTarget(const ShellFlight& flight, const TargetBox& target, double timeStep, double maxTime) {
  requirePositive(timeStep, "timeStep");
  requirePositive(maxTime, "maxTime");
  requireNonNegative(target.size.x, "target.size.x");
  requireNonNegative(target.size.y, "target.size.y");
  requireNonNegative(target.size.z, "target.size.z");
  requireFinite(target.center, "target.center");
  const Vec3d lo = target.center - target.size * 0.5;
  const Vec3d hi = target.center + target.size * 0.5;

  ShotResult result;
  ShellState previous = flight.at(0.0);
  result.trajectory.push_back(previous);
  for (int step = 1;; ++step) {
    const double t = std::min(maxTime, timeStep * step);
    ShellState current = flight.at(t);
    // The ground (y = 0) first, so that the chord to test ends at the ground.
    bool grounded = false;
    if (current.position.y <= 0.0) {
      double below = t;
      double above = previous.time;
      for (int i = 0; i < 200 && below - above > 1e-9; ++i) {
        const double mid = 0.5 * (above + below);
        (flight.at(mid).position.y > 0.0 ? above : below) = mid;
      }
      current = flight.at(below);
      current.position.y = 0.0;
      grounded = true;
    }
    const double entry = segmentEntry(previous.position, current.position, lo, hi);
    if (entry >= 0.0) {
      const double hitTime = previous.time + entry * (current.time - previous.time);
      result.outcome = ShotOutcome::hit;
      result.time = hitTime;
      result.position = lerp(previous.position, current.position, entry);
      result.velocity = flight.at(hitTime).velocity;
      result.trajectory.push_back({hitTime, result.position, result.velocity});
      return result;
    }
    result.trajectory.push_back(current);
    if (grounded || t >= maxTime) {
      result.outcome = grounded ? ShotOutcome::ground : ShotOutcome::timeout;
      result.time = current.time;
      result.position = current.position;
      result.velocity = current.velocity;
      return result;
    }
    previous = current;
  }
}

RifleShot rifleShot(double distance, double muzzleSpeed, double gravity) {
  requireNonNegative(distance, "distance");
  requirePositive(muzzleSpeed, "muzzleSpeed");
  requireNonNegative(gravity, "gravity");
  const double t = distance / muzzleSpeed;
  return {t, 0.5 * gravity * t * t};
}

} // namespace impetus
