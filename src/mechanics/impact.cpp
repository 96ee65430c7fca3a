#include <impetus/mechanics/impact.hpp>
