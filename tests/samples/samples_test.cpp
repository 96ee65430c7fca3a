// impetus-samples headless: every sample, the command line, and one reference picture.
//
// Each sample runs twice. First without rendering (--no-render: the simulation, the drawing into
// memory and the panel's layout, no OpenGL), under the sanitizers' leak check when built with
// them. Then with Mesa's software OpenGL through SDL's offscreen driver to a 320 x 240 PNG; Mesa
// and SDL's drivers keep allocations until exit that LeakSanitizer reports, so that run alone
// has leak detection off (the first run covers our own code).
#include "cli/cli_process.hpp"
#include "image_compare.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace impetus::testing {
namespace {

/// "Category/Name" of every sample, from the app itself (run when the tests are listed).
std::vector<std::string> sampleNames() {
  std::vector<std::string> names;
  FILE* pipe = popen((shellQuote(IMPETUS_CLI_PATH) + " --list").c_str(), "r");
  if (pipe == nullptr) {
    return names;
  }
  char line[1024];
  while (std::fgets(line, sizeof line, pipe) != nullptr) {
    // "Category/Name<tab>description": names may hold spaces.
    const std::string text(line);
    const std::size_t tab = text.find('\t');
    if (tab != std::string::npos && tab > 0) {
      names.push_back(text.substr(0, tab));
    }
  }
  pclose(pipe);
  return names;
}

/// A gtest-friendly name: "Engine/Joint grid" -> "Engine_Joint_grid".
std::string testName(const std::string& sample) {
  std::string out;
  for (const char c : sample) {
    out.push_back(std::isalnum(static_cast<unsigned char>(c)) != 0 ? c : '_');
  }
  return out;
}

std::string screenshotPath(const std::string& sample) {
  return std::string(IMPETUS_SCREENSHOT_DIR) + "/" + testName(sample) + ".png";
}

/// Runs the app with `args`, and `environment` ("NAME=value ...", shell-quoted by the caller)
/// before it; stdout and stderr captured (cli_process.hpp's impetus() names its stderr file after
/// the test, and parameterized tests have a '/' in their names).
CliRun runApp(const std::vector<std::string>& args, const std::string& environment = "") {
  static int calls = 0;
  const std::string errPath = ::testing::TempDir() + "impetus_samples_stderr_" + std::to_string(getpid()) + "_" +
                              std::to_string(++calls) + ".txt";
  // Appends only: GCC 12 warns falsely (-Wrestrict) about some string concatenations.
  std::string command;
  if (!environment.empty()) {
    command.append(environment).append(" ");
  }
  command.append(shellQuote(IMPETUS_CLI_PATH));
  for (const std::string& a : args) {
    command.append(" ").append(shellQuote(a));
  }
  command.append(" 2>").append(shellQuote(errPath));
  CliRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) {
    return run;
  }
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) {
    run.out.append(buffer, n);
  }
  const int raw = pclose(pipe);
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream err(errPath);
  std::stringstream ss;
  ss << err.rdbuf();
  run.err = ss.str();
  std::filesystem::remove(errPath);
  return run;
}

/// Rendering runs with leak detection off: Mesa's and SDL's drivers keep allocations until exit.
CliRun renderRun(const std::vector<std::string>& args) {
  const char* old = std::getenv("ASAN_OPTIONS");
  std::string options = old != nullptr ? old : "";
  options.append(options.empty() ? "" : ":").append("detect_leaks=0");
  std::string environment = "ASAN_OPTIONS=";
  environment.append(shellQuote(options));
  return runApp(args, environment);
}

class SampleRuns : public ::testing::TestWithParam<std::string> {};

TEST_P(SampleRuns, Runs120FramesFiniteAndItsScreenshotIsNotBlank) {
  const std::string& sample = GetParam();
  // At the smallest window the panels are laid out for (800 x 450): no panel text runs past a
  // panel's edge (the app measures every line it lays out, wrapped or not).
  const CliRun simulated =
      runApp({"--sample", sample, "--frames", "120", "--no-render", "--width", "800", "--height", "450"});
  ASSERT_EQ(simulated.status, 0) << simulated.out << simulated.err;
  EXPECT_NE(simulated.out.find("state finite"), std::string::npos) << simulated.out;
  EXPECT_NE(simulated.out.find("panels fit"), std::string::npos) << simulated.out;
  // ... and at a 1920 x 1080 screen, where the panels are wider.
  const CliRun wide =
      runApp({"--sample", sample, "--frames", "30", "--no-render", "--width", "1920", "--height", "1080"});
  ASSERT_EQ(wide.status, 0) << wide.out << wide.err;
  EXPECT_NE(wide.out.find("panels fit"), std::string::npos) << wide.out;

  // The scene alone (--hide-ui), so the colour count measures what the sample drew.
  const std::string png = screenshotPath(sample);
  std::filesystem::remove(png);
  const CliRun rendered = renderRun(
      {"--sample", sample, "--frames", "120", "--screenshot", png, "--width", "320", "--height", "240", "--hide-ui"});
  ASSERT_EQ(rendered.status, 0) << rendered.out << rendered.err;
  const std::optional<Image> image = readPng(png);
  ASSERT_TRUE(image.has_value()) << png;
  EXPECT_EQ(image->width, 320);
  EXPECT_EQ(image->height, 240);
  // Not blank: the background, the grid and its axes are three colours; a sample draws more
  // colours (shapes, fills, outlines, text) over a visible share of the picture (a bare ground
  // line and a cross are 0.45 %).
  EXPECT_GE(distinctColours(*image), 5u) << png << " looks blank";
  EXPECT_GE(fractionBeyondCommonest(*image, 3), 0.006) << png << " looks blank";
}

INSTANTIATE_TEST_SUITE_P(Samples, SampleRuns, ::testing::ValuesIn(sampleNames()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return testName(p.param); });

// The integrators side by side on a spring: double-precision arithmetic of the integrate layer
// and Dear ImGui's panel, no solver whose tuning may change. Software rasterisation is
// deterministic on one machine; the tolerance absorbs a different CPU's code paths in llvmpipe.
// After a deliberate change to the sample or the app, regenerate it:
//   impetus-samples --sample Book/Integrators --frames 120 --width 320 --height 240
//                   --screenshot tests/samples/reference/book_integrators_320x240.png
TEST(SamplesReference, IntegratorsMatchTheCommittedPicture) {
  const std::string png = screenshotPath("reference Book/Integrators");
  const CliRun run = renderRun(
      {"--sample", "Book/Integrators", "--frames", "120", "--screenshot", png, "--width", "320", "--height", "240"});
  ASSERT_EQ(run.status, 0) << run.out << run.err;
  const std::string referencePath =
      std::string(IMPETUS_SOURCE_DIR) + "/tests/samples/reference/book_integrators_320x240.png";
  const std::optional<Image> reference = readPng(referencePath);
  ASSERT_TRUE(reference.has_value()) << referencePath;
  const std::optional<Image> image = readPng(png);
  ASSERT_TRUE(image.has_value()) << png;
  // A pixel differs when a channel is off by more than 24 of 255; at most 1 % of them may.
  EXPECT_LE(differingFraction(*image, *reference, 24), 0.01) << png << " differs from " << referencePath;
}

/// The number after `key` in a headless run's summary (NaN when it is not there).
double numberAfter(const std::string& out, const std::string& key) {
  const std::size_t at = out.find(key);
  return at == std::string::npos ? std::nan("") : std::strtod(out.c_str() + at + key.size(), nullptr);
}

/// What each sample is about happens within its first two seconds (120 frames), in view.
TEST(SamplesFraming, EachFeatureHappensInTheFirstTwoSeconds) {
  const auto run = [](const char* sample) {
    const CliRun r = runApp({"--sample", sample, "--frames", "120", "--no-render"});
    EXPECT_EQ(r.status, 0) << r.out << r.err;
    return r.out;
  };
  // Bumper cars: the craft collide (in both worlds) before 2 s.
  const std::string cars = run("Book/Bumper cars");
  EXPECT_LT(numberAfter(cars, "book's impulse: hit at "), 2.0) << cars;
  EXPECT_LT(numberAfter(cars, "soft step: hit at "), 2.0) << cars;
  // Ray casts: the ray hits a shape at the screenshot's frame.
  const std::string rays = run("Engine/Ray casts");
  EXPECT_NE(rays.find("the ray hits at"), std::string::npos) << rays;
  // Smash: the projectile is still inside the initial view (x from -16.5 to 22.5 m).
  const std::string smash = run("Engine/Smash");
  const double x = numberAfter(smash, "the projectile is at x = ");
  EXPECT_GT(x, -16.5) << smash;
  EXPECT_LT(x, 22.5) << smash;
  // Cloth: the flag moves by more than a cell (0.35 m) in its first two seconds.
  const std::string cloth = run("Book/Cloth");
  EXPECT_GT(numberAfter(cloth, "largest travel of a particle from its start "), 0.35) << cloth;
}

TEST(SamplesApp, ListsEverySampleOnceAsCategorySlashName) {
  const std::vector<std::string> names = sampleNames();
  ASSERT_FALSE(names.empty());
  const std::set<std::string> unique(names.begin(), names.end());
  EXPECT_EQ(unique.size(), names.size());
  for (const std::string& name : names) {
    EXPECT_NE(name.find('/'), std::string::npos) << name;
  }
  EXPECT_TRUE(unique.contains("Engine/Pyramid"));
  EXPECT_TRUE(unique.contains("Engine/Joint grid"));
}

TEST(SamplesApp, RefusesAnUnknownSample) {
  expectUsageError(impetus({"--sample", "Engine/No such sample", "--frames", "1", "--no-render"}),
                   "unknown sample 'Engine/No such sample'");
}

TEST(SamplesApp, RefusesFramesBelowOne) {
  expectUsageError(impetus({"--sample", "Engine/Pyramid", "--frames", "0", "--no-render"}), "--frames");
  expectUsageError(impetus({"--sample", "Engine/Pyramid", "--frames", "-5", "--no-render"}), "--frames");
  expectUsageError(impetus({"--sample", "Engine/Pyramid", "--frames", "ten", "--no-render"}), "not a whole number");
}

TEST(SamplesApp, RefusesAnUnwritableScreenshotPath) {
  expectUsageError(impetus({"--sample", "Engine/Pyramid", "--frames", "1", "--screenshot", "/nonexistent/dir/x.png"}),
                   "does not exist");
}

TEST(SamplesApp, RefusesAScreenshotThatIsNotAPng) {
  expectUsageError(impetus({"--sample", "Engine/Pyramid", "--frames", "1", "--screenshot", "x.txt"}),
                   "--screenshot = x.txt: must end in .png");
}

TEST(SamplesApp, OpensTheShowcaseWithoutASample) {
  const CliRun run = impetus({"--frames", "2", "--no-render"});
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("Engine/Ragdolls: 2 frames"), std::string::npos) << run.out;
}

TEST(SamplesApp, RefusesAHeadlessRunWithoutFramesAndUnknownOptions) {
  expectUsageError(impetus({"--sample", "Engine/Pyramid", "--screenshot", "x.png"}), "needs --frames");
  expectUsageError(impetus({"--frobnicate"}), "unknown option '--frobnicate'");
  expectUsageError(impetus({"--width", "10", "--no-render", "--frames", "1"}), "--width");
}

} // namespace
} // namespace impetus::testing
