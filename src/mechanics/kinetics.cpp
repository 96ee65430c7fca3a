#include <impetus/mechanics/kinetics.hpp>
