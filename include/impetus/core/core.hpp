// The core layer: constants, ids and pools, mass properties (chapter 1).
#pragma once

#include <impetus/core/constants.hpp>
#include <impetus/core/id_pool.hpp>
#include <impetus/core/mass_properties.hpp>
#include <impetus/core/mesh_mass.hpp>
#include <impetus/core/polygon_mass.hpp>
#include <impetus/core/solid.hpp>
#include <impetus/core/state_hash.hpp>
#include <impetus/error.hpp>
