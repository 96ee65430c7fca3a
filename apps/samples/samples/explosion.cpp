// Book/Explosion (ch. 2): the book's kinematic particle explosion. Each particle flies out of a
// point on the closed-form trajectory x = v cos(theta) t, y = v sin(theta) t + g t^2 / 2, with a
// speed in [v/2, v] and a life in [0.8, 1] x the set life, fading as it ages
// (mechanics/explosion.hpp). Positions are evaluated at the time asked for, so the effect runs at
// the same speed at any frame rate; a seed makes every explosion reproducible. The setup is
// `impetus demo explosion`'s; a burst goes off every 1.2 s near it, and a click sets one off there.
// Plots: particles alive, and the spread (the farthest particle from the origin, m).
#include "sample.hpp"

#include "plot.hpp"
#include "ui.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/mechanics/explosion.hpp>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>

namespace impetus::samples {
namespace {

/// `impetus demo explosion`'s: 20 m up, up to 15 m/s, up to 2 s of life.
ExplosionSettings demoSettings() {
  ExplosionSettings s;
  s.origin = {0.0, 20.0};
  s.speed = 15.0;
  s.life = 2.0;
  return s;
}

class Explosion final : public Sample {
public:
  void setup() override {
    settings_.seed = seed_;
    bursts_.clear();
    t_ = 0.0;
    nextBurst_ = 0.0;
    nextOrigin_ = 0;
  }

  void step(float dt) override {
    t_ += dt;
    // A new burst every `interval_` seconds, at one of a few fixed points around the set origin
    // (fireworks); each lives until its last particle dies.
    if (t_ >= nextBurst_) {
      static constexpr double offsets[][2] = {{0.0, 0.0}, {-9.0, -4.0}, {8.0, -2.0}, {-4.0, 5.0}, {5.0, 6.0}};
      ExplosionSettings s = settings_;
      s.origin += Vec2d{offsets[nextOrigin_ % 5][0], offsets[nextOrigin_ % 5][1]};
      ++nextOrigin_;
      ++settings_.seed; // each burst differs, and the sequence is the same every run
      bursts_.push_back({KinematicExplosion(s), t_});
      nextBurst_ = t_ + static_cast<double>(interval_);
    }
    while (!bursts_.empty() && t_ - bursts_.front().start > bursts_.front().explosion.endTime()) {
      bursts_.pop_front();
    }
    std::size_t alive = 0;
    double spread = 0.0;
    for (const Burst& b : bursts_) {
      alive += b.explosion.aliveCount(t_ - b.start);
    }
    if (!bursts_.empty()) {
      const Burst& newest = bursts_.back();
      for (std::size_t i = 0; i < newest.explosion.particles().size(); ++i) {
        const ParticleSnapshot p = newest.explosion.particleAt(i, t_ - newest.start);
        if (p.alive) {
          spread = std::max(spread, distance(p.position, newest.explosion.origin()));
        }
      }
    }
    alive_.push(static_cast<float>(alive));
    spread_.push(static_cast<float>(spread));
  }

  [[nodiscard]] bool finite() const override {
    for (const Burst& b : bursts_) {
      for (std::size_t i = 0; i < b.explosion.particles().size(); ++i) {
        const ParticleSnapshot p = b.explosion.particleAt(i, t_ - b.start);
        if (!std::isfinite(p.position.x) || !std::isfinite(p.position.y) || !std::isfinite(p.fade)) {
          return false;
        }
      }
    }
    return true;
  }

  [[nodiscard]] CameraView initialView() const override { return {{0.0f, 15.0f}, 16.0f, 22.0f}; }
  [[nodiscard]] std::string_view controls() const override { return "Click to set off a burst there."; }

  bool mouseDown(const Vec2f& p, MouseButton /*button*/) override {
    ExplosionSettings s = settings_;
    s.origin = {p.x, p.y};
    ++settings_.seed;
    bursts_.push_back({KinematicExplosion(s), t_});
    return true;
  }

  void draw(DebugDraw& draw) override {
    draw.segment({-40.0f, 0.0f}, {40.0f, 0.0f}, palette::staticBody);
    for (const Burst& b : bursts_) {
      const Vec2d o = b.explosion.origin();
      draw.cross({static_cast<float>(o.x), static_cast<float>(o.y)}, 10.0f, palette::reference.withAlpha(0.5f));
      for (std::size_t i = 0; i < b.explosion.particles().size(); ++i) {
        const ParticleSnapshot p = b.explosion.particleAt(i, t_ - b.start);
        if (p.alive) {
          // Hot to cold as the particle fades: yellow-white to red, then transparent.
          const auto f = static_cast<float>(p.fade);
          const Color c{1.0f, 0.3f + 0.7f * f, 0.1f + 0.6f * f * f, 0.25f + 0.75f * f};
          draw.point({static_cast<float>(p.position.x), static_cast<float>(p.position.y)}, 6.0f, c);
        }
      }
    }
  }

  void ui() override {
    float speed = static_cast<float>(settings_.speed);
    float life = static_cast<float>(settings_.life);
    float gravity = static_cast<float>(settings_.gravity);
    bool changed = slider("strength (max speed)", &speed, 1.0f, 50.0f, "%.1f m/s");
    changed |= slider("duration (max life)", &life, 0.2f, 6.0f, "%.2f s");
    changed |= slider("vertical acceleration", &gravity, -20.0f, 5.0f, "%.2f m/s^2");
    changed |= slider("particles", &settings_.count, 1, 2000, "%d", ImGuiSliderFlags_Logarithmic);
    changed |= checkbox("a cone instead of all around", &cone_);
    if (cone_) {
      changed |= slider("direction", &directionDeg_, -180.0f, 180.0f, "%.0f deg");
      changed |= slider("half-width", &spreadDeg_, 1.0f, 90.0f, "%.0f deg");
    }
    slider("a burst every", &interval_, 0.2f, 5.0f, "%.1f s");
    if (changed) {
      settings_.speed = speed;
      settings_.life = life;
      settings_.gravity = gravity;
      settings_.direction = cone_ ? std::optional<double>(degToRad(static_cast<double>(directionDeg_))) : std::nullopt;
      settings_.spread = degToRad(static_cast<double>(spreadDeg_));
    }
    textWrapped("%zu bursts alive, t = %.2f s", bursts_.size(), t_);
    alive_.plot("particles alive", "%.0f");
    spread_.plot("spread of the newest burst: farthest particle from its origin (m)", "%.2f m");
  }

private:
  struct Burst {
    KinematicExplosion explosion;
    double start = 0.0; ///< s
  };

  ExplosionSettings settings_ = demoSettings();
  std::uint32_t seed_ = 2024;
  bool cone_ = false;
  float directionDeg_ = 90.0f;
  float spreadDeg_ = 10.0f;
  float interval_ = 1.2f; // s
  std::deque<Burst> bursts_;
  double t_ = 0.0;
  double nextBurst_ = 0.0;
  std::size_t nextOrigin_ = 0;
  History alive_;
  History spread_;
};

const SampleRegistrar registrar{"Book", "Explosion",
                                "The book's kinematic particle explosion (ch. 2): closed-form trajectories that "
                                "fade with age, the same at any frame rate; click to explode.",
                                [] { return std::make_unique<Explosion>(); }};

} // namespace
} // namespace impetus::samples
