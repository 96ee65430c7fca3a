#include "calc/calc.hpp"

namespace impetus::cli {

void registerKinematicsModels(Registry& /*registry*/) {}

} // namespace impetus::cli
