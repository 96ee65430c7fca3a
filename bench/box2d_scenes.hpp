// The 2D benchmark scenes (rigid2d_scenes.hpp) built in Box2D 2.4.1, the peer impetus-bench
// compares against: the same bodies, boxes and circles, gravity, density and friction. Box2D's
// polygons carry its fixed skin of b2_polygonRadius (1 cm) around the given box; that is Box2D's
// own collision margin, not a change of geometry. Sleeping as the scene says (off but in v3's smash and tumbler), as in
// Impetus. Continuous collision is off by default: no body in these scenes moves far enough in a step to tunnel
// (Impetus' sweep against static shapes, for bodies that move more than their core radius in a
// step, finds nothing to stop here), while Box2D 2.4.1 computes a time of impact for every
// contact of a dynamic body with a static or kinematic one, every step.
// Only the impetus-bench app compiles this, so the scene library needs no Box2D.
#pragma once

#include "rigid2d_scenes.hpp"

#include <box2d/box2d.h>

#include <memory>
#include <vector>

namespace impetus::bench {

/// Box2D 2.4.1's documented default iteration counts, used by impetus-bench.
inline constexpr int box2dVelocityIterations = 8;
inline constexpr int box2dPositionIterations = 3;

/// The scene built in Box2D; `bodies[i]` is the scene's body i.
struct Box2DScene {
  std::unique_ptr<b2World> world;
  std::vector<b2Body*> bodies;
};
/// `continuous`: Box2D's continuous collision (time of impact) for dynamic bodies against static
/// ones (Box2D's default: on). On, it costs Box2D 2.4.1 a pass over every contact per impact
/// found, which turns quadratic when thousands of bodies land in the same step (rain).
[[nodiscard]] Box2DScene buildBox2DScene(const Rigid2dScene& scene, bool continuous = false);
/// Every body's transform (of its origin), in scene order.
[[nodiscard]] std::vector<Transform2f> bodyTransforms(const Box2DScene& built);

} // namespace impetus::bench
