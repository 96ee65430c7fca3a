// Reads a particle scene (world settings, particles, obstacles, springs, constraints, ropes,
// cloths, attractors, emitters) from a JSON file into a ParticleWorld: the input of
// `impetus run`. Format: docs/scene-format.md.
#pragma once

#include <impetus/particles/particle_world.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace impetus::cli {

/// The most particles a particle scene file may make.
inline constexpr std::int64_t maxSceneParticles = 10'000'000;

/// A loaded scene: the world, ready to step, and what the file asked for.
struct ParticleScene {
  std::string description;
  ParticleWorld world;
  /// The name of each particle the file created, in creation order (which is the world's
  /// order before the first step, and the `particle` number in the output); "" when unnamed.
  std::vector<std::string> particleNames;
  std::size_t ropeCount = 0;
  std::size_t clothCount = 0;
  std::size_t emitterCount = 0;
  std::size_t attractorCount = 0;
};

/// Parses a scene document. Throws impetus::Error whose message starts with the JSON path of
/// the offending value (e.g. "particles[3].mass = -1: must be finite and positive") for
/// malformed JSON, unknown keys, missing or invalid values and references to unknown particles.
[[nodiscard]] ParticleScene parseScene(const std::string& jsonText);

/// Reads and parses a file; an unreadable file is an impetus::Error naming the path.
[[nodiscard]] ParticleScene loadScene(const std::string& path);

} // namespace impetus::cli
