#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/sensors/tilt_sprite.hpp>

#include <cmath>

namespace impetus::sensors {
namespace {

/// The acceleration of a sliding ball: pull - mu_k N v/|v| - c v (N per kg, m/s^2).
Vec2d slidingAcceleration(const Vec2d& pull, double frictionPerKg, double drag, const Vec2d& v) {
  return pull - normalize(v) * frictionPerKg - v * drag;
}

} // namespace

TiltSprite::TiltSprite(const TiltSpriteSettings& s) : settings_(s) {
  requirePositive(s.worldSize.x, "worldSize.x");
  requirePositive(s.worldSize.y, "worldSize.y");
  requirePositive(s.spriteSize.x, "spriteSize.x");
  requirePositive(s.spriteSize.y, "spriteSize.y");
  if (s.spriteSize.x > s.worldSize.x) {
    throwInvalid("spriteSize.x", s.spriteSize.x, "must not exceed worldSize.x");
  }
  if (s.spriteSize.y > s.worldSize.y) {
    throwInvalid("spriteSize.y", s.spriteSize.y, "must not exceed worldSize.y");
  }
  requireNonNegative(s.gravity, "gravity");
  requireNonNegative(s.staticFriction, "staticFriction");
  requireNonNegative(s.kineticFriction, "kineticFriction");
  if (s.kineticFriction > s.staticFriction) {
    throwInvalid("kineticFriction", s.kineticFriction, "must not exceed staticFriction");
  }
  requireNonNegative(s.drag, "drag");
  requireNonNegative(s.restitution, "restitution");
  if (s.restitution > 1.0) {
    throwInvalid("restitution", s.restitution, "must be at most 1");
  }
  // Centred (the book adds half the sprite to the centre, which puts it off centre).
  position_ = maxPosition() * 0.5;
}

void TiltSprite::setState(const Vec2d& position, const Vec2d& velocity) {
  requireFinite(position, "position");
  requireFinite(velocity, "velocity");
  const Vec2d hi = maxPosition();
  if (position.x < 0.0 || position.x > hi.x) {
    throwInvalid("position.x", position.x, "must keep the sprite on the screen");
  }
  if (position.y < 0.0 || position.y > hi.y) {
    throwInvalid("position.y", position.y, "must keep the sprite on the screen");
  }
  position_ = position;
  velocity_ = velocity;
  contact_[0] = position.x <= 0.0 ? 1 : (position.x >= hi.x ? 2 : 0);
  contact_[1] = position.y <= 0.0 ? 1 : (position.y >= hi.y ? 2 : 0);
}

double TiltSprite::update(const Vec3d& readingG, double timestamp) {
  requireFinite(timestamp, "timestamp");
  if (!lastTime_) {
    requireFinite(readingG, "reading");
    lastTime_ = timestamp;
    return 0.0;
  }
  if (timestamp < *lastTime_) {
    throwInvalid("timestamp", timestamp, "goes back");
  }
  const double dt = timestamp - *lastTime_;
  step(readingG, dt);
  lastTime_ = timestamp;
  return dt;
}

void TiltSprite::step(const Vec3d& readingG, double dt) {
  requireFinite(readingG, "reading");
  requireNonNegative(dt, "dt");
  const TiltSpriteSettings& s = settings_;
  // In the gravity-direction convention the reading points where the ball would fall.
  const Vec3d g = s.convention == AccelConvention::gravityDirection ? readingG : -readingG;
  const Vec2d pull{g.x * s.gravity, g.y * s.gravity};
  const double normalPerKg = std::abs(g.z) * s.gravity;
  const double kinetic = s.kineticFriction * normalPerKg;
  double remaining = dt;
  // At most two phases: sliding until the velocity reaches zero, then at rest or sliding anew.
  for (int phase = 0; phase < 2 && remaining > 0.0; ++phase) {
    if (lengthSquared(velocity_) == 0.0) {
      if (length(pull) <= s.staticFriction * normalPerKg) {
        break; // held by static friction
      }
      // Starts to slide along the pull: friction opposes the pull for this step.
      const Vec2d a = pull - normalize(pull) * kinetic;
      position_ += a * (0.5 * remaining * remaining);
      velocity_ = a * remaining;
      remaining = 0.0;
      break;
    }
    const Vec2d a = slidingAcceleration(pull, kinetic, s.drag, velocity_);
    const Vec2d vNext = velocity_ + a * remaining;
    const double along = dot(a, velocity_);
    if (dot(vNext, velocity_) <= 0.0 && along < 0.0 && kinetic > 0.0) {
      // The velocity along its own direction reaches zero at t_s = -|v|^2 / (a . v): stop there.
      const double ts = std::min(remaining, -lengthSquared(velocity_) / along);
      position_ += velocity_ * ts + a * (0.5 * ts * ts);
      velocity_ = {};
      remaining -= ts;
      continue;
    }
    position_ += velocity_ * remaining + a * (0.5 * remaining * remaining);
    velocity_ = vNext;
    remaining = 0.0;
  }
  // The screen's edges.
  const Vec2d hi = maxPosition();
  for (int axis = 0; axis < 2; ++axis) {
    double& p = axis == 0 ? position_.x : position_.y;
    double& v = axis == 0 ? velocity_.x : velocity_.y;
    const double top = axis == 0 ? hi.x : hi.y;
    const bool low = p <= 0.0;
    const bool high = p >= top;
    if (p < 0.0 || p > top) {
      p = p < 0.0 ? 0.0 : top;
      v = -s.restitution * v;
    }
    // A hit is an arrival: the step in which the sprite comes to an edge it was not resting on.
    const int edge = low ? 1 : (high ? 2 : 0);
    if (edge != 0 && edge != contact_[axis]) {
      ++edgeHits_;
    }
    contact_[axis] = edge;
  }
}

Vec2d TiltSprite::screenPosition(const Vec2d& viewPixels) const noexcept {
  const double convertX = viewPixels.x / settings_.worldSize.x;
  const double convertY = viewPixels.y / settings_.worldSize.y;
  return {position_.x * convertX, (settings_.worldSize.y - position_.y - settings_.spriteSize.y) * convertY};
}

} // namespace impetus::sensors
