// The command line of impetus-samples.
//
//   impetus-samples                                  the app, on the first sample
//   impetus-samples --list                           every sample's "Category/Name" and what it shows
//   impetus-samples --sample "Engine/Pyramid"        the app, on that sample
//   impetus-samples --sample S --frames N --screenshot out.png [--width W --height H] [--hide-ui]
//                                                    headless: N frames of 1/60 s, then a PNG
//   impetus-samples --sample S --frames N --no-render
//                                                    headless without OpenGL: simulate, draw into
//                                                    memory and lay out the panel, no pixels
// Exit status: 0; 1 when the sample threw, produced NaN/inf or the screenshot failed; 2 for a bad
// command line (unknown sample or option, frames <= 0, an unwritable screenshot path).
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace impetus::samples {

/// The sample the app opens without --sample (and ./run demo shows): what the engine does best.
inline constexpr std::string_view showcaseSample = "Engine/Ragdolls";

struct AppOptions {
  std::string sample;                              ///< "Category/Name"; empty: the first one
  std::optional<int> frames;                       ///< stop after this many frames
  std::optional<std::filesystem::path> screenshot; ///< PNG of the last frame (headless)
  int width = 1280;                                ///< window, pixels
  int height = 800;
  bool hideUi = false;   ///< the scene alone, no panels
  bool noRender = false; ///< no window and no OpenGL at all
  bool list = false;
  bool help = false;

  /// No display needed: a screenshot or no rendering was asked for.
  [[nodiscard]] bool headless() const noexcept { return screenshot.has_value() || noRender; }
};

/// A command-line mistake; the message names the option and the value.
class UsageError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Parses argv[1..]; throws UsageError. Does not look samples up (the caller knows the registry).
[[nodiscard]] AppOptions parseOptions(std::span<const char* const> args);

/// The usage text (--help).
[[nodiscard]] std::string usage();

} // namespace impetus::samples
