// The particle layer (ch. 8, 13): the particle world with its effectors, obstacles, springs,
// distance constraints and emitters.
#pragma once

#include <impetus/particles/particle_types.hpp>
#include <impetus/particles/particle_world.hpp>
