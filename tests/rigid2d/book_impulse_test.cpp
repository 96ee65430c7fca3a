// SolverKind::bookImpulse: the book's one-impulse response (ch. 9-10, errata fixed), checked
// against the spec's worked impulses (../shared/spec/ch07-10.md, 5.5) and Newton's law of
// restitution.
#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace impetus::rigid2d {
namespace {

constexpr float dt = 1.0f / 60.0f;

WorldDef bookWorld(Vec2f gravity = {}) {
  WorldDef def;
  def.solver = SolverKind::bookImpulse;
  def.gravity = gravity;
  def.enableSleep = false;
  return def;
}

/// A dynamic disc of the given mass (density from the area), frictionless.
BodyId addDisc(World& world, const Vec2f& position, const Vec2f& velocity, float radius, float mass,
               float restitution) {
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = position;
  def.linearVelocity = velocity;
  const BodyId b = world.createBody(def);
  ShapeDef shape;
  shape.density = mass / (pi<float> * radius * radius);
  shape.friction = 0.0f;
  shape.restitution = restitution;
  world.createShape(b, shape, Circle{{}, radius});
  return b;
}

// Spec C-2: m1 = m2 = 100 kg, v1 = (10, 0), v2 = 0, e = 0.5, central impact:
// J = 750 N s, v1' = (2.5, 0), v2' = (7.5, 0); momentum 1000 kg m/s kept, KE 5000 -> 3125 J.
TEST(BookImpulse2D, head_on_discs_match_the_worked_impulse) {
  World world(bookWorld());
  const BodyId one = addDisc(world, {0.0f, 0.0f}, {10.0f, 0.0f}, 1.0f, 100.0f, 0.5f);
  const BodyId two = addDisc(world, {2.05f, 0.0f}, {}, 1.0f, 100.0f, 0.5f);
  for (int i = 0; i < 30; ++i) {
    world.step(dt);
  }
  // Float masses from a density: relative error ~1e-6; the impulse is computed in double.
  EXPECT_NEAR(world.linearVelocity(one).x, 2.5f, 1e-4f);
  EXPECT_NEAR(world.linearVelocity(two).x, 7.5f, 1e-4f);
  EXPECT_NEAR(world.linearVelocity(one).y, 0.0f, 1e-6f);
  const float momentum = world.mass(one) * world.linearVelocity(one).x + world.mass(two) * world.linearVelocity(two).x;
  EXPECT_NEAR(momentum, 1000.0f, 0.05f);
  const float energy = 0.5f * world.mass(one) * std::pow(world.linearVelocity(one).x, 2.0f) +
                       0.5f * world.mass(two) * std::pow(world.linearVelocity(two).x, 2.0f);
  EXPECT_NEAR(energy, 3125.0f, 0.5f);
  ASSERT_EQ(world.contactEvents().hits.size(), 0U); // the hit was reported in its own step
}

// An off-centre frictionless hit of a box on a free box: linear and angular momentum (about the
// origin) are conserved, and the contact point's normal relative velocity after the impulse is
// -e times before (Newton's law, which the book's impulse is built on).
TEST(BookImpulse2D, off_centre_box_hit_obeys_newton_restitution_and_conserves_momentum) {
  World world(bookWorld());
  ShapeDef shape;
  shape.friction = 0.0f;
  shape.restitution = 0.8f;
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = {0.0f, 0.4f};
  def.linearVelocity = {6.0f, 0.0f};
  const BodyId moving = world.createBody(def);
  world.createShape(moving, shape, makeBox(0.5f, 0.5f));
  def.position = {1.02f, -0.3f};
  def.linearVelocity = {};
  const BodyId target = world.createBody(def);
  world.createShape(target, shape, makeBox(0.5f, 0.5f));
  const auto momentum = [&] {
    Vec2f p;
    float l = 0.0f;
    for (BodyId b : {moving, target}) {
      const Vec2f v = world.linearVelocity(b) * world.mass(b);
      p += v;
      l += cross(world.worldCenterOfMass(b), v) + world.rotationalInertia(b) * world.angularVelocity(b);
    }
    return std::pair{p, l};
  };
  const auto [p0, l0] = momentum();
  world.step(dt);
  const auto [p1, l1] = momentum();
  ASSERT_GT(std::abs(world.angularVelocity(target)), 0.1f) << "the off-centre hit must spin the target";
  EXPECT_NEAR(p1.x, p0.x, 1e-4f * length(p0));
  EXPECT_NEAR(p1.y, p0.y, 1e-4f * length(p0));
  // The hit happens mid-step; positions then advance by v dt, which does not change L either.
  EXPECT_NEAR(l1, l0, 1e-4f * std::abs(l0) + 1e-4f);
  // Face contact on x = 0.5 (midpoint of the overlap y in [-0.1, 0.2] from the mover's side):
  // the relative normal velocity reverses with factor e.
  const Vec2f contact{0.51f, 0.05f};
  const auto pointVelocity = [&](BodyId b) {
    return world.linearVelocity(b) + cross(world.angularVelocity(b), contact - world.worldCenterOfMass(b));
  };
  const float after = pointVelocity(target).x - pointVelocity(moving).x;
  EXPECT_NEAR(after, 0.8f * 6.0f, 0.05f) << "separating speed e times the approach speed";
}

// A ball dropped from h rebounds to e^2 h: the impulse reverses the impact speed with factor e.
// The impulse acts in the frame the gap would close, up to one frame's travel (v dt = 0.1 m at
// 6.3 m/s) above the floor, and the rebound starts from there: 5% of e^2 h covers it.
TEST(BookImpulse2D, dropped_ball_rebounds_to_e_squared_h) {
  World world(bookWorld({0.0f, -10.0f}));
  const BodyId ground = world.createBody({});
  world.createShape(ground, {}, makeOffsetBox(10.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
  const float radius = 0.25f;
  const float h = 2.0f;
  const BodyId ball = addDisc(world, {0.0f, radius + h}, {}, radius, 1.0f, 0.7f);
  float peak = 0.0f;
  bool bounced = false;
  for (int i = 0; i < 200; ++i) {
    world.step(dt);
    if (world.linearVelocity(ball).y > 0.0f) {
      bounced = true;
    }
    if (bounced) {
      peak = std::max(peak, world.position(ball).y - radius);
    }
    if (bounced && world.linearVelocity(ball).y < 0.0f) {
      break;
    }
  }
  EXPECT_NEAR(peak, 0.49f * h, 0.05f * 0.49f * h);
}

// Resting contact: a box on the ground neither sinks nor jitters (slow impacts do not bounce,
// and overlap beyond linearSlop is pushed out).
TEST(BookImpulse2D, box_rests_on_the_ground) {
  World world(bookWorld({0.0f, -10.0f}));
  const BodyId ground = world.createBody({});
  world.createShape(ground, {}, makeOffsetBox(10.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = {0.0f, 0.6f};
  const BodyId box = world.createBody(def);
  ShapeDef shape;
  shape.restitution = 0.5f;
  world.createShape(box, shape, makeBox(0.5f, 0.5f));
  for (int i = 0; i < 180; ++i) {
    world.step(dt);
  }
  EXPECT_NEAR(world.position(box).y, 0.5f, 0.01f);
  EXPECT_LT(std::abs(world.linearVelocity(box).y), 0.2f);
  EXPECT_NEAR(world.angle(box), 0.0f, 1e-3f);
}

} // namespace
} // namespace impetus::rigid2d

namespace impetus::rigid2d {
namespace {

// Joints work in the book's mode too (solved once per frame): a 1 m pendulum keeps its length
// within 1% and swings with the small-angle period 2 pi sqrt(L/g) within 2% (one semi-implicit
// Euler step per frame of 1/60 s).
TEST(BookImpulse2D, joints_are_solved_in_the_book_mode) {
  World world(bookWorld({0.0f, -10.0f}));
  const BodyId pivot = world.createBody({});
  const BodyId bob = addDisc(world, {0.1f, -std::sqrt(1.0f - 0.01f)}, {}, 0.02f, 1.0f, 0.0f);
  RevoluteJointDef joint;
  joint.bodyA = pivot;
  joint.bodyB = bob;
  joint.localAnchorB = -world.position(bob);
  world.createJoint(joint);
  float previous = 0.0f;
  std::vector<float> turns;
  for (int i = 1; i < 600 && turns.size() < 3; ++i) {
    world.step(dt);
    const float v = world.linearVelocity(bob).x;
    if (i > 1 && ((previous < 0.0f) != (v < 0.0f))) {
      turns.push_back(static_cast<float>(i) * dt);
    }
    previous = v;
    EXPECT_NEAR(length(world.position(bob)), 1.0f, 0.01f);
  }
  ASSERT_EQ(turns.size(), 3U);
  const float period = turns[2] - turns[0];
  EXPECT_NEAR(period, 2.0f * pi<float> * std::sqrt(1.0f / 10.0f), 0.02f * 1.987f);
}

} // namespace
} // namespace impetus::rigid2d
