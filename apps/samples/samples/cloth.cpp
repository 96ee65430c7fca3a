// Book/Cloth (ch. 13, the 1st edition's flag): a rows x columns grid of particles joined by
// structural, shear and bend connections (particles/cloth.hpp), pinned along its left edge to a
// pole, in a gusting wind. The cloth catches the wind through the world's quadratic drag on each
// particle's velocity relative to the air (F = -1/2 rho Cd pi r^2 |v - w| (v - w)): a strong wind
// streams the flag out, a weak one lets gravity fold it down along the pole. The wind has a small
// cross component travelling along the flag (0.25 of its speed, a wave of 2 rad/m at 6 rad/s), which
// starts the flutter; the flag starts turned 46 degrees about the pole, so the wind swings it
// round at once. The cloth is 3D: it is drawn in an oblique view (x + 0.5 z, y + 0.35 z) so
// its folds show. XPBD constraints by default (rigid structural edges, soft shear and bend), or
// the book's spring-dampers. Plots: the largest stretch of a structural edge (%), the free bottom
// corner's height (m) and the kinetic energy (J). Drag it with the mouse.
#include "sample.hpp"

#include "particle_drag.hpp"
#include "particle_draw.hpp"
#include "plot.hpp"
#include "ui.hpp"

#include <impetus/particles/cloth.hpp>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace impetus::samples {
namespace {

class ClothSample final : public Sample {
public:
  void setup() override {
    world_.emplace(settings());
    ClothDef def;
    def.origin = {0.0f, 8.0f, 0.0f};
    // Turned about the pole, out of the wind's line: the wind swings it round from the first
    // step, and the folds show at once (a flag in the plane of the wind and gravity stays flat
    // until something breaks the symmetry).
    def.across = {width_ * std::cos(startTurn), 0.0f, width_ * std::sin(startTurn)};
    def.down = {0.0f, -height_, 0.0f};
    def.rows = rows_;
    def.columns = columns_;
    def.totalMass = mass_;
    def.particleRadius = 0.5f * width_ / static_cast<float>(columns_ - 1); // areas roughly tile the flag
    def.model = springs_ ? ClothModel::bookSprings : ClothModel::xpbd;
    for (int r = 0; r < rows_; ++r) {
      def.pinned.push_back({r, 0}); // the pole
    }
    cloth_ = createCloth(*world_, def);
    start_.assign(world_->positions().begin(), world_->positions().end());
    travel_ = 0.0f;
    restX_ = width_ / static_cast<float>(columns_ - 1);
    restY_ = height_ / static_cast<float>(rows_ - 1);
    stretch_.clear();
    corner_.clear();
    energy_.clear();
    drag_.reset();
  }

  void step(float dt) override {
    drag_.apply(*world_);
    world_->step(dt);
    for (std::size_t i = 0; i < start_.size(); ++i) {
      travel_ = std::max(travel_, length(world_->positions()[i] - start_[i]));
    }
    stretch_.push(100.0f * largestStretch());
    corner_.push(world_->position(cloth_.at(rows_ - 1, columns_ - 1)).y);
    energy_.push(static_cast<float>(world_->kineticEnergy()));
  }

  [[nodiscard]] bool finite() const override {
    return std::ranges::all_of(world_->positions(), [](const Vec3f& p) {
      return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    });
  }

  [[nodiscard]] std::string summary() const override {
    char text[96];
    std::snprintf(text, sizeof text, "largest travel of a particle from its start %.2f m",
                  static_cast<double>(travel_));
    return text;
  }

  [[nodiscard]] CameraView initialView() const override {
    return {{0.5f * width_, 8.0f - 0.5f * height_ - 1.0f}, 0.5f * height_ + 4.0f, 0.6f * width_ + 1.0f};
  }
  [[nodiscard]] std::string_view controls() const override { return "Left-drag the cloth."; }

  bool mouseDown(const Vec2f& p, MouseButton /*button*/) override {
    if (drag_.active()) {
      return true; // one particle at a time
    }
    std::vector<ParticleId> pinned;
    pinned.reserve(static_cast<std::size_t>(rows_));
    for (int r = 0; r < rows_; ++r) {
      pinned.push_back(cloth_.at(r, 0));
    }
    return drag_.grab(*world_, p, 0.5f, pinned);
  }
  void mouseMove(const Vec2f& p) override { drag_.moveTo(p); }
  void mouseUp(const Vec2f& /*p*/, MouseButton /*button*/) override { drag_.release(*world_); }

  void draw(DebugDraw& draw) override {
    draw.segment({0.0f, -4.0f}, {0.0f, 8.5f}, palette::staticBody); // the pole
    draw.segment({-2.0f, -4.0f}, {width_ + 4.0f, -4.0f}, palette::staticBody);
    const auto at = [&](int r, int c) { return project(world_->position(cloth_.at(r, c))); };
    // Filled cells, then the structural edges coloured by stretch (blue slack to red stretched).
    for (int r = 0; r + 1 < rows_; ++r) {
      for (int c = 0; c + 1 < columns_; ++c) {
        const Color fill = ((r + c) % 2 == 0 ? palette::series[2] : palette::series[0]).withAlpha(0.25f);
        draw.triangle(at(r, c), at(r, c + 1), at(r + 1, c + 1), fill);
        draw.triangle(at(r, c), at(r + 1, c + 1), at(r + 1, c), fill);
      }
    }
    const auto edge = [&](int r0, int c0, int r1, int c1, float rest) {
      const float s = distance(at(r0, c0), at(r1, c1)) / rest - 1.0f;
      const float t = std::clamp(s * 20.0f, -1.0f, 1.0f); // +-5 % is full colour
      const Color c = t > 0.0f ? Color{0.6f + 0.4f * t, 0.6f - 0.3f * t, 0.6f - 0.4f * t, 1.0f}
                               : Color{0.6f + 0.3f * t, 0.6f, 0.6f - 0.4f * t, 1.0f};
      draw.segment(at(r0, c0), at(r1, c1), c);
    };
    for (int r = 0; r < rows_; ++r) {
      for (int c = 0; c < columns_; ++c) {
        if (c + 1 < columns_) {
          edge(r, c, r, c + 1, restX_);
        }
        if (r + 1 < rows_) {
          edge(r, c, r + 1, c, restY_);
        }
      }
    }
    draw.arrow({width_ + 1.0f, 9.0f}, {width_ + 1.0f + 0.25f * gust(world_->time()), 9.0f}, palette::particle);
    draw.text({width_ + 1.0f, 10.0f}, "wind", palette::particle);
  }

  void ui() override {
    bool live = slider("wind", &wind_, 0.0f, 30.0f, "%.1f m/s");
    live |= slider("gusts, share of the wind", &gusts_, 0.0f, 1.0f, "+-%.2f");
    live |= slider("drag coefficient Cd", &cd_, 0.0f, 3.0f, "%.2f");
    if (live) {
      world_->setSettings(settings());
    }
    bool rebuild = checkbox("the book's springs (not XPBD)", &springs_);
    rebuild |= slider("rows", &rows_, 3, 30);
    rebuild |= slider("columns", &columns_, 3, 40);
    rebuild |= slider("mass", &mass_, 0.05f, 5.0f, "%.2f kg");
    rebuild |= slider("substeps", &substeps_, 1, 32);
    if (rebuild) {
      setup();
    }
    stretch_.plot("largest structural stretch (%)", "%.2f %%", 50.0f);
    corner_.plot("free bottom corner's height (m)", "%.2f m", 50.0f);
    energy_.plot("kinetic energy (J)", "%.3f J", 50.0f);
  }

private:
  static constexpr float startTurn = 0.8f; ///< rad about the pole at the start (46 degrees)

  /// The oblique view: depth (z) shifts a point right and up.
  static Vec2f project(const Vec3f& p) { return {p.x + 0.5f * p.z, p.y + 0.35f * p.z}; }

  /// The wind speed along +x at time t: gusting about the set speed.
  [[nodiscard]] float gust(float t) const {
    return wind_ * (1.0f + gusts_ * (0.6f * std::sin(1.3f * t) + 0.4f * std::sin(3.1f * t + 1.0f)));
  }

  [[nodiscard]] ParticleWorldSettings settings() const {
    ParticleWorldSettings s;
    s.substeps = substeps_;
    s.dragCoefficient = cd_;
    // A gusting wind, with a small cross wave travelling down the flag that starts the flutter.
    s.windField = [this](const Vec3f& p, float t) {
      const float w = gust(t - 0.15f * p.x);
      return Vec3f{w, 0.0f, 0.25f * w * std::sin(2.0f * p.x - 6.0f * t)};
    };
    return s;
  }

  [[nodiscard]] float largestStretch() const {
    float largest = 0.0f;
    for (int r = 0; r < rows_; ++r) {
      for (int c = 0; c + 1 < columns_; ++c) {
        const Vec3f a = world_->position(cloth_.at(r, c));
        const Vec3f b = world_->position(cloth_.at(r, c + 1));
        largest = std::max(largest, length(b - a) / restX_ - 1.0f);
      }
    }
    return largest;
  }

  std::optional<ParticleWorld> world_;
  Cloth cloth_;
  ParticleDrag drag_;
  float width_ = 6.0f;  // m
  float height_ = 4.0f; // m
  int rows_ = 12;
  int columns_ = 18;
  float mass_ = 2.0f; // kg
  float wind_ = 3.0f; // m/s
  float gusts_ = 0.5f;
  float cd_ = 0.5f;
  int substeps_ = 8;
  bool springs_ = false;
  float restX_ = 1.0f;
  float restY_ = 1.0f;
  std::vector<Vec3f> start_; ///< m: every particle where setup() put it
  float travel_ = 0.0f;      ///< m: the farthest any particle got from its start
  History stretch_;
  History corner_;
  History energy_;
};

const SampleRegistrar registrar{"Book", "Cloth",
                                "The flag (ch. 13): a grid of particles with structural, shear and bend "
                                "constraints, pinned to a pole, folding and fluttering in a gusting wind.",
                                [] { return std::make_unique<ClothSample>(); }};

} // namespace
} // namespace impetus::samples
