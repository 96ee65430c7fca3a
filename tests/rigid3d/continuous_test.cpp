// Continuous collision: fast bodies do not pass through thin walls, however fast (up to the speed
// cap), and bullets do not pass through thin moving bodies.
#include <impetus/rigid3d/world.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace impetus::rigid3d {
namespace {

constexpr float dt = 1.0f / 60.0f;

/// A static wall 1 cm thick across the x axis at x = 5 m, 4 m square.
void addWall(World& world) {
  BodyDef def;
  def.position = {5.0f, 0.0f, 0.0f};
  world.createShape(world.createBody(def), ShapeDef{}, makeBoxHull({0.005f, 2.0f, 2.0f}));
}

BodyId shoot(World& world, const ShapeGeometry& shape, float speed, bool bullet = false) {
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.linearVelocity = {speed, 0.0f, 0.0f};
  def.angularVelocity = {3.0f, 20.0f, -7.0f}; // tumbling
  def.isBullet = bullet;
  const BodyId body = world.createBody(def);
  world.createShape(body, ShapeDef{}, shape);
  return body;
}

TEST(Rigid3dContinuous, a_fast_body_does_not_pass_through_a_thin_wall) {
  // At 300 m/s a step carries a body 5 m: from 0 m it would be past a wall at 5 m after one
  // step, and its speculative contacts (2 cm) never see the wall. Swept, it stops there.
  for (const float speed : {300.0f, 400.0f}) {
    for (const ShapeGeometry& shape :
         {ShapeGeometry{Sphere{{}, 0.05f}}, ShapeGeometry{Capsule{{0.0f, -0.1f, 0.0f}, {0.0f, 0.1f, 0.0f}, 0.03f}},
          ShapeGeometry{makeBoxHull({0.05f, 0.1f, 0.02f})}}) {
      World world(WorldDef{{0.0f, 0.0f, 0.0f}});
      addWall(world);
      const BodyId body = shoot(world, shape, speed);
      float farthest = -1e9f;
      for (int i = 0; i < 30; ++i) {
        world.step(dt);
        farthest = std::max(farthest, world.position(body).x);
      }
      EXPECT_LT(farthest, 5.0f) << "speed " << speed << " shape " << shape.index();
      EXPECT_LT(world.linearVelocity(body).x, 1.0f) << "stopped or bounced back";
    }
  }
}

TEST(Rigid3dContinuous, without_the_wall_the_shot_flies_on) {
  // The reference the test above needs: the same shot with no wall goes 150 m in half a second.
  World world(WorldDef{{0.0f, 0.0f, 0.0f}});
  const BodyId body = shoot(world, Sphere{{}, 0.05f}, 300.0f);
  for (int i = 0; i < 30; ++i) {
    world.step(dt);
  }
  EXPECT_NEAR(world.position(body).x, 150.0f, 1e-3f);
}

TEST(Rigid3dContinuous, a_bullet_does_not_pass_through_a_thin_moving_plate) {
  // A dynamic plate 1 cm thick drifting sideways, and a bullet at 300 m/s: swept against the
  // plate where it ends each step, the bullet hits it and pushes it on. A body that is not a
  // bullet passes through (what the flag is for).
  for (const bool bullet : {true, false}) {
    World world(WorldDef{{0.0f, 0.0f, 0.0f}});
    BodyDef plateDef;
    plateDef.type = BodyType::dynamicBody;
    plateDef.position = {5.0f, 0.0f, 0.0f};
    plateDef.linearVelocity = {0.0f, 0.0f, 0.5f};
    const BodyId plate = world.createBody(plateDef);
    world.createShape(plate, ShapeDef{}, makeBoxHull({0.005f, 1.0f, 1.0f}));
    const BodyId body = shoot(world, Sphere{{}, 0.05f}, 300.0f, bullet);
    for (int i = 0; i < 10; ++i) {
      world.step(dt);
    }
    if (bullet) {
      EXPECT_LT(world.position(body).x, world.position(plate).x);
      EXPECT_GT(world.linearVelocity(plate).x, 0.1f);
    } else {
      EXPECT_GT(world.position(body).x, 10.0f);
    }
  }
}

} // namespace
} // namespace impetus::rigid3d
