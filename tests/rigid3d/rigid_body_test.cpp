// The 3D world's bodies against closed forms: free fall, impulses at points, forces and torques,
// damping, axis locks; ids, determinism and bad input.
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/rigid3d/world.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace impetus::rigid3d {
namespace {

constexpr float dt = 1.0f / 60.0f;

/// A uniform box's mass data: mass m, full edge lengths, centre at the origin.
MassData boxMass(float m, const Vec3f& size) {
  const float x2 = size.x * size.x;
  const float y2 = size.y * size.y;
  const float z2 = size.z * size.z;
  return {m, {}, Mat33f::diagonal({m * (y2 + z2) / 12.0f, m * (x2 + z2) / 12.0f, m * (x2 + y2) / 12.0f})};
}

BodyDef dynamicBody(const Vec3f& position = {}) {
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = position;
  return def;
}

TEST(Rigid3dBody, falls_as_semi_implicit_euler_says_and_keeps_its_exact_speed) {
  // Under constant gravity the substeps' symplectic Euler gives v = v0 + g t exactly and
  // x = x0 + v0 t + g t^2/2 + g h t/2 (h the substep): the discrete sum of h (v0 + k g h).
  World world;
  BodyDef def = dynamicBody({1.0f, 50.0f, -2.0f});
  def.linearVelocity = {3.0f, 4.0f, 0.0f};
  const BodyId body = world.createBody(def);
  const int steps = 120;
  for (int i = 0; i < steps; ++i) {
    world.step(dt);
  }
  const double t = steps * static_cast<double>(dt);
  const double h = dt / 4.0;
  const Vec3f v = world.linearVelocity(body);
  EXPECT_NEAR(v.y, 4.0 - 10.0 * t, 1e-4);
  EXPECT_NEAR(v.x, 3.0, 1e-6);
  const Vec3f p = world.position(body);
  EXPECT_NEAR(p.y, 50.0 + 4.0 * t - 5.0 * t * t - 5.0 * h * t, 2e-4);
  EXPECT_NEAR(p.x, 1.0 + 3.0 * t, 2e-4);
  EXPECT_FLOAT_EQ(p.z, -2.0f);
}

TEST(Rigid3dBody, an_impulse_at_a_point_gives_the_momenta_the_box_inertia_says) {
  // A 2 kg box of 1 x 2 x 3 m at rest, struck at its corner-ish point r by P:
  // v = P / m, w = I^-1 (r x P) with I = m/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2).
  World world{WorldDef{{0.0f, 0.0f, 0.0f}}};
  BodyDef def = dynamicBody({1.0f, 2.0f, 3.0f});
  def.massData = boxMass(2.0f, {1.0f, 2.0f, 3.0f});
  const BodyId body = world.createBody(def);
  const Vec3f r{0.5f, 1.0f, -1.5f};
  const Vec3f impulse{2.0f, -1.0f, 4.0f};
  world.applyLinearImpulse(body, impulse, Vec3f{1.0f, 2.0f, 3.0f} + r);
  const Vec3f v = world.linearVelocity(body);
  EXPECT_NEAR(v.x, 1.0, 1e-6);
  EXPECT_NEAR(v.y, -0.5, 1e-6);
  EXPECT_NEAR(v.z, 2.0, 1e-6);
  const Vec3f torqueImpulse = cross(r, impulse); // (2.5, -5, -2.5)
  const Vec3f w = world.angularVelocity(body);
  EXPECT_NEAR(w.x, torqueImpulse.x / (2.0 * 13.0 / 12.0), 1e-5);
  EXPECT_NEAR(w.y, torqueImpulse.y / (2.0 * 10.0 / 12.0), 1e-5);
  EXPECT_NEAR(w.z, torqueImpulse.z / (2.0 * 5.0 / 12.0), 1e-5);
}

TEST(Rigid3dBody, the_impulse_of_a_rotated_body_goes_through_its_world_inertia) {
  // The same box turned a quarter turn about z: its world inertia swaps the x and y moments.
  World world{WorldDef{{0.0f, 0.0f, 0.0f}}};
  BodyDef def = dynamicBody();
  def.rotation = Quatf::fromAxisAngle({0.0f, 0.0f, 1.0f}, 0.5f * pi<float>);
  def.massData = boxMass(2.0f, {1.0f, 2.0f, 3.0f});
  const BodyId body = world.createBody(def);
  world.applyAngularImpulse(body, {1.0f, 1.0f, 0.0f});
  const Vec3f w = world.angularVelocity(body);
  EXPECT_NEAR(w.x, 1.0 / (2.0 * 10.0 / 12.0), 1e-5);
  EXPECT_NEAR(w.y, 1.0 / (2.0 * 13.0 / 12.0), 1e-5);
  EXPECT_NEAR(w.z, 0.0, 1e-6);
  const Mat33f inertia = world.worldInertia(body);
  EXPECT_NEAR(inertia(0, 0), 2.0 * 10.0 / 12.0, 1e-5);
  EXPECT_NEAR(inertia(1, 1), 2.0 * 13.0 / 12.0, 1e-5);
}

TEST(Rigid3dBody, a_force_off_the_centre_pushes_and_turns) {
  // A force F at r for one step: dv = F dt / m, and (for a sphere-like unit inertia, slowly
  // turning) dw = (r x F) dt / I; the gyroscopic term of a spherical tensor is zero.
  World world{WorldDef{{0.0f, 0.0f, 0.0f}}};
  BodyDef def = dynamicBody();
  def.massData = MassData{4.0f, {}, Mat33f::diagonal({2.0f, 2.0f, 2.0f})};
  const BodyId body = world.createBody(def);
  world.applyForce(body, {0.0f, 8.0f, 0.0f}, {0.5f, 0.0f, 0.0f});
  world.step(dt);
  EXPECT_NEAR(world.linearVelocity(body).y, 8.0 * dt / 4.0, 1e-6);
  EXPECT_NEAR(world.angularVelocity(body).z, 4.0 * dt / 2.0, 1e-6);
  // Forces last one step.
  world.step(dt);
  EXPECT_NEAR(world.linearVelocity(body).y, 8.0 * dt / 4.0, 1e-6);
}

TEST(Rigid3dBody, damping_decays_speed_as_the_implicit_rule_says) {
  // Per substep v <- v / (1 + c h): after n substeps v0 (1 + c h)^-n, which tends to exp(-c t).
  World world{WorldDef{{0.0f, 0.0f, 0.0f}}};
  BodyDef def = dynamicBody();
  def.linearVelocity = {10.0f, 0.0f, 0.0f};
  def.angularVelocity = {0.0f, 2.0f, 0.0f};
  def.linearDamping = 0.5f;
  def.angularDamping = 1.0f;
  const BodyId body = world.createBody(def);
  for (int i = 0; i < 60; ++i) {
    world.step(dt);
  }
  const double h = dt / 4.0;
  // Float rounding over 240 substeps: 240 x 6e-8 relative.
  EXPECT_NEAR(world.linearVelocity(body).x, 10.0 * std::pow(1.0 + 0.5 * h, -240.0), 10.0 * 2e-5);
  EXPECT_NEAR(world.angularVelocity(body).y, 2.0 * std::pow(1.0 + 1.0 * h, -240.0), 2.0 * 2e-5);
  // The continuous law exp(-c t), to the rule's first-order error c t (c h) / 2 = 5e-4 relative.
  EXPECT_NEAR(world.linearVelocity(body).x, 10.0 * std::exp(-0.5), 10.0 * 1e-3);
}

TEST(Rigid3dBody, locked_axes_take_no_motion_and_the_free_axis_turns_with_its_own_moment) {
  // A body kept in the x-y plane (no z motion, turning about z only) with a tilted inertia
  // tensor: a torque about x does nothing; one about z turns it at tau / I_zz of the world
  // tensor (the locks' torques hold the other axes), not at (I^-1)_zz.
  World world{WorldDef{{0.0f, -10.0f, 0.0f}}};
  BodyDef def = dynamicBody();
  def.rotation = Quatf::fromAxisAngle({1.0f, 1.0f, 0.0f}, 0.7f);
  def.massData = boxMass(3.0f, {0.5f, 1.0f, 2.0f});
  def.locks = AxisLocks{false, false, true, true, true, false};
  def.linearVelocity = {0.0f, 0.0f, 5.0f}; // removed at the next step
  const BodyId body = world.createBody(def);
  const Mat33f inertia = world.worldInertia(body);
  world.applyTorque(body, {6.0f, 0.0f, 0.0f});
  world.step(dt);
  EXPECT_EQ(world.linearVelocity(body).z, 0.0f);
  EXPECT_EQ(world.angularVelocity(body).x, 0.0f);
  EXPECT_EQ(world.angularVelocity(body).z, 0.0f);
  EXPECT_NEAR(world.linearVelocity(body).y, -10.0 * dt, 1e-5);
  world.applyAngularImpulse(body, {0.0f, 0.0f, 1.0f});
  EXPECT_NEAR(world.angularVelocity(body).z, 1.0 / inertia(2, 2), 1e-4);
  EXPECT_EQ(world.angularVelocity(body).y, 0.0f);
}

TEST(Rigid3dBody, static_and_kinematic_bodies_ignore_forces_and_kinematic_ones_keep_their_speed) {
  World world;
  BodyDef def;
  def.type = BodyType::kinematicBody;
  def.linearVelocity = {1.0f, 0.0f, 0.0f};
  def.angularVelocity = {0.0f, 3.0f, 0.0f};
  const BodyId kinematic = world.createBody(def);
  const BodyId ground = world.createBody(BodyDef{});
  world.applyForceToCenter(kinematic, {100.0f, 0.0f, 0.0f});
  world.applyLinearImpulse(ground, {100.0f, 0.0f, 0.0f}, {});
  for (int i = 0; i < 60; ++i) {
    world.step(dt);
  }
  EXPECT_NEAR(world.position(kinematic).x, 1.0, 1e-5);
  EXPECT_FLOAT_EQ(world.linearVelocity(kinematic).x, 1.0f);
  // A turn at 3 rad/s for 1 s: its angle about y.
  EXPECT_NEAR(2.0 * std::atan2(world.rotation(kinematic).y, world.rotation(kinematic).w), 3.0, 1e-4);
  EXPECT_EQ(world.position(ground).x, 0.0f);
  EXPECT_EQ(world.linearVelocity(ground).x, 0.0f);
}

TEST(Rigid3dBody, the_spin_cap_holds_a_quarter_turn_a_substep_unless_fast_rotation_is_allowed) {
  World world{WorldDef{{0.0f, 0.0f, 0.0f}}};
  BodyDef def = dynamicBody();
  def.angularVelocity = {0.0f, 1000.0f, 0.0f};
  const BodyId capped = world.createBody(def);
  def.allowFastRotation = true;
  const BodyId free = world.createBody(def);
  world.step(dt);
  const float cap = 0.25f * pi<float> * 4.0f / dt;
  EXPECT_NEAR(world.angularVelocity(capped).y, cap, 1e-2);
  EXPECT_FLOAT_EQ(world.angularVelocity(free).y, 1000.0f);
}

TEST(Rigid3dBody, shifting_the_origin_moves_every_body_and_changes_nothing_else) {
  WorldDef def;
  World a{def};
  World b{def};
  BodyDef body = dynamicBody({1.0e5f, 20.0f, -3.0e4f});
  body.angularVelocity = {1.0f, 2.0f, 3.0f};
  body.massData = boxMass(1.0f, {1.0f, 2.0f, 0.5f});
  const BodyId inA = a.createBody(body);
  body.position = {0.0f, 20.0f, 0.0f};
  const BodyId inB = b.createBody(body);
  a.shiftOrigin({1.0e5f, 0.0f, -3.0e4f});
  EXPECT_EQ(a.position(inA).x, 0.0f);
  EXPECT_EQ(a.position(inA).z, 0.0f);
  for (int i = 0; i < 30; ++i) {
    a.step(dt);
    b.step(dt);
  }
  EXPECT_EQ(a.stateHash(), b.stateHash());
  EXPECT_EQ(a.worldCenter(inA).y, b.worldCenter(inB).y);
}

TEST(Rigid3dBody, the_same_inputs_give_the_same_bits) {
  const auto run = [] {
    World world;
    for (int i = 0; i < 20; ++i) {
      BodyDef def = dynamicBody({static_cast<float>(i), 1.0f, 0.0f});
      def.angularVelocity = {0.3f * static_cast<float>(i), 1.0f, -2.0f};
      def.massData = boxMass(1.0f + static_cast<float>(i), {1.0f, 0.2f, 3.0f});
      world.createBody(def);
    }
    for (int i = 0; i < 200; ++i) {
      world.step(dt);
    }
    return world.stateHash();
  };
  EXPECT_EQ(run(), run());
}

TEST(Rigid3dBody, ids_are_generational_and_belong_to_their_world) {
  World world;
  World other;
  const BodyId a = world.createBody(dynamicBody());
  EXPECT_TRUE(world.isValid(a));
  EXPECT_FALSE(other.isValid(a));
  EXPECT_THROW((void)other.position(a), Error);
  world.destroyBody(a);
  EXPECT_FALSE(world.isValid(a));
  EXPECT_THROW((void)world.position(a), Error);
  const BodyId b = world.createBody(dynamicBody());
  EXPECT_EQ(b.index, a.index);
  EXPECT_NE(b.generation, a.generation);
  EXPECT_EQ(world.bodyCount(), 1U);
}

TEST(Rigid3dBody, bad_input_is_refused_naming_the_field) {
  World world;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  BodyDef def = dynamicBody();
  def.position.y = nan;
  EXPECT_NE(thrownMessage([&] { world.createBody(def); }).find("position.y"), std::string::npos);
  def = dynamicBody();
  def.rotation = Quatf{0.0f, 0.0f, 0.0f, 0.0f};
  EXPECT_NE(thrownMessage([&] { world.createBody(def); }).find("rotation"), std::string::npos);
  def = dynamicBody();
  def.massData = MassData{-1.0f, {}, Mat33f::identity()};
  EXPECT_NE(thrownMessage([&] { world.createBody(def); }).find("mass"), std::string::npos);
  def.massData = MassData{1.0f, {}, Mat33f{1.0f, 0.5f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f}};
  EXPECT_NE(thrownMessage([&] { world.createBody(def); }).find("symmetric"), std::string::npos);
  def.massData = MassData{1.0f, {}, Mat33f::diagonal({1.0f, 1.0f, 3.0f})};
  EXPECT_NE(thrownMessage([&] { world.createBody(def); }).find("triangle inequality"), std::string::npos);
  def.massData = MassData{1.0f, {}, Mat33f::diagonal({1.0f, 1.0f, -1.0f})};
  EXPECT_NE(thrownMessage([&] { world.createBody(def); }).find("principal moment"), std::string::npos);
  def.massData = MassData{1.0f, {}, Mat33f::diagonal({1.0f, 1.0f, 0.0f})}; // a rod: no moment about itself
  EXPECT_NE(thrownMessage([&] { world.createBody(def); }).find("positive definite"), std::string::npos);
  def.massData = MassData{1.0f, {nan, 0.0f, 0.0f}, Mat33f::identity()};
  EXPECT_NE(thrownMessage([&] { world.createBody(def); }).find("center.x"), std::string::npos);
  def = dynamicBody();
  def.linearDamping = -1.0f;
  EXPECT_NE(thrownMessage([&] { world.createBody(def); }).find("linearDamping"), std::string::npos);
  const BodyId body = world.createBody(dynamicBody());
  EXPECT_NE(thrownMessage([&] {
              world.applyForceToCenter(body, {nan, 0.0f, 0.0f});
            }).find("force.x"),
            std::string::npos);
  EXPECT_NE(thrownMessage([&] {
              world.setTransform(body, {}, Quatf{nan, 0.0f, 0.0f, 0.0f});
            }).find("rotation"),
            std::string::npos);
  EXPECT_NE(thrownMessage([&] { world.step(0.0f); }).find("dt"), std::string::npos);
  EXPECT_NE(thrownMessage([&] { world.step(5.0f); }).find("dt"), std::string::npos);
  EXPECT_NE(thrownMessage([] { World{WorldDef{{}, 0}}; }).find("substeps"), std::string::npos);
  EXPECT_NE(thrownMessage([&] { world.setGravity({0.0f, nan, 0.0f}); }).find("gravity.y"), std::string::npos);
  // Nothing refused left a trace.
  EXPECT_EQ(world.bodyCount(), 1U);
}

} // namespace
} // namespace impetus::rigid3d
