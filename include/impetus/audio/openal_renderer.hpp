// 3D sound through OpenAL Soft, rendered without sound hardware (impetus::audio).
//
// The renderer opens OpenAL Soft's loopback device (ALC_SOFT_loopback): instead of playing to
// a sound card it mixes on demand into memory, as many frames as asked for, so a scene renders
// to a WAV file on a headless server or in a test. A listener and sources follow the
// simulation's bodies: before each block of frames the renderer reads every follower's
// position and velocity (audio/motion.hpp) and hands them to OpenAL, which pans, attenuates
// with distance and shifts the pitch by Doppler.
//
// Physical units: positions in m, velocities in m/s. OpenAL's speed of sound is set to
// c / metresPerUnit (343.3 m/s by default), so with a Doppler factor of 1 the shift is the
// physical one; each source's distance model (audio/propagation.hpp) with inverse-clamped
// attenuation and rolloff 1 makes the amplitude fall as 1/r beyond its reference distance (the
// intensity as 1/r^2).
//
// One renderer is one OpenAL device and context; calls make its context current, so use
// renderers from one thread.
#pragma once

#include <impetus/audio/audio_clip.hpp>
#include <impetus/audio/motion.hpp>
#include <impetus/audio/propagation.hpp>
#include <impetus/audio/waves.hpp>

#include <cstddef>
#include <functional>
#include <memory>

namespace impetus::audio {

struct RendererSettings {
  int sampleRate = 44100;                   ///< Hz, 8000..192000
  double speedOfSound = openALSpeedOfSound; ///< m/s, > 0
  double metresPerUnit = 1.0;               ///< size of a world unit, m, > 0
  double dopplerFactor = 1.0;               ///< >= 0: 1 physical, 0 off
  /// Frames mixed between two updates of the followers (10 ms at 44.1 kHz): positions and
  /// velocities are sampled at this rate. > 0.
  std::size_t updateFrames = 441;
};

struct SourceSettings {
  DistanceAttenuation attenuation{}; ///< OpenAL's per-source distance model
  double gain = 1.0;                 ///< >= 0, amplitude at the reference distance
  bool looping = true;
};

class LoopbackRenderer {
public:
  using SourceId = int;

  /// Opens the loopback device with a stereo float output. Throws impetus::Error naming
  /// "device" when OpenAL Soft's loopback device is not available (no OpenAL library, no
  /// ALC_SOFT_loopback, or the format refused), or the setting at fault.
  explicit LoopbackRenderer(const RendererSettings& settings = {});
  ~LoopbackRenderer();
  LoopbackRenderer(LoopbackRenderer&&) noexcept;
  LoopbackRenderer& operator=(LoopbackRenderer&&) noexcept;
  LoopbackRenderer(const LoopbackRenderer&) = delete;
  LoopbackRenderer& operator=(const LoopbackRenderer&) = delete;

  /// Adds a source playing `clip` (mono; any sample rate) with its distance model, stopped.
  /// Throws impetus::Error naming "clip" or the setting at fault.
  SourceId addSource(const AudioClip& clip, const SourceSettings& settings = {});

  /// The listener's position and velocity, facing `forward` with `up` overhead (OpenAL's
  /// default: facing -z, y up).
  void setListener(const Motion& motion, const Vec3d& forward = {0.0, 0.0, -1.0}, const Vec3d& up = {0.0, 1.0, 0.0});
  void setSource(SourceId source, const Motion& motion);
  /// Reads the listener's / a source's motion from `follow` before every block of frames.
  void followListener(std::function<Motion()> follow);
  void followSource(SourceId source, std::function<Motion()> follow);

  void play(SourceId source);
  void stop(SourceId source);

  /// Mixes `frames` stereo frames. Before each block of updateFrames, `beforeBlock(t)` runs
  /// (t: the time of the block's first frame since the renderer started, s; e.g. to step the
  /// simulation to t) and the followers are read.
  [[nodiscard]] AudioClip render(std::size_t frames, const std::function<void(double)>& beforeBlock = {});

  [[nodiscard]] int sampleRate() const noexcept;
  /// Time rendered so far, s.
  [[nodiscard]] double time() const noexcept;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// A tone of `frequency` (Hz) as a mono clip that loops seamlessly: a whole number of periods
/// in about `seconds` (0 < seconds <= 3600; the period count rounded, so the tone is f within
/// 0.5 / frames). Peak `amplitude` (0..1].
[[nodiscard]] AudioClip loopingTone(double frequency, int sampleRate = 44100, double seconds = 1.0,
                                    double amplitude = 0.5);

} // namespace impetus::audio
