// Collisions (ch. 5): impulse, restitution, particle and rigid-body impulses, friction.
#pragma once

namespace impetus {} // namespace impetus
