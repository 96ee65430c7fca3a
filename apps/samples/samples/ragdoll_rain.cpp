// Engine/Ragdoll rain: Box2D v3's rain benchmark (bench::rainScene): v3's ragdolls (capsule bones,
// revolute joints with limits, springs and pin friction) spawned in columns above five floors,
// eight steps apart; once forty columns stand, each new column destroys the oldest first. Bodies
// and joints are created and destroyed while thousands of others fall, pile up and sleep: the
// plots show how many bodies are alive and how many sleep.
#include "bench_scene_sample.hpp"
#include "ui.hpp"

#include <imgui.h>

#include <memory>

namespace impetus::samples {
namespace {

class RagdollRain final : public BenchSceneSample {
public:
  void setup() override {
    buildScene(bench::rainScene());
    spawner_ = std::make_unique<bench::ImpetusSpawner>(world());
    script_ = scene().makeScript();
    stepIndex_ = 0;
    bodies_.clear();
    asleep_.clear();
  }
  /// The five floors, 250 m wide and 180 m from the lowest to the highest.
  [[nodiscard]] CameraView initialView() const override { return {{0.0f, 100.0f}, 110.0f, 130.0f}; }

protected:
  void beforeStep(float /*dt*/) override { script_(stepIndex_++, *spawner_); }

  void afterStep(float /*dt*/) override {
    bodies_.push(static_cast<float>(spawner_->liveBodies()));
    std::size_t sleeping = 0;
    for (const rigid2d::BodyId b : spawner_->bodies()) {
      sleeping += world().isAwake(b) ? 0 : 1;
    }
    asleep_.push(static_cast<float>(sleeping));
  }

  void parameters() override {
    sceneControls();
    textWrapped("a column of %d groups of %d ragdolls every %d steps, %d columns at most", bench::rainFloors,
                bench::rainGroupSize, bench::rainSpawnInterval, bench::rainColumns);
    bodies_.plot("ragdoll bodies alive", "%.0f");
    asleep_.plot("ragdoll bodies asleep", "%.0f");
  }

private:
  std::unique_ptr<bench::ImpetusSpawner> spawner_;
  bench::SceneScript script_;
  int stepIndex_ = 0;
  History bodies_;
  History asleep_;
};

const SampleRegistrar registrar{"Engine", "Ragdoll rain",
                                "Box2D v3's rain benchmark: ragdolls spawned in columns above five floors and "
                                "destroyed again, while thousands fall, pile up and sleep.",
                                [] { return std::make_unique<RagdollRain>(); }};

} // namespace
} // namespace impetus::samples
