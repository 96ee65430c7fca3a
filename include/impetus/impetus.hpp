// The whole public API of Impetus.
#pragma once

#include <impetus/core/core.hpp>
#include <impetus/error.hpp>
#include <impetus/math/math.hpp>
#include <impetus/version.hpp>
