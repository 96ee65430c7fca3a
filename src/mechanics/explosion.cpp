#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/mechanics/explosion.hpp>

#include <algorithm>
#include <random>

namespace impetus {

KinematicExplosion::KinematicExplosion(const ExplosionSettings& settings)
    : origin_(settings.origin), gravity_(requireFinite(settings.gravity, "gravity")) {
  requireFinite(settings.origin, "origin");
  requireNonNegative(settings.speed, "speed");
  requirePositive(settings.life, "life");
  requireNonNegative(settings.spread, "spread");
  if (settings.direction) {
    requireFinite(*settings.direction, "direction");
  }
  if (settings.count < 1 || settings.count > 100000) {
    throwInvalid("count", settings.count, "must be between 1 and 100000");
  }
  // std::mt19937 is specified bit for bit by the standard; the distributions are not, so the
  // uniform numbers are made here from its raw output to stay identical across libraries.
  std::mt19937 rng(settings.seed);
  const auto uniform = [&rng](double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(rng()) / 4294967296.0);
  };
  particles_.reserve(static_cast<std::size_t>(settings.count));
  for (int i = 0; i < settings.count; ++i) {
    const double speed = uniform(0.5 * settings.speed, settings.speed);
    const double angle = settings.direction ? *settings.direction + uniform(-settings.spread, settings.spread)
                                            : uniform(0.0, 2.0 * pi<double>);
    const double life = settings.life * uniform(0.8, 1.0);
    particles_.push_back({{speed * std::cos(angle), speed * std::sin(angle)}, life});
  }
}

ParticleSnapshot KinematicExplosion::particleAt(std::size_t index, double time) const {
  const ExplosionParticle& p = particles_.at(index);
  requireNonNegative(time, "time");
  ParticleSnapshot s;
  s.position = origin_ + p.velocity * time + Vec2d{0.0, 0.5 * gravity_ * time * time};
  s.alive = time < p.life;
  s.fade = s.alive ? (p.life - time) / p.life : 0.0;
  return s;
}

std::size_t KinematicExplosion::aliveCount(double time) const noexcept {
  return static_cast<std::size_t>(std::count_if(particles_.begin(), particles_.end(),
                                                [time](const ExplosionParticle& p) { return time < p.life; }));
}

double KinematicExplosion::endTime() const noexcept {
  double end = 0.0;
  for (const ExplosionParticle& p : particles_) {
    end = std::max(end, p.life);
  }
  return end;
}

} // namespace impetus
