#include <impetus/mechanics/aiming.hpp>

#include <gtest/gtest.h>
