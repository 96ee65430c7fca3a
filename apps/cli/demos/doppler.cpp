// The Doppler demo (ch. 26): a source of frequency F passes a listener in a straight line at
// V m/s, closest approach 10 m at the middle of the clip, rendered through OpenAL Soft's
// loopback device (impetus::audio) so it needs no sound hardware:
//   impetus demo doppler --speed V --frequency F --out FILE.wav
// It prints the Doppler formula's frequencies (approaching f c/(c - v), receding f c/(c + v))
// next to the pitch measured in the rendering by zero crossings, over the pass. The book's
// OpenAL demo (a Creative SDK "PlayStatic" variant) set the velocity to a tenth of the real
// speed and hid it behind a Doppler factor of 10; here the velocity is the source's own and the
// factor 1, so the shift is the physical one.
//
// Output (with --out): FILE.wav when it ends in .wav, else DIR/doppler.wav and DIR/doppler.csv
// (time, formula and measured pitch). Without impetus::audio (OpenAL Soft, libsndfile) the demo
// says so and exits with demoUnavailable.
#include "demos/demos.hpp"

#include <impetus/audio/doppler.hpp>
#include <impetus/error.hpp>
#if IMPETUS_HAVE_AUDIO
#include <impetus/audio/pass_by_render.hpp>
#include <impetus/audio/pitch.hpp>
#include <impetus/audio/wav_file.hpp>
#endif

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

namespace impetus::cli {
namespace {

constexpr double closestApproach = 10.0; // m
constexpr double speedOfSound = audio::openALSpeedOfSound;

} // namespace

int demoDoppler(const DemoOptions& options) {
  audio::PassBy pass;
  pass.frequency = options.frequency.value_or(440.0);
  pass.speed = options.speed.value_or(30.0);
  pass.closestApproach = closestApproach;
  pass.speedOfSound = speedOfSound;
  try {
    audio::requireValid(pass);
  } catch (const Error& e) {
    fmt::print(stderr, "error: --{}\n", e.what());
    return 2;
  }
  const double c = speedOfSound;
  const double approaching = pass.frequency * c / (c - pass.speed);
  const double receding = pass.frequency * c / (c + pass.speed);
  fmt::print("Doppler pass (ch. 26): a {} Hz source at {} m/s passes a listener {} m away, c = {} m/s\n",
             pass.frequency, pass.speed, closestApproach, c);
  fmt::print("the formula: approaching f c/(c - v) = {:.2f} Hz, receding f c/(c + v) = {:.2f} Hz, {:.2f} semitones "
             "down as it passes\n",
             approaching, receding, 12.0 * std::log2(approaching / receding));
#if IMPETUS_HAVE_AUDIO
  audio::PassByRender render;
  const double duration = audio::passByDuration(pass.speed);
  try {
    render = audio::renderPassBy(pass, duration);
  } catch (const Error& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return e.field() == "device" ? 1 : 2;
  }
  const std::vector<float> mono = render.clip.mono();
  const int rate = render.clip.sampleRate;
  audio::PassBy rendered = render.pass;
  rendered.frequency = render.toneFrequency;
  fmt::print("rendered by OpenAL Soft (loopback device, {} Hz stereo), {:.1f} s, the closest point at {:.1f} s; "
             "pitch measured by zero crossings over 0.25 s:\n",
             rate, duration, render.pass.closestTime);
  fmt::print("{:>7} {:>9} {:>12} {:>12} {:>9}\n", "t s", "x m", "formula Hz", "measured Hz", "error %");
  std::vector<std::vector<double>> rows;
  const double window = 0.25;
  const auto count = static_cast<std::size_t>(window * rate);
  for (double t = 0.5; t <= duration - 0.5 + 1e-9; t += (duration - 1.0) / 12.0) {
    const auto begin = static_cast<std::size_t>(t * rate) - count / 2;
    const double measured = audio::zeroCrossingPitch(mono, rate, begin, count).frequency;
    // OpenAL shifts by the positions now (no propagation delay): the formula with cos(theta) now.
    const double formula = audio::passByInstantaneousFrequency(rendered, t);
    const double x = audio::passBySourcePosition(rendered, t).x;
    fmt::print("{:>7.2f} {:>9.1f} {:>12.2f} {:>12.2f} {:>9.3f}\n", t, x, formula, measured,
               100.0 * (measured / formula - 1.0));
    rows.push_back({t, x, formula, audio::passByHeardFrequency(rendered, t), measured});
  }
  const double first =
      audio::zeroCrossingPitch(mono, rate, static_cast<std::size_t>(0.5 * rate) - count / 2, count).frequency;
  const double last =
      audio::zeroCrossingPitch(mono, rate, static_cast<std::size_t>((duration - 0.5) * rate) - count / 2, count)
          .frequency;
  fmt::print("well before the pass: {:.2f} Hz measured, {:.2f} Hz by f c/(c - v) ({:+.3f} %)\n", first, approaching,
             100.0 * (first / approaching - 1.0));
  fmt::print("well after the pass:  {:.2f} Hz measured, {:.2f} Hz by f c/(c + v) ({:+.3f} %)\n", last, receding,
             100.0 * (last / receding - 1.0));
  if (options.outDir) {
    const std::filesystem::path out = *options.outDir;
    std::filesystem::path wav = out;
    if (out.extension() != ".wav") {
      makeOutputDirectory(out);
      wav = out / "doppler.wav";
      writeCsv(options, "doppler.csv", "t_s,x_m,openal_formula_hz,retarded_formula_hz,measured_hz", rows);
    } else if (out.has_parent_path()) {
      makeOutputDirectory(out.parent_path());
    }
    try {
      audio::writeWav(wav, render.clip);
    } catch (const Error& e) {
      fmt::print(stderr, "error: {}\n", e.what());
      return 1;
    }
    fmt::print("wrote {} ({:.1f} s, {} Hz, 16-bit stereo)\n", wav.string(), duration, rate);
  }
  return 0;
#else
  fmt::print(stderr, "error: this impetus was built without impetus::audio (OpenAL Soft and libsndfile: install "
                     "libopenal-dev and libsndfile1-dev and rebuild); the formula's frequencies are above, nothing "
                     "was rendered\n");
  return demoUnavailable;
#endif
}

} // namespace impetus::cli
