// Aiming (ch. 2, 6): launch angles that hit a point, minimum launch speed.
#pragma once

namespace impetus {} // namespace impetus
