#include "particle_drag.hpp"

#include <algorithm>

namespace impetus::samples {

bool ParticleDrag::grab(ParticleWorld& world, const Vec2f& point, float reach, std::span<const ParticleId> pinned) {
  const auto positions = world.positions();
  const auto ids = world.ids();
  float best = reach * reach;
  std::optional<std::size_t> found;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const float d2 = lengthSquared(Vec2f{positions[i].x, positions[i].y} - point);
    if (d2 <= best) {
      best = d2;
      found = i;
    }
  }
  if (!found) {
    return false;
  }
  const ParticleId id = ids[*found];
  grabbed_ = Grab{id, std::find(pinned.begin(), pinned.end(), id) != pinned.end()};
  target_ = point;
  world.setPinned(id, true);
  return true;
}

void ParticleDrag::apply(ParticleWorld& world, float maxMove) const {
  if (grabbed_ && world.isValid(grabbed_->particle)) {
    const Vec3f p = world.position(grabbed_->particle);
    Vec2f move = target_ - Vec2f{p.x, p.y};
    const float distance = length(move);
    if (distance > maxMove) {
      move *= maxMove / distance;
    }
    world.setPosition(grabbed_->particle, {p.x + move.x, p.y + move.y, p.z});
    world.setVelocity(grabbed_->particle, {});
  }
}

void ParticleDrag::release(ParticleWorld& world) {
  if (grabbed_ && world.isValid(grabbed_->particle) && !grabbed_->wasPinned) {
    world.setPinned(grabbed_->particle, false);
  }
  grabbed_.reset();
}

} // namespace impetus::samples
