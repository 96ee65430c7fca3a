// Engine/Conveyor and platform: the game hooks of the 2D world. Boxes drop onto a conveyor belt
// (a static box whose surface runs at ShapeDef::tangentSpeed: friction carries what rests on it
// to the belt's speed), ride it to a jump pad that throws them up at a set speed, and fly up
// through a one-way platform (World::setPreSolve: solid only for what is above its top and not
// rising) to land on it. With "teams", boxes of the same colour pass through each other
// (World::setCustomFilter). The plot is the speed of the newest box on the belt, with the belt's.
#include "rigid2d_sample.hpp"
#include "ui.hpp"

#include <imgui.h>

#include <cmath>
#include <deque>

namespace impetus::samples {
namespace {

using namespace impetus::rigid2d;

constexpr float boxHalf = 0.4f;     // m
constexpr float beltTop = 0.0f;     // m
constexpr float beltEnd = 4.0f;     // m, x of the belt's right end
constexpr float padLeft = 5.0f;     // m, the jump pad's span
constexpr float padRight = 10.0f;   // m
constexpr float platformTop = 3.0f; // m
constexpr float padTop = -3.0f;     // m
constexpr int maxBoxes = 40;        // the oldest go, to keep a steady stream

class ConveyorAndPlatform final : public Rigid2dSample {
public:
  void setup() override {
    resetWorld({});
    const BodyId ground = world().createBody({});
    ShapeDef belt;
    belt.friction = 0.8f;
    belt.tangentSpeed = beltSpeed_;
    belt_ = world().createShape(ground, belt, makeOffsetBox(7.0f, 0.25f, {beltEnd - 7.0f, beltTop - 0.25f}, 0.0f));
    // The floor the pad stands on, and a wall behind the platform.
    world().createShape(ground, {}, makeOffsetBox(8.0f, 0.5f, {6.0f, padTop - 0.5f}, 0.0f));
    world().createShape(ground, {}, makeOffsetBox(0.25f, 6.0f, {14.25f, 3.0f}, 0.0f));
    ShapeDef oneWay;
    oneWay.enablePreSolveEvents = true;
    platform_ = world().createShape(ground, oneWay, makeOffsetBox(3.5f, 0.2f, {10.5f, platformTop - 0.2f}, 0.0f));
    world().setPreSolve([this](ShapeId a, ShapeId b, const Manifold& m) {
      if (a != platform_ && b != platform_) {
        return true;
      }
      // The normal points from A to B: up out of the platform when it is A.
      const float up = a == platform_ ? m.normal.y : -m.normal.y;
      const BodyId other = world().shapeBody(a == platform_ ? b : a);
      const float bottom = world().position(other).y - boxHalf;
      return up > 0.9f && bottom > platformTop - 0.1f && world().linearVelocity(other).y <= 0.5f;
    });
    world().setCustomFilter([this](ShapeId a, ShapeId b) {
      const auto team = [&](ShapeId s) { return static_cast<int>(world().shapeBody(s).index % 2); };
      const bool boxes = world().bodyType(world().shapeBody(a)) == BodyType::dynamicBody &&
                         world().bodyType(world().shapeBody(b)) == BodyType::dynamicBody;
      return !(teams_ && boxes && team(a) == team(b));
    });
    boxes_.clear();
    sinceSpawn_ = spawnInterval_;
    speed_.clear();
  }
  [[nodiscard]] CameraView initialView() const override { return {{2.0f, 3.0f}, 12.0f, 12.0f}; }
  [[nodiscard]] std::string_view controls() const override {
    return "Drag boxes about; change the belt's speed and the pad's throw in the panel.";
  }

protected:
  void beforeStep(float dt) override {
    sinceSpawn_ += dt;
    if (sinceSpawn_ >= spawnInterval_) {
      sinceSpawn_ = 0.0f;
      spawn();
    }
    // The jump pad: a box sliding onto it is thrown straight up.
    for (const BodyId box : boxes_) {
      const Vec2f p = world().position(box);
      const Vec2f v = world().linearVelocity(box);
      if (p.x > padLeft && p.x < padRight && p.y < padTop + boxHalf + 0.05f && v.y <= 0.1f) {
        world().setLinearVelocity(box, {2.0f, throwSpeed_});
      }
    }
  }

  void afterStep(float /*dt*/) override {
    if (!boxes_.empty()) {
      const BodyId newest = boxes_.back();
      const Vec2f p = world().position(newest);
      const bool onBelt = p.x < beltEnd && std::abs(p.y - (beltTop + boxHalf)) < 0.05f;
      speed_.push(onBelt ? world().linearVelocity(newest).x : 0.0f);
    }
  }

  void parameters() override {
    if (slider("belt speed", &beltSpeed_, -1.0f, 6.0f, "%.1f m/s")) {
      setup(); // the tangent speed is a shape's material: the belt is made again
    }
    slider("pad throws up at", &throwSpeed_, 6.0f, 16.0f, "%.1f m/s");
    slider("a box every", &spawnInterval_, 0.3f, 3.0f, "%.1f s");
    if (checkbox("teams (a custom filter)", &teams_)) {
      setup();
    }
    textWrapped("A box thrown at %.1f m/s rises %.1f m (v^2 / 2g); the platform's top is %.1f m above the pad.",
                static_cast<double>(throwSpeed_), static_cast<double>(throwSpeed_ * throwSpeed_ / 20.0f),
                static_cast<double>(platformTop - padTop));
    speed_.plot("newest box's speed on the belt (m/s)", "%.2f m/s", 80.0f, std::min(0.0f, beltSpeed_),
                std::max(0.5f, beltSpeed_ * 1.2f));
  }

  [[nodiscard]] std::optional<Color> bodyColorOf(BodyId body) const override {
    if (!teams_ || world().bodyType(body) != BodyType::dynamicBody) {
      return std::nullopt;
    }
    return body.index % 2 == 0 ? palette::warning : palette::reference;
  }

private:
  void spawn() {
    if (static_cast<int>(boxes_.size()) >= maxBoxes) {
      world().destroyBody(boxes_.front());
      boxes_.pop_front();
    }
    BodyDef def;
    def.type = BodyType::dynamicBody;
    def.position = {-8.0f, beltTop + boxHalf + 1.0f};
    const BodyId box = world().createBody(def);
    ShapeDef shape;
    shape.friction = 0.8f;
    shape.enableCustomFiltering = true;
    world().createShape(box, shape, makeBox(boxHalf, boxHalf));
    boxes_.push_back(box);
  }

  ShapeId belt_;
  ShapeId platform_;
  std::deque<BodyId> boxes_;
  float beltSpeed_ = 3.0f;     // m/s
  float throwSpeed_ = 12.0f;   // m/s
  float spawnInterval_ = 1.0f; // s
  float sinceSpawn_ = 0.0f;    // s
  bool teams_ = false;
  History speed_;
};

const SampleRegistrar registrar{"Engine", "Conveyor and platform",
                                "A conveyor belt (a shape's tangent speed), a jump pad and a one-way platform (the "
                                "pre-solve callback); with teams, a custom filter lets same-colour boxes pass.",
                                [] { return std::make_unique<ConveyorAndPlatform>(); }};

} // namespace
} // namespace impetus::samples
