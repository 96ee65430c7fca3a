// Engine/Pyramid: the benchmark's pyramids of boxes (bench::largePyramidScene and
// pyramidRowScene) on the soft-step solver. A stack is the hardest test of a contact solver:
// every box's weight passes through the ones below, and an iterative solver that does not converge
// lets the stack sink or slide. The plots are the benchmark's quality figures: how far the top box
// has sunk (m, from its start) and the deepest overlap between two boxes (m), with the kinetic
// energy, which should fall to almost nothing once the stack settles.
#include "bench_scene_sample.hpp"
#include "ui.hpp"

#include <imgui.h>

namespace impetus::samples {
namespace {

class Pyramid final : public BenchSceneSample {
public:
  void setup() override {
    buildScene(many_ ? bench::pyramidRowScene(count_, base_) : bench::largePyramidScene(base_));
    sink_.clear();
    overlap_.clear();
    energy_.clear();
  }

protected:
  void afterStep(float /*dt*/) override {
    const std::vector<Transform2f> xf = transforms();
    sink_.push(1000.0f * bench::topSink(scene(), xf));
    energy_.push(kineticEnergy());
    if (++steps_ % 6 == 0 || overlap_.empty()) { // the overlap sweep costs a narrowphase pass
      overlap_.push(1000.0f * bench::largestOverlap(scene(), xf));
    }
  }

  void parameters() override {
    bool rebuild = checkbox("ten pyramids side by side", &many_);
    slider("base", &base_, 2, 100, "%d boxes");
    rebuild |= ImGui::IsItemDeactivatedAfterEdit();
    if (many_) {
      slider("pyramids", &count_, 1, 20);
      rebuild |= ImGui::IsItemDeactivatedAfterEdit();
    }
    if (rebuild) {
      setup();
    }
    sceneControls();
    textWrapped("boxes of %.1f m, density %.0f kg/m^2, friction %.1f, steps of 1/60 s", 2.0 * bench::pyramidBoxHalfSize,
                static_cast<double>(bench::sceneDensity), static_cast<double>(bench::sceneFriction));
    sink_.plot("top box sinking (mm)", "%.2f mm");
    overlap_.plot("deepest overlap (mm)", "%.2f mm");
    energy_.plot("kinetic energy (J per m of depth)", "%.3g J");
  }

private:
  bool many_ = false;
  int base_ = 20;
  int count_ = bench::pyramidRowCount;
  long steps_ = 0;
  History sink_;
  History overlap_{100};
  History energy_;
};

const SampleRegistrar registrar{"Engine", "Pyramid",
                                "The benchmark's pyramid of boxes: a stack's weight through the contact solver; "
                                "the top box's sinking and the deepest overlap are the quality figures.",
                                [] { return std::make_unique<Pyramid>(); }};

} // namespace
} // namespace impetus::samples
