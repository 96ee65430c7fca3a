// Friction (ch. 3): static and kinetic Coulomb friction, material pairs, angle of repose.
#pragma once

namespace impetus {} // namespace impetus
