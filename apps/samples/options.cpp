#include "options.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <string>
#include <string_view>

namespace impetus::samples {
namespace {

int parseInt(std::string_view option, std::string_view text, int min, int max) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size()) {
    throw UsageError(std::string(option) + ": '" + std::string(text) + "' is not a whole number");
  }
  if (value < min || value > max) {
    throw UsageError(std::string(option) + ": " + std::string(text) + " is out of range [" + std::to_string(min) +
                     ", " + std::to_string(max) + "]");
  }
  return value;
}

} // namespace

AppOptions parseOptions(std::span<const char* const> args) {
  AppOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string_view arg = args[i];
    const auto value = [&]() -> std::string_view {
      if (i + 1 >= args.size()) {
        throw UsageError(std::string(arg) + " needs a value");
      }
      return args[++i];
    };
    if (arg == "--list") {
      options.list = true;
    } else if (arg == "--help" || arg == "-h") {
      options.help = true;
    } else if (arg == "--sample") {
      options.sample = value();
    } else if (arg == "--frames") {
      options.frames = parseInt(arg, value(), 1, 1000000);
    } else if (arg == "--screenshot") {
      const std::string_view path = value();
      if (path.empty()) {
        throw UsageError("--screenshot: empty path");
      }
      options.screenshot = std::filesystem::path(path);
      std::string extension = options.screenshot->extension().string();
      std::transform(extension.begin(), extension.end(), extension.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      if (extension != ".png") {
        throw UsageError("--screenshot = " + std::string(path) + ": must end in .png (screenshots are PNG files)");
      }
    } else if (arg == "--width") {
      options.width = parseInt(arg, value(), 64, 8192);
    } else if (arg == "--height") {
      options.height = parseInt(arg, value(), 64, 8192);
    } else if (arg == "--hide-ui") {
      options.hideUi = true;
    } else if (arg == "--no-render") {
      options.noRender = true;
    } else {
      throw UsageError("unknown option '" + std::string(arg) + "' (impetus-samples --help)");
    }
  }
  if (options.noRender && options.screenshot) {
    throw UsageError("--no-render and --screenshot exclude each other: a screenshot needs rendering");
  }
  if (options.headless() && !options.frames) {
    throw UsageError(std::string(options.noRender ? "--no-render" : "--screenshot") +
                     " runs headless and needs --frames N");
  }
  return options;
}

std::string usage() {
  return "impetus-samples: the samples of Impetus (SDL2, OpenGL 3.3, Dear ImGui)\n"
         "\n"
         "  impetus-samples [--sample \"Category/Name\"]      open the app (on that sample; default: the showcase, " +
         std::string(showcaseSample) +
         ")\n"
         "  impetus-samples --list                           list the samples\n"
         "  impetus-samples --sample S --frames N --screenshot out.png [--width W] [--height H] [--hide-ui]\n"
         "                                                   render N frames without a display, save the last\n"
         "  impetus-samples --sample S --frames N --no-render\n"
         "                                                   simulate N frames without OpenGL\n"
         "\n"
         "Keys: P pause, O single step, R reset, F12 screenshot (impetus-samples-N.png); mouse: left-drag a\n"
         "body, right-drag to pan, wheel to zoom. Exit status 1 if the sample threw or produced NaN/inf, or\n"
         "the screenshot failed; 2 for a bad command line.\n";
}

} // namespace impetus::samples
