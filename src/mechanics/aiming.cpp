#include <impetus/mechanics/aiming.hpp>
