#include <impetus/mechanics/aerodynamics.hpp>
