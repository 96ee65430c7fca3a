// The integrate layer (ch. 7): fixed-step integrators generic over the state, and adaptive
// drivers (step doubling, Dormand-Prince RK5(4)).
#pragma once

#include <impetus/integrate/adaptive.hpp>
#include <impetus/integrate/steppers.hpp>
