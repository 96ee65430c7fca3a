// The OpenAL Soft loopback renderer. The loopback entry points are extensions: looked up with
// alcGetProcAddress after checking ALC_SOFT_loopback, so a library without them is a clear
// error rather than a link failure.
#include <impetus/audio/openal_renderer.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>

#include <AL/al.h>
#include <AL/alc.h>
#include <AL/alext.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace impetus::audio {
namespace {

template <class F> F procAddress(ALCdevice* device, const char* name) {
  // alcGetProcAddress returns the function as an object pointer (void*); converting it back is
  // what the OpenAL API requires of its callers.
  return reinterpret_cast<F>(alcGetProcAddress(device, name));
}

ALenum distanceModelEnum(DistanceModel m) {
  switch (m) {
  case DistanceModel::none:
    return AL_NONE;
  case DistanceModel::inverse:
    return AL_INVERSE_DISTANCE;
  case DistanceModel::inverseClamped:
    return AL_INVERSE_DISTANCE_CLAMPED;
  case DistanceModel::linear:
    return AL_LINEAR_DISTANCE;
  case DistanceModel::linearClamped:
    return AL_LINEAR_DISTANCE_CLAMPED;
  case DistanceModel::exponent:
    return AL_EXPONENT_DISTANCE;
  case DistanceModel::exponentClamped:
    return AL_EXPONENT_DISTANCE_CLAMPED;
  }
  return AL_INVERSE_DISTANCE_CLAMPED;
}

constexpr double maxClipSeconds = 3600.0;

void requireFiniteVector(const Vec3d& v, const char* field) {
  if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))) {
    throwInvalid(field, length(v), "must be finite");
  }
}

} // namespace

struct LoopbackRenderer::Impl {
  RendererSettings settings;
  ALCdevice* device = nullptr;
  ALCcontext* context = nullptr;
  LPALCRENDERSAMPLESSOFT renderSamples = nullptr;
  std::vector<ALuint> buffers;
  std::vector<ALuint> sources;
  std::vector<std::function<Motion()>> sourceFollowers;
  std::function<Motion()> listenerFollower;
  std::size_t framesRendered = 0;

  ~Impl() {
    if (context != nullptr) {
      alcMakeContextCurrent(context);
      if (!sources.empty()) {
        alSourceStopv(static_cast<ALsizei>(sources.size()), sources.data());
        alDeleteSources(static_cast<ALsizei>(sources.size()), sources.data());
      }
      if (!buffers.empty()) {
        alDeleteBuffers(static_cast<ALsizei>(buffers.size()), buffers.data());
      }
      alcMakeContextCurrent(nullptr);
      alcDestroyContext(context);
    }
    if (device != nullptr) {
      alcCloseDevice(device);
    }
  }

  void makeCurrent() const {
    if (alcGetCurrentContext() != context) {
      alcMakeContextCurrent(context);
    }
  }

  /// Throws naming "openal" when the last AL call failed.
  static void check(const char* what) {
    const ALenum error = alGetError();
    if (error != AL_NO_ERROR) {
      const ALchar* text = alGetString(error);
      throw Error("openal", std::string("OpenAL ") + what + " failed: " + (text != nullptr ? text : "unknown error"));
    }
  }

  ALuint sourceAt(SourceId id) const {
    if (id < 0 || static_cast<std::size_t>(id) >= sources.size()) {
      throwInvalid("source", id, "is not a source of this renderer");
    }
    return sources[static_cast<std::size_t>(id)];
  }

  void applySource(SourceId id, const Motion& m) const {
    requireFiniteVector(m.position, "position");
    requireFiniteVector(m.velocity, "velocity");
    const ALuint s = sourceAt(id);
    alSource3f(s, AL_POSITION, static_cast<ALfloat>(m.position.x), static_cast<ALfloat>(m.position.y),
               static_cast<ALfloat>(m.position.z));
    alSource3f(s, AL_VELOCITY, static_cast<ALfloat>(m.velocity.x), static_cast<ALfloat>(m.velocity.y),
               static_cast<ALfloat>(m.velocity.z));
    check("alSource3f");
  }

  static void applyListener(const Motion& m) {
    requireFiniteVector(m.position, "position");
    requireFiniteVector(m.velocity, "velocity");
    alListener3f(AL_POSITION, static_cast<ALfloat>(m.position.x), static_cast<ALfloat>(m.position.y),
                 static_cast<ALfloat>(m.position.z));
    alListener3f(AL_VELOCITY, static_cast<ALfloat>(m.velocity.x), static_cast<ALfloat>(m.velocity.y),
                 static_cast<ALfloat>(m.velocity.z));
    check("alListener3f");
  }
};

LoopbackRenderer::LoopbackRenderer(const RendererSettings& settings) : impl_(std::make_unique<Impl>()) {
  if (settings.sampleRate < 8000 || settings.sampleRate > 192000) {
    throwInvalid("sampleRate", settings.sampleRate, "must be within 8000..192000 Hz");
  }
  requirePositive(settings.speedOfSound, "speedOfSound");
  requirePositive(settings.metresPerUnit, "metresPerUnit");
  requireNonNegative(settings.dopplerFactor, "dopplerFactor");
  if (settings.updateFrames == 0) {
    throwInvalid("updateFrames", 0.0, "must be positive");
  }
  impl_->settings = settings;
  if (alcIsExtensionPresent(nullptr, "ALC_SOFT_loopback") != ALC_TRUE) {
    throw Error("device", "no OpenAL loopback device: the OpenAL library lacks ALC_SOFT_loopback (OpenAL Soft has it)");
  }
  const auto openLoopback = procAddress<LPALCLOOPBACKOPENDEVICESOFT>(nullptr, "alcLoopbackOpenDeviceSOFT");
  const auto formatSupported = procAddress<LPALCISRENDERFORMATSUPPORTEDSOFT>(nullptr, "alcIsRenderFormatSupportedSOFT");
  impl_->renderSamples = procAddress<LPALCRENDERSAMPLESSOFT>(nullptr, "alcRenderSamplesSOFT");
  if (openLoopback == nullptr || formatSupported == nullptr || impl_->renderSamples == nullptr) {
    throw Error("device", "no OpenAL loopback device: ALC_SOFT_loopback's functions are missing");
  }
  impl_->device = openLoopback(nullptr);
  if (impl_->device == nullptr) {
    throw Error("device", "no OpenAL loopback device: alcLoopbackOpenDeviceSOFT failed");
  }
  if (formatSupported(impl_->device, settings.sampleRate, ALC_STEREO_SOFT, ALC_FLOAT_SOFT) != ALC_TRUE) {
    throw Error("device", "the OpenAL loopback device cannot render stereo float at " +
                              std::to_string(settings.sampleRate) + " Hz");
  }
  // Stereo float at the asked rate; HRTF off: plain panning, the same on every machine.
  const ALCint attributes[] = {ALC_FORMAT_CHANNELS_SOFT,
                               ALC_STEREO_SOFT,
                               ALC_FORMAT_TYPE_SOFT,
                               ALC_FLOAT_SOFT,
                               ALC_FREQUENCY,
                               settings.sampleRate,
                               ALC_HRTF_SOFT,
                               ALC_FALSE,
                               0};
  impl_->context = alcCreateContext(impl_->device, attributes);
  if (impl_->context == nullptr || alcMakeContextCurrent(impl_->context) != ALC_TRUE) {
    throw Error("device", "the OpenAL loopback device refused a context");
  }
  alGetError(); // clear
  // Physical units: c in world units per second. Per-source distance models.
  alSpeedOfSound(static_cast<ALfloat>(settings.speedOfSound / settings.metresPerUnit));
  alDopplerFactor(static_cast<ALfloat>(settings.dopplerFactor));
  alEnable(AL_SOURCE_DISTANCE_MODEL);
  Impl::check("context setup");
}

LoopbackRenderer::~LoopbackRenderer() = default;
LoopbackRenderer::LoopbackRenderer(LoopbackRenderer&&) noexcept = default;
LoopbackRenderer& LoopbackRenderer::operator=(LoopbackRenderer&&) noexcept = default;

LoopbackRenderer::SourceId LoopbackRenderer::addSource(const AudioClip& clip, const SourceSettings& settings) {
  if (clip.channels != 1) {
    throwInvalid("clip", clip.channels, "a positional source must be mono (channels given)");
  }
  if (clip.sampleRate <= 0) {
    throwInvalid("clip", clip.sampleRate, "must have a positive sample rate (rate given)");
  }
  if (clip.samples.empty()) {
    throwInvalid("clip", 0.0, "must have samples (sample count given)");
  }
  requireNonNegative(settings.gain, "gain");
  const DistanceAttenuation& a = settings.attenuation;
  (void)distanceGain(a, a.referenceDistance); // validates the model's parameters
  impl_->makeCurrent();
  // 16-bit PCM: every OpenAL implementation takes it.
  std::vector<std::int16_t> pcm(clip.samples.size());
  for (std::size_t i = 0; i < pcm.size(); ++i) {
    const float s = clip.samples[i];
    if (!std::isfinite(s)) {
      throwInvalid("clip", s, "samples must be finite");
    }
    pcm[i] = static_cast<std::int16_t>(std::lround(std::clamp(s, -1.0f, 1.0f) * 32767.0f));
  }
  ALuint buffer = 0;
  alGenBuffers(1, &buffer);
  Impl::check("alGenBuffers");
  alBufferData(buffer, AL_FORMAT_MONO16, pcm.data(), static_cast<ALsizei>(pcm.size() * sizeof(std::int16_t)),
               clip.sampleRate);
  impl_->buffers.push_back(buffer);
  Impl::check("alBufferData");
  ALuint source = 0;
  alGenSources(1, &source);
  Impl::check("alGenSources");
  impl_->sources.push_back(source);
  impl_->sourceFollowers.emplace_back();
  alSourcei(source, AL_BUFFER, static_cast<ALint>(buffer));
  alSourcei(source, AL_LOOPING, settings.looping ? AL_TRUE : AL_FALSE);
  alSourcef(source, AL_GAIN, static_cast<ALfloat>(settings.gain));
  alSourcef(source, AL_MAX_GAIN, std::max(1.0f, static_cast<ALfloat>(settings.gain)));
  alSourcei(source, AL_DISTANCE_MODEL, distanceModelEnum(a.model));
  alSourcef(source, AL_REFERENCE_DISTANCE, static_cast<ALfloat>(a.referenceDistance / impl_->settings.metresPerUnit));
  alSourcef(source, AL_MAX_DISTANCE,
            static_cast<ALfloat>(std::min(a.maxDistance / impl_->settings.metresPerUnit,
                                          static_cast<double>(std::numeric_limits<float>::max()))));
  alSourcef(source, AL_ROLLOFF_FACTOR, static_cast<ALfloat>(a.rolloff));
  Impl::check("source setup");
  return static_cast<SourceId>(impl_->sources.size() - 1);
}

void LoopbackRenderer::setListener(const Motion& motion, const Vec3d& forward, const Vec3d& up) {
  requireFiniteVector(forward, "forward");
  requireFiniteVector(up, "up");
  if (!(length(forward) > 0.0)) {
    throwInvalid("forward", length(forward), "must be non-zero (length given)");
  }
  if (!(length(cross(forward, up)) > 0.0)) {
    throwInvalid("up", length(up), "must be non-zero and not parallel to forward (length given)");
  }
  impl_->makeCurrent();
  Impl::applyListener(motion);
  const ALfloat orientation[] = {static_cast<ALfloat>(forward.x), static_cast<ALfloat>(forward.y),
                                 static_cast<ALfloat>(forward.z), static_cast<ALfloat>(up.x),
                                 static_cast<ALfloat>(up.y),      static_cast<ALfloat>(up.z)};
  alListenerfv(AL_ORIENTATION, orientation);
  Impl::check("alListenerfv");
}

void LoopbackRenderer::setSource(SourceId source, const Motion& motion) {
  impl_->makeCurrent();
  impl_->applySource(source, motion);
}

void LoopbackRenderer::followListener(std::function<Motion()> follow) { impl_->listenerFollower = std::move(follow); }

void LoopbackRenderer::followSource(SourceId source, std::function<Motion()> follow) {
  (void)impl_->sourceAt(source);
  impl_->sourceFollowers[static_cast<std::size_t>(source)] = std::move(follow);
}

void LoopbackRenderer::play(SourceId source) {
  impl_->makeCurrent();
  alSourcePlay(impl_->sourceAt(source));
  Impl::check("alSourcePlay");
}

void LoopbackRenderer::stop(SourceId source) {
  impl_->makeCurrent();
  alSourceStop(impl_->sourceAt(source));
  Impl::check("alSourceStop");
}

AudioClip LoopbackRenderer::render(std::size_t frames, const std::function<void(double)>& beforeBlock) {
  impl_->makeCurrent();
  AudioClip clip;
  clip.channels = 2;
  clip.sampleRate = impl_->settings.sampleRate;
  clip.samples.resize(frames * 2);
  std::size_t done = 0;
  while (done < frames) {
    if (beforeBlock) {
      beforeBlock(time());
    }
    if (impl_->listenerFollower) {
      Impl::applyListener(impl_->listenerFollower());
    }
    for (std::size_t i = 0; i < impl_->sourceFollowers.size(); ++i) {
      if (impl_->sourceFollowers[i]) {
        impl_->applySource(static_cast<SourceId>(i), impl_->sourceFollowers[i]());
      }
    }
    const std::size_t block = std::min(impl_->settings.updateFrames, frames - done);
    impl_->renderSamples(impl_->device, clip.samples.data() + 2 * done, static_cast<ALCsizei>(block));
    done += block;
    impl_->framesRendered += block;
  }
  return clip;
}

int LoopbackRenderer::sampleRate() const noexcept { return impl_->settings.sampleRate; }

double LoopbackRenderer::time() const noexcept {
  return static_cast<double>(impl_->framesRendered) / impl_->settings.sampleRate;
}

AudioClip loopingTone(double frequency, int sampleRate, double seconds, double amplitude) {
  requirePositive(frequency, "frequency");
  if (sampleRate <= 0) {
    throwInvalid("sampleRate", sampleRate, "must be positive");
  }
  requirePositive(seconds, "seconds");
  // The clip is held in memory: an hour is 159 million frames at 44.1 kHz (a larger value
  // would overflow the frame count or exhaust memory rather than be refused).
  if (seconds > maxClipSeconds) {
    throwInvalid("seconds", seconds, "must be at most 3600 s");
  }
  if (!(frequency < 0.5 * sampleRate)) {
    throwInvalid("frequency", frequency, "must be below the Nyquist frequency, half the sample rate");
  }
  if (!(std::isfinite(amplitude) && amplitude > 0.0 && amplitude <= 1.0)) {
    throwInvalid("amplitude", amplitude, "must be within (0, 1]");
  }
  // A whole number of periods k in about `seconds`, over n frames: the loop joins without a
  // click and plays k sampleRate / n Hz, within 0.5/n of f.
  const double periods = std::max(1.0, std::round(frequency * seconds));
  const auto n = static_cast<std::size_t>(std::lround(periods * sampleRate / frequency));
  AudioClip clip;
  clip.channels = 1;
  clip.sampleRate = sampleRate;
  clip.samples.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    clip.samples[i] = static_cast<float>(
        amplitude * std::sin(2.0 * pi<double> * periods * static_cast<double>(i) / static_cast<double>(n)));
  }
  return clip;
}

} // namespace impetus::audio
