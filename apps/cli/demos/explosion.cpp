#include "demos/demos.hpp"

namespace impetus::cli {

int demoExplosion(const DemoOptions& /*options*/) { return 0; }

} // namespace impetus::cli
