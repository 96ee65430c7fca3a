// Book/Hourglass (ch. 8 and 21): the book's suggestion of sand as particles in an hourglass on a
// phone, flowing when the phone is turned over (sensors/hourglass.hpp). The phone turns on the
// screen by the tilt slider, or a flip button turns it half a turn in a second (a scripted flip
// every few seconds by default); the accelerometer reads gravity in the phone's axes and the
// grains fall accordingly through the neck. Drawn: the phone, the glass and the grains turned
// with it, gravity's arrow. Plots: grains in each bulb (the bulbs named in the phone's frame).
#include "sample.hpp"

#include "plot.hpp"
#include "ui.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/sensors/hourglass.hpp>

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <optional>

namespace impetus::samples {
namespace {

using namespace impetus::sensors;

class HourglassSample final : public Sample {
public:
  void setup() override {
    HourglassSettings s;
    s.grainCount = grains_;
    s.neckWidth = neckMillimetres_ * 1e-3;
    s.wallFriction = wallFriction_;
    hourglass_.emplace(s, Bulb::top);
    tiltDeg_ = 0.0f;
    flipFrom_ = 0.0f;
    flipTime_ = -1.0;
    sinceFlip_ = 0.0;
    top_.clear();
    bottom_.clear();
  }

  void step(float dt) override {
    // A flip turns the phone by half a turn counter-clockwise in one second, smoothly.
    sinceFlip_ += dt;
    if (autoFlip_ && flipTime_ < 0.0 && sinceFlip_ > 4.0) {
      startFlip();
    }
    if (flipTime_ >= 0.0) {
      flipTime_ += dt;
      const double u = std::min(1.0, flipTime_);
      const double eased = 0.5 - 0.5 * std::cos(pi<double> * u);
      tiltDeg_ = static_cast<float>(std::remainder(flipFrom_ + 180.0 * eased, 360.0));
      if (u >= 1.0) {
        flipTime_ = -1.0;
      }
    }
    // The accelerometer's reading (iOS sign): gravity in the phone's axes, held upright in the
    // screen's plane and turned by the tilt.
    const double tilt = degToRad(static_cast<double>(tiltDeg_));
    reading_ = {std::sin(tilt), -std::cos(tilt), 0.0};
    hourglass_->step(reading_, dt);
    top_.push(static_cast<float>(hourglass_->grainsIn(Bulb::top)));
    bottom_.push(static_cast<float>(hourglass_->grainsIn(Bulb::bottom)));
  }

  [[nodiscard]] bool finite() const override {
    for (const Vec3f& p : hourglass_->positions()) {
      if (!isFinite(p)) {
        return false;
      }
    }
    return true;
  }

  [[nodiscard]] CameraView initialView() const override { return {{0.0f, 0.0f}, 0.09f, 0.09f}; }
  [[nodiscard]] std::string_view controls() const override { return "The tilt slider or Flip turns the phone."; }
  [[nodiscard]] std::string summary() const override {
    char text[160];
    std::snprintf(text, sizeof text, "tilt %.0f deg: %d grains in the top bulb, %d in the bottom (phone's frame)",
                  static_cast<double>(tiltDeg_), hourglass_->grainsIn(Bulb::top), hourglass_->grainsIn(Bulb::bottom));
    return text;
  }

  void draw(DebugDraw& draw) override {
    // The phone's frame turned by the tilt onto the screen: screen = R(tilt) device.
    const auto tilt = static_cast<float>(degToRad(static_cast<double>(tiltDeg_)));
    const float c = std::cos(tilt);
    const float s = std::sin(tilt);
    const auto turn = [&](float x, float y) { return Vec2f{c * x - s * y, s * x + c * y}; };
    const HourglassSettings& hs = hourglass_->settings();
    const auto hw = static_cast<float>(0.5 * hs.bulbWidth + 0.012);
    const auto hh = static_cast<float>(hs.bulbHeight + 0.012);
    const Vec2f phone[4] = {turn(-hw, -hh), turn(hw, -hh), turn(hw, hh), turn(-hw, hh)};
    draw.solidPolygon(phone, Color{0.06f, 0.07f, 0.10f, 1.0f}, palette::grid.scaled(2.5f));
    const auto& outline = hourglass_->outline();
    for (std::size_t i = 0; i < outline.size(); ++i) {
      const Vec2d& a = outline[i];
      const Vec2d& b = outline[(i + 1) % outline.size()];
      draw.segment(turn(static_cast<float>(a.x), static_cast<float>(a.y)),
                   turn(static_cast<float>(b.x), static_cast<float>(b.y)), palette::particle);
    }
    const auto positions = hourglass_->positions();
    const auto radii = hourglass_->radii();
    const Color sand{0.86f, 0.70f, 0.40f, 1.0f};
    for (std::size_t i = 0; i < positions.size(); ++i) {
      draw.solidCircle(turn(positions[i].x, positions[i].y), radii[i], 0.0f, sand, sand.scaled(0.7f));
    }
    // The phone's top edge, and gravity (always down on the screen).
    draw.text(turn(-0.01f, hh + 0.004f), "top", palette::text);
    draw.arrow({hw + 0.02f, 0.02f}, {hw + 0.02f, -0.02f}, palette::warning);
    char text[96];
    std::snprintf(text, sizeof text, "reading (%.2f, %.2f) g", reading_.x, reading_.y);
    draw.text({hw + 0.005f, -0.03f}, text, palette::text);
  }

  void ui() override {
    slider("tilt (0 upright, 180 over)", &tiltDeg_, -180.0f, 180.0f, "%.0f deg");
    if (ImGui::Button("Flip")) {
      startFlip();
    }
    ImGui::SameLine();
    checkbox("flip every 4 s", &autoFlip_);
    bool changed = slider("grains", &grains_, 50, 400);
    changed |= slider("neck (grains are 2 mm)", &neckMillimetres_, 3.0f, 14.0f, "%.1f mm");
    changed |= slider("glass friction", &wallFriction_, 0.0f, 1.0f, "%.2f");
    if (changed) {
      setup();
    }
    top_.plot("grains in the top bulb", "%.0f", 60.0f, 0.0f, static_cast<float>(grains_));
    bottom_.plot("grains in the bottom bulb", "%.0f", 60.0f, 0.0f, static_cast<float>(grains_));
    textWrapped("A granular flow through a neck does not depend on the sand's height above it (Beverloo), "
                "unlike a liquid's: the count falls at a steady rate until the last grains.");
  }

private:
  void startFlip() {
    flipFrom_ = tiltDeg_;
    flipTime_ = 0.0;
    sinceFlip_ = 0.0;
  }

  int grains_ = 300;
  float neckMillimetres_ = 8.0f;
  float wallFriction_ = 0.5f;
  float tiltDeg_ = 0.0f;
  float flipFrom_ = 0.0f;
  double flipTime_ = -1.0; ///< s into a flip, or < 0
  double sinceFlip_ = 0.0;
  bool autoFlip_ = true;
  Vec3d reading_{};
  std::optional<Hourglass> hourglass_;
  History top_, bottom_;
};

const SampleRegistrar registrar{"Book", "Hourglass",
                                "Sand in an hourglass on a phone (ch. 8 and 21): grains on the particle world fall "
                                "through the neck under the accelerometer's gravity; turn the phone over and it "
                                "flows back.",
                                [] { return std::make_unique<HourglassSample>(); }};

} // namespace
} // namespace impetus::samples
