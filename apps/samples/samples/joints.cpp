// Engine/Joints: one of every joint of the 2D world, side by side (joint.hpp):
//   revolute  a bar spun by the joint's motor (a target speed with a torque limit) about a pin;
//   prismatic a piston on a slider with limits, driven back and forth by its motor;
//   distance  a box hanging on a spring (frequency and damping ratio) and a ball on a rope
//             (a distance joint with a zero minimum: it goes slack);
//   weld      a soft cantilever of welded boxes that bends under its weight;
//   wheel     a wheel on a suspension axis, spun by its motor;
//   motor     a box driven toward a moving target pose with bounded force and torque;
//   mouse     drag anything with the left button.
// The plots follow the revolute joint's angle (rad), the piston's travel (m) and the spring's
// length (m); the spring's undamped period is 1/f.
#include "rigid2d_sample.hpp"
#include "ui.hpp"

#include <imgui.h>

#include <cmath>

namespace impetus::samples {
namespace {

using namespace impetus::rigid2d;

class Joints final : public Rigid2dSample {
public:
  void setup() override {
    resetWorld({});
    ground_ = world().createBody({});
    world().createShape(ground_, {}, makeOffsetBox(30.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    const auto dynamicBody = [&](Vec2f p) {
      BodyDef def;
      def.type = BodyType::dynamicBody;
      def.position = p;
      return world().createBody(def);
    };

    // Revolute: a bar pinned at its centre, spun by the motor.
    bar_ = dynamicBody({-20.0f, 6.0f});
    world().createShape(bar_, {}, makeBox(2.0f, 0.15f));
    RevoluteJointDef pin;
    pin.bodyA = ground_;
    pin.bodyB = bar_;
    pin.localAnchorA = {-20.0f, 6.0f};
    pin.enableMotor = true;
    pin.motorSpeed = motorSpeed_;
    pin.maxMotorTorque = 50.0f;
    revolute_ = world().createJoint(pin);

    // Prismatic: a piston sliding vertically between limits, its motor reversed at each end.
    piston_ = dynamicBody({-13.0f, 4.0f});
    world().createShape(piston_, {}, makeBox(0.8f, 0.5f));
    PrismaticJointDef slider;
    slider.bodyA = ground_;
    slider.bodyB = piston_;
    slider.localAnchorA = {-13.0f, 4.0f};
    slider.localAxisA = {0.0f, 1.0f};
    slider.enableLimit = true;
    slider.lowerTranslation = -2.0f;
    slider.upperTranslation = 3.0f;
    slider.enableMotor = true;
    slider.motorSpeed = 2.0f;
    slider.maxMotorForce = 200.0f;
    prismatic_ = world().createJoint(slider);

    // Distance: a spring and a rope.
    springBox_ = dynamicBody({-7.0f, 5.0f});
    world().createShape(springBox_, {}, makeBox(0.5f, 0.5f));
    DistanceJointDef spring;
    spring.bodyA = ground_;
    spring.bodyB = springBox_;
    spring.localAnchorA = {-7.0f, 10.0f};
    spring.localAnchorB = {0.0f, 0.5f};
    spring.length = 4.0f;
    spring.enableSpring = true;
    spring.hertz = springHertz_;
    spring.dampingRatio = 0.05f;
    spring_ = world().createJoint(spring);
    const BodyId ball = dynamicBody({-1.0f, 9.0f});
    world().createShape(ball, {}, Circle{{}, 0.5f});
    DistanceJointDef rope;
    rope.bodyA = ground_;
    rope.bodyB = ball;
    rope.localAnchorA = {-4.0f, 10.0f};
    rope.length = 4.0f;
    rope.enableLimit = true;
    rope.minLength = 0.0f;
    rope.maxLength = 4.0f;
    rope.enableSpring = true; // with hertz 0: no spring force, only the limits (slack rope)
    world().createJoint(rope);

    // Weld: a soft cantilever.
    BodyId previous = ground_;
    Vec2f anchor{1.0f, 8.0f};
    for (int i = 0; i < 5; ++i) {
      const BodyId box = dynamicBody({1.5f + static_cast<float>(i), 8.0f});
      world().createShape(box, {}, makeBox(0.5f, 0.2f));
      WeldJointDef weld;
      weld.bodyA = previous;
      weld.bodyB = box;
      weld.localAnchorA = anchor;
      weld.localAnchorB = {-0.5f, 0.0f};
      weld.linearHertz = 0.0f;
      weld.angularHertz = 4.0f;
      weld.angularDampingRatio = 0.5f;
      world().createJoint(weld);
      previous = box;
      anchor = {0.5f, 0.0f};
    }

    // Wheel: on a suspension axis from the ground, spun by its motor.
    const BodyId wheel = dynamicBody({10.0f, 2.5f});
    world().createShape(wheel, {}, Circle{{}, 0.8f});
    WheelJointDef axle;
    axle.bodyA = ground_;
    axle.bodyB = wheel;
    axle.localAnchorA = {10.0f, 2.5f};
    axle.hertz = 2.0f;
    axle.dampingRatio = 0.3f;
    axle.enableMotor = true;
    axle.motorSpeed = 3.0f;
    axle.maxMotorTorque = 20.0f;
    world().createJoint(axle);

    // Motor: a box driven to a target that circles (set every step).
    follower_ = dynamicBody({17.0f, 5.0f});
    world().createShape(follower_, {}, makeBox(0.6f, 0.6f));
    MotorJointDef motor;
    motor.bodyA = ground_;
    motor.bodyB = follower_;
    motor.linearOffset = {17.0f, 5.0f};
    motor.maxForce = 200.0f;
    motor.maxTorque = 50.0f;
    motorJoint_ = world().createJoint(motor);

    angle_.clear();
    travel_.clear();
    length_.clear();
  }
  [[nodiscard]] CameraView initialView() const override { return {{-1.0f, 6.0f}, 7.0f, 24.5f}; }
  [[nodiscard]] std::string_view controls() const override { return "Left-drag any body (the mouse joint)."; }

protected:
  void beforeStep(float /*dt*/) override {
    // The piston's motor reverses at each limit: a crank without a crank.
    const float t = prismaticTranslation(world(), prismatic_);
    if (t > 2.9f || t < -1.9f) {
      setPrismaticMotor(world(), prismatic_, true, t > 0.0f ? -2.0f : 2.0f, 200.0f);
    }
    // The motor joint's target circles at 1 rad/s, radius 2 m, turning as it goes.
    const float phase = time();
    setMotorJointTarget(world(), motorJoint_, Vec2f{17.0f + 2.0f * std::cos(phase), 6.0f + 2.0f * std::sin(phase)},
                        phase);
  }

  void afterStep(float /*dt*/) override {
    angle_.push(revoluteAngle(world(), revolute_));
    travel_.push(prismaticTranslation(world(), prismatic_));
    length_.push(distanceJointLength(world(), spring_));
  }

  void drawOverlay(DebugDraw& draw) override {
    const struct {
      Vec2f at;
      const char* name;
    } labels[] = {{{-22.0f, 9.5f}, "revolute + motor"}, {{-14.5f, 11.0f}, "prismatic"},
                  {{-8.5f, 12.5f}, "distance: spring"}, {{-3.5f, 11.0f}, "rope"},
                  {{1.0f, 9.5f}, "weld (soft)"},        {{9.0f, 5.0f}, "wheel"},
                  {{14.5f, 9.5f}, "motor joint"}};
    for (const auto& l : labels) {
      draw.text(l.at, l.name, palette::text);
    }
    const float phase = time();
    draw.cross({17.0f + 2.0f * std::cos(phase), 6.0f + 2.0f * std::sin(phase)}, 12.0f, palette::reference);
  }

  void parameters() override {
    if (slider("revolute motor", &motorSpeed_, -10.0f, 10.0f, "%.1f rad/s")) {
      setRevoluteMotor(world(), revolute_, true, motorSpeed_, 50.0f);
    }
    slider("spring", &springHertz_, 0.2f, 5.0f, "%.2f Hz");
    if (ImGui::IsItemDeactivatedAfterEdit()) {
      setup();
    }
    angle_.plot("revolute joint angle (rad)", "%.2f rad", 50.0f, -3.2f, 3.2f);
    travel_.plot("prismatic travel (m)", "%.2f m", 50.0f, -2.2f, 3.2f);
    length_.plot("spring length (m)", "%.3f m", 50.0f);
    textWrapped("undamped spring period 1/f = %.2f s", 1.0 / static_cast<double>(springHertz_));
  }

private:
  BodyId ground_;
  BodyId bar_;
  BodyId piston_;
  BodyId springBox_;
  BodyId follower_;
  rigid2d::RevoluteJointId revolute_;
  rigid2d::PrismaticJointId prismatic_;
  rigid2d::DistanceJointId spring_;
  rigid2d::MotorJointId motorJoint_;
  float motorSpeed_ = 2.0f;  // rad/s
  float springHertz_ = 0.8f; // Hz
  History angle_;
  History travel_;
  History length_;
};

const SampleRegistrar registrar{"Engine", "Joints",
                                "One of every joint: revolute with a motor, prismatic with limits, distance "
                                "spring and rope, soft weld, wheel, motor joint, and the mouse.",
                                [] { return std::make_unique<Joints>(); }};

} // namespace
} // namespace impetus::samples
