#include <impetus/error.hpp>
#include <impetus/sensors/touch_explosion.hpp>

namespace impetus::sensors {

TouchExplosions::TouchExplosions(const TouchExplosionSettings& settings)
    : settings_(settings), tracker_(settings.maxJump) {
  requirePositive(settings.screen.screenHeight, "screenHeight");
  requirePositive(settings.screen.pixelsPerMetre, "pixelsPerMetre");
  if (settings.maxExplosions < 1) {
    throwInvalid("maxExplosions", 0.0, "must be at least 1");
  }
  (void)KinematicExplosion(settings.explosion); // validates the burst settings now, not at the first touch
}

void TouchExplosions::setExplosion(const ExplosionSettings& explosion) {
  (void)KinematicExplosion(explosion);
  settings_.explosion = explosion;
}

std::size_t TouchExplosions::update(double time, std::span<const Vec2d> screenPoints) {
  const std::span<const TrackedTouch> touches = tracker_.update(time, screenPoints);
  std::size_t began = 0;
  const std::size_t down = tracker_.activeCount();
  for (const TrackedTouch& t : touches) {
    if (t.phase != TouchPhase::began || (!settings_.multitouch && down != 1)) {
      continue;
    }
    ExplosionSettings s = settings_.explosion;
    s.origin = settings_.screen.toWorld(t.position);
    // A seed per burst: the same recording gives the same particles, and bursts differ.
    s.seed = settings_.explosion.seed + static_cast<std::uint32_t>(started_);
    bursts_.push_back({KinematicExplosion(s), time, t.id});
    ++started_;
    ++began;
    if (bursts_.size() > settings_.maxExplosions) {
      bursts_.pop_front();
    }
  }
  while (!bursts_.empty() && time - bursts_.front().start >= bursts_.front().explosion.endTime()) {
    bursts_.pop_front();
  }
  return began;
}

std::size_t TouchExplosions::aliveParticles(double time) const noexcept {
  std::size_t n = 0;
  for (const TouchBurst& b : bursts_) {
    if (time >= b.start) {
      n += b.explosion.aliveCount(time - b.start);
    }
  }
  return n;
}

} // namespace impetus::sensors
