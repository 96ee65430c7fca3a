// Links the installed impetus::audio (OpenAL Soft and libsndfile underneath) and round-trips a
// tone through a float WAV file; no sound device is needed.
#include <impetus/audio/openal_renderer.hpp>
#include <impetus/audio/wav_file.hpp>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer_audio SCRATCH.wav\n");
    return 2;
  }
  using namespace impetus::audio;
  const AudioClip tone = loopingTone(440.0, 8000, 0.25);
  writeWav(argv[1], tone, WavEncoding::float32);
  const AudioClip back = readWav(argv[1]);
  // 32-bit float WAV stores the samples exactly: the clip comes back identical.
  const bool same =
      back.channels == tone.channels && back.sampleRate == tone.sampleRate && back.samples == tone.samples;
  std::printf("WAV round trip of a 440 Hz tone: %zu frames at %d Hz, %s\n", back.frames(), back.sampleRate,
              same ? "identical" : "DIFFERENT");
  return same ? 0 : 1;
}
