// Variable mass (ch. 6): the rocket equation, thrust, burn-out speed and altitude.
#pragma once

namespace impetus {} // namespace impetus
