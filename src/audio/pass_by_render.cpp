#include <impetus/audio/pass_by_render.hpp>
#include <impetus/error.hpp>

#include <algorithm>
#include <cmath>

namespace impetus::audio {

double passByDuration(double speed) {
  requireNonNegative(speed, "speed");
  const double half = speed > 0.0 ? std::clamp(200.0 / speed, 2.0, 10.0) : 2.0;
  return 2.0 * half;
}

PassByRender renderPassBy(const PassBy& pass, double duration, int sampleRate) {
  // The renderer's range, checked first: the Nyquist test below would blame "frequency".
  if (sampleRate < 8000 || sampleRate > 192000) {
    throwInvalid("sampleRate", sampleRate, "must be within 8000..192000 Hz");
  }
  requirePositive(duration, "duration");
  // The rendering is held in memory (an hour of stereo float at 44.1 kHz is 1.3 GB).
  if (duration > 3600.0) {
    throwInvalid("duration", duration, "must be at most 3600 s");
  }
  PassByRender out;
  out.pass = pass;
  out.pass.closestTime = 0.5 * duration;
  requireValid(out.pass);
  // The tone itself must stay below Nyquist once shifted up by the approach.
  const double highest = pass.frequency * pass.speedOfSound / (pass.speedOfSound - pass.speed);
  if (!(highest < 0.45 * sampleRate)) {
    throwInvalid("frequency", pass.frequency, "shifted up by the approach it would pass 0.45 times the sample rate");
  }
  RendererSettings settings;
  settings.sampleRate = sampleRate;
  settings.speedOfSound = pass.speedOfSound;
  LoopbackRenderer renderer(settings);
  const AudioClip tone = loopingTone(pass.frequency, sampleRate, 1.0, 0.5);
  // loopingTone's whole number of periods in its 1 s loop.
  out.toneFrequency = std::max(1.0, std::round(pass.frequency)) * sampleRate / static_cast<double>(tone.frames());
  SourceSettings source;
  source.attenuation = {DistanceModel::inverseClamped, pass.closestApproach, 1e30, 1.0};
  source.gain = 1.0;
  const LoopbackRenderer::SourceId id = renderer.addSource(tone, source);
  renderer.setListener({});
  // The library's pass runs along x at y = d; in OpenAL's frame the listener faces -z, so the
  // source passes in front of it at z = -d.
  const PassBy p = out.pass;
  renderer.followSource(id, [&renderer, p] {
    const Vec3d s = passBySourcePosition(p, renderer.time());
    return Motion{{s.x, 0.0, -s.y}, {p.speed, 0.0, 0.0}};
  });
  renderer.play(id);
  out.clip = renderer.render(static_cast<std::size_t>(std::lround(duration * sampleRate)));
  return out;
}

} // namespace impetus::audio
