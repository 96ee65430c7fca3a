// Kinetics (ch. 4): ship with thrust and linear resistance, box tipping versus sliding.
#pragma once

namespace impetus {} // namespace impetus
