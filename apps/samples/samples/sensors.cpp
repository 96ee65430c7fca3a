// Engine/Sensors: sensor shapes detect overlap without colliding: they report begin and end events
// (World::sensorEvents) and push nothing. Balls and boxes rain through three sensors (a static
// box, a box on a kinematic body sliding back and forth, a static circle); each sensor lights up
// while something is inside, and the plots count the visitors of each from the events alone.
// Bodies are recycled (the oldest destroyed) to keep a steady stream: a destroyed visitor ends its
// overlaps too.
#include "rigid2d_sample.hpp"
#include "ui.hpp"

#include <imgui.h>

#include <array>
#include <cmath>
#include <deque>

namespace impetus::samples {
namespace {

using namespace impetus::rigid2d;

class Sensors final : public Rigid2dSample {
public:
  void setup() override {
    WorldDef def;
    resetWorld(def);
    const BodyId ground = world().createBody({});
    world().createShape(ground, {}, makeOffsetBox(14.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    world().createShape(ground, {}, makeOffsetBox(0.5f, 4.0f, {-14.5f, 3.0f}, 0.0f));
    world().createShape(ground, {}, makeOffsetBox(0.5f, 4.0f, {14.5f, 3.0f}, 0.0f));
    ShapeDef sensorDef;
    sensorDef.isSensor = true;
    sensors_[0] = world().createShape(ground, sensorDef, makeOffsetBox(3.0f, 1.5f, {-8.0f, 5.0f}, 0.0f));
    BodyDef slider;
    slider.type = BodyType::kinematicBody;
    slider.position = {0.0f, 8.0f};
    slider_ = world().createBody(slider);
    sensors_[1] = world().createShape(slider_, sensorDef, makeBox(2.0f, 1.0f));
    sensors_[2] = world().createShape(ground, sensorDef, Circle{{8.0f, 3.0f}, 2.0f});
    inside_ = {};
    for (History& h : visitors_) {
      h.clear();
    }
    spawned_.clear();
    spawnClock_ = 0.0f;
    seed_ = 12345u;
  }
  [[nodiscard]] CameraView initialView() const override { return {{0.0f, 7.0f}, 9.0f, 16.0f}; }

protected:
  void beforeStep(float dt) override {
    // The kinematic sensor sweeps +-8 m at 2 m/s peak: v = A w cos(w t) with A w = 2 m/s.
    const float w = 0.25f;
    world().setLinearVelocity(slider_, {8.0f * w * std::cos(w * time()), 0.0f});
    spawnClock_ += dt;
    while (spawnClock_ >= spawnInterval_) {
      spawnClock_ -= spawnInterval_;
      spawn();
    }
  }

  void afterStep(float /*dt*/) override {
    const SensorEvents& events = world().sensorEvents();
    for (const SensorEvent& e : events.begins) {
      for (std::size_t i = 0; i < sensors_.size(); ++i) {
        inside_[i] += e.sensor == sensors_[i] ? 1 : 0;
      }
    }
    for (const SensorEvent& e : events.ends) {
      for (std::size_t i = 0; i < sensors_.size(); ++i) {
        inside_[i] -= e.sensor == sensors_[i] ? 1 : 0;
      }
    }
    for (std::size_t i = 0; i < sensors_.size(); ++i) {
      visitors_[i].push(static_cast<float>(inside_[i]));
    }
  }

  void drawOverlay(DebugDraw& draw) override {
    // A lit sensor: its shape filled brighter while anything is inside.
    for (std::size_t i = 0; i < sensors_.size(); ++i) {
      if (inside_[i] > 0) {
        const BodyId body = world().shapeBody(sensors_[i]);
        drawShape(draw, world().shapeGeometry(sensors_[i]), world().transform(body), palette::sensor.withAlpha(0.35f),
                  palette::sensor);
      }
      const Vec2f at = i == 1 ? world().position(slider_) : (i == 0 ? Vec2f{-8.0f, 5.0f} : Vec2f{8.0f, 3.0f});
      draw.text(at + Vec2f{-0.8f, 0.4f}, std::to_string(inside_[i]) + " inside", palette::text);
    }
  }

  void parameters() override {
    slider("a body every", &spawnInterval_, 0.05f, 1.0f, "%.2f s");
    slider("at most", &maxBodies_, 10, 300, "%d bodies");
    static constexpr const char* names[] = {"static box sensor: bodies inside",
                                            "moving (kinematic) sensor: bodies inside",
                                            "static circle sensor: bodies inside"};
    for (std::size_t i = 0; i < visitors_.size(); ++i) {
      visitors_[i].plot(names[i], "%.0f", 45.0f, -0.5f, 12.0f);
    }
  }

private:
  float random01() {
    seed_ = seed_ * 1664525u + 1013904223u; // a fixed sequence: every run drops the same bodies
    return static_cast<float>(seed_ >> 8) / 16777216.0f;
  }

  void spawn() {
    BodyDef def;
    def.type = BodyType::dynamicBody;
    def.position = {-12.0f + 24.0f * random01(), 16.0f};
    def.angularVelocity = 4.0f * (random01() - 0.5f);
    const BodyId body = world().createBody(def);
    ShapeDef shape;
    shape.restitution = 0.3f;
    if (random01() < 0.5f) {
      world().createShape(body, shape, Circle{{}, 0.3f + 0.3f * random01()});
    } else {
      world().createShape(body, shape, makeBox(0.3f + 0.3f * random01(), 0.3f + 0.2f * random01()));
    }
    spawned_.push_back(body);
    while (static_cast<int>(spawned_.size()) > maxBodies_) {
      world().destroyBody(spawned_.front()); // its sensor overlaps end in the next step's events
      spawned_.pop_front();
    }
  }

  std::array<ShapeId, 3> sensors_{};
  std::array<int, 3> inside_{};
  std::array<History, 3> visitors_;
  BodyId slider_;
  std::deque<BodyId> spawned_;
  float spawnInterval_ = 0.2f; // s
  float spawnClock_ = 0.0f;
  int maxBodies_ = 80;
  std::uint32_t seed_ = 12345u;
};

const SampleRegistrar registrar{"Engine", "Sensors",
                                "Sensor shapes report overlap begin and end events without colliding: bodies "
                                "rain through a static, a moving and a round sensor.",
                                [] { return std::make_unique<Sensors>(); }};

} // namespace
} // namespace impetus::samples
