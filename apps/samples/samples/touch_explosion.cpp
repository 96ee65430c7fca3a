// Book/Touch explosion (ch. 20): the book's touch-screen particle explosion driven by recorded
// touch input, with gestures. A 480 x 320 px phone screen (20 px/m: 24 x 16 m of world) plays a
// recorded six-second script of touches in a loop: taps, a two-finger pinch, a drag, a two-finger
// twist and three fingers at once. Every finger that touches down sets off the ch. 2 explosion
// where it touched (sensors/touch_explosion.hpp: a TouchTracker gives each finger a stable id, so
// a held or dragged finger explodes once; the book's multitouch version runs one explosion per
// touch). The same tracked touches feed a GestureRecognizer (sensors/gestures.hpp): a pinch's
// scale sets the strength of the bursts to come, a twist turns them into a cone in the twist's
// direction, a drag leaves its track. Click and drag with the mouse to touch the screen yourself
// (one more finger, through the same tracker). Plots: particles alive, the strength.
#include "sample.hpp"

#include "plot.hpp"
#include "ui.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/sensors/gestures.hpp>
#include <impetus/sensors/touch_explosion.hpp>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace impetus::samples {
namespace {

using namespace impetus::sensors;

constexpr double screenWidthPx = 480.0;
constexpr double screenHeightPx = 320.0;
constexpr double pixelsPerMetre = 20.0;
constexpr double scriptPeriod = 6.0; // s

/// The recorded script: the fingers down at time t (s, in [0, 6)), screen pixels, y down.
std::vector<Vec2d> scriptedTouches(double t) {
  const auto lerp1 = [](double a, double b, double f) { return a + (b - a) * std::clamp(f, 0.0, 1.0); };
  std::vector<Vec2d> p;
  if (t >= 0.2 && t < 0.3) { // tap
    p.push_back({120.0, 100.0});
  } else if (t >= 0.8 && t < 0.9) { // tap
    p.push_back({360.0, 220.0});
  } else if (t >= 1.4 && t < 2.0) { // two fingers spreading from 90 to 200 px: a pinch of 2.2 x
    const double f = (t - 1.4) / 0.5;
    p.push_back({lerp1(195.0, 140.0, f), 160.0});
    p.push_back({lerp1(285.0, 340.0, f), 160.0});
  } else if (t >= 2.4 && t < 3.3) { // a drag across the bottom
    p.push_back({lerp1(80.0, 400.0, (t - 2.4) / 0.8), 270.0});
  } else if (t >= 3.6 && t < 4.3) {                                // a twist: 90 degrees counter-clockwise on screen
    const double a = degToRad(lerp1(0.0, -90.0, (t - 3.6) / 0.6)); // screen y down: negative is CCW
    const Vec2d r{70.0 * std::cos(a), 70.0 * std::sin(a)};
    p.push_back(Vec2d{240.0, 160.0} - r);
    p.push_back(Vec2d{240.0, 160.0} + r);
  } else if (t >= 4.6 && t < 4.8) { // three fingers at once
    p.push_back({100.0, 80.0});
    p.push_back({240.0, 250.0});
    p.push_back({380.0, 80.0});
  }
  return p;
}

class TouchExplosionSample final : public Sample {
public:
  void setup() override {
    TouchExplosionSettings s;
    s.screen = {screenHeightPx, pixelsPerMetre};
    s.explosion.speed = baseSpeed_;
    s.explosion.life = life_;
    s.explosion.count = count_;
    s.explosion.seed = 20;
    s.multitouch = multitouch_;
    s.maxExplosions = 12;
    demo_.emplace(s);
    gestures_ = GestureRecognizer({0.3, 10.0, 0.05, degToRad(5.0)});
    strength_ = 1.0;
    direction_.reset();
    t_ = 0.0;
    mouse_.reset();
    log_.clear();
    trail_.clear();
    alive_.clear();
    strengthPlot_.clear();
  }

  void step(float dt) override {
    t_ += dt;
    std::vector<Vec2d> points = playing_ ? scriptedTouches(std::fmod(t_, scriptPeriod)) : std::vector<Vec2d>{};
    if (mouse_) {
      points.push_back(*mouse_);
    }
    demo_->update(t_, points);
    for (const GestureEvent& e : gestures_.update(t_, demo_->tracker().touches())) {
      react(e);
    }
    alive_.push(static_cast<float>(demo_->aliveParticles(t_)));
    strengthPlot_.push(static_cast<float>(strength_));
  }

  [[nodiscard]] bool finite() const override {
    for (const TouchBurst& b : demo_->bursts()) {
      for (std::size_t i = 0; i < b.explosion.particles().size(); ++i) {
        const ParticleSnapshot p = b.explosion.particleAt(i, std::max(0.0, t_ - b.start));
        if (!std::isfinite(p.position.x) || !std::isfinite(p.position.y)) {
          return false;
        }
      }
    }
    return std::isfinite(strength_);
  }

  [[nodiscard]] CameraView initialView() const override { return {{12.0f, 8.0f}, 10.0f, 14.0f}; }
  [[nodiscard]] std::string_view controls() const override {
    return "Click and drag on the screen to touch it (one more finger).";
  }
  [[nodiscard]] std::string summary() const override {
    char text[160];
    std::snprintf(text, sizeof text, "%zu bursts set off, %zu particles alive, strength x%.2f, %zu gestures",
                  demo_->burstCount(), demo_->aliveParticles(t_), strength_, gestureCount_);
    return text;
  }

  bool mouseDown(const Vec2f& p, MouseButton button) override {
    if (button != MouseButton::left) {
      return false;
    }
    mouse_ = toScreen(p);
    return true;
  }
  void mouseMove(const Vec2f& p) override {
    if (mouse_) {
      mouse_ = toScreen(p);
    }
  }
  void mouseUp(const Vec2f& /*p*/, MouseButton /*button*/) override { mouse_.reset(); }

  void draw(DebugDraw& draw) override {
    const auto w = [](const Vec2d& v) { return Vec2f{static_cast<float>(v.x), static_cast<float>(v.y)}; };
    // The phone's screen.
    const Vec2f upper{static_cast<float>(screenWidthPx / pixelsPerMetre),
                      static_cast<float>(screenHeightPx / pixelsPerMetre)};
    const Vec2f corners[4] = {{0.0f, 0.0f}, {upper.x, 0.0f}, upper, {0.0f, upper.y}};
    draw.solidPolygon(corners, Color{0.05f, 0.06f, 0.09f, 1.0f}, palette::grid.scaled(2.5f));
    draw.text({0.2f, upper.y + 1.2f}, "480 x 320 px touch screen (20 px/m); explosions where fingers touch down",
              palette::text);
    // Drag tracks.
    for (std::size_t i = 1; i < trail_.size(); ++i) {
      draw.segment(w(trail_[i - 1]), w(trail_[i]), palette::trajectory.withAlpha(0.6f));
    }
    // Particles, hot to cold as they fade.
    for (const TouchBurst& b : demo_->bursts()) {
      draw.cross(w(b.explosion.origin()), 8.0f, palette::reference.withAlpha(0.4f));
      for (std::size_t i = 0; i < b.explosion.particles().size(); ++i) {
        const ParticleSnapshot p = b.explosion.particleAt(i, std::max(0.0, t_ - b.start));
        if (p.alive) {
          const auto f = static_cast<float>(p.fade);
          draw.point(w(p.position), 5.0f, Color{1.0f, 0.3f + 0.7f * f, 0.1f + 0.6f * f * f, 0.25f + 0.75f * f});
        }
      }
    }
    // The fingers down now, with their ids.
    const ScreenToWorld map{screenHeightPx, pixelsPerMetre};
    for (const TrackedTouch& t : demo_->tracker().touches()) {
      if (t.phase == TouchPhase::ended) {
        continue;
      }
      const Vec2f c = w(map.toWorld(t.position));
      draw.solidCircle(c, 0.8f, 0.0f, palette::sensor.withAlpha(0.35f), palette::sensor);
      char id[16];
      std::snprintf(id, sizeof id, "%d", t.id);
      draw.text(c + Vec2f{0.9f, 0.9f}, id, palette::text);
    }
    if (direction_) {
      const Vec2f c{12.0f, 8.0f};
      draw.arrow(
          c,
          c + Vec2f{3.0f * static_cast<float>(std::cos(*direction_)), 3.0f * static_cast<float>(std::sin(*direction_))},
          palette::warning.withAlpha(0.6f));
    }
  }

  void ui() override {
    bool changed = slider("base strength (max speed)", &baseSpeed_, 2.0f, 30.0f, "%.1f m/s");
    changed |= slider("duration (max life)", &life_, 0.3f, 4.0f, "%.2f s");
    changed |= slider("particles per burst", &count_, 5, 400);
    changed |= checkbox("multitouch (one burst per finger)", &multitouch_);
    checkbox("play the recorded script", &playing_);
    if (changed) {
      setup();
    }
    textWrapped("Pinch: strength x%.2f. Twist: %s.", strength_,
                direction_ ? "a cone along the arrow" : "none yet (all around)");
    textWrapped("%zu bursts so far; %zu fingers down", demo_->burstCount(), demo_->tracker().activeCount());
    for (const std::string& line : log_) {
      ImGui::TextUnformatted(line.c_str());
    }
    alive_.plot("particles alive", "%.0f");
    strengthPlot_.plot("strength (pinch scale)", "x%.2f");
  }

private:
  [[nodiscard]] static Vec2d toScreen(const Vec2f& world) {
    return ScreenToWorld{screenHeightPx, pixelsPerMetre}.toScreen({world.x, world.y});
  }

  void react(const GestureEvent& e) {
    const ScreenToWorld map{screenHeightPx, pixelsPerMetre};
    if (e.phase != GesturePhase::changed) {
      ++gestureCount_;
      char line[96];
      std::snprintf(line, sizeof line, "t %.2f s: %s %s", t_, gestureKindName(e.kind), gesturePhaseName(e.phase));
      log_.push_back(line);
      if (log_.size() > 6) {
        log_.pop_front();
      }
    }
    switch (e.kind) {
    case GestureKind::pinch:
      if (e.phase == GesturePhase::ended) {
        strength_ = std::clamp(e.scale, 0.25, 4.0);
        applyExplosion();
      }
      break;
    case GestureKind::rotate:
      if (e.phase == GesturePhase::ended) {
        // Screen y points down: a twist of -90 degrees on screen is +90 degrees in the world.
        direction_ = degToRad(90.0) - e.rotation;
        applyExplosion();
      }
      break;
    case GestureKind::drag:
      if (e.phase == GesturePhase::began) {
        trail_.clear();
      }
      trail_.push_back(map.toWorld(e.position));
      break;
    case GestureKind::tap:
      break;
    }
  }

  void applyExplosion() {
    ExplosionSettings s = demo_->settings().explosion;
    s.speed = static_cast<double>(baseSpeed_) * strength_;
    s.direction = direction_;
    s.spread = degToRad(25.0);
    demo_->setExplosion(s);
  }

  float baseSpeed_ = 10.0f;
  float life_ = 1.5f;
  int count_ = 100;
  bool multitouch_ = true;
  bool playing_ = true;
  std::optional<TouchExplosions> demo_;
  GestureRecognizer gestures_;
  double strength_ = 1.0;
  std::optional<double> direction_;
  double t_ = 0.0;
  std::optional<Vec2d> mouse_;
  std::deque<std::string> log_;
  std::vector<Vec2d> trail_;
  std::size_t gestureCount_ = 0;
  History alive_;
  History strengthPlot_;
};

const SampleRegistrar registrar{"Book", "Touch explosion",
                                "The book's touch-screen explosion (ch. 20) on recorded multitouch input: one "
                                "burst per finger, pinch for strength, twist for direction; click to touch.",
                                [] { return std::make_unique<TouchExplosionSample>(); }};

} // namespace
} // namespace impetus::samples
