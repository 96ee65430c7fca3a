// `impetus demo`: headless demos that print what they show and, given --out DIR, write their
// trajectories as CSV. The samples app replaces them with interactive versions later; these
// stay as a smoke test of the whole stack.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace impetus::cli {

struct DemoOptions {
  /// Where to write CSV files; none: print only. (doppler: a .wav file, or a directory for
  /// doppler.wav.)
  std::optional<std::filesystem::path> outDir;
  /// doppler: the source's speed (m/s) and frequency (Hz); none: the demo's defaults.
  std::optional<double> speed;
  std::optional<double> frequency;
};

/// The exit status of a demo that needs an optional part Impetus was built without (e.g.
/// impetus::audio): explicit runs fail with it, the run of every demo skips the demo.
inline constexpr int demoUnavailable = 3;

/// Writes `rows` under `header` (comma-separated column names) to outDir/fileName when an
/// output directory was given, creating it; prints the path written. Numbers are written with
/// full round-trip precision.
void writeCsv(const DemoOptions& options, const std::string& fileName, const std::string& header,
              const std::vector<std::vector<double>>& rows);

/// Makes the directory `dir` (and its parents) for --out; refuses, with an impetus::Error naming
/// --out, a path that is a file or that cannot be made (its reason).
void makeOutputDirectory(const std::filesystem::path& dir);

/// Runs the named demo ("" = all of them); exit status 0, or 2 with one line on stderr for an
/// unknown name or an --out that is not a directory.
int runDemo(const std::string& name, bool list, const DemoOptions& options);

// One function per demo (demos/<name>.cpp).
int demoCarDriverFuel(const DemoOptions& options);
int demoTumblingBox(const DemoOptions& options);
int demoCannon(const DemoOptions& options);
int demoCannon2(const DemoOptions& options);
int demoExplosion(const DemoOptions& options);
int demoMagnus(const DemoOptions& options);
int demoHovercraft(const DemoOptions& options);
int demoBumperCars(const DemoOptions& options);
int demoDoppler(const DemoOptions& options);

} // namespace impetus::cli
