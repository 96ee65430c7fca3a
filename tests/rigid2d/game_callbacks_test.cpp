// What a game hooks into the 2D world (after Box2D v3): conveyor belts (a shape's tangent speed),
// one-way platforms (the pre-solve callback), game rules for which shapes collide (the custom
// filter), and the bodies that moved each step (move events). Each is checked by what it does to
// the motion: the belt's speed reached through friction, a body passing a platform from below and
// landing on it from above, a box falling through its own team and onto the other. And where the
// broadphase begins pairing shapes (their fat boxes' margins), seen through the custom filter.
#include "support/error_field.hpp"

#include <impetus/rigid2d/constants.hpp>
#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace impetus::rigid2d {
namespace {

constexpr float dt = 1.0f / 60.0f;

BodyId addDynamic(World& world, const Vec2f& position, const Polygon& polygon, const ShapeDef& shape = {}) {
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = position;
  def.enableSleep = false;
  const BodyId body = world.createBody(def);
  world.createShape(body, shape, polygon);
  return body;
}

TEST(Conveyor, a_box_on_a_belt_is_carried_at_the_belts_speed) {
  for (const float beltSpeed : {2.0f, -3.0f}) {
    World world;
    const BodyId ground = world.createBody({});
    ShapeDef belt;
    belt.friction = 0.8f;
    belt.tangentSpeed = beltSpeed; // clockwise around the belt: +x along its top face
    world.createShape(ground, belt, makeOffsetBox(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f)); // top at y = 0
    const BodyId box = addDynamic(world, {0.0f, 0.5f}, makeBox(0.5f, 0.5f));
    // Friction mu g = 8 m/s^2 accelerates it to the belt's speed within 0.4 s; then it rides.
    for (int i = 0; i < 120; ++i) {
      world.step(dt);
    }
    EXPECT_NEAR(world.linearVelocity(box).x, beltSpeed, 0.01f * std::abs(beltSpeed)) << beltSpeed;
    EXPECT_NEAR(world.linearVelocity(box).y, 0.0f, 1e-3f);
    EXPECT_NEAR(world.angularVelocity(box), 0.0f, 1e-2f);
  }
}

TEST(Conveyor, a_belt_above_a_box_drives_it_the_other_way) {
  // Clockwise around the belt: its bottom face runs toward -x. No gravity; the box is pressed up
  // against the belt by a steady force.
  WorldDef def;
  def.gravity = {};
  World world(def);
  const BodyId ceiling = world.createBody({});
  ShapeDef belt;
  belt.friction = 0.8f;
  belt.tangentSpeed = 2.0f;
  world.createShape(ceiling, belt, makeOffsetBox(20.0f, 0.5f, {0.0f, 1.5f}, 0.0f)); // bottom at y = 1
  const BodyId box = addDynamic(world, {0.0f, 0.5f}, makeBox(0.5f, 0.5f));
  for (int i = 0; i < 120; ++i) {
    world.applyForce(box, {0.0f, 10.0f}, world.worldCenterOfMass(box));
    world.step(dt);
  }
  EXPECT_NEAR(world.linearVelocity(box).x, -2.0f, 0.02f);
}

TEST(Conveyor, a_tangent_speed_that_is_not_finite_is_refused) {
  World world;
  const BodyId ground = world.createBody({});
  ShapeDef belt;
  belt.tangentSpeed = std::nanf("");
  expectErrorField([&] { (void)world.createShape(ground, belt, makeBox(1.0f, 1.0f)); }, "tangentSpeed");
  belt.tangentSpeed = std::numeric_limits<float>::infinity();
  expectErrorField([&] { (void)world.createShape(ground, belt, makeBox(1.0f, 1.0f)); }, "tangentSpeed");
}

TEST(PreSolve, a_one_way_platform_lets_a_box_through_from_below_and_holds_it_from_above) {
  World world;
  const BodyId ground = world.createBody({});
  ShapeDef platformDef;
  platformDef.enablePreSolveEvents = true;
  const ShapeId platform = world.createShape(ground, platformDef, makeOffsetBox(3.0f, 0.25f, {0.0f, 3.0f}, 0.0f));
  // Thrown up from 1 m below the platform at 9 m/s: it would rise 4 m, through the platform.
  const BodyId box = addDynamic(world, {0.0f, 1.5f}, makeBox(0.25f, 0.25f));
  world.setLinearVelocity(box, {0.0f, 9.0f});
  std::atomic<int> asked{0};
  // Solid only for what is above the platform's top and not moving up through it: the contact
  // normal points from the platform up (or, with the shapes the other way, down from the box).
  world.setPreSolve([&](ShapeId a, ShapeId b, const Manifold& m) {
    ++asked;
    const float up = a == platform ? m.normal.y : -m.normal.y;
    const ShapeId other = a == platform ? b : a;
    const float bottom = world.position(world.shapeBody(other)).y - 0.25f;
    return up > 0.9f && bottom > 3.25f - 0.05f;
  });
  float highest = 0.0f;
  for (int i = 0; i < 180; ++i) {
    world.step(dt);
    highest = std::max(highest, world.position(box).y);
  }
  EXPECT_GT(asked.load(), 0);
  EXPECT_GT(highest, 4.0f); // it went through, above the platform (top at 3.25 m)
  // And came down onto it: resting on the top face, box centre 0.25 m above it.
  EXPECT_NEAR(world.position(box).y, 3.5f, 0.02f);
  EXPECT_NEAR(world.linearVelocity(box).y, 0.0f, 0.05f);
}

TEST(CustomFilter, a_box_falls_through_its_own_team_and_lands_on_the_other) {
  for (const bool sameTeam : {true, false}) {
    World world;
    const BodyId ground = world.createBody({});
    world.createShape(ground, {}, makeOffsetBox(5.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    ShapeDef team;
    team.enableCustomFiltering = true;
    const BodyId lower = addDynamic(world, {0.0f, 0.5f}, makeBox(0.5f, 0.5f), team);
    const BodyId upper = addDynamic(world, {0.0f, 3.0f}, makeBox(0.5f, 0.5f), team);
    int asked = 0;
    // The rule: team mates (the two boxes, when on one team) pass through each other.
    world.setCustomFilter([&](ShapeId a, ShapeId b) {
      ++asked;
      const bool mates = world.shapeBody(a) != ground && world.shapeBody(b) != ground;
      return !(sameTeam && mates);
    });
    for (int i = 0; i < 120; ++i) {
      world.step(dt);
    }
    EXPECT_GT(asked, 0);
    if (sameTeam) {
      // Through its team mate, onto the ground beside it: both centres at 0.5 m.
      EXPECT_NEAR(world.position(upper).y, 0.5f, 0.02f);
    } else {
      EXPECT_NEAR(world.position(upper).y, 1.5f, 0.02f); // on top of the other team's box
    }
    EXPECT_NEAR(world.position(lower).y, 0.5f, 0.02f);
  }
}

TEST(BodyMoveEvents, list_the_bodies_that_moved_and_those_that_fell_asleep) {
  World world;
  const BodyId ground = world.createBody({});
  world.createShape(ground, {}, makeOffsetBox(5.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = {0.0f, 0.5f};
  def.userData = 7;
  const BodyId box = world.createBody(def);
  world.createShape(box, {}, makeBox(0.5f, 0.5f));
  world.step(dt);
  ASSERT_EQ(world.bodyMoveEvents().size(), 1u); // the box; never the static ground
  const BodyMoveEvent& e = world.bodyMoveEvents()[0];
  EXPECT_EQ(e.body, box);
  EXPECT_EQ(e.userData, 7u);
  EXPECT_FALSE(e.fellAsleep);
  EXPECT_EQ(e.transform.p.y, world.transform(box).p.y);
  // Resting, it falls asleep after timeToSleep (0.5 s): one last event says so, then none.
  int asleepEvents = 0;
  int step = 0;
  for (; step < 120 && world.isAwake(box); ++step) {
    world.step(dt);
    for (const BodyMoveEvent& m : world.bodyMoveEvents()) {
      asleepEvents += m.fellAsleep ? 1 : 0;
    }
  }
  EXPECT_FALSE(world.isAwake(box));
  EXPECT_EQ(asleepEvents, 1);
  world.step(dt);
  EXPECT_TRUE(world.bodyMoveEvents().empty());
}

// The broadphase pairs two shapes once their fat boxes overlap: each box reaches
// speculativeDistance plus the shape's margin past the shape, the margin an eighth of the
// shape's extent (h sqrt 2 for a box of half-size h), at most aabbMargin (as Box2D v3). The custom
// filter is asked exactly when a pair is found, so it shows where pairing begins: for two boxes
// side by side, at a gap of 2 (speculativeDistance + margin), 7.5 cm for boxes of 0.2 m and 14 cm
// for boxes of 2 m. Each gap is 1.5 cm or more from its threshold.
TEST(FatBoxes, two_boxes_pair_within_a_margin_that_scales_with_their_size) {
  struct Case {
    float half;
    float gap;
    bool paired;
  };
  for (const Case c :
       {Case{0.1f, 0.06f, true}, Case{0.1f, 0.09f, false}, Case{1.0f, 0.12f, true}, Case{1.0f, 0.16f, false}}) {
    WorldDef def;
    def.gravity = {0.0f, 0.0f};
    World world(def);
    ShapeDef shape;
    shape.enableCustomFiltering = true;
    addDynamic(world, {0.0f, 0.0f}, makeBox(c.half, c.half), shape);
    addDynamic(world, {2.0f * c.half + c.gap, 0.0f}, makeBox(c.half, c.half), shape);
    int found = 0;
    world.setCustomFilter([&](ShapeId, ShapeId) {
      ++found;
      return true;
    });
    world.step(dt);
    const float margin = std::min(aabbMargin, aabbMarginFraction * c.half * std::sqrt(2.0f));
    EXPECT_EQ(found > 0, c.paired) << "half-size " << c.half << " m, gap " << c.gap << " m; pairs within "
                                   << 2.0f * (speculativeDistance + margin) << " m";
  }
}

} // namespace
} // namespace impetus::rigid2d
