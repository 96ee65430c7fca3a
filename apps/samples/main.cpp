// impetus-samples: see options.hpp for the command line and app.hpp for the app.
#include "app.hpp"
#include "options.hpp"
#include "sample.hpp"
#include "screenshot.hpp"

#include <cstdio>
#include <exception>
#include <span>

int main(int argc, char** argv) {
  using namespace impetus::samples;
  AppOptions options;
  try {
    options = parseOptions(std::span<const char* const>(argv + 1, static_cast<std::size_t>(argc - 1)));
  } catch (const UsageError& e) {
    std::fprintf(stderr, "impetus-samples: %s\n", e.what());
    return 2;
  }
  if (options.help) {
    std::fputs(usage().c_str(), stdout);
    return 0;
  }
  const auto& registry = sampleRegistry();
  if (options.list) {
    // One sample a line: its "Category/Name" (which may hold spaces), a tab, what it shows.
    for (const SampleInfo& info : registry) {
      std::printf("%s\t%s\n", info.fullName().c_str(), info.description.c_str());
    }
    return 0;
  }
  std::size_t index = 0;
  {
    const std::string name = options.sample.empty() ? std::string(showcaseSample) : options.sample;
    const auto found = findSample(name);
    if (!found) {
      std::fprintf(stderr, "impetus-samples: unknown sample '%s' (impetus-samples --list)\n", name.c_str());
      return 2;
    }
    index = *found;
  }
  if (options.screenshot) {
    try {
      checkWritable(*options.screenshot); // before minutes of simulation, not after
    } catch (const std::exception& e) {
      std::fprintf(stderr, "impetus-samples: --screenshot: %s\n", e.what());
      return 2;
    }
  }
  return runApp(options, index);
}
