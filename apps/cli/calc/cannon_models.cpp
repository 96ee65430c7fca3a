#include "calc/calc.hpp"

namespace impetus::cli {

void registerCannonModels(Registry& /*registry*/) {}

} // namespace impetus::cli
