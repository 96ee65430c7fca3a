// Engine/Tumbler: the benchmark's tumbler (bench::kinematicTumblerScene): a kinematic drum turning at a set
// rate stirs a grid of small boxes. A kinematic body moves at its velocity whatever hits it (it has
// infinite mass for the solver), so the drum feeds energy in at every contact; the plots show the
// boxes' kinetic energy and how high the pile is carried (the mean height of the boxes above the
// drum's centre).
#include "bench_scene_sample.hpp"
#include "ui.hpp"

#include <imgui.h>
#include <impetus/math/scalar.hpp>

namespace impetus::samples {
namespace {

constexpr float degrees = pi<float> / 180.0f;

class Tumbler final : public BenchSceneSample {
public:
  void setup() override {
    buildScene(bench::kinematicTumblerScene(grid_));
    drum_ = {};
    for (std::size_t i = 0; i < scene().bodies.size(); ++i) {
      if (scene().bodies[i].type == rigid2d::BodyType::kinematicBody) {
        drum_ = sceneBodies()[i];
        drumCenter_ = scene().bodies[i].position;
      }
    }
    setDrumSpeed();
    energy_.clear();
    height_.clear();
  }

protected:
  void afterStep(float /*dt*/) override {
    energy_.push(kineticEnergy());
    float sum = 0.0f;
    int n = 0;
    for (std::size_t i = 0; i < sceneBodies().size(); ++i) {
      if (scene().bodies[i].type == rigid2d::BodyType::dynamicBody) {
        sum += world().position(sceneBodies()[i]).y - drumCenter_.y;
        ++n;
      }
    }
    height_.push(n > 0 ? sum / static_cast<float>(n) : 0.0f);
  }

  void parameters() override {
    slider("boxes per side", &grid_, 2, bench::tumblerGrid);
    if (ImGui::IsItemDeactivatedAfterEdit()) {
      setup();
    }
    if (slider("drum", &speedDegrees_, -90.0f, 90.0f, "%.0f deg/s")) {
      setDrumSpeed();
    }
    sceneControls();
    energy_.plot("kinetic energy of the boxes (J per m of depth)", "%.1f J");
    height_.plot("mean height of the boxes above the drum's centre (m)", "%.2f m");
  }

private:
  void setDrumSpeed() {
    if (world().isValid(drum_)) {
      world().setAngularVelocity(drum_, speedDegrees_ * degrees);
    }
  }

  int grid_ = 30;
  float speedDegrees_ = bench::tumblerSpeed / degrees;
  rigid2d::BodyId drum_;
  Vec2f drumCenter_;
  History energy_;
  History height_;
};

const SampleRegistrar registrar{"Engine", "Tumbler",
                                "The benchmark's tumbler: a kinematic drum (moved by its velocity, deaf to "
                                "contacts) stirs a grid of small boxes.",
                                [] { return std::make_unique<Tumbler>(); }};

} // namespace
} // namespace impetus::samples
