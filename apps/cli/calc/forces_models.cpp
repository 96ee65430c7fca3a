#include "calc/calc.hpp"

namespace impetus::cli {

void registerForceModels(Registry& /*registry*/) {}

} // namespace impetus::cli
