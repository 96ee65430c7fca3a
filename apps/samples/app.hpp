// The samples app: the window, the frame loop and the panels.
//
// Each frame: events (keys, mouse, quit), the simulation (a fixed step per sample: the frame's
// real time times the time scale is stepped through in steps of timeStep(); headless, every frame
// is exactly 1/60 s, so a run is the same on every machine), the finite() check, the panels (the
// sample list with pause/step/reset/time scale on the left; the sample's parameters and plots on
// the right), the scene through DebugDraw, and the UI on top.
#pragma once

#include "options.hpp"

#include <cstddef>

namespace impetus::samples {

/// Runs the app on the registry's sample `sampleIndex`; returns the exit status (0; 1 when the
/// sample failed in a headless run, the display could not be opened or the screenshot failed).
[[nodiscard]] int runApp(const AppOptions& options, std::size_t sampleIndex);

} // namespace impetus::samples
