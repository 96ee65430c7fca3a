// Book/Tilt sprite (ch. 21): the book's tilt-controlled sprite with a simulated accelerometer.
// A phone 0.5 x 0.75 m of world (the book's kWorldWidth/Height idea) is tilted by a slow scripted
// wobble (or the arrow keys); the accelerometer reads gravity in the phone's axes in the book's
// iOS convention (sensors/tilt.hpp: gravityReading), plus the sensor's noise, clipped at its
// +-2.3 g range, and a first-order low-pass filter with its cut-off in Hz takes the noise out
// (sensors/sensor_filters.hpp). Sixty readings a second drive the sprite (sensors/tilt_sprite.hpp):
// the book's constant-acceleration step with the measured interval, plus the friction, drag and
// bouncing edges the book suggests. Drawn: the screen, the sprite and its velocity, its track, and
// a bubble level showing the filtered tilt. Plots: the raw and filtered x reading, the speed.
#include "sample.hpp"

#include "plot.hpp"
#include "ui.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/sensors/accelerometer.hpp>
#include <impetus/sensors/sensor_filters.hpp>
#include <impetus/sensors/tilt.hpp>
#include <impetus/sensors/tilt_sprite.hpp>

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <deque>
#include <optional>
#include <random>

namespace impetus::samples {
namespace {

using namespace impetus::sensors;

class TiltSpriteSample final : public Sample {
public:
  void setup() override {
    TiltSpriteSettings s;
    s.staticFriction = staticFriction_;
    s.kineticFriction = std::min(kineticFriction_, staticFriction_);
    s.drag = drag_;
    s.restitution = restitution_;
    sprite_.emplace(s);
    filterX_.emplace(cutoffHz_, 60.0);
    filterY_.emplace(cutoffHz_, 60.0);
    filterZ_.emplace(cutoffHz_, 60.0);
    rng_.seed(5);
    t_ = 0.0;
    manual_ = {};
    track_.clear();
    raw_.clear();
    filtered_.clear();
    speed_.clear();
  }

  void keys(const KeyState& k) override {
    keyPitch_ = (k.right ? 1.0 : 0.0) - (k.left ? 1.0 : 0.0);
    keyRoll_ = (k.down ? 1.0 : 0.0) - (k.up ? 1.0 : 0.0); // up: top edge down, the ball rolls up
  }

  void step(float dt) override {
    t_ += dt;
    // The phone's attitude: arrows tilt it by hand; otherwise a slow figure of eight.
    if (keyPitch_ != 0.0 || keyRoll_ != 0.0) {
      manual_.pitch = std::clamp(manual_.pitch + keyPitch_ * 0.6 * dt, -0.6, 0.6);
      manual_.roll = std::clamp(manual_.roll + keyRoll_ * 0.6 * dt, -0.6, 0.6);
      attitude_ = manual_;
    } else if (autoTilt_) {
      attitude_.pitch = 0.25 * std::sin(0.9 * t_);
      attitude_.roll = 0.18 * std::sin(1.7 * t_ + 0.4);
      manual_ = attitude_;
    }
    // The accelerometer: gravity in the phone's axes (iOS sign), noise, clipping at +-2.3 g.
    const Vec3d truth = gravityReading(attitude_, AccelConvention::gravityDirection);
    std::normal_distribution<double> noise(0.0, static_cast<double>(noise_));
    const Vec3d raw{clipReading(truth.x + noise(rng_), 2.3), clipReading(truth.y + noise(rng_), 2.3),
                    clipReading(truth.z + noise(rng_), 2.3)};
    const Vec3d reading =
        filter_ ? Vec3d{filterX_->update(raw.x, dt), filterY_->update(raw.y, dt), filterZ_->update(raw.z, dt)} : raw;
    reading_ = reading;
    sprite_->step(reading, dt);
    const Vec2d c = sprite_->position() + sprite_->settings().spriteSize * 0.5;
    if (track_.empty() || distance(track_.back(), c) > 0.004) {
      track_.push_back(c);
      if (track_.size() > 400) {
        track_.pop_front();
      }
    }
    raw_.push(static_cast<float>(raw.x));
    filtered_.push(static_cast<float>(reading.x));
    speed_.push(static_cast<float>(length(sprite_->velocity())));
  }

  [[nodiscard]] bool finite() const override {
    return isFinite(sprite_->position()) && isFinite(sprite_->velocity()) && isFinite(reading_);
  }

  [[nodiscard]] CameraView initialView() const override { return {{0.45f, 0.375f}, 0.45f, 0.75f}; }
  [[nodiscard]] std::string_view controls() const override { return "Arrow keys tilt the phone by hand."; }
  [[nodiscard]] std::string summary() const override {
    char text[160];
    std::snprintf(text, sizeof text, "sprite at (%.3f, %.3f) m, %.3f m/s, %d edge hits; tilt pitch %.1f roll %.1f deg",
                  sprite_->position().x, sprite_->position().y, length(sprite_->velocity()), sprite_->edgeHits(),
                  radToDeg(attitude_.pitch), radToDeg(attitude_.roll));
    return text;
  }

  void draw(DebugDraw& draw) override {
    const auto f = [](const Vec2d& v) { return Vec2f{static_cast<float>(v.x), static_cast<float>(v.y)}; };
    const TiltSpriteSettings& s = sprite_->settings();
    const Vec2f world = f(s.worldSize);
    const Vec2f screen[4] = {{0.0f, 0.0f}, {world.x, 0.0f}, world, {0.0f, world.y}};
    draw.solidPolygon(screen, Color{0.06f, 0.07f, 0.10f, 1.0f}, palette::grid.scaled(2.5f));
    draw.text({0.0f, world.y + 0.05f}, "the phone's screen, 0.5 x 0.75 m of world", palette::text);
    for (std::size_t i = 1; i < track_.size(); ++i) {
      const float a = 0.15f + 0.6f * static_cast<float>(i) / static_cast<float>(track_.size());
      draw.segment(f(track_[i - 1]), f(track_[i]), palette::trajectory.withAlpha(a));
    }
    const Vec2f lo = f(sprite_->position());
    const Vec2f hi = lo + f(s.spriteSize);
    const Vec2f box[4] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
    draw.solidPolygon(box, palette::awake.withAlpha(0.8f), palette::awake);
    const Vec2f centre = (lo + hi) * 0.5f;
    draw.arrow(centre, centre + f(sprite_->velocity()) * 0.3f, palette::warning);
    // A bubble level to the right: the filtered reading's in-plane part (where the ball rolls).
    const Vec2f level{0.78f, 0.55f};
    draw.circle(level, 0.12f, palette::grid.scaled(3.0f));
    draw.cross(level, 10.0f, palette::grid.scaled(3.0f));
    const Vec2f pull{static_cast<float>(reading_.x), static_cast<float>(reading_.y)};
    draw.solidCircle(level + pull * 0.25f, 0.02f, 0.0f, palette::sensor, palette::sensor);
    char text[96];
    std::snprintf(text, sizeof text, "reading (%.2f, %.2f, %.2f) g", reading_.x, reading_.y, reading_.z);
    draw.text({0.6f, 0.38f}, text, palette::text);
    std::snprintf(text, sizeof text, "pitch %.1f, roll %.1f deg", radToDeg(attitude_.pitch), radToDeg(attitude_.roll));
    draw.text({0.6f, 0.33f}, text, palette::text);
  }

  void ui() override {
    bool changed = slider("static friction mu_s", &staticFriction_, 0.0f, 0.5f, "%.2f");
    changed |= slider("kinetic friction mu_k (<= mu_s)", &kineticFriction_, 0.0f, 0.5f, "%.2f");
    changed |= slider("drag", &drag_, 0.0f, 3.0f, "%.2f 1/s");
    changed |= slider("edge restitution (0: the book)", &restitution_, 0.0f, 1.0f, "%.2f");
    changed |= slider("low-pass cut-off (samples at 60 Hz)", &cutoffHz_, 0.2f, 25.0f, "%.1f Hz");
    slider("sensor noise", &noise_, 0.0f, 0.3f, "%.2f g rms");
    checkbox("low-pass filter", &filter_);
    ImGui::SameLine();
    checkbox("scripted tilt", &autoTilt_);
    if (changed) {
      setup();
    }
    textWrapped("%d edge hits", sprite_->edgeHits());
    raw_.plot("raw x reading (g)", "%.3f g");
    filtered_.plot("x reading the sprite uses (g)", "%.3f g");
    speed_.plot("sprite speed (m/s)", "%.3f m/s");
  }

private:
  float staticFriction_ = 0.05f;
  float kineticFriction_ = 0.03f;
  float drag_ = 0.2f;
  float restitution_ = 0.4f;
  float cutoffHz_ = 3.0f;
  float noise_ = 0.08f;
  bool filter_ = true;
  bool autoTilt_ = true;
  std::optional<TiltSprite> sprite_;
  std::optional<LowPassFilter> filterX_, filterY_, filterZ_;
  std::mt19937 rng_{5};
  double t_ = 0.0;
  double keyPitch_ = 0.0, keyRoll_ = 0.0;
  Tilt attitude_{};
  Tilt manual_{};
  Vec3d reading_{};
  std::deque<Vec2d> track_;
  History raw_, filtered_, speed_;
};

const SampleRegistrar registrar{"Book", "Tilt sprite",
                                "The book's tilt-controlled sprite (ch. 21): a simulated noisy accelerometer, "
                                "low-pass filtered, moves a ball with friction, drag and bouncing screen edges.",
                                [] { return std::make_unique<TiltSpriteSample>(); }};

} // namespace
} // namespace impetus::samples
