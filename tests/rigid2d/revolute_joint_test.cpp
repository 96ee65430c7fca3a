// The revolute joint against mechanics: pendulum periods, limits under load, motors, chains,
// and the joint bookkeeping (collision between connected bodies, break events, bad input).
#include "support/error_field.hpp"

#include "bodies.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>
#include <vector>

namespace impetus::rigid2d {
namespace {

constexpr float dt = 1.0f / 60.0f;
constexpr float g = 10.0f;

using test::addBall;

/// Complete elliptic integral of the first kind, K(k) = pi / (2 AGM(1, sqrt(1 - k^2))).
double ellipticK(double k) {
  double a = 1.0;
  double b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 30; ++i) {
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return pi<double> / (2.0 * a);
}

/// Period of a pendulum released from rest at `amplitude` (rad): the time between the first and
/// fifth turning points (where the bob's horizontal velocity changes sign), halved.
double measurePeriod(float amplitude, float armLength, float radius, int substeps) {
  WorldDef def;
  def.gravity = {0.0f, -g};
  def.substeps = substeps;
  World world(def);
  const BodyId pivot = world.createBody({});
  const Vec2f bob{armLength * std::sin(amplitude), -armLength * std::cos(amplitude)};
  const BodyId ball = addBall(world, bob, radius);
  RevoluteJointDef joint;
  joint.bodyA = pivot;
  joint.bodyB = ball;
  joint.localAnchorA = {};
  joint.localAnchorB = -bob; // the pivot, in the ball's frame (not rotated yet)
  world.createJoint(joint);
  // Times at which the bob's horizontal velocity changes sign (the turning points), linearly
  // interpolated within the step.
  std::vector<double> turns;
  float previous = world.linearVelocity(ball).x;
  for (int i = 1; i < 60 * 30 && turns.size() < 5; ++i) {
    world.step(dt);
    const float v = world.linearVelocity(ball).x;
    if (i > 1 && ((previous < 0.0f && v >= 0.0f) || (previous > 0.0f && v <= 0.0f))) {
      turns.push_back((static_cast<double>(i - 1) + static_cast<double>(previous / (previous - v))) * dt);
    }
    previous = v;
  }
  EXPECT_GE(turns.size(), 5U);
  // A full period spans two half swings; average two.
  return (turns[4] - turns[0]) / 2.0;
}

// A point-like bob (small disc) on a massless arm: T = 2 pi sqrt(L/g) for small swings, and
// 4 sqrt(L/g) K(sin(theta0/2)) for large ones. The disc's own inertia makes it a physical
// pendulum: T = 2 pi sqrt((L^2 + r^2/2) / (g L)), which is what is compared.
TEST(RevoluteJoint2D, pendulum_period_matches_small_and_large_angle_theory) {
  const float length = 2.0f;
  const float radius = 0.05f;
  const double effective = (length * length + 0.5 * radius * radius) / length; // equivalent simple length
  const double small = 2.0 * pi<double> * std::sqrt(effective / g);
  EXPECT_NEAR(measurePeriod(0.05f, length, radius, 4), small, 0.005 * small);
  // At 90 degrees within 0.1% of the elliptic integral (the soft step at 240 substeps a second
  // has a period error of order (omega h)^2, 10^-5 here; the rest is the measurement's).
  const float big = 0.5f * pi<float>;
  const double large = 4.0 * std::sqrt(effective / g) * ellipticK(std::sin(0.5 * static_cast<double>(big)));
  EXPECT_NEAR(measurePeriod(big, length, radius, 4), large, 0.001 * large);
}

// A horizontal bar hinged at one end with limits [-0.1, 0.1] rad holds under its own weight: the
// lower limit stops it within half a degree.
TEST(RevoluteJoint2D, limit_holds_under_load) {
  World world;
  const BodyId ground = world.createBody({});
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = {2.0f, 0.0f};
  const BodyId bar = world.createBody(def);
  ShapeDef heavy;
  heavy.density = 20.0f;
  world.createShape(bar, heavy, makeBox(2.0f, 0.1f));
  RevoluteJointDef joint;
  joint.bodyA = ground;
  joint.bodyB = bar;
  joint.localAnchorA = {0.0f, 0.0f};
  joint.localAnchorB = {-2.0f, 0.0f};
  joint.enableLimit = true;
  joint.lowerAngle = -0.1f;
  joint.upperAngle = 0.1f;
  const auto id = world.createJoint(joint);
  for (int i = 0; i < 300; ++i) {
    world.step(dt);
  }
  EXPECT_NEAR(revoluteAngle(world, id), -0.1f, 0.5f * pi<float> / 180.0f);
  // The limit carries the bar's weight moment: m g L/2 = (4 * 0.2 * 20) * 10 * 2 = 320 N m.
  EXPECT_NEAR(world.jointReactionTorque(id), 320.0f, 0.02f * 320.0f);
  // And the pin its weight: 160 N up on the bar.
  EXPECT_NEAR(world.jointReactionForce(id).y, 160.0f, 0.02f * 160.0f);
}

// A motor spins a free wheel up to its speed and never applies more than its torque: with a
// disc of inertia I and max torque T, the speed ramps at T/I until it reaches motorSpeed.
TEST(RevoluteJoint2D, motor_reaches_its_speed_within_its_torque) {
  WorldDef def;
  def.gravity = {};
  World world(def);
  const BodyId ground = world.createBody({});
  const BodyId wheel = addBall(world, {}, 0.5f);
  RevoluteJointDef joint;
  joint.bodyA = ground;
  joint.bodyB = wheel;
  joint.enableMotor = true;
  joint.motorSpeed = 10.0f;
  joint.maxMotorTorque = 0.5f;
  const auto id = world.createJoint(joint);
  const float inertia = world.rotationalInertia(wheel);
  world.step(dt);
  // One step at full torque: w = T dt / I.
  EXPECT_NEAR(world.angularVelocity(wheel), 0.5f * dt / inertia, 1e-4f);
  EXPECT_LE(std::abs(revoluteMotorTorque(world, id)), 0.5f * 1.0001f);
  float peak = 0.0f;
  for (int i = 0; i < 600; ++i) {
    world.step(dt);
    peak = std::max(peak, std::abs(revoluteMotorTorque(world, id)));
  }
  EXPECT_NEAR(world.angularVelocity(wheel), 10.0f, 1e-3f);
  EXPECT_LE(peak, 0.5f * 1.0001f);
}

// A chain of 20 links, the bottom one 10 times heavier than the rest, hangs from a pin and swings
// without stretching more than 2%: the sum of the gaps that open at its 20 pins (each pin's two
// anchors should coincide) stays under 2% of its length, at every step.
TEST(RevoluteJoint2D, chain_with_ten_to_one_mass_ratio_hangs_without_stretching) {
  World world;
  const BodyId ground = world.createBody({});
  const float linkLength = 0.5f;
  BodyId previous = ground;
  Vec2f anchor{0.0f, 20.0f};
  struct Pin {
    BodyId a, b;
    Vec2f localA, localB;
  };
  std::vector<Pin> pins;
  BodyId last;
  for (int i = 0; i < 20; ++i) {
    BodyDef def;
    def.type = BodyType::dynamicBody;
    def.position = {anchor.x, anchor.y - 0.5f * linkLength};
    def.enableSleep = false;
    const BodyId link = world.createBody(def);
    ShapeDef shape;
    shape.density = i == 19 ? 10.0f : 1.0f;
    world.createShape(link, shape, Capsule{{0.0f, -0.25f * linkLength}, {0.0f, 0.25f * linkLength}, 0.05f});
    RevoluteJointDef joint;
    joint.bodyA = previous;
    joint.bodyB = link;
    joint.localAnchorA = previous == ground ? anchor : Vec2f{0.0f, -0.5f * linkLength};
    joint.localAnchorB = {0.0f, 0.5f * linkLength};
    world.createJoint(joint);
    pins.push_back({previous, link, joint.localAnchorA, joint.localAnchorB});
    previous = link;
    last = link;
    anchor.y -= linkLength;
  }
  // A kick that sends the heavy link off at about 3 m/s.
  world.applyLinearImpulse(last, {3.0f * world.mass(last), 0.0f}, world.worldCenterOfMass(last));
  const float nominal = 20.0f * linkLength;
  float worst = 0.0f;
  for (int i = 0; i < 600; ++i) {
    world.step(dt);
    float gaps = 0.0f;
    for (const Pin& p : pins) {
      gaps += distance(transformPoint(world.transform(p.a), p.localA), transformPoint(world.transform(p.b), p.localB));
    }
    worst = std::max(worst, gaps);
  }
  EXPECT_LT(worst, 0.02f * nominal) << "the pins opened by " << worst << " m in all";
}

// Connected bodies do not collide unless asked; break limits raise one event.
TEST(RevoluteJoint2D, connected_bodies_do_not_collide_and_breaks_are_reported) {
  World world;
  const BodyId ground = world.createBody({});
  world.createShape(ground, {}, makeOffsetBox(10.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
  const BodyId ball = addBall(world, {0.0f, 0.5f}, 0.5f, 4.0f);
  RevoluteJointDef joint;
  joint.bodyA = ground;
  joint.bodyB = ball;
  joint.localAnchorA = {0.0f, 0.2f}; // inside the ground's top face: would push it out if colliding
  joint.localAnchorB = {0.0f, -0.3f};
  joint.breakForce = 10.0f; // the ball weighs pi 0.25 4 10 = 31.4 N
  const auto id = world.createJoint(joint);
  world.step(dt);
  EXPECT_EQ(world.contactCount(), 0U);
  ASSERT_EQ(world.jointEvents().breaks.size(), 1U);
  EXPECT_EQ(world.jointEvents().breaks[0].joint, id);
  EXPECT_GT(world.jointEvents().breaks[0].force, 10.0f);
  world.step(dt);
  EXPECT_TRUE(world.jointEvents().breaks.empty()) << "reported once while over the limit";
  world.destroyJoint(id);
  EXPECT_FALSE(world.isValid(id));
  for (int i = 0; i < 60; ++i) {
    world.step(dt);
  }
  EXPECT_EQ(world.contactCount(), 1U) << "free again, the ball rests on the ground";
  expectErrorField([&] { (void)revoluteAngle(world, id); }, "joint id");
}

TEST(RevoluteJoint2D, bad_definitions_name_the_field) {
  World world;
  const BodyId a = world.createBody({});
  const BodyId b = addBall(world, {}, 0.5f);
  RevoluteJointDef def;
  def.bodyA = a;
  def.bodyB = b;
  def.enableLimit = true;
  def.lowerAngle = 1.0f;
  def.upperAngle = -1.0f;
  expectErrorField([&] { (void)world.createJoint(def); }, "lowerAngle");
  def.enableLimit = false;
  def.maxMotorTorque = -1.0f;
  expectErrorField([&] { (void)world.createJoint(def); }, "maxMotorTorque");
  def.maxMotorTorque = 0.0f;
  def.localAnchorB = {std::nanf(""), 0.0f};
  expectErrorField([&] { (void)world.createJoint(def); }, "localAnchorB.x");
  def.localAnchorB = {};
  def.bodyB = a;
  expectErrorField([&] { (void)world.createJoint(def); }, "bodyB");
  def.bodyB = BodyId{};
  expectErrorField([&] { (void)world.createJoint(def); }, "bodyB");
  EXPECT_EQ(world.jointCount(), 0U);
}

// A body asleep on a joint wakes with its partner; destroying a body takes its joints along.
TEST(RevoluteJoint2D, joints_share_sleep_and_die_with_their_bodies) {
  World world;
  const BodyId ground = world.createBody({});
  world.createShape(ground, {}, makeOffsetBox(10.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = {0.0f, 0.5f};
  const BodyId a = world.createBody(def);
  world.createShape(a, {}, makeBox(0.5f, 0.5f));
  def.position = {1.5f, 0.5f};
  const BodyId b = world.createBody(def);
  world.createShape(b, {}, makeBox(0.5f, 0.5f));
  RevoluteJointDef joint;
  joint.bodyA = a;
  joint.bodyB = b;
  joint.localAnchorA = {0.75f, 0.0f};
  joint.localAnchorB = {-0.75f, 0.0f};
  const auto id = world.createJoint(joint);
  for (int i = 0; i < 120; ++i) {
    world.step(dt);
  }
  EXPECT_FALSE(world.isAwake(a));
  EXPECT_FALSE(world.isAwake(b));
  world.applyLinearImpulse(a, {0.0f, 2.0f}, world.worldCenterOfMass(a));
  world.step(dt);
  EXPECT_TRUE(world.isAwake(b)) << "woken through the joint";
  world.destroyBody(a);
  EXPECT_FALSE(world.isValid(id));
  EXPECT_EQ(world.jointCount(), 0U);
}

} // namespace

// A joint type's functions take its typed id only: a prismatic joint's id is not a revolute's,
// while every typed id is a JointId for what all joints have.
static_assert(!std::is_convertible_v<PrismaticJointId, RevoluteJointId>);
static_assert(std::is_convertible_v<PrismaticJointId, JointId>);
static_assert(!std::is_convertible_v<JointId, RevoluteJointId>);

} // namespace impetus::rigid2d
