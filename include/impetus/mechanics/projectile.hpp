// Projectiles (ch. 6): vacuum trajectories with a launch height, terminal velocity.
#pragma once

namespace impetus {} // namespace impetus
