// Relativistic time (ch. 1, 22): Lorentz factor, GPS clock rates.
#pragma once

namespace impetus {} // namespace impetus
