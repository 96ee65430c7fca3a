#include <impetus/mechanics/forces.hpp>
