#include "demos/demos.hpp"

namespace impetus::cli {

int demoCannon2(const DemoOptions& /*options*/) { return 0; }

} // namespace impetus::cli
