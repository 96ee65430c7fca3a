#include <impetus/mechanics/aerodynamics.hpp>

#include <gtest/gtest.h>
