#include <impetus/mechanics/kinematics.hpp>
