// Aerodynamics of a ball (ch. 6): Reynolds number, sphere drag, Magnus lift, flight.
#pragma once

namespace impetus {} // namespace impetus
