// Engine/Smash: the benchmark's smash (bench::smashAwakeScene): in zero gravity a 4 m box at 40 m/s hits
// a block of small boxes. At 40 m/s the projectile moves 0.67 m a step, more than three of the
// block's 0.2 m boxes: without continuous collision (a bullet: time of impact against dynamic
// bodies too) it can pass through the first boxes before any contact is found. Switch "bullet" off
// to see the difference. The plots show the projectile's speed (m/s) and the total momentum
// (kg m/s per m of depth), which contacts conserve (equal and opposite impulses).
#include "bench_scene_sample.hpp"
#include "ui.hpp"

#include <imgui.h>

#include <cstdio>
#include <string>

namespace impetus::samples {
namespace {

class Smash final : public BenchSceneSample {
public:
  /// From the projectile's start (its left face at x = -14 m) to where it is two seconds later
  /// (x = 17 m), with the block flying apart between.
  [[nodiscard]] CameraView initialView() const override { return {{3.0f, 0.0f}, 10.0f, 19.5f}; }
  void setup() override {
    bench::Rigid2dScene scene = bench::smashAwakeScene(grid_);
    projectileIndex_ = 0;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      if (lengthSquared(scene.bodies[i].linearVelocity) > 0.0f) {
        projectileIndex_ = i;
        scene.bodies[i].bullet = bullet_; // the scene is plain data: change it before building
        scene.bodies[i].linearVelocity.x = speed_;
      }
    }
    buildScene(std::move(scene));
    speedHistory_.clear();
    momentum_.clear();
  }

protected:
  void afterStep(float /*dt*/) override {
    speedHistory_.push(length(world().linearVelocity(sceneBodies()[projectileIndex_])));
    Vec2f p;
    for (const rigid2d::BodyId body : sceneBodies()) {
      if (world().bodyType(body) == rigid2d::BodyType::dynamicBody) {
        p += world().linearVelocity(body) * world().mass(body);
      }
    }
    momentum_.push(length(p));
  }

  [[nodiscard]] std::string summary() const override {
    char text[64];
    std::snprintf(text, sizeof text, "; the projectile is at x = %.1f m",
                  static_cast<double>(world().transform(sceneBodies()[projectileIndex_]).p.x));
    return BenchSceneSample::summary() + text;
  }

  [[nodiscard]] std::optional<Color> bodyColorOf(rigid2d::BodyId body) const override {
    if (body == sceneBodies()[projectileIndex_]) {
      return palette::bullet;
    }
    return std::nullopt;
  }

  void parameters() override {
    bool rebuild = checkbox("bullet (continuous collision)", &bullet_);
    slider("boxes per side of the block", &grid_, 4, bench::smashGrid);
    rebuild |= ImGui::IsItemDeactivatedAfterEdit();
    slider("projectile", &speed_, 5.0f, 200.0f, "%.0f m/s");
    rebuild |= ImGui::IsItemDeactivatedAfterEdit();
    if (rebuild) {
      setup();
    }
    sceneControls();
    textWrapped("the projectile moves %.2f m per 1/60 s step; the boxes are 0.2 m", speed_ / 60.0);
    speedHistory_.plot("projectile speed (m/s)", "%.1f m/s");
    momentum_.plot("total momentum (kg m/s per m of depth)", "%.1f kg m/s");
  }

private:
  bool bullet_ = true;
  int grid_ = 30;
  float speed_ = 40.0f;
  std::size_t projectileIndex_ = 0;
  History speedHistory_;
  History momentum_;
};

const SampleRegistrar registrar{"Engine", "Smash",
                                "The benchmark's smash: a 40 m/s box hits a block of small boxes in zero "
                                "gravity; continuous collision (bullet) stops it tunnelling.",
                                [] { return std::make_unique<Smash>(); }};

} // namespace
} // namespace impetus::samples
