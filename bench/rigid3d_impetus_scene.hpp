// A 3D benchmark scene (rigid3d_scenes.hpp) built in Impetus' rigid3d::World: each body with its
// box (a hull, makeBoxHull) or sphere, its density and friction, no restitution.
#pragma once

#include "rigid3d_scenes.hpp"

#include <impetus/rigid3d/world.hpp>

#include <vector>

namespace impetus::bench {

/// Solver settings a benchmark run may change; the defaults are WorldDef's but for sleeping, off
/// as in Box3D's and Jolt's runs of these scenes (and Bullet's here): what is timed is the solver
/// at work, and a pyramid that falls asleep would cost almost nothing.
struct Impetus3dSettings {
  int substeps = rigid3d::WorldDef{}.substeps;
  float contactHertz = rigid3d::WorldDef{}.contactHertz; ///< Hz
  bool enableSleep = false;
};

/// The scene in an Impetus world (the scene's gravity); `bodies[i]` is the id of the scene's body i.
struct Impetus3dScene {
  rigid3d::World world;
  std::vector<rigid3d::BodyId> bodies;
};
[[nodiscard]] Impetus3dScene buildImpetus3dScene(const Rigid3dScene& scene, const Impetus3dSettings& settings = {});
/// Every body's pose (its origin's transform), in scene order.
[[nodiscard]] std::vector<Transform3f> bodyPoses(const Impetus3dScene& built);

} // namespace impetus::bench
