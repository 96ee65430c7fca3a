// 3D audio through OpenAL Soft's loopback device (impetus::audio), measured: a source passing
// at a known speed rendered to a WAV file, read back, its pitch measured by zero crossings well
// before and well after the pass against the Doppler formula (within 1 %); a listener moving
// toward a still source; the 1/r distance model; and bad input.
#include <impetus/audio/doppler.hpp>
#include <impetus/audio/openal_renderer.hpp>
#include <impetus/audio/pass_by_render.hpp>
#include <impetus/audio/pitch.hpp>
#include <impetus/audio/wav_file.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

namespace impetus::audio {
namespace {

/// Zero-crossing pitch of a mono signal over [t - window/2, t + window/2].
double pitchAt(const std::vector<float>& mono, int rate, double t, double window = 0.25) {
  const auto count = static_cast<std::size_t>(window * rate);
  const auto begin = static_cast<std::size_t>(t * rate) - count / 2;
  return zeroCrossingPitch(mono, rate, begin, count).frequency;
}

double rms(const std::vector<float>& s, std::size_t begin, std::size_t count) {
  double sum = 0.0;
  for (std::size_t i = begin; i < begin + count; ++i) {
    sum += static_cast<double>(s[i]) * s[i];
  }
  return std::sqrt(sum / static_cast<double>(count));
}

TEST(OpenALRender, passing_source_pitch_in_the_wav_matches_the_doppler_formula) {
  for (const double speed : {20.0, 40.0}) {
    const PassBy pass{440.0, speed, 10.0, 0.0, 343.3};
    const double duration = passByDuration(speed);
    const PassByRender r = renderPassBy(pass, duration);
    ASSERT_EQ(r.clip.channels, 2);
    EXPECT_NEAR(r.clip.duration(), duration, 1e-3);
    const std::filesystem::path file = std::filesystem::path(::testing::TempDir()) / "impetus_pass_by.wav";
    writeWav(file, r.clip);
    const AudioClip back = readWav(file);
    ASSERT_EQ(back.sampleRate, 44100);
    ASSERT_EQ(back.frames(), r.clip.frames());
    const std::vector<float> mono = back.mono();
    // Well before: the source ~190 m off, approaching almost head-on; well after: receding.
    const double before = 0.5;
    const double after = duration - 0.5;
    const double approaching = pitchAt(mono, back.sampleRate, before);
    const double receding = pitchAt(mono, back.sampleRate, after);
    const double c = pass.speedOfSound;
    const double f = r.toneFrequency;
    // The plain formula f c / (c -+ v) and the geometry's own cos(theta) (OpenAL's: positions now).
    EXPECT_NEAR(approaching / (f * c / (c - speed)), 1.0, 0.01) << speed;
    EXPECT_NEAR(receding / (f * c / (c + speed)), 1.0, 0.01) << speed;
    PassBy rendered = r.pass;
    rendered.frequency = f;
    EXPECT_NEAR(approaching / passByInstantaneousFrequency(rendered, before), 1.0, 0.002) << speed;
    EXPECT_NEAR(receding / passByInstantaneousFrequency(rendered, after), 1.0, 0.002) << speed;
    std::printf("pass at %.0f m/s: approaching %.2f Hz (formula %.2f), receding %.2f Hz (formula %.2f)\n", speed,
                approaching, f * c / (c - speed), receding, f * c / (c + speed));
    // At the pass itself the pitch crosses f and the level peaks (reference distance 10 m).
    EXPECT_NEAR(pitchAt(mono, back.sampleRate, 0.5 * duration, 0.05) / f, 1.0, 0.01);
    const auto window = static_cast<std::size_t>(0.1 * back.sampleRate);
    EXPECT_GT(rms(mono, back.frames() / 2 - window / 2, window), 5.0 * rms(mono, 0, window));
    std::filesystem::remove(file);
  }
}

TEST(OpenALRender, a_listener_following_a_moving_body_hears_the_shift) {
  LoopbackRenderer renderer;
  const LoopbackRenderer::SourceId id = renderer.addSource(loopingTone(500.0), {});
  renderer.setSource(id, {{0.0, 0.0, -1000.0}, {}});
  // The listener runs toward the source at 25 m/s: f (c + v_L) / c.
  renderer.followListener([&renderer] { return Motion{{0.0, 0.0, -25.0 * renderer.time()}, {0.0, 0.0, -25.0}}; });
  renderer.play(id);
  const AudioClip clip = renderer.render(44100);
  const std::vector<float> mono = clip.mono();
  EXPECT_NEAR(zeroCrossingPitch(mono, 44100.0, 4410, 35280).frequency / (500.0 * (343.3 + 25.0) / 343.3), 1.0, 0.002);
  EXPECT_NEAR(renderer.time(), 1.0, 1e-12);
}

TEST(OpenALRender, inverse_distance_model_halves_the_amplitude_at_twice_the_distance) {
  double level[2] = {};
  for (int k = 0; k < 2; ++k) {
    LoopbackRenderer renderer;
    SourceSettings s;
    s.attenuation = {DistanceModel::inverseClamped, 1.0, 1e30, 1.0};
    const LoopbackRenderer::SourceId id = renderer.addSource(loopingTone(300.0), s);
    renderer.setListener({});
    renderer.setSource(id, {{0.0, 0.0, -5.0 * (k + 1)}, {}});
    renderer.play(id);
    const std::vector<float> mono = renderer.render(22050).mono();
    level[k] = rms(mono, 4410, 17640);
  }
  EXPECT_NEAR(level[1] / level[0], 0.5, 0.01); // amplitude ~ 1/r (intensity ~ 1/r^2)
}

TEST(OpenALRender, bad_input_is_rejected) {
  expectErrorField([] { LoopbackRenderer r(RendererSettings{0}); }, "sampleRate");
  expectErrorField([] { (void)renderPassBy({440.0, 400.0, 10.0, 0.0, 343.3}, 4.0); }, "speed");
  expectErrorField([] { (void)renderPassBy({440.0, 30.0, 10.0, 0.0, 343.3}, 0.0); }, "duration");
  expectErrorField([] { (void)renderPassBy({21000.0, 30.0, 10.0, 0.0, 343.3}, 4.0); }, "frequency");
  LoopbackRenderer renderer;
  expectErrorField([&] { renderer.play(3); }, "source");
  AudioClip stereo;
  stereo.channels = 2;
  stereo.samples = {0.0f, 0.0f};
  expectErrorField([&] { (void)renderer.addSource(stereo); }, "clip");
  expectErrorField([&] { renderer.setListener({{NAN, 0.0, 0.0}, {}}); }, "position");
  expectErrorField([] { writeWav("/nonexistent-dir/x.wav", loopingTone(440.0)); }, "path");
  expectErrorField([] { (void)readWav("/nonexistent-dir/x.wav"); }, "path");
  expectErrorField([] { (void)loopingTone(30000.0); }, "frequency");
}

} // namespace
} // namespace impetus::audio
