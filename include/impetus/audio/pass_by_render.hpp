// The Doppler pass, rendered (ch. 26, impetus::audio): a source of frequency f passes a
// listener in a straight line at v m/s, closest approach d, the closest point at the middle of
// the clip. What `impetus demo doppler` writes to a WAV file and the tests measure.
//
// Geometry (OpenAL's frame: x right, y up, -z ahead of the listener at the origin): the source
// moves along x at z = -d, from the left (-x) to the right, passing in front of the listener.
// Its distance model is inverse-clamped with the reference distance d: full level at the pass,
// amplitude falling as 1/r on either side.
#pragma once

#include <impetus/audio/audio_clip.hpp>
#include <impetus/audio/doppler.hpp>
#include <impetus/audio/openal_renderer.hpp>

namespace impetus::audio {

struct PassByRender {
  AudioClip clip;           ///< stereo, the pass centred
  PassBy pass;              ///< the pass rendered (closestTime = half the duration)
  double toneFrequency = 0; ///< the looping tone's exact frequency (f within 0.5/44100), Hz
};

/// Renders the pass over `duration` s (0 < duration <= 3600) at `sampleRate` Hz (8000..192000).
/// pass.closestTime is ignored (set to duration/2); pass.speedOfSound sets the renderer's.
/// Throws impetus::Error for an invalid pass (speed at or above c), duration, sample rate or an
/// unavailable OpenAL device ("device").
[[nodiscard]] PassByRender renderPassBy(const PassBy& pass, double duration, int sampleRate = 44100);

/// The default duration for a pass at `speed` (m/s): the source starts about 200 m away
/// (20 closest approaches), at least 2 s and at most 10 s each side.
[[nodiscard]] double passByDuration(double speed);

} // namespace impetus::audio
