// Engine/Smash: the benchmark's smash (bench::smashAwakeScene): in zero gravity a 4 m box at 40 m/s hits
// a block of small boxes. At 40 m/s the projectile moves 0.67 m a step, more than three of the
// block's 0.2 m boxes: without continuous collision (a bullet: time of impact against dynamic
// bodies too) it can pass through the first boxes before any contact is found. Switch "bullet" off
// to see the difference. The plots show the projectile's speed (m/s) and the total momentum
// (kg m/s per m of depth), which contacts conserve (equal and opposite impulses).
#include "bench_scene_sample.hpp"

#include <imgui.h>

namespace impetus::samples {
namespace {

class Smash final : public BenchSceneSample {
public:
  /// Wide enough for the debris: the block flies apart at several metres a second.
  [[nodiscard]] CameraView initialView() const override { return {{2.0f, 0.0f}, 10.0f, 16.0f}; }
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

  [[nodiscard]] std::optional<Color> bodyColorOf(rigid2d::BodyId body) const override {
    if (body == sceneBodies()[projectileIndex_]) {
      return palette::bullet;
    }
    return std::nullopt;
  }

  void parameters() override {
    bool rebuild = ImGui::Checkbox("bullet (continuous collision)", &bullet_);
    ImGui::SliderInt("##grid", &grid_, 4, bench::smashGrid, "boxes per side of the block: %d");
    rebuild |= ImGui::IsItemDeactivatedAfterEdit();
    ImGui::SliderFloat("##speed", &speed_, 5.0f, 200.0f, "projectile: %.0f m/s");
    rebuild |= ImGui::IsItemDeactivatedAfterEdit();
    if (rebuild) {
      setup();
    }
    sceneControls();
    ImGui::TextWrapped("the projectile moves %.2f m per 1/60 s step; the boxes are 0.2 m", speed_ / 60.0);
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
