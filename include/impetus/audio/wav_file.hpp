// WAV files through libsndfile (impetus::audio): a rendered scene written where no sound
// hardware exists, and read back to be measured.
#pragma once

#include <impetus/audio/audio_clip.hpp>

#include <filesystem>

namespace impetus::audio {

enum class WavEncoding {
  pcm16,   ///< 16-bit integer PCM: plays everywhere; samples clipped to -1..1
  float32, ///< 32-bit IEEE float: keeps the rendering's exact values
};

/// Writes `clip` as a WAV file. Throws impetus::Error naming "clip" for an empty or malformed
/// clip (channels 1..8, sample rate > 0, samples a whole number of frames, all finite) and
/// "path" when the file cannot be written (the message gives libsndfile's reason).
void writeWav(const std::filesystem::path& path, const AudioClip& clip, WavEncoding encoding = WavEncoding::pcm16);

/// Reads a WAV (or any libsndfile format) file as float samples. Throws impetus::Error naming
/// "path" when it cannot be read.
[[nodiscard]] AudioClip readWav(const std::filesystem::path& path);

} // namespace impetus::audio
