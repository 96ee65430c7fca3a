// A 2D body or a particle as a sound source or listener: the engines' state as audio::Motion.
// A bridge between layers (rigid2d and particles on one side, audio on the other), so it
// belongs to the umbrella impetus::impetus and no layer includes it.
#pragma once

#include <impetus/audio/motion.hpp>
#include <impetus/particles/particle_world.hpp>
#include <impetus/rigid2d/world.hpp>

namespace impetus::audio {

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
