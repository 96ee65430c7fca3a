// Dragging a particle of a ParticleWorld with the mouse: the nearest particle within reach is
// pinned (infinite mass) and moved toward the pointer before every step, by at most `maxMove` a
// step (0.2 m: 12 m/s at 60 Hz), so the constraints and springs attached to it pull the rest
// along; released, it is unpinned (unless it was pinned before). The limit matters: a grabbed
// particle teleported metres in one step yanks its neighbours to thousands of m/s, where the
// world's explicit quadratic drag overshoots and the state runs away to NaN.
#pragma once

#include <impetus/math/vec2.hpp>
#include <impetus/particles/particle_world.hpp>

#include <optional>
#include <span>

namespace impetus::samples {

class ParticleDrag {
public:
  /// Grabs the particle of `world` nearest to `point` (x-y plane) within `reach` metres; false
  /// when there is none. `pinned` lists the particles that are pinned already (kept pinned).
  bool grab(ParticleWorld& world, const Vec2f& point, float reach, std::span<const ParticleId> pinned);
  void moveTo(const Vec2f& point) { target_ = point; }
  /// Puts the grabbed particle at the target, at rest: call before each step, with the world it
  /// was grabbed in (as release).
  void apply(ParticleWorld& world, float maxMove = 0.2f) const;
  void release(ParticleWorld& world);
  /// Forget the grab without touching a world (it was rebuilt).
  void reset() { grabbed_.reset(); }
  [[nodiscard]] bool active() const noexcept { return grabbed_.has_value(); }
  [[nodiscard]] const Vec2f& target() const noexcept { return target_; }

private:
  struct Grab {
    ParticleId particle;
    bool wasPinned;
  };
  std::optional<Grab> grabbed_;
  Vec2f target_;
};

} // namespace impetus::samples
