// Engine/Car: a car on wheel joints driving over hilly ground (a one-sided chain). Each wheel is a
// circle joined to the chassis by a wheel joint: it slides along the chassis' vertical axis on a
// spring-damper (the suspension, given by its frequency in Hz and damping ratio, which stay
// meaningful whatever the masses) and turns freely, driven by the joint's motor (a target speed
// with a torque limit: the engine). The plots show the speed (km/h), the rear suspension's
// compression (m) and the rear motor's torque (N m per metre of depth).
#include "rigid2d_sample.hpp"
#include "ui.hpp"

#include <imgui.h>

#include <array>
#include <cmath>

namespace impetus::samples {
namespace {

using namespace impetus::rigid2d;

class Car final : public Rigid2dSample {
public:
  void setup() override {
    resetWorld({});
    const BodyId ground = world().createBody({});
    // Rolling hills, listed right to left so that the free side is up (chain.hpp).
    ChainDef terrain;
    for (int i = 120; i >= -20; --i) {
      const float x = static_cast<float>(i);
      const float y =
          1.5f * std::sin(0.15f * x) + 0.6f * std::sin(0.43f * x) + (x > 60.0f ? 0.08f * (x - 60.0f) : 0.0f);
      terrain.points.push_back({x, y});
    }
    world().createChain(ground, {}, terrain);

    BodyDef body;
    body.type = BodyType::dynamicBody;
    body.position = {0.0f, 3.0f};
    chassis_ = world().createBody(body);
    const Vec2f hull[] = {{-2.0f, -0.4f}, {2.0f, -0.4f}, {2.0f, 0.1f}, {0.6f, 0.7f}, {-1.2f, 0.7f}, {-2.0f, 0.2f}};
    ShapeDef chassisShape;
    chassisShape.density = 1.0f;
    world().createShape(chassis_, chassisShape, makePolygon(hull, 0.1f));

    ShapeDef tyre;
    tyre.density = 2.0f;
    tyre.friction = 1.2f;
    tyre.rollingResistance = 0.02f;
    for (int i = 0; i < 2; ++i) {
      const Vec2f offset{i == 0 ? -1.3f : 1.3f, -0.6f}; // m, in the chassis' frame
      BodyDef wheel;
      wheel.type = BodyType::dynamicBody;
      wheel.position = body.position + offset;
      wheels_[static_cast<std::size_t>(i)] = world().createBody(wheel);
      world().createShape(wheels_[static_cast<std::size_t>(i)], tyre, Circle{{}, 0.45f});
      WheelJointDef joint;
      joint.bodyA = chassis_;
      joint.bodyB = wheels_[static_cast<std::size_t>(i)];
      joint.localAnchorA = offset;
      joint.localAnchorB = {};
      joint.localAxisA = {0.0f, 1.0f};
      joint.hertz = hertz_;
      joint.dampingRatio = dampingRatio_;
      joint.enableLimit = true;
      joint.lowerTranslation = -0.25f;
      joint.upperTranslation = 0.25f;
      joint.enableMotor = true;
      joint.maxMotorTorque = torque_;
      springs_[static_cast<std::size_t>(i)] = world().createJoint(joint);
      anchors_[static_cast<std::size_t>(i)] = offset;
    }
    speed_.clear();
    compression_.clear();
    motorTorque_.clear();
  }

  /// The camera follows the car (until the view is panned or zoomed).
  [[nodiscard]] CameraView initialView() const override {
    return {world().isValid(chassis_) ? world().position(chassis_) + Vec2f{4.0f, 0.0f} : Vec2f{}, 6.0f, 10.0f};
  }
  [[nodiscard]] std::string_view controls() const override {
    return "Right/D: drive forward, Left/A: reverse, S or Down: brake. The camera follows the car.";
  }

  void keys(const KeyState& keys) override {
    throttle_ = (keys.right || keys.d ? 1 : 0) - (keys.left || keys.a ? 1 : 0);
    brake_ = keys.s || keys.down;
  }

protected:
  void beforeStep(float /*dt*/) override {
    // The motor's speed is the wheel's spin relative to the chassis (rad/s); negative spins a
    // wheel clockwise, which rolls the car forward (+x). With no key the autopilot drives on.
    const int throttle = throttle_ != 0 ? throttle_ : (autopilot_ ? 1 : 0);
    const float speed = brake_ ? 0.0f : -static_cast<float>(throttle) * wheelSpeed_;
    for (const rigid2d::WheelJointId j : springs_) {
      setWheelMotor(world(), j, throttle != 0 || brake_, speed, torque_);
    }
  }

  void afterStep(float /*dt*/) override {
    // Speed along the chassis' forward axis, m/s to km/h.
    const Transform2f xf = world().transform(chassis_);
    speed_.push(3.6f * dot(world().linearVelocity(chassis_), rotate(xf.q, Vec2f{1.0f, 0.0f})));
    // Travel: how far the rear wheel has moved up its axis from the anchor, m.
    const Vec2f anchor = transformPoint(xf, anchors_[0]);
    const Vec2f axis = rotate(xf.q, Vec2f{0.0f, 1.0f});
    compression_.push(dot(world().position(wheels_[0]) - anchor, axis));
    motorTorque_.push(wheelMotorTorque(world(), springs_[0]));
  }

  void parameters() override {
    checkbox("autopilot (drive on without keys)", &autopilot_);
    slider("wheel speed", &wheelSpeed_, 1.0f, 60.0f, "%.0f rad/s");
    slider("motor torque limit", &torque_, 0.0f, 100.0f, "%.0f N m");
    slider("suspension", &hertz_, 0.5f, 10.0f, "%.1f Hz");
    bool rebuild = ImGui::IsItemDeactivatedAfterEdit();
    slider("damping ratio", &dampingRatio_, 0.0f, 2.0f, "%.2f");
    rebuild |= ImGui::IsItemDeactivatedAfterEdit();
    if (rebuild) {
      setup();
    }
    speed_.plot("speed (km/h)", "%.1f km/h");
    compression_.plot("rear suspension travel (m, + up)", "%.3f m", 60.0f, -0.3f, 0.3f);
    motorTorque_.plot("rear motor torque (N m per m of depth)", "%.1f N m");
  }

private:
  BodyId chassis_;
  std::array<BodyId, 2> wheels_{};
  std::array<rigid2d::WheelJointId, 2> springs_{};
  std::array<Vec2f, 2> anchors_{};
  int throttle_ = 0;
  bool brake_ = false;
  bool autopilot_ = true;
  float wheelSpeed_ = 20.0f; // rad/s
  float torque_ = 20.0f;     // N m
  float hertz_ = 4.0f;       // Hz
  float dampingRatio_ = 0.7f;
  History speed_;
  History compression_;
  History motorTorque_;
};

const SampleRegistrar registrar{"Engine", "Car",
                                "A car on wheel joints (spring suspension, motor) over hilly chain ground; "
                                "drive it with the arrow keys.",
                                [] { return std::make_unique<Car>(); }};

} // namespace
} // namespace impetus::samples
