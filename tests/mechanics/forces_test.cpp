#include <impetus/mechanics/forces.hpp>

#include <gtest/gtest.h>
