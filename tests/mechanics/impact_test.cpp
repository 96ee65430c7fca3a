#include <impetus/mechanics/impact.hpp>

#include <gtest/gtest.h>
