#include <impetus/mechanics/rocket.hpp>
