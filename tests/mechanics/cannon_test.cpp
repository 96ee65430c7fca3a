#include <impetus/mechanics/cannon.hpp>

#include <gtest/gtest.h>
