#include <impetus/mechanics/explosion.hpp>
