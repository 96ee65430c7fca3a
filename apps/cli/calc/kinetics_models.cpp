#include "calc/calc.hpp"

namespace impetus::cli {

void registerKineticsModels(Registry& /*registry*/) {}

} // namespace impetus::cli
