// The input validation audit of the audio layer (docs/reliability.md, "Input validation"):
// waves, propagation, reflection, Doppler, binaural cues and pitch measurement refuse NaN,
// infinity, negative or zero values where none is meaningful, supersonic sources and degenerate
// geometry with an impetus::Error naming the field and showing the value. With
// IMPETUS_TEST_AUDIO_RENDER (impetus::audio built) the OpenAL renderer and WAV files too.
#include "support/validation_table.hpp"

#include <impetus/audio/binaural.hpp>
#include <impetus/audio/doppler.hpp>
#include <impetus/audio/pitch.hpp>
#include <impetus/audio/propagation.hpp>
#include <impetus/audio/reflection.hpp>
#include <impetus/audio/waves.hpp>
#include <impetus/math/scalar.hpp>
#if IMPETUS_TEST_AUDIO_RENDER
#include <impetus/audio/openal_renderer.hpp>
#include <impetus/audio/pass_by_render.hpp>
#include <impetus/audio/wav_file.hpp>
#endif

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace impetus::audio {
namespace {

using impetus::testing::expectAccepted;
using impetus::testing::expectRejected;
using impetus::testing::infd;
using impetus::testing::inff;
using impetus::testing::nand;
using impetus::testing::nanf;

TEST(AudioValidation, waves_propagation_and_reflection) {
  const auto wave = [](auto change) {
    return [change] {
      HarmonicWave w;
      change(w);
      WaveSum().add(w);
    };
  };
  const auto gain = [](auto change, double distance = 2.0) {
    return [change, distance] {
      DistanceAttenuation a;
      change(a);
      (void)distanceGain(a, distance);
    };
  };
  const Vec3d source{0.0, 1.0, 0.0};
  const Vec3d listener{3.0, 1.0, 0.0};
  const Vec3d up{0.0, 1.0, 0.0};
  expectRejected({
      {"amplitude", "-1", wave([](HarmonicWave& w) { w.amplitude = -1.0; })},
      {"frequency", "0", wave([](HarmonicWave& w) { w.frequency = 0.0; })},
      {"phase", "nan", wave([](HarmonicWave& w) { w.phase = nand; })},
      {"speedOfSound", "inf", wave([](HarmonicWave& w) { w.speedOfSound = infd; })},
      {"frequency", "-440",
       [] {
         const std::vector<HarmonicWave> waves{{1.0, 440.0}, {1.0, -440.0}};
         WaveSum s(waves);
       }},
      {"x", "nan", [] { (void)WaveSum().sample(nand, 44100.0, 4); }},
      {"sampleRate", "0", [] { (void)WaveSum().sample(0.0, 0.0, 4); }},
      {"frequency", "0", [] { (void)wavelength(0.0); }},
      {"speedOfSound", "-343.3", [] { (void)wavelength(440.0, -343.3); }},
      {"wavelength", "-1", [] { (void)frequencyFromWavelength(-1.0); }},
      {"frequency2", "nan", [] { (void)beatFrequency(440.0, nand); }},
      {"temperature", "-273.15", [] { (void)speedOfSoundInAir(-273.15); }},
      {"temperature", "nan", [] { (void)speedOfSoundInAir(nand); }},
      {"power", "-1", [] { (void)intensityAtDistance(-1.0, 1.0); }},
      {"distance", "0", [] { (void)intensityAtDistance(1.0, 0.0); }},
      {"intensity", "0", [] { (void)intensityLevel(0.0); }},
      {"level", "nan", [] { (void)intensityFromLevel(nand); }},
      {"pressure", "-1", [] { (void)pressureLevel(-1.0); }},
      {"level", "inf", [] { (void)pressureFromLevel(infd); }},
      {"level", "-inf", [] { (void)levelAtDistance(-infd, 1.0, 2.0); }},
      {"distance1", "0", [] { (void)levelAtDistance(90.0, 0.0, 2.0); }},
      {"distance2", "nan", [] { (void)amplitudeRatio(1.0, nand); }},
      {"distance1", "-1", [] { (void)intensityRatio(-1.0, 2.0); }},
      {"levelDifference", "nan", [] { (void)loudnessRatio(nand); }},
      {"distance", "-1", [] { (void)flashToBangDelay(-1.0); }},
      {"speedOfSound", "0", [] { (void)flashToBangDelay(1000.0, 0.0); }},
      {"delay", "nan", [] { (void)distanceFromFlashToBang(nand); }},
      {"distance", "-1", gain([](DistanceAttenuation&) {}, -1.0)},
      {"distance", "nan", gain([](DistanceAttenuation&) {}, nand)},
      {"referenceDistance", "0", gain([](DistanceAttenuation& a) { a.referenceDistance = 0.0; })},
      {"maxDistance", "nan", gain([](DistanceAttenuation& a) { a.maxDistance = nand; })},
      {"rolloff", "-1", gain([](DistanceAttenuation& a) { a.rolloff = -1.0; })},
      {"maxDistance", "0.5", gain([](DistanceAttenuation& a) { a.maxDistance = 0.5; })},
      {"model", "42", gain([](DistanceAttenuation& a) { a.model = static_cast<DistanceModel>(42); })},
      {"distance", "-1", [] { (void)echoDelay(-1.0); }},
      {"delay", "inf", [] { (void)reflectorDistance(infd); }},
      {"speedOfSound", "0", [] { (void)reflectorDistance(1.0, 0.0); }},
      {"absorption", "1.5", [] { (void)reflectionCoefficient(1.5); }},
      {"absorption", "nan", [] { (void)reflectionCoefficient(nand); }},
      {"source.x", "nan",
       [&] {
         (void)reflectOffPlane({nand, 1.0, 0.0}, listener, {}, up);
       }},
      {"planeNormal.y", "inf",
       [&] {
         (void)reflectOffPlane(source, listener, {}, {0.0, infd, 0.0});
       }},
      {"planeNormal", "0", [&] { (void)reflectOffPlane(source, listener, {}, {}); }},
      {"coefficient", "1.5", [&] { (void)reflectOffPlane(source, listener, {}, up, 1.5); }},
      {"speedOfSound", "nan", [&] { (void)reflectOffPlane(source, listener, {}, up, 1.0, nand); }},
      // Signed distances from the floor y = 0, m.
      {"source", "0",
       [&] {
         (void)reflectOffPlane({1.0, 0.0, 0.0}, listener, {}, up);
       }},
      {"listener", "-1",
       [&] {
         (void)reflectOffPlane(source, {3.0, -1.0, 0.0}, {}, up);
       }},
      {"listener", "0", [&] { (void)reflectOffPlane(source, source, {}, up); }},
  });
  expectAccepted({
      {"a silent wave", wave([](HarmonicWave& w) { w.amplitude = 0.0; })},
      {"no samples", [] { (void)WaveSum().sample(0.0, 44100.0, 0); }},
      {"zero power, zero distance to the flash", [] { (void)(intensityAtDistance(0.0, 1.0) + flashToBangDelay(0.0)); }},
      {"zero rolloff, zero distance", gain([](DistanceAttenuation& a) { a.rolloff = 0.0; }, 0.0)},
      {"an unclamped model beyond maxDistance", gain(
                                                    [](DistanceAttenuation& a) {
                                                      a.model = DistanceModel::inverse;
                                                      a.maxDistance = 0.5;
                                                    },
                                                    10.0)},
      {"full absorption", [] { EXPECT_EQ(reflectionCoefficient(1.0), 0.0); }},
      {"a perfect absorber", [&] { (void)reflectOffPlane(source, listener, {}, up, 0.0); }},
  });
}

TEST(AudioValidation, doppler_binaural_and_pitch) {
  const auto pass = [](auto change) {
    return [change] {
      PassBy p;
      change(p);
      (void)passByHeardFrequency(p, 0.0);
    };
  };
  const Vec3d here{};
  const Vec3d there{100.0, 0.0, 0.0};
  std::vector<float> tone(4410);
  for (std::size_t i = 0; i < tone.size(); ++i) {
    tone[i] = static_cast<float>(std::sin(2.0 * pi<double> * 440.0 * static_cast<double>(i) / 44100.0));
  }
  expectRejected({
      {"frequency", "0", [] { (void)dopplerFrequency(0.0, 10.0, 0.0); }},
      {"speedOfSound", "0", [] { (void)dopplerFrequency(440.0, 10.0, 0.0, 0.0); }},
      {"sourceSpeed", "nan", [] { (void)dopplerFrequency(440.0, nand, 0.0); }},
      // At or above c the source outruns its sound; a listener receding at c never hears it.
      {"sourceSpeed", "343.3", [] { (void)dopplerFrequency(440.0, 343.3, 0.0); }},
      {"listenerSpeed", "-343.3", [] { (void)dopplerFrequency(440.0, 0.0, -343.3); }},
      {"sourcePosition.x", "nan",
       [&] {
         (void)dopplerFrequency(440.0, {nand, 0.0, 0.0}, {}, there, {});
       }},
      {"listenerVelocity.z", "inf",
       [&] {
         (void)dopplerFrequency(440.0, here, {}, there, {0.0, 0.0, infd});
       }},
      {"listenerPosition", "0", [&] { (void)dopplerFrequency(440.0, here, {}, here, {}); }},
      {"dopplerFactor", "-1", [&] { (void)openALDopplerFrequency(440.0, here, {}, there, {}, -1.0); }},
      {"sourceVelocity.y", "nan",
       [&] {
         (void)openALDopplerFrequency(440.0, here, {0.0, nand, 0.0}, there, {});
       }},
      {"sourceVelocity", "343.3",
       [&] {
         (void)openALDopplerFrequency(440.0, here, {343.3, 0.0, 0.0}, there, {});
       }},
      {"frequency", "0", pass([](PassBy& p) { p.frequency = 0.0; })},
      {"speed", "343.3", pass([](PassBy& p) { p.speed = 343.3; })},
      {"speed", "-1", pass([](PassBy& p) { p.speed = -1.0; })},
      {"closestApproach", "0", pass([](PassBy& p) { p.closestApproach = 0.0; })},
      {"closestTime", "nan", pass([](PassBy& p) { p.closestTime = nand; })},
      {"speedOfSound", "inf", pass([](PassBy& p) { p.speedOfSound = infd; })},
      {"time", "nan", [] { (void)passBySourcePosition(PassBy{}, nand); }},
      {"time", "inf", [] { (void)passByEmissionTime(PassBy{}, infd); }},
      {"time", "-inf", [] { (void)passByInstantaneousFrequency(PassBy{}, -infd); }},
      {"amplitudeAt1m", "nan", [] { (void)passByPressure(PassBy{}, 0.0, nand); }},
      {"azimuth", "nan", [] { (void)interauralTimeDifference(nand); }},
      {"earSpacing", "0", [] { (void)interauralTimeDifference(0.5, 0.0); }},
      {"speedOfSound", "inf", [] { (void)interauralTimeDifference(0.5, 0.17, infd); }},
      {"azimuth", "inf", [] { (void)woodworthTimeDifference(infd); }},
      {"headRadius", "-0.0875", [] { (void)woodworthTimeDifference(0.5, -0.0875); }},
      {"angleFromEarAxis", "nan", [] { (void)headShadowGain(nand, 1000.0); }},
      {"frequency", "0", [] { (void)headShadowGain(0.5, 0.0); }},
      {"headRadius", "nan", [] { (void)headShadowGain(0.5, 1000.0, nand); }},
      {"speedOfSound", "-343.3", [] { (void)headShadowGain(0.5, 1000.0, 0.0875, -343.3); }},
      {"azimuth", "-inf", [] { (void)interauralLevelDifference(-infd, 1000.0); }},
      {"frequency", "-1", [] { (void)interauralLevelDifference(0.5, -1.0); }},
      {"sampleRate", "0", [&] { (void)zeroCrossingPitch(tone, 0.0); }},
      {"sampleRate", "nan", [&] { (void)zeroCrossingPitch(tone, nand); }},
      // Silence has no upward zero crossing.
      {"samples", "0", [] { (void)zeroCrossingPitch(std::vector<float>(100, 0.0f), 44100.0); }},
      {"samples", "4410", [&] { (void)zeroCrossingPitch(tone, 44100.0, 4400, 20); }},
      {"samples", "nan",
       [&] {
         std::vector<float> bad = tone;
         bad[1000] = nanf;
         (void)zeroCrossingPitch(bad, 44100.0);
       }},
      {"samples", "-inf",
       [&] {
         std::vector<float> bad = tone;
         bad[3] = -inff;
         (void)zeroCrossingPitch(bad, 44100.0, 0, 100);
       }},
  });
  expectAccepted({
      {"a listener at rest, a source at rest", [] { (void)dopplerFrequency(440.0, 0.0, 0.0); }},
      {"a source receding faster than sound", [] { (void)dopplerFrequency(440.0, -500.0, 0.0); }},
      {"Doppler off",
       [&] {
         (void)openALDopplerFrequency(440.0, here, {400.0, 0.0, 0.0}, there, {}, 0.0);
       }},
      {"coincident OpenAL positions", [&] { (void)openALDopplerFrequency(440.0, here, {}, here, {}); }},
      {"a source at rest passing by", pass([](PassBy& p) { p.speed = 0.0; })},
      {"a NaN outside the window",
       [&] {
         std::vector<float> bad = tone;
         bad[4000] = nanf;
         (void)zeroCrossingPitch(bad, 44100.0, 0, 1000);
       }},
  });
}

#if IMPETUS_TEST_AUDIO_RENDER
TEST(AudioValidation, renderer_and_wav_files) {
  const auto settings = [](auto change) {
    return [change] {
      RendererSettings s;
      change(s);
      LoopbackRenderer r(s);
    };
  };
  LoopbackRenderer renderer;
  const AudioClip mono = loopingTone(440.0);
  const auto source = [&renderer, &mono](auto change) {
    return [&renderer, &mono, change] {
      AudioClip clip = mono;
      SourceSettings s;
      change(clip, s);
      (void)renderer.addSource(clip, s);
    };
  };
  const auto wav = [](auto change) {
    return [change] {
      AudioClip clip = loopingTone(440.0, 8000, 0.01);
      change(clip);
      writeWav(::testing::TempDir() + "impetus_validation.wav", clip);
    };
  };
  const LoopbackRenderer::SourceId id = renderer.addSource(mono);
  expectRejected({
      {"frequency", "0", [] { (void)loopingTone(0.0); }},
      {"sampleRate", "0", [] { (void)loopingTone(440.0, 0); }},
      {"seconds", "0", [] { (void)loopingTone(440.0, 44100, 0.0); }},
      // Held in memory: a billion seconds would overflow the frame count or the memory.
      {"seconds", "1e+09", [] { (void)loopingTone(440.0, 44100, 1e9); }},
      {"frequency", "30000", [] { (void)loopingTone(30000.0); }},
      {"amplitude", "0", [] { (void)loopingTone(440.0, 44100, 1.0, 0.0); }},
      {"amplitude", "1.5", [] { (void)loopingTone(440.0, 44100, 1.0, 1.5); }},
      {"sampleRate", "7999", settings([](RendererSettings& s) { s.sampleRate = 7999; })},
      {"speedOfSound", "0", settings([](RendererSettings& s) { s.speedOfSound = 0.0; })},
      {"metresPerUnit", "nan", settings([](RendererSettings& s) { s.metresPerUnit = nand; })},
      {"dopplerFactor", "-1", settings([](RendererSettings& s) { s.dopplerFactor = -1.0; })},
      {"updateFrames", "0", settings([](RendererSettings& s) { s.updateFrames = 0; })},
      {"clip", "2", source([](AudioClip& c, SourceSettings&) { c.channels = 2; })},
      {"clip", "0", source([](AudioClip& c, SourceSettings&) { c.sampleRate = 0; })},
      {"clip", "0", source([](AudioClip& c, SourceSettings&) { c.samples.clear(); })},
      {"clip", "nan", source([](AudioClip& c, SourceSettings&) { c.samples[7] = nanf; })},
      {"gain", "-1", source([](AudioClip&, SourceSettings& s) { s.gain = -1.0; })},
      {"referenceDistance", "0", source([](AudioClip&, SourceSettings& s) { s.attenuation.referenceDistance = 0.0; })},
      {"model", "42",
       source([](AudioClip&, SourceSettings& s) { s.attenuation.model = static_cast<DistanceModel>(42); })},
      {"forward", "0",
       [&] {
         renderer.setListener({}, {}, {0.0, 1.0, 0.0});
       }},
      {"up", "2",
       [&] {
         renderer.setListener({}, {0.0, 0.0, -1.0}, {0.0, 0.0, 2.0});
       }},
      {"up", "0",
       [&] {
         renderer.setListener({}, {0.0, 0.0, -1.0}, {});
       }},
      {"position", "nan",
       [&] {
         renderer.setListener({{nand, 0.0, 0.0}, {}});
       }},
      {"velocity", "inf",
       [&] {
         renderer.setSource(id, {{}, {0.0, infd, 0.0}});
       }},
      {"source", "5", [&] { renderer.setSource(5, {}); }},
      {"source", "-1", [&] { renderer.play(-1); }},
      {"source", "3", [&] { renderer.followSource(3, {}); }},
      {"sampleRate", "0", [] { (void)renderPassBy(PassBy{}, 4.0, 0); }},
      {"duration", "0", [] { (void)renderPassBy(PassBy{}, 0.0); }},
      {"duration", "4000", [] { (void)renderPassBy(PassBy{}, 4000.0); }},
      {"speed", "400",
       [] {
         (void)renderPassBy({440.0, 400.0, 10.0, 0.0, 343.3}, 4.0);
       }},
      {"speed", "-1", [] { (void)passByDuration(-1.0); }},
      {"clip", "0", wav([](AudioClip& c) { c.channels = 0; })},
      {"clip", "-8000", wav([](AudioClip& c) { c.sampleRate = -8000; })},
      // 73 samples (4 periods of 440 Hz at 8 kHz) are not a whole number of stereo frames.
      {"clip", "73", wav([](AudioClip& c) { c.channels = 2; })},
      {"clip", "inf", wav([](AudioClip& c) { c.samples[3] = inff; })},
  });
  expectAccepted({
      {"no Doppler effect", settings([](RendererSettings& s) { s.dopplerFactor = 0.0; })},
      {"a silent source", source([](AudioClip&, SourceSettings& s) { s.gain = 0.0; })},
      {"zero frames", [&] { (void)renderer.render(0); }},
  });
  // A file that cannot be written or read names "path" and the file (a text value, shown as
  // "'<file>'" in the message).
  for (const auto& call : {std::function<void()>([] { writeWav("/nonexistent-dir/x.wav", loopingTone(440.0)); }),
                           std::function<void()>([] { (void)readWav("/nonexistent-dir/x.wav"); })}) {
    try {
      call();
      ADD_FAILURE() << "accepted a file in a directory that does not exist";
    } catch (const Error& e) {
      EXPECT_EQ(e.field(), "path");
      EXPECT_NE(std::string(e.what()).find("'/nonexistent-dir/x.wav'"), std::string::npos) << e.what();
    }
  }
}
#endif

} // namespace
} // namespace impetus::audio
