// The whole public API of Impetus.
#pragma once

#include <impetus/audio/audio.hpp>
#include <impetus/core/core.hpp>
#include <impetus/display/display.hpp>
#include <impetus/error.hpp>
#include <impetus/geo/geo.hpp>
#include <impetus/integrate/integrate.hpp>
#include <impetus/math/math.hpp>
#include <impetus/mechanics/mechanics.hpp>
#include <impetus/particles/particles.hpp>
#include <impetus/sensors/sensors.hpp>
#include <impetus/version.hpp>
