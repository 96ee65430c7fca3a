// The wheel joint against mechanics: a car's suspension sag, driving at the rolling speed, the
// motor's torque bound, and bad input.
#include "support/error_field.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/world.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace impetus::rigid2d {
namespace {

constexpr float dt = 1.0f / 60.0f;
constexpr float g = 10.0f;
constexpr float wheelRadius = 0.4f;

/// A 3 m x 0.6 m box chassis (1.8 kg) on two discs of radius 0.4 m (0.503 kg) 2 m apart, with
/// vertical suspension at the wheels' hubs, on flat ground (top at y = 0). The springs are at
/// rest (translation 0) as built.
struct Car {
  World world;
  BodyId ground, chassis;
  std::array<BodyId, 2> wheels;
  std::array<WheelJointId, 2> joints;
  std::array<WheelJointDef, 2> defs;

  Car(float hertz, float dampingRatio) {
    ground = world.createBody({});
    ShapeDef flat;
    flat.friction = 0.9f;
    world.createShape(ground, flat, makeOffsetBox(200.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    BodyDef def;
    def.type = BodyType::dynamicBody;
    def.enableSleep = false;
    def.position = {0.0f, 1.1f};
    chassis = world.createBody(def);
    world.createShape(chassis, {}, makeBox(1.5f, 0.3f));
    for (int i = 0; i < 2; ++i) {
      const float x = i == 0 ? -1.0f : 1.0f;
      def.position = {x, wheelRadius};
      wheels[i] = world.createBody(def);
      ShapeDef tyre;
      tyre.friction = 0.9f;
      world.createShape(wheels[i], tyre, Circle{{}, wheelRadius});
      WheelJointDef& j = defs[i];
      j.bodyA = chassis;
      j.bodyB = wheels[i];
      j.localAnchorA = {x, wheelRadius - 1.1f};
      j.localAnchorB = {};
      j.localAxisA = {0.0f, 1.0f};
      j.hertz = hertz;
      j.dampingRatio = dampingRatio;
      joints[i] = world.createJoint(j);
    }
  }

  /// The suspension's translation: hub minus chassis anchor along the chassis' axis, m.
  [[nodiscard]] float translation(int i) const {
    const Vec2f pA = transformPoint(world.transform(chassis), defs[i].localAnchorA);
    const Vec2f pB = transformPoint(world.transform(wheels[i]), defs[i].localAnchorB);
    return dot(pB - pA, rotate(world.transform(chassis).q, defs[i].localAxisA));
  }
};

// Static sag. The spring acts on the translation x between chassis anchor and hub with the
// effective mass of that relative motion, m_eff = 1 / (1/M + 1/m + L^2/I) (M, I: the chassis'
// mass and inertia; L = 1 m: the hub's lever arm about the chassis' centre across the axis; the
// hub sits at the wheel's centre, so the wheel's inertia does not enter), so k = m_eff (2 pi f)^2.
// At rest each spring carries half the chassis' weight (the wheels' own weight goes to the
// ground): x = M g / (2 k). At 4 Hz: m_eff = 0.307 kg, k = 194 N/m, x = 46.4 mm. Within 5%.
TEST(WheelJoint2D, static_sag_is_half_the_chassis_weight_over_the_spring_rate) {
  Car car(4.0f, 0.7f);
  for (int i = 0; i < 240; ++i) {
    car.world.step(dt);
  }
  const float chassisMass = car.world.mass(car.chassis);
  const float inertia = car.world.rotationalInertia(car.chassis);
  const float wheelMass = car.world.mass(car.wheels[0]);
  const float lever = 1.0f;
  const double effective = 1.0 / (1.0 / chassisMass + 1.0 / wheelMass + lever * lever / inertia);
  const double k = effective * std::pow(2.0 * pi<double> * 4.0, 2.0);
  const double sag = chassisMass * g / (2.0 * k);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(car.translation(i), sag, 0.05 * sag) << "wheel " << i;
    // The joint carries M g / 2 up on the chassis, i.e. down on the wheel.
    EXPECT_NEAR(car.world.jointReactionForce(car.joints[i]).y, -0.5f * chassisMass * g, 0.01f * chassisMass * g);
  }
  EXPECT_NEAR(car.world.angle(car.chassis), 0.0f, 1e-3f);
}

// The motor turns each wheel at motorSpeed relative to the chassis; rolling without slip on flat
// ground the car then moves at -motorSpeed r (a clockwise wheel rolls to +x): -10 rad/s with
// r = 0.4 m is 4 m/s, within 2%. The torque readout never exceeds maxMotorTorque, and is at it
// while the car accelerates.
TEST(WheelJoint2D, motor_drives_the_car_at_the_rolling_speed) {
  Car car(4.0f, 0.7f);
  const float maxTorque = 2.0f;
  for (const WheelJointId id : car.joints) {
    setWheelMotor(car.world, id, true, -10.0f, maxTorque);
  }
  float peak = 0.0f;
  for (int i = 0; i < 300; ++i) {
    car.world.step(dt);
    for (const WheelJointId id : car.joints) {
      peak = std::max(peak, std::abs(wheelMotorTorque(car.world, id)));
    }
    if (i == 10) {
      EXPECT_NEAR(wheelMotorTorque(car.world, car.joints[0]), -maxTorque, 1e-3f * maxTorque);
    }
  }
  EXPECT_LE(peak, maxTorque * 1.0001f);
  const float speed = -(-10.0f) * wheelRadius;
  EXPECT_NEAR(car.world.linearVelocity(car.chassis).x, speed, 0.02f * speed);
  for (const BodyId wheel : car.wheels) {
    // Rolling: the contact point is at rest.
    EXPECT_NEAR(car.world.linearVelocity(wheel).x + car.world.angularVelocity(wheel) * wheelRadius, 0.0f,
                0.02f * speed);
  }
  EXPECT_NEAR(car.world.angle(car.chassis), 0.0f, 0.01f);
}

TEST(WheelJoint2D, bad_definitions_name_the_field) {
  World world;
  const BodyId a = world.createBody({});
  BodyDef def;
  def.type = BodyType::dynamicBody;
  const BodyId b = world.createBody(def);
  world.createShape(b, {}, Circle{{}, 0.5f});
  WheelJointDef joint;
  joint.bodyA = a;
  joint.bodyB = b;
  joint.localAxisA = {0.0f, 0.0f};
  expectErrorField([&] { (void)world.createJoint(joint); }, "localAxisA");
  joint.localAxisA = {std::nanf(""), 1.0f};
  expectErrorField([&] { (void)world.createJoint(joint); }, "localAxisA.x");
  joint.localAxisA = {0.0f, 1.0f};
  joint.maxMotorTorque = -1.0f;
  expectErrorField([&] { (void)world.createJoint(joint); }, "maxMotorTorque");
  joint.maxMotorTorque = 0.0f;
  joint.dampingRatio = -0.5f;
  expectErrorField([&] { (void)world.createJoint(joint); }, "dampingRatio");
  EXPECT_EQ(world.jointCount(), 0U);
}

} // namespace
} // namespace impetus::rigid2d
