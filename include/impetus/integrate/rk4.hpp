// Kept for compatibility: rk4Step now lives with the other steppers.
#pragma once

#include <impetus/integrate/steppers.hpp>
