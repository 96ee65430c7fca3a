// `impetus calc` for sound and `impetus demo doppler`, black-box: the spec's Doppler oracle,
// a supersonic source refused, and the demo's WAV (when impetus::audio is built) whose pitch,
// measured here by zero crossings, matches the formula within 1 % before and after the pass.
#include "cli/cli_process.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using impetus::testing::CliRun;
using impetus::testing::impetus;
using nlohmann::json;

TEST(AudioCli, doppler_and_a_supersonic_source) {
  const CliRun run = impetus({"calc", "doppler", "--frequency", "440", "--source-speed", "20", "--json"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NEAR(json::parse(run.out).at("outputs").at("frequency").at("value").get<double>(), 467.22, 0.005);
  const CliRun boom = impetus({"calc", "doppler", "--source-speed", "400"});
  EXPECT_EQ(boom.status, 2);
  EXPECT_NE(boom.err.find("--source-speed = 400"), std::string::npos) << boom.err;
}

/// A 16-bit PCM stereo WAV's samples, mixed to mono (the demo's format; a minimal RIFF reader
/// so this test does not use the code it checks).
std::vector<float> readPcm16Mono(const std::string& path, int& rate) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
  };
  std::size_t pos = 12;
  int channels = 0;
  std::vector<float> mono;
  while (pos + 8 <= bytes.size()) {
    const std::string id(bytes.data() + pos, 4);
    const std::uint32_t size = u32(pos + 4);
    if (id == "fmt ") {
      std::uint16_t ch = 0;
      std::memcpy(&ch, bytes.data() + pos + 10, 2);
      channels = ch;
      rate = static_cast<int>(u32(pos + 12));
    } else if (id == "data" && channels > 0) {
      const std::size_t frames = size / (2u * static_cast<std::size_t>(channels));
      for (std::size_t i = 0; i < frames; ++i) {
        float sum = 0.0f;
        for (int c = 0; c < channels; ++c) {
          std::int16_t s = 0;
          std::memcpy(&s, bytes.data() + pos + 8 + 2 * (i * static_cast<std::size_t>(channels) + c), 2);
          sum += static_cast<float>(s);
        }
        mono.push_back(sum);
      }
    }
    pos += 8 + size + (size & 1u);
  }
  return mono;
}

/// Upward zero crossings over [t - 0.125, t + 0.125] s: (n - 1) periods between the first and last.
double pitch(const std::vector<float>& s, int rate, double t) {
  const auto begin = static_cast<std::size_t>((t - 0.125) * rate);
  const auto end = static_cast<std::size_t>((t + 0.125) * rate);
  double first = -1.0;
  double last = 0.0;
  int n = 0;
  for (std::size_t i = begin + 1; i < end; ++i) {
    if (s[i - 1] < 0.0f && s[i] >= 0.0f) {
      last = (static_cast<double>(i - 1) + s[i - 1] / (s[i - 1] - s[i])) / rate;
      if (first < 0.0) {
        first = last;
      }
      ++n;
    }
  }
  return (n - 1) / (last - first);
}

TEST(AudioCli, demo_doppler_writes_a_wav_whose_pitch_follows_the_formula) {
  const std::string wav = ::testing::TempDir() + "impetus_demo_doppler.wav";
  const CliRun run = impetus({"demo", "doppler", "--speed", "25", "--frequency", "500", "--out", wav});
  if (run.status == 3) {
    GTEST_SKIP() << "impetus was built without impetus::audio: " << run.err;
  }
  ASSERT_EQ(run.status, 0) << run.err;
  int rate = 0;
  const std::vector<float> mono = readPcm16Mono(wav, rate);
  ASSERT_EQ(rate, 44100);
  // 25 m/s: the source starts 200 m away, 8 s each side.
  ASSERT_NEAR(static_cast<double>(mono.size()) / rate, 16.0, 0.01);
  const double c = 343.3;
  EXPECT_NEAR(pitch(mono, rate, 0.5) / (500.0 * c / (c - 25.0)), 1.0, 0.01);
  EXPECT_NEAR(pitch(mono, rate, 15.5) / (500.0 * c / (c + 25.0)), 1.0, 0.01);
  std::filesystem::remove(wav);
  // Without --speed below c it refuses, naming the option.
  const CliRun boom = impetus({"demo", "doppler", "--speed", "343.3"});
  EXPECT_EQ(boom.status, 2);
  EXPECT_NE(boom.err.find("--speed = 343.3"), std::string::npos) << boom.err;
}

} // namespace
