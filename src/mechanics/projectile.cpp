#include <impetus/mechanics/projectile.hpp>
