// Draws a ParticleWorld (a 3D world) in the x-y plane: particles as round dots of their collision
// radius (at least a few pixels), and the static obstacles the sample made (the world does not
// list its obstacles).
#pragma once

#include "draw.hpp"

#include <impetus/particles/particle_world.hpp>

namespace impetus::samples {

/// Every particle of the world, x-y projection.
void drawParticles(const ParticleWorld& world, DebugDraw& draw, const Color& color);

/// The ground (or any plane), drawn as the line it cuts in the x-y plane, `extent` metres long
/// each side of its point nearest the origin, hatched on the solid side.
void drawObstacle(DebugDraw& draw, const PlaneObstacle& plane, float extent);
void drawObstacle(DebugDraw& draw, const SphereObstacle& sphere);
/// The box's outline in the x-y plane (its rotation about z only).
void drawObstacle(DebugDraw& draw, const BoxObstacle& box);

} // namespace impetus::samples
