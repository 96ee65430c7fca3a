// Forces (ch. 3): gravitation, weight, drag, pressure, buoyancy, spring-damper, torque.
#pragma once

namespace impetus {} // namespace impetus
