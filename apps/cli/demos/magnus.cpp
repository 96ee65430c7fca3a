#include "demos/demos.hpp"

namespace impetus::cli {

int demoMagnus(const DemoOptions& /*options*/) { return 0; }

} // namespace impetus::cli
