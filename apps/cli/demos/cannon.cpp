#include "demos/demos.hpp"

namespace impetus::cli {

int demoCannon(const DemoOptions& /*options*/) { return 0; }

} // namespace impetus::cli
