#include <impetus/mechanics/cannon.hpp>
