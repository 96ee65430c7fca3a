// What the benchmark scenes' tests ask of a scene again and again: how many bodies of a type it
// has, its bodies' transforms as built, and a number of steps of an Impetus build of it.
#pragma once

#include "rigid2d_scenes.hpp"

#include <cstddef>
#include <vector>

namespace impetus::bench::test {

inline std::size_t countOf(const Rigid2dScene& scene, rigid2d::BodyType type) {
  std::size_t n = 0;
  for (const SceneBody& b : scene.bodies) {
    n += b.type == type ? 1 : 0;
  }
  return n;
}

/// Every body at its starting position, unrotated (as every scene builds them).
inline std::vector<Transform2f> startTransforms(const Rigid2dScene& scene) {
  std::vector<Transform2f> start;
  start.reserve(scene.bodies.size());
  for (const SceneBody& b : scene.bodies) {
    start.push_back({b.position, Rot2f::identity()});
  }
  return start;
}

inline void step(ImpetusScene& built, int steps) {
  for (int i = 0; i < steps; ++i) {
    built.world.step(sceneTimeStep);
  }
}

} // namespace impetus::bench::test
