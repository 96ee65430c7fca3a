#include <impetus/mechanics/kinetics.hpp>

#include <gtest/gtest.h>
