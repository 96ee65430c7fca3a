#include <impetus/mechanics/friction.hpp>

#include <gtest/gtest.h>
