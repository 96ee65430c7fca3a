#include <impetus/mechanics/friction.hpp>
