// Book/Rope (ch. 13): the book's rope, ten 1 kg particles in a line pinned at one end, released
// horizontal, in two models side by side (particles/rope.hpp):
//   left, XPBD distance constraints (the default): stable at any stiffness, slack allowed; its
//   error is residual stretch, which more substeps shrink as h^2;
//   right, the book's chain of spring-dampers (k = 1000 N/m, d = 100 N s/m): a penalty force that
//   stretches under load (segment j of an N-segment rope carries (N - j) m g, stretching it by
//   that over k), and semi-implicit Euler is stable only while the substep h < sqrt(m/k) and
//   h < m / (2 d).
// Plots: each rope's stretch (length over rest length, minus 1, %) and its mechanical energy
// (kinetic + gravitational + elastic, J), which damping and the constraint projection remove.
// Drag a particle with the mouse.
#include "sample.hpp"

#include "particle_drag.hpp"
#include "particle_draw.hpp"
#include "plot.hpp"
#include "ui.hpp"

#include <impetus/particles/rope.hpp>

#include <imgui.h>

#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace impetus::samples {
namespace {

constexpr std::array<const char*, 2> modelNames{"XPBD constraints", "book's springs"};

class RopeSample final : public Sample {
public:
  void setup() override {
    for (std::size_t i = 0; i < 2; ++i) {
      ParticleWorldSettings settings;
      settings.substeps = substeps_;
      worlds_[i].emplace(settings);
      RopeDef def = RopeDef::along({anchorX(i), 8.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, length_);
      def.segments = segments_;
      def.totalMass = mass_;
      def.particleRadius = 0.1f;
      def.model = i == 0 ? RopeModel::xpbd : RopeModel::bookSprings;
      def.compliance = compliance_;
      def.stiffness = stiffness_;
      def.damping = damping_;
      ropes_[i] = createRope(*worlds_[i], def);
      stretch_[i].clear();
      energy_[i].clear();
    }
    drag_.reset();
  }

  void step(float dt) override {
    for (std::size_t i = 0; i < 2; ++i) {
      if (drag_.active() && dragged_ == i) {
        drag_.apply(*worlds_[i]);
      }
      worlds_[i]->step(dt);
      const float len = ropeLength(*worlds_[i], ropes_[i]);
      stretch_[i].push(100.0f * (len / ropes_[i].restLength - 1.0f));
      energy_[i].push(
          static_cast<float>(worlds_[i]->kineticEnergy() + worlds_[i]->potentialEnergy() + worlds_[i]->springEnergy()));
    }
  }

  [[nodiscard]] bool finite() const override {
    for (const auto& w : worlds_) {
      for (const Vec3f& p : w->positions()) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
          return false;
        }
      }
    }
    return true;
  }

  [[nodiscard]] CameraView initialView() const override { return {{0.0f, 4.0f}, 7.0f, 2.0f * length_ + 1.0f}; }
  [[nodiscard]] std::string_view controls() const override { return "Left-drag a particle of either rope."; }

  bool mouseDown(const Vec2f& p, MouseButton /*button*/) override {
    if (drag_.active()) {
      return true; // one particle at a time
    }
    for (std::size_t i = 0; i < 2; ++i) {
      const std::array<ParticleId, 1> pinned{ropes_[i].particles.front()};
      if (drag_.grab(*worlds_[i], p, 0.6f, pinned)) {
        dragged_ = i;
        return true;
      }
    }
    return false;
  }
  void mouseMove(const Vec2f& p) override { drag_.moveTo(p); }
  void mouseUp(const Vec2f& /*p*/, MouseButton /*button*/) override {
    if (drag_.active()) {
      drag_.release(*worlds_[dragged_]);
    }
  }

  void draw(DebugDraw& draw) override {
    for (std::size_t i = 0; i < 2; ++i) {
      std::vector<Vec2f> line;
      for (const ParticleId id : ropes_[i].particles) {
        const Vec3f p = worlds_[i]->position(id);
        line.push_back({p.x, p.y});
      }
      draw.polyline(line, palette::series[i]);
      drawParticles(*worlds_[i], draw, palette::series[i]);
      draw.cross({anchorX(i), 8.0f}, 14.0f, palette::staticBody);
      draw.text({anchorX(i) - 0.5f, 9.4f}, modelNames[i], palette::series[i]);
    }
  }

  void ui() override {
    bool changed = slider("segments", &segments_, 1, 40);
    changed |= slider("total mass", &mass_, 0.5f, 50.0f, "%.1f kg");
    changed |= slider("length", &length_, 1.0f, 12.0f, "%.1f m");
    changed |= slider("substeps", &substeps_, 1, 32);
    changed |= slider("XPBD compliance", &compliance_, 0.0f, 0.01f, "%.4f m/N");
    changed |= slider("springs k", &stiffness_, 10.0f, 5000.0f, "%.0f N/m", ImGuiSliderFlags_Logarithmic);
    changed |= slider("springs d", &damping_, 0.0f, 200.0f, "%.0f N s/m");
    if (changed) {
      setup();
    }
    const double m = static_cast<double>(mass_) / (segments_ + 1);
    const double h = 1.0 / 60.0 / substeps_;
    textWrapped("springs stable while h = %.4f s < sqrt(m/k) = %.4f s and < m/(2d) = %.4f s", h,
                std::sqrt(m / static_cast<double>(stiffness_)), damping_ > 0.0f ? m / (2.0 * damping_) : 1e9);
    for (std::size_t i = 0; i < 2; ++i) {
      ImGui::PushStyleColor(ImGuiCol_PlotLines,
                            ImVec4(palette::series[i].r, palette::series[i].g, palette::series[i].b, 1.0f));
      stretch_[i].plot(i == 0 ? "XPBD: stretch (%)" : "springs: stretch (%)", "%.2f %%", 45.0f);
      energy_[i].plot(i == 0 ? "XPBD: mechanical energy (J)" : "springs: mechanical energy (J)", "%.1f J", 45.0f);
      ImGui::PopStyleColor();
    }
  }

private:
  [[nodiscard]] float anchorX(std::size_t i) const { return i == 0 ? -length_ - 0.5f : 0.5f; }

  std::array<std::optional<ParticleWorld>, 2> worlds_;
  std::array<Rope, 2> ropes_;
  std::array<History, 2> stretch_;
  std::array<History, 2> energy_;
  ParticleDrag drag_;
  std::size_t dragged_ = 0;
  int segments_ = 9;    // the book's
  float mass_ = 10.0f;  // kg: the book's 10 particles of 1 kg
  float length_ = 6.0f; // m
  int substeps_ = 4;
  float compliance_ = 0.0f;   // m/N
  float stiffness_ = 1000.0f; // N/m, the book's
  float damping_ = 100.0f;    // N s/m, the book's
};

const SampleRegistrar registrar{"Book", "Rope",
                                "The book's rope (ch. 13) as XPBD constraints and as its spring-dampers, side "
                                "by side: stretch and energy; drag it with the mouse.",
                                [] { return std::make_unique<RopeSample>(); }};

} // namespace
} // namespace impetus::samples
