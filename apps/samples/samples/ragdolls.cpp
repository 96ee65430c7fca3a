// Engine/Ragdolls: the benchmark's ragdolls (bench::ragdollScene): ten boxes and a circle head
// each, joined by revolute joints with angle limits at the elbows, knees, shoulders, hips and neck,
// dropped in a heap into an open box. Limits are one-sided constraints that switch on and off as
// the limbs fold; the plots show the widest joint gap (m) and the kinetic energy as the pile
// settles. Drag a ragdoll with the mouse.
#include "bench_scene_sample.hpp"
#include "ui.hpp"

#include <imgui.h>

namespace impetus::samples {
namespace {

class Ragdolls final : public BenchSceneSample {
public:
  void setup() override {
    buildScene(bench::ragdollScene(columns_, rows_));
    gap_.clear();
    energy_.clear();
  }
  [[nodiscard]] std::string_view controls() const override { return "Left-drag a limb to pull a ragdoll around."; }

protected:
  void afterStep(float /*dt*/) override {
    gap_.push(1000.0f * bench::largestJointGap(scene(), transforms()));
    energy_.push(kineticEnergy());
  }

  void parameters() override {
    slider("columns", &columns_, 1, bench::ragdollColumns);
    bool rebuild = ImGui::IsItemDeactivatedAfterEdit();
    slider("rows", &rows_, 1, bench::ragdollRows);
    rebuild |= ImGui::IsItemDeactivatedAfterEdit();
    if (rebuild) {
      setup();
    }
    sceneControls();
    gap_.plot("widest joint gap (mm)", "%.2f mm");
    energy_.plot("kinetic energy (J per m of depth)", "%.1f J");
  }

private:
  int columns_ = 4;
  int rows_ = 3;
  History gap_;
  History energy_;
};

const SampleRegistrar registrar{"Engine", "Ragdolls",
                                "The benchmark's ragdolls: boxes and a head on revolute joints with limits, "
                                "dropped in a heap; drag them with the mouse.",
                                [] { return std::make_unique<Ragdolls>(); }};

} // namespace
} // namespace impetus::samples
