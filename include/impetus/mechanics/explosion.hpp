// Kinematic particle explosion (ch. 2): spawn, life, gravity, fade.
#pragma once

namespace impetus {} // namespace impetus
