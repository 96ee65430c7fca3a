#include <impetus/mechanics/kinematics.hpp>

#include <gtest/gtest.h>
