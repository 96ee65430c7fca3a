// Engine/Newton's cradle: restitution as a sequence of impacts. Five touching steel-like balls
// hang on 5 m distance joints; the first k are pulled aside and let go. Below, a row of touching
// boxes on a frictionless floor is struck by k boxes sliding at 3 m/s. Each contact bounces when
// its own approach is met, so the impact passes along each row as equal-mass elastic collisions,
// each swapping two velocities: the last k balls swing out and the last k boxes slide away
// (docs/rigid2d.md, "Restitution"). The plot is the kinetic energy of each row, which an elastic
// row keeps.
#include "rigid2d_sample.hpp"
#include "ui.hpp"

#include <impetus/math/scalar.hpp>

#include <imgui.h>

#include <cmath>
#include <vector>

namespace impetus::samples {
namespace {

using namespace impetus::rigid2d;

constexpr int ballCount = 5;
constexpr float ballRadius = 0.5f;   // m
constexpr float stringLength = 5.0f; // m, pivot to ball centre
constexpr float frameHeight = 9.0f;  // m, the pivots' height
constexpr int boxCount = 7;
constexpr float boxHalf = 0.5f;     // m
constexpr float strikeSpeed = 3.0f; // m/s, the sliding strikers' speed
constexpr float strikerGap = 3.0f;  // m between the strikers and the row at the start

class NewtonsCradle final : public Rigid2dSample {
public:
  void setup() override {
    WorldDef def;
    def.restitutionThreshold = 0.05f; // the balls' slow late swings still bounce
    resetWorld(def);
    const BodyId ground = world().createBody({});
    ShapeDef floor;
    floor.friction = 0.0f;
    world().createShape(ground, floor, makeOffsetBox(20.0f, 0.5f, {4.0f, -0.5f}, 0.0f));
    world().createShape(ground, {}, makeOffsetBox(3.5f, 0.1f, {0.0f, frameHeight + 0.1f}, 0.0f));
    balls_.clear();
    boxes_.clear();
    const float releaseAngle = releaseDegrees_ * pi<float> / 180.0f;
    for (int i = 0; i < ballCount; ++i) {
      const Vec2f pivot{static_cast<float>(i - ballCount / 2) * 2.0f * ballRadius, frameHeight};
      const bool raised = i < raised_;
      BodyDef body;
      body.type = BodyType::dynamicBody;
      body.enableSleep = false;
      body.bullet = true;
      body.position = raised ? pivot + Vec2f{-std::sin(releaseAngle), -std::cos(releaseAngle)} * stringLength
                             : pivot + Vec2f{0.0f, -stringLength};
      const BodyId ball = world().createBody(body);
      ShapeDef shape;
      shape.density = 10.0f;
      shape.friction = 0.0f;
      shape.restitution = restitution_;
      world().createShape(ball, shape, Circle{{0.0f, 0.0f}, ballRadius});
      DistanceJointDef string;
      string.bodyA = ground;
      string.bodyB = ball;
      string.localAnchorA = pivot;
      string.length = stringLength;
      world().createJoint(string);
      balls_.push_back(ball);
    }
    for (int i = 0; i < boxCount; ++i) {
      const bool striker = i < raised_;
      BodyDef body;
      body.type = BodyType::dynamicBody;
      body.enableSleep = false;
      body.position = {5.0f + static_cast<float>(i) * 2.0f * boxHalf - (striker ? strikerGap : 0.0f), boxHalf};
      body.linearVelocity = {striker ? strikeSpeed : 0.0f, 0.0f};
      const BodyId box = world().createBody(body);
      ShapeDef shape;
      shape.friction = 0.0f;
      shape.restitution = restitution_;
      world().createShape(box, shape, makeBox(boxHalf, boxHalf));
      boxes_.push_back(box);
    }
    ballEnergy_.clear();
    boxEnergy_.clear();
  }
  [[nodiscard]] CameraView initialView() const override { return {{3.0f, 4.5f}, 10.0f, 6.0f}; }
  [[nodiscard]] std::string_view controls() const override {
    return "Drag a ball aside and let go; choose how many strike and how elastic they are in the panel.";
  }

protected:
  void afterStep(float /*dt*/) override {
    ballEnergy_.push(kineticEnergy(balls_));
    boxEnergy_.push(kineticEnergy(boxes_));
  }

  void parameters() override {
    bool changed = slider("balls striking", &raised_, 1, 3);
    changed = slider("restitution", &restitution_, 0.5f, 1.0f, "%.2f") || changed;
    changed = slider("balls released from", &releaseDegrees_, 10.0f, 60.0f, "%.0f deg") || changed;
    if (changed || ImGui::Button("again")) {
      setup();
    }
    ballEnergy_.plot("balls' kinetic energy (J)", "%.0f J", 80.0f, 0.0f);
    boxEnergy_.plot("boxes' kinetic energy (J)", "%.1f J", 80.0f, 0.0f);
  }

private:
  [[nodiscard]] float kineticEnergy(const std::vector<BodyId>& bodies) const {
    float energy = 0.0f;
    for (const BodyId b : bodies) {
      const Vec2f v = world().linearVelocity(b);
      const float w = world().angularVelocity(b);
      energy += 0.5f * world().mass(b) * dot(v, v) + 0.5f * world().rotationalInertia(b) * w * w;
    }
    return energy;
  }

  std::vector<BodyId> balls_;
  std::vector<BodyId> boxes_;
  int raised_ = 1;
  float restitution_ = 1.0f;
  float releaseDegrees_ = 30.0f;
  History ballEnergy_;
  History boxEnergy_;
};

const SampleRegistrar registrar{"Engine", "Newton's cradle",
                                "Touching balls on strings and a row of touching boxes, struck at one end: each "
                                "contact bounces as its approach is met, so the impact passes along the row.",
                                [] { return std::make_unique<NewtonsCradle>(); }};

} // namespace
} // namespace impetus::samples
