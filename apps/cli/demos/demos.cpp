#include "demos/demos.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <impetus/error.hpp>

#include <fstream>

#include <functional>
#include <vector>

namespace impetus::cli {
namespace {

struct Demo {
  const char* name;
  const char* summary;
  std::function<int(const DemoOptions&)> run;
};

const std::vector<Demo>& demos() {
  static const std::vector<Demo> all{
      {"car-driver-fuel", "the book's example 1.1: mass properties of a car, its driver and fuel (ch. 1)",
       demoCarDriverFuel},
      {"tumbling-box", "torque-free rotation of a box about its intermediate axis (ch. 1, 11): it flips",
       demoTumblingBox},
      {"cannon", "the book's cannon (ch. 2): a shell in vacuum at a target box, from direction cosines", demoCannon},
      {"cannon2", "the book's Cannon2 (ch. 4): the cannon with linear drag and wind, book's and correct wind",
       demoCannon2},
      {"explosion", "the book's kinematic particle explosion (ch. 2): spawn, fly, fade", demoExplosion},
      {"magnus", "the book's Magnus demo (ch. 6), corrected: a spinning ball curves", demoMagnus},
      {"hovercraft", "the book's ch. 9 hovercraft on the 2D engine: thrust, drag aft of the CG, soft turns",
       demoHovercraft},
      {"bumper-cars", "the book's ch. 10 collision: two hovercraft, e = 0.5, book impulse vs soft step",
       demoBumperCars},
      {"doppler", "ch. 26: a source passing at --speed V with --frequency F, rendered by OpenAL Soft to a WAV",
       demoDoppler},
  };
  return all;
}

} // namespace

void writeCsv(const DemoOptions& options, const std::string& fileName, const std::string& header,
              const std::vector<std::vector<double>>& rows) {
  if (!options.outDir) {
    return;
  }
  makeOutputDirectory(*options.outDir);
  const std::filesystem::path path = *options.outDir / fileName;
  std::ofstream out(path);
  out << header << '\n';
  for (const std::vector<double>& row : rows) {
    out << fmt::format("{}", fmt::join(row, ",")) << '\n';
  }
  fmt::print("wrote {} ({} rows)\n", path.string(), rows.size());
}

void makeOutputDirectory(const std::filesystem::path& dir) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec)) {
    throw Error("--out", fmt::format("--out = {}: is a file, not a directory (the demos write their CSV files into a "
                                     "directory)",
                                     dir.string()));
  }
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    throw Error("--out", fmt::format("--out = {}: cannot make the directory ({})", dir.string(), ec.message()));
  }
}

namespace {

int runDemos(const std::string& name, bool list, const DemoOptions& options) {
  // --out is checked before anything runs: a demo should not print its results and then fail.
  // (doppler alone takes a .wav file.)
  if (options.outDir && !(name == "doppler" && options.outDir->extension() == ".wav")) {
    makeOutputDirectory(*options.outDir);
  }
  if (list) {
    for (const Demo& d : demos()) {
      fmt::print("{:<18} {}\n", d.name, d.summary);
    }
    return 0;
  }
  if (name.empty()) {
    int status = 0;
    for (const Demo& d : demos()) {
      fmt::print("== {} ==\n", d.name);
      const int result = d.run(options);
      status |= result == demoUnavailable ? 0 : result;
      fmt::print("\n");
    }
    return status;
  }
  for (const Demo& d : demos()) {
    if (name == d.name) {
      return d.run(options);
    }
  }
  fmt::print(stderr, "error: unknown demo '{}' (impetus demo --list lists them)\n", name);
  return 2;
}

} // namespace

int runDemo(const std::string& name, bool list, const DemoOptions& options) {
  try {
    return runDemos(name, list, options);
  } catch (const Error& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  }
}

} // namespace impetus::cli
