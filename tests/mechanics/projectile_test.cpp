#include <impetus/mechanics/projectile.hpp>

#include <gtest/gtest.h>
