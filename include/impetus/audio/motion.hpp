// Where a sound source or listener is and how it moves (ch. 26): what 3D audio needs from the
// simulation each update. OpenAL takes both: the position for panning and distance attenuation,
// the velocity for the Doppler shift (without a velocity there is no Doppler, however the
// position changes). Set the velocity to the body's own (dx/dt), not to a per-frame step: the
// book's demo sets a tenth of the real speed and hides it behind a Doppler factor of 10.
// A rigid2d body's or a particle's motion: impetus/bridges/audio_motion.hpp (audio is a layer
// of its own and does not depend on the engines).
#pragma once

#include <impetus/math/vec3.hpp>

namespace impetus::audio {

struct Motion {
  Vec3d position{}; ///< m (world units)
  Vec3d velocity{}; ///< m/s
};

} // namespace impetus::audio
