#include <impetus/mechanics/rocket.hpp>

#include <gtest/gtest.h>
