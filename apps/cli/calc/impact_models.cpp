#include "calc/calc.hpp"

namespace impetus::cli {

void registerImpactModels(Registry& /*registry*/) {}

} // namespace impetus::cli
