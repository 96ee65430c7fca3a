// The particle layer (ch. 8, 13): the particle world with its effectors, obstacles, springs,
// distance constraints and emitters; the rope and cloth builders.
#pragma once

#include <impetus/particles/cloth.hpp>
#include <impetus/particles/particle_types.hpp>
#include <impetus/particles/particle_world.hpp>
#include <impetus/particles/rope.hpp>
