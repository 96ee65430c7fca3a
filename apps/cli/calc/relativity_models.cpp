#include "calc/calc.hpp"

namespace impetus::cli {

void registerRelativityModels(Registry& /*registry*/) {}

} // namespace impetus::cli
