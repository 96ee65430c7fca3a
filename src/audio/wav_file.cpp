// WAV files through libsndfile.
#include <impetus/audio/wav_file.hpp>
#include <impetus/error.hpp>

#include <sndfile.h>

#include <cmath>
#include <string>

namespace impetus::audio {

void writeWav(const std::filesystem::path& path, const AudioClip& clip, WavEncoding encoding) {
  if (clip.channels < 1 || clip.channels > 8) {
    throwInvalid("clip", clip.channels, "must have 1 to 8 channels (channels given)");
  }
  if (clip.sampleRate <= 0) {
    throwInvalid("clip", clip.sampleRate, "must have a positive sample rate (rate given)");
  }
  if (clip.samples.size() % static_cast<std::size_t>(clip.channels) != 0) {
    throwInvalid("clip", static_cast<double>(clip.samples.size()), "must hold a whole number of frames");
  }
  for (const float s : clip.samples) {
    if (!std::isfinite(s)) {
      throwInvalid("clip", s, "samples must be finite");
    }
  }
  SF_INFO info{};
  info.samplerate = clip.sampleRate;
  info.channels = clip.channels;
  info.format = SF_FORMAT_WAV | (encoding == WavEncoding::pcm16 ? SF_FORMAT_PCM_16 : SF_FORMAT_FLOAT);
  SNDFILE* file = sf_open(path.string().c_str(), SFM_WRITE, &info);
  if (file == nullptr) {
    throw Error("path", "cannot write WAV file '" + path.string() + "': " + sf_strerror(nullptr));
  }
  // Clip to full scale rather than wrap when a float sample exceeds 1.
  sf_command(file, SFC_SET_CLIPPING, nullptr, SF_TRUE);
  const auto frames = static_cast<sf_count_t>(clip.frames());
  const sf_count_t written = sf_writef_float(file, clip.samples.data(), frames);
  const std::string reason = sf_strerror(file);
  sf_close(file);
  if (written != frames) {
    throw Error("path", "cannot write WAV file '" + path.string() + "': " + reason);
  }
}

AudioClip readWav(const std::filesystem::path& path) {
  SF_INFO info{};
  SNDFILE* file = sf_open(path.string().c_str(), SFM_READ, &info);
  if (file == nullptr) {
    throw Error("path", "cannot read sound file '" + path.string() + "': " + sf_strerror(nullptr));
  }
  AudioClip clip;
  clip.channels = info.channels;
  clip.sampleRate = info.samplerate;
  clip.samples.resize(static_cast<std::size_t>(info.frames) * static_cast<std::size_t>(info.channels));
  const sf_count_t read = sf_readf_float(file, clip.samples.data(), info.frames);
  sf_close(file);
  if (read != info.frames) {
    throw Error("path", "cannot read sound file '" + path.string() + "': short read");
  }
  return clip;
}

} // namespace impetus::audio
