// The particle-world scenes the benchmarks time (bench/particles_bench.cpp) and a test checks
// (tests/bench/particle_scenes_test.cpp): one definition, so the figures in docs/performance.md
// are for the scenes the test describes.
#pragma once

#include <impetus/particles/particle_world.hpp>

#include <cstddef>

namespace impetus::bench {

/// Particle size and mass shared by both scenes: 5 cm spheres of 0.05 kg (a hail stone).
inline constexpr float sceneParticleRadius = 0.05f; ///< m
inline constexpr float sceneParticleMass = 0.05f;   ///< kg

/// "Rain": `count` particles on a square grid in x-z (spacing `rainSpacing`), each dropped from a
/// height in [r, r + `rainDropHeight`] (a low-discrepancy sequence: the heights are spread evenly
/// and the same every run), at rest. The world: gravity (0, -9.81, 0) m/s^2, quadratic drag
/// relative to a wind of `rainWind` (Cd = 0.47, a sphere; rho = 1.225 kg/m^3), a ground plane
/// y = 0 (e = 0.6, mu = 0.4), no particle-particle collisions, default substeps (4).
/// Within 2.5 s every particle has landed, bounced and come to rest on the ground, where static
/// friction (mu m g = 0.2 N) holds it against the wind's drag (0.06 N): from then on every
/// particle touches the ground in every substep.
inline constexpr float rainSpacing = 0.2f;         ///< m
inline constexpr float rainDropHeight = 2.0f;      ///< m
inline constexpr Vec3f rainWind{5.0f, 0.0f, 2.0f}; ///< m/s
[[nodiscard]] ParticleWorld makeRainScene(std::size_t count);

/// "Box": `count` particles on a lattice of `boxLayers` square layers (spacing `boxSpacing`, so
/// no two touch) in the lower part of a closed box of six inward-facing planes, with random
/// velocities of up to `boxMaxSpeed` per axis (a fixed seed: the same every run); gravity,
/// particle-particle collisions on (e = 0.5), walls with e = 0.6, mu = 0.4, default substeps (4).
/// The particles fall (0.55 s) into a pile about ten particles deep on the floor, where most touch
/// several others; the pile's depth is the same at every count, so each particle's work is too
/// and the cost should grow linearly with the count. The floor is square with inner side
/// boxSide(count); the box is boxHeight tall.
inline constexpr std::size_t boxLayers = 10;
inline constexpr float boxSpacing = 0.15f;                                                ///< m
inline constexpr float boxMaxSpeed = 1.0f;                                                ///< m/s
inline constexpr float boxHeight = 2.0f * static_cast<float>(boxLayers + 1) * boxSpacing; ///< m
/// Lattice points per edge of a layer: the smallest k with boxLayers k^2 >= count.
[[nodiscard]] std::size_t boxLatticeSide(std::size_t count);
/// Inner side of the box's floor, m: the lattice plus one spacing of margin.
[[nodiscard]] float boxSide(std::size_t count);
[[nodiscard]] ParticleWorld makeBoxScene(std::size_t count);

} // namespace impetus::bench
