#include <impetus/mechanics/relativity.hpp>

#include <gtest/gtest.h>
