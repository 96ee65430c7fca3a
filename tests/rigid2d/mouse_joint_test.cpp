// The mouse joint against mechanics: a damped spring of the given frequency (period, decay,
// static sag g / omega^2, the lag behind a moving target 2 zeta v / omega), whose pull never
// exceeds maxForce, with a little angular damping; bad input names the field.
#include "support/error_field.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace impetus::rigid2d {
namespace {

constexpr float dt = 1.0f / 60.0f;

WorldDef noGravity() {
  WorldDef def;
  def.gravity = {};
  return def;
}

BodyId addBox(World& world, const Vec2f& position, float hx, float hy, float density = 1.0f) {
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = position;
  def.enableSleep = false;
  const BodyId b = world.createBody(def);
  ShapeDef shape;
  shape.density = density;
  world.createShape(b, shape, makeBox(hx, hy));
  return b;
}

MouseJointId grab(World& world, BodyId body, const Vec2f& localAnchor, const Vec2f& target, float hertz,
                  float dampingRatio, float maxForce) {
  MouseJointDef def;
  def.bodyB = body;
  def.localAnchorB = localAnchor;
  def.target = target;
  def.hertz = hertz;
  def.dampingRatio = dampingRatio;
  def.maxForce = maxForce;
  return world.createJoint(def);
}

// Dragged from 3 m away (no gravity) by a 5 Hz spring of damping ratio 0.7 with ample force,
// held at its centre: after 2 s the body is on the target (the brief's 1 cm; the decay time
// 1 / (zeta omega) = 45 ms leaves only round-off) and at rest.
TEST(MouseJoint2D, drags_the_grabbed_point_onto_the_target) {
  World world(noGravity());
  const BodyId box = addBox(world, {}, 0.5f, 0.25f);
  const Vec2f target{2.0f, -2.2f};
  grab(world, box, {}, target, 5.0f, 0.7f, 1000.0f);
  for (int i = 0; i < 120; ++i) {
    world.step(dt);
  }
  EXPECT_LT(length(world.position(box) - target), 0.01f);
  EXPECT_LT(length(world.linearVelocity(box)), 0.01f);
}

// Held at a corner instead, the drag also swings the body round: the grabbed point comes onto
// the target and the body spins about it, for a point spring exerts no torque about its own
// point. Only the angular damping (-I rate w, about the centre) slows the spin; about the
// grabbed point, at distance r from the centre, the spin decays at rate I / (I + m r^2) (0.15/s
// here): checked between 3 s and 6 s within 5 % (the spring's stretch, omega^2 r / omega_s^2,
// 2 % of r, moves the centre a little). The grabbed point is within 1 cm of the target.
TEST(MouseJoint2D, a_body_held_off_centre_spins_about_the_target_and_slows) {
  World world(noGravity());
  const BodyId box = addBox(world, {}, 0.5f, 0.25f);
  const Vec2f anchor{0.5f, 0.25f};
  const Vec2f target{2.0f, -2.2f};
  grab(world, box, anchor, target, 5.0f, 0.7f, 1000.0f);
  float w3 = 0.0f;
  for (int i = 1; i <= 360; ++i) {
    world.step(dt);
    if (i == 180) {
      w3 = world.angularVelocity(box);
    }
  }
  EXPECT_LT(length(transformPoint(world.transform(box), anchor) - target), 0.01f);
  const float m = world.mass(box);
  const float inertia = world.rotationalInertia(box);
  const float rate = 0.6f * inertia / (inertia + m * dot(anchor, anchor));
  const float w6 = world.angularVelocity(box);
  EXPECT_GT(std::abs(w3), 1.0f) << "the drag has set it spinning";
  EXPECT_NEAR(std::log(w3 / w6) / 3.0f, rate, 0.05f * rate);
  // The centre circles the grabbed point: its speed is |w| r.
  EXPECT_NEAR(length(world.linearVelocity(box)), std::abs(w6) * length(anchor), 0.05f * std::abs(w6) * length(anchor));
}

// A free body (no gravity) held at its centre of mass, released 1 m from the target: a damped
// oscillator m x'' = -k x - c x' with k = m omega^2, c = 2 zeta m omega (the soft constraint's
// spring for the effective mass, here m). Period T = 1 / (f sqrt(1 - zeta^2)) and the ratio of
// successive same-side peaks exp(-2 pi zeta / sqrt(1 - zeta^2)). The step is 60 Hz with 4
// substeps: omega h = 0.026, so the soft step's discretization is well under 1 %; the brief
// asks 5 % on the period, the decay is checked at 5 % too.
TEST(MouseJoint2D, oscillates_as_a_damped_spring_of_the_given_frequency) {
  const float hertz = 1.0f;
  const float zeta = 0.1f;
  World world(noGravity());
  const BodyId box = addBox(world, {1.0f, 0.0f}, 0.5f, 0.5f, 4.0f);
  grab(world, box, {}, {}, hertz, zeta, 1.0e4f); // peak pull m omega^2 x = 158 N
  std::vector<double> crossings;                 // times the displacement changes sign
  std::vector<float> speeds;                     // |v| at those crossings (the velocity's peaks)
  float x = world.position(box).x;
  float v = 0.0f;
  for (int i = 1; i <= 60 * 6; ++i) {
    world.step(dt);
    const float nx = world.position(box).x;
    const float nv = world.linearVelocity(box).x;
    if ((x > 0.0f) != (nx > 0.0f)) {
      const float fraction = x / (x - nx);
      crossings.push_back((static_cast<double>(i - 1) + static_cast<double>(fraction)) * dt);
      speeds.push_back(std::abs(v + (nv - v) * fraction));
    }
    x = nx;
    v = nv;
    ASSERT_LT(std::abs(world.position(box).y), 1e-5f);
  }
  ASSERT_GE(crossings.size(), 9U);
  const double period = (crossings[8] - crossings[0]) / 4.0; // four periods
  const double expected = 1.0 / (hertz * std::sqrt(1.0 - zeta * zeta));
  EXPECT_NEAR(period, expected, 0.05 * expected);
  EXPECT_NEAR(period, expected, 0.01 * expected) << "the discretization should be far smaller than 5 %";
  // The effective damping ratio from the decay over four periods: r = exp(-2 pi zeta / sqrt(1 - zeta^2)).
  const double logDecay = std::log(static_cast<double>(speeds[0] / speeds[8])) / 4.0;
  const double zetaMeasured = logDecay / std::sqrt(4.0 * pi<double> * pi<double> + logDecay * logDecay);
  const double omegaH = 2.0 * pi<double> * hertz * dt / 4.0;
  EXPECT_GT(zetaMeasured, zeta);
  EXPECT_LT(zetaMeasured, zeta + 1.5 * omegaH);
  RecordProperty("period", std::to_string(period));
  RecordProperty("zeta", std::to_string(zetaMeasured));
}

// Hanging from the cursor under gravity, held at its centre: the spring stretches by the static
// sag m g / k = g / omega^2 (1.01 cm at 5 Hz), which the soft step reproduces exactly at rest
// (float round-off: 1 %), and the reaction readout is the weight.
TEST(MouseJoint2D, static_sag_under_gravity_is_g_over_omega_squared) {
  World world; // gravity -10
  const BodyId box = addBox(world, {0.0f, 1.0f}, 0.5f, 0.5f);
  const MouseJointId id = grab(world, box, {}, {0.0f, 1.0f}, 5.0f, 0.7f, 1000.0f);
  for (int i = 0; i < 120; ++i) {
    world.step(dt);
  }
  const float omega = 2.0f * pi<float> * 5.0f;
  EXPECT_NEAR(1.0f - world.position(box).y, 10.0f / (omega * omega), 0.01f * 10.0f / (omega * omega));
  EXPECT_NEAR(world.jointReactionForce(id).y, world.mass(box) * 10.0f, 0.001f * world.mass(box) * 10.0f);
}

// A 100 kg crate dragged 5 m with maxForce 50 N: the pull saturates, so the reaction readout
// stays at or under maxForce every step (0.1 % round-off) and the crate accelerates at
// maxForce / m while saturated (1 %), straight at the target.
TEST(MouseJoint2D, pull_never_exceeds_max_force) {
  World world(noGravity());
  const BodyId crate = addBox(world, {}, 1.0f, 1.0f, 25.0f); // 100 kg
  const float maxForce = 50.0f;
  const MouseJointId id = grab(world, crate, {}, {5.0f, 0.0f}, 5.0f, 0.7f, maxForce);
  const float m = world.mass(crate);
  float v = 0.0f;
  float worst = 0.0f;
  for (int i = 0; i < 60 * 4; ++i) {
    world.step(dt);
    const float force = length(world.jointReactionForce(id));
    worst = std::max(worst, force);
    const float nv = world.linearVelocity(crate).x;
    if (i < 60) { // far from the target (the spring wants k x = 100 kg * 987 1/s^2 * 4 m): saturated
      EXPECT_NEAR(force, maxForce, 0.001f * maxForce) << "step " << i;
      EXPECT_NEAR((nv - v) / dt, maxForce / m, 0.01f * maxForce / m) << "step " << i;
    }
    v = nv;
  }
  EXPECT_LE(worst, maxForce * 1.001f);
  EXPECT_GT(world.position(crate).x, 1.0f); // it has been dragged toward the target
}

// A target moving at v = 2 m/s drags the body along: once the transient has died (decay time
// 1 / (zeta omega) = 0.23 s), the body moves at v (measured over the last second, 1 %), behind
// the target by the spring-damper's steady lag c v / k = 2 zeta v / omega (44.6 cm at 1 Hz,
// zeta 0.7). Two discretization effects move it, each by about v dt / 2 (1.7 cm, 3.7 %), in
// opposite directions: the target is set once per step (a staircase, on average half a step
// behind the last value set), and the soft step's implicit spring adds numerical damping of
// about omega h to zeta (see the oscillation test), lengthening the lag by 2 h v = v dt / 2.
// The tolerance is v dt / 2; the measured lag is 44.1 cm.
TEST(MouseJoint2D, moving_target_drags_the_body_along) {
  World world(noGravity());
  const BodyId box = addBox(world, {}, 0.5f, 0.5f);
  const float hertz = 1.0f;
  const float zeta = 0.7f;
  const MouseJointId id = grab(world, box, {}, {}, hertz, zeta, 1000.0f);
  const float speed = 2.0f;
  Vec2f target;
  float x2 = 0.0f;
  for (int i = 1; i <= 180; ++i) {
    target = {speed * static_cast<float>(i) * dt, 0.0f};
    setMouseTarget(world, id, target);
    world.step(dt);
    if (i == 120) {
      x2 = world.position(box).x;
    }
  }
  const float omega = 2.0f * pi<float> * hertz;
  EXPECT_NEAR(target.x - world.position(box).x, 2.0f * zeta * speed / omega, speed * dt / 2.0f);
  EXPECT_NEAR((world.position(box).x - x2) / (60.0f * dt), speed, 0.01f * speed);
  EXPECT_NEAR(world.position(box).y, 0.0f, 1e-5f);
}

// The angular damping: a body held at its centre and spinning at 5 rad/s (the spring exerts no
// torque about the centre) slows as w' = -rate w: after 1 s, w = 5 exp(-0.6) (1 %). Without it
// a body swung about the grab point would spin on forever.
TEST(MouseJoint2D, angular_damping_lets_a_spinning_body_settle) {
  World world(noGravity());
  const BodyId box = addBox(world, {}, 1.0f, 0.5f);
  world.setAngularVelocity(box, 5.0f);
  const MouseJointId id = grab(world, box, {}, {}, 5.0f, 0.7f, 1000.0f);
  for (int i = 0; i < 60; ++i) {
    world.step(dt);
  }
  EXPECT_NEAR(world.angularVelocity(box), 5.0f * std::exp(-0.6f), 0.01f * 5.0f * std::exp(-0.6f));
  // The readout is the damping torque -I rate w.
  EXPECT_NEAR(world.jointReactionTorque(id), -world.rotationalInertia(box) * 0.6f * world.angularVelocity(box),
              0.01f * world.rotationalInertia(box) * 0.6f * world.angularVelocity(box));
}

TEST(MouseJoint2D, bad_definitions_name_the_field) {
  World world;
  const BodyId b = addBox(world, {}, 0.5f, 0.5f);
  MouseJointDef def;
  def.bodyB = b;
  def.maxForce = -1.0f;
  expectErrorField([&] { (void)world.createJoint(def); }, "maxForce");
  def.maxForce = 10.0f;
  def.hertz = -1.0f;
  expectErrorField([&] { (void)world.createJoint(def); }, "hertz");
  def.hertz = 5.0f;
  def.target = {std::nanf(""), 0.0f};
  expectErrorField([&] { (void)world.createJoint(def); }, "target.x");
  def.target = {};
  EXPECT_EQ(world.jointCount(), 0U);
  const auto id = world.createJoint(def); // bodyA left null: the world
  expectErrorField([&] { setMouseTarget(world, id, {0.0f, std::nanf("")}); }, "target.y");
  expectErrorField([&] { setMotorJointTarget(world, MotorJointId{id}, {}, 0.0f); }, "joint id");
}

} // namespace
} // namespace impetus::rigid2d
