// Engine/Joint grid: the benchmark's joint grid (bench::jointGridScene): circles joined to their
// neighbours by revolute joints, hung from a few static circles in the middle of the top row, swing
// as a net. A joint is a constraint the solver can only approximately satisfy in a fixed number of
// iterations; the plot shows the widest gap between a joint's two anchors (m), the benchmark's
// quality figure, with the net's kinetic energy.
#include "bench_scene_sample.hpp"
#include "ui.hpp"

#include <imgui.h>

namespace impetus::samples {
namespace {

class JointGrid final : public BenchSceneSample {
public:
  void setup() override {
    buildScene(bench::jointGridScene(grid_));
    gap_.clear();
    energy_.clear();
  }

protected:
  void afterStep(float /*dt*/) override {
    gap_.push(1000.0f * bench::largestJointGap(scene(), transforms()));
    energy_.push(kineticEnergy());
  }

  void parameters() override {
    slider("circles per side", &grid_, 2, bench::jointGridSize);
    if (ImGui::IsItemDeactivatedAfterEdit()) {
      setup();
    }
    sceneControls();
    textWrapped("circles of radius 0.4 m, 1 m apart; they do not collide (one negative group)");
    gap_.plot("widest joint gap (mm)", "%.2f mm");
    energy_.plot("kinetic energy (J per m of depth)", "%.1f J");
  }

private:
  int grid_ = 20;
  History gap_;
  History energy_;
};

const SampleRegistrar registrar{"Engine", "Joint grid",
                                "The benchmark's joint grid: a net of circles on revolute joints swings from "
                                "a few fixed points; the widest joint gap is the quality figure.",
                                [] { return std::make_unique<JointGrid>(); }};

} // namespace
} // namespace impetus::samples
