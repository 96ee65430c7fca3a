// Where a sound source or listener is and how it moves (ch. 26): what 3D audio needs from the
// simulation each update. OpenAL takes both: the position for panning and distance attenuation,
// the velocity for the Doppler shift (without a velocity there is no Doppler, however the
// position changes). Set the velocity to the body's own (dx/dt), not to a per-frame step: the
// book's demo sets a tenth of the real speed and hides it behind a Doppler factor of 10.
#pragma once

#include <impetus/math/vec3.hpp>
#include <impetus/particles/particle_world.hpp>
#include <impetus/rigid2d/world.hpp>

namespace impetus::audio {

struct Motion {
  Vec3d position{}; ///< m (world units)
  Vec3d velocity{}; ///< m/s
};

/// A 2D body as a sound source or listener: its centre-of-mass velocity and origin, in the
/// plane z = `depth` (m) of the 3D sound scene (x right, y up, as the 2D world).
[[nodiscard]] inline Motion motionOf(const rigid2d::World& world, rigid2d::BodyId body, double depth = 0.0) {
  const Vec2f p = world.position(body);
  const Vec2f v = world.linearVelocity(body);
  return {{p.x, p.y, depth}, {v.x, v.y, 0.0}};
}

/// A particle as a sound source or listener.
[[nodiscard]] inline Motion motionOf(const ParticleWorld& world, ParticleId particle) {
  const Vec3f p = world.position(particle);
  const Vec3f v = world.velocity(particle);
  return {{p.x, p.y, p.z}, {v.x, v.y, v.z}};
}

} // namespace impetus::audio
