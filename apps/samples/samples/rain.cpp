// Engine/Rain: the benchmark's rain (bench::circleRainScene): circles dropped at rest into an open box.
// Thousands of bodies landing on each other are the broadphase's test (the dynamic AABB tree finds
// the pairs) and the solver's (deep piles); the plots show the kinetic energy, which the
// collisions dissipate (no restitution), and the number of touching contacts.
#include "bench_scene_sample.hpp"
#include "ui.hpp"

#include <imgui.h>

namespace impetus::samples {
namespace {

class Rain final : public BenchSceneSample {
public:
  void setup() override {
    buildScene(bench::circleRainScene(static_cast<std::size_t>(count_)));
    energy_.clear();
    contacts_.clear();
  }

protected:
  void afterStep(float /*dt*/) override {
    energy_.push(kineticEnergy());
    contacts_.push(static_cast<float>(world().contactCount()));
  }

  void parameters() override {
    slider("circles", &count_, 10, 10000, "%d", ImGuiSliderFlags_Logarithmic);
    if (ImGui::IsItemDeactivatedAfterEdit()) {
      setup();
    }
    sceneControls();
    textWrapped("circles of radius %.2f m in %zu rows", static_cast<double>(bench::rainRadius), bench::rainRows);
    energy_.plot("kinetic energy (J per m of depth)", "%.1f J");
    contacts_.plot("touching contacts", "%.0f");
  }

private:
  int count_ = 1000;
  History energy_;
  History contacts_;
};

const SampleRegistrar registrar{"Engine", "Rain",
                                "The benchmark's rain: circles dropped into an open box; the broadphase and "
                                "the solver at work on a deep pile.",
                                [] { return std::make_unique<Rain>(); }};

} // namespace
} // namespace impetus::samples
