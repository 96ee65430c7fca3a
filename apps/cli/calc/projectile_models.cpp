#include "calc/calc.hpp"

namespace impetus::cli {

void registerProjectileModels(Registry& /*registry*/) {}

} // namespace impetus::cli
