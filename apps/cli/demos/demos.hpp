// `impetus demo`: headless demos that print what they show. The samples app replaces them
// with interactive versions later; these stay as a smoke test of the whole stack.
#pragma once

#include <string>

namespace impetus::cli {

/// Runs the named demo ("" = the flagship demo); exit status 0, or 2 for an unknown name.
int runDemo(const std::string& name, bool list);

int demoCarDriverFuel();
int demoTumblingBox();

} // namespace impetus::cli
