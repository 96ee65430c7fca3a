// Chains in the world: terrain without ghost collisions, one-sided, containers.
#include "support/error_field.hpp"

#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace impetus::rigid2d {
namespace {

constexpr float dt = 1.0f / 60.0f;

/// A flat ground at y = 0 from x = -50 to 50 made of 1 m segments (listed right to left: solid
/// below).
ChainDef flatGround() {
  ChainDef chain;
  for (int i = 50; i >= -50; --i) {
    chain.points.push_back({static_cast<float>(i), 0.0f});
  }
  return chain;
}

// A box sliding along a 100-segment flat chain crosses a seam every metre and never catches:
// it decelerates at mu g and stops after v0^2 / (2 mu g), within 2%, never hopping.
TEST(Chain2D, box_slides_across_seams_and_stops_where_friction_says) {
  WorldDef def;
  def.enableSleep = false;
  World world(def);
  const BodyId ground = world.createBody({});
  world.createChain(ground, {}, flatGround());
  BodyDef body;
  body.type = BodyType::dynamicBody;
  body.position = {-40.0f, 0.25f};
  const BodyId box = world.createBody(body);
  ShapeDef shape;
  shape.friction = 0.2f;
  world.createShape(box, shape, makeBox(0.25f, 0.25f));
  for (int i = 0; i < 30; ++i) { // settle
    world.step(dt);
  }
  const float start = world.position(box).x;
  const float v0 = 8.0f;
  world.setLinearVelocity(box, {v0, 0.0f});
  // Friction pair: sqrt(0.2 * 0.6).
  const float mu = std::sqrt(0.2f * 0.6f);
  float highest = 0.0f;
  for (int i = 0; i < 600; ++i) {
    world.step(dt);
    highest = std::max(highest, world.position(box).y);
  }
  const float expected = v0 * v0 / (2.0f * mu * 10.0f);
  EXPECT_NEAR(world.position(box).x - start, expected, 0.02f * expected);
  EXPECT_LT(highest, 0.25f + 0.005f) << "the box hopped on a seam";
  EXPECT_NEAR(world.angle(box), 0.0f, 1e-3f);
}

// One-sided: a ball thrown up from below passes through the chain and lands on top of it.
TEST(Chain2D, shapes_pass_through_from_the_solid_side) {
  World world;
  const BodyId ground = world.createBody({});
  world.createChain(ground, {}, flatGround());
  BodyDef body;
  body.type = BodyType::dynamicBody;
  body.position = {0.0f, -1.0f};
  body.linearVelocity = {0.0f, 8.0f};
  const BodyId ball = world.createBody(body);
  world.createShape(ball, {}, Circle{{}, 0.25f});
  for (int i = 0; i < 240; ++i) {
    world.step(dt);
  }
  EXPECT_NEAR(world.position(ball).y, 0.25f, 0.01f);
}

// A clockwise loop is a container: balls dropped inside stay inside.
TEST(Chain2D, clockwise_loop_contains_what_is_inside) {
  World world;
  const BodyId ground = world.createBody({});
  ChainDef box;
  box.points = {{-5.0f, 0.0f}, {-5.0f, 10.0f}, {5.0f, 10.0f}, {5.0f, 0.0f}}; // clockwise
  box.isLoop = true;
  EXPECT_EQ(world.createChain(ground, {}, box).size(), 4U);
  std::vector<BodyId> balls;
  BodyDef body;
  body.type = BodyType::dynamicBody;
  ShapeDef bouncy;
  bouncy.restitution = 0.8f;
  for (int i = 0; i < 30; ++i) {
    body.position = {-4.0f + 0.27f * static_cast<float>(i), 2.0f + 0.2f * static_cast<float>(i % 7)};
    body.linearVelocity = {static_cast<float>((i * 7) % 11) - 5.0f, 6.0f};
    balls.push_back(world.createBody(body));
    world.createShape(balls.back(), bouncy, Circle{{}, 0.2f});
  }
  for (int i = 0; i < 600; ++i) {
    world.step(dt);
  }
  for (BodyId b : balls) {
    const Vec2f p = world.position(b);
    EXPECT_TRUE(p.x > -5.0f && p.x < 5.0f && p.y > 0.0f && p.y < 10.0f) << p.x << ", " << p.y;
  }
}

TEST(Chain2D, bad_chains_name_the_field) {
  World world;
  const BodyId ground = world.createBody({});
  ChainDef one;
  one.points = {{0.0f, 0.0f}};
  expectErrorField([&] { (void)world.createChain(ground, {}, one); }, "points.size");
  ChainDef repeated;
  repeated.points = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 0.0f}};
  expectErrorField([&] { (void)world.createChain(ground, {}, repeated); }, "points[2]");
  EXPECT_EQ(world.shapeCount(), 0U);
}

} // namespace
} // namespace impetus::rigid2d
