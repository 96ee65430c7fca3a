// The scenes of Box2D v3's own benchmark (its shared/benchmarks.c), as plain data, so that each
// engine runs v3's scenes like for like: many_pyramids, tumbler and smash (large_pyramid and
// joint_grid are in rigid2d_scenes.cpp; v3's rain of ragdolls spawned and destroyed is not yet
// here). The geometry, densities, speeds and step counts are v3's; see rigid2d_scenes.hpp.
#include "rigid2d_scene_parts.hpp"

namespace impetus::bench {
using namespace parts;

Rigid2dScene manyPyramidsScene(int rows, int columns) {
  Rigid2dScene scene;
  scene.name = "many_pyramids";
  constexpr int base = manyPyramidsBase;
  constexpr float h = pyramidBoxHalfSize;
  // A row of pyramids per floor: each pyramid as wide as its base, one box of space between.
  const float floorPitch = 2.0f * h * static_cast<float>(base + 1); // m between floors
  const float floorWidth = floorPitch * static_cast<float>(columns);
  const float baseWidth = 2.0f * h * static_cast<float>(base);
  const std::uint32_t ground = addBody(scene, BodyType::staticBody, {0.0f, 0.0f});
  for (int i = 0; i < rows; ++i) {
    const float y = static_cast<float>(i) * floorPitch;
    addSegment(scene, ground, {-0.5f * floorWidth, y}, {0.5f * floorWidth, y});
  }
  for (int i = 0; i < rows; ++i) {
    const float baseY = static_cast<float>(i) * floorPitch;
    for (int j = 0; j < columns; ++j) {
      // v3's column j starts at `left` and its pyramid's centre stands base h - 0.5 m right of it.
      const float left = -0.5f * floorWidth + static_cast<float>(j) * (baseWidth + 2.0f * h) + 2.0f * h;
      addPyramid(scene, base, left + static_cast<float>(base) * h - 0.5f, h, baseY);
    }
  }
  scene.defaultSteps = 200;
  return scene;
}

Rigid2dScene tumblerScene(int grid) {
  Rigid2dScene scene;
  scene.name = "tumbler";
  scene.enableSleep = true;
  const std::uint32_t ground = addBody(scene, BodyType::staticBody, {0.0f, 0.0f});
  const std::uint32_t drum = addBody(scene, BodyType::dynamicBody, {0.0f, 10.0f});
  const std::size_t firstWall = scene.shapes.size();
  addBox(scene, drum, 0.5f, 10.0f, {10.0f, 0.0f});
  addBox(scene, drum, 0.5f, 10.0f, {-10.0f, 0.0f});
  addBox(scene, drum, 10.0f, 0.5f, {0.0f, 10.0f});
  addBox(scene, drum, 10.0f, 0.5f, {0.0f, -10.0f});
  for (std::size_t k = firstWall; k < scene.shapes.size(); ++k) {
    scene.shapes[k].density = tumblerDrumDensity;
  }
  SceneJoint motor;
  motor.bodyA = ground;
  motor.bodyB = drum;
  motor.anchor = {0.0f, 10.0f};
  motor.enableMotor = true;
  motor.motorSpeed = tumblerSpeed;
  motor.maxMotorTorque = tumblerMotorTorque;
  scene.joints.push_back(motor);
  const float start = -0.2f * static_cast<float>(grid);
  for (int i = 0; i < grid; ++i) {
    for (int j = 0; j < grid; ++j) {
      const Vec2f p{start + 0.4f * static_cast<float>(j), start + 10.0f + 0.4f * static_cast<float>(i)};
      addBox(scene, addBody(scene, BodyType::dynamicBody, p), 0.125f, 0.125f);
    }
  }
  scene.defaultSteps = 750;
  return scene;
}

Rigid2dScene smashScene(int columns, int rows) {
  Rigid2dScene scene;
  scene.name = "smash";
  scene.gravity = {};
  scene.enableSleep = true;
  const std::uint32_t projectile = addBody(scene, BodyType::dynamicBody, {-20.0f, 0.0f});
  scene.bodies[projectile].linearVelocity = {40.0f, 0.0f};
  addBox(scene, projectile, 4.0f, 4.0f);
  scene.shapes.back().density = 8.0f;
  constexpr float d = 0.4f; // box size, m
  for (int i = 0; i < columns; ++i) {
    for (int j = 0; j < rows; ++j) {
      const Vec2f p{static_cast<float>(i) * d + 30.0f, (static_cast<float>(j) - 0.5f * static_cast<float>(rows)) * d};
      const std::uint32_t b = addBody(scene, BodyType::dynamicBody, p);
      scene.bodies[b].awake = false;
      addBox(scene, b, 0.5f * d, 0.5f * d);
    }
  }
  scene.defaultSteps = 300;
  return scene;
}

} // namespace impetus::bench
