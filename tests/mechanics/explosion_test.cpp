#include <impetus/mechanics/explosion.hpp>

#include <gtest/gtest.h>
