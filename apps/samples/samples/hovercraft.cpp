// Book/Hovercraft (ch. 9): the book's hovercraft on the 2D engine (vehicles/hovercraft.hpp): a
// 100 kg, 20 m x 10 m craft pushed by an aft propeller through its centre of mass, steered by two
// bow thrusters, and slowed by air drag acting at a centre of drag 5 m aft of the centre of mass.
// The drag's moment about the centre of mass turns the bow into the direction of travel
// (weathervaning), so turns are "soft": the craft keeps sliding along its old track for a while,
// since only air drag removes the sideways velocity (the sideslip plot). Keys as in the book: up
// and down change the thrust, right fires the port thruster (a right turn), left the starboard
// one. Without keys an autopilot slaloms. Plots: speed (m/s), thrust (N), sideslip (deg).
#include "rigid2d_sample.hpp"
#include "ui.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/vehicles/hovercraft.hpp>

#include <imgui.h>

#include <cmath>
#include <deque>
#include <optional>
#include <vector>

namespace impetus::samples {
namespace {

using vehicles::HovercraftControls;
using vehicles::HovercraftLoads;
using vehicles::HovercraftParams;

constexpr float toDegrees = 57.2957795f;

class HovercraftSample final : public Rigid2dSample {
public:
  void setup() override {
    rigid2d::WorldDef def;
    def.gravity = {}; // seen from above
    resetWorld(def);
    craft_.emplace(world(), params_, Vec2f{0.0f, 0.0f}, 0.0f, 5.0f);
    trail_.clear();
    trailClock_ = 0.0f;
    speed_.clear();
    thrust_.clear();
    sideslip_.clear();
  }

  [[nodiscard]] CameraView initialView() const override {
    return {craft_ ? world().position(craft_->body()) : Vec2f{}, 45.0f, 70.0f};
  }
  [[nodiscard]] std::string_view controls() const override {
    return "Up/Down: more/less thrust. Right: port thruster (turn right), Left: starboard (turn left). The camera "
           "follows the craft.";
  }

  void keys(const KeyState& keys) override {
    keyControls_ = {(keys.up ? 1 : 0) - (keys.down ? 1 : 0), keys.right, keys.left};
    keysHeld_ = keys.up || keys.down || keys.left || keys.right;
  }

protected:
  void beforeStep(float dt) override {
    HovercraftControls controls = keyControls_;
    if (!keysHeld_ && autopilot_) {
      // Straight for 8 s, then a slalom: 6 s right, 2 s straight, 6 s left, 2 s straight.
      const float t = time() - 8.0f;
      const float phase = std::fmod(std::max(t, 0.0f), 16.0f);
      controls = {1, t > 0.0f && phase<6.0f, t> 0.0f && phase >= 8.0f && phase < 14.0f};
    }
    controls_ = controls;
    loads_ = craft_->applyLoads(controls, dt);
  }

  void afterStep(float dt) override {
    const rigid2d::BodyId body = craft_->body();
    const Vec2f v = world().linearVelocity(body);
    speed_.push(length(v));
    thrust_.push(craft_->thrust());
    const float heading = world().angle(body);
    const float slip = length(v) > 0.05f ? std::remainder(heading - std::atan2(v.y, v.x), 2.0f * pi<float>) : 0.0f;
    sideslip_.push(slip * toDegrees);
    trailClock_ += dt;
    if (trailClock_ >= 0.25f) {
      trailClock_ = 0.0f;
      trail_.push_back(world().position(body));
      if (trail_.size() > 600) {
        trail_.pop_front();
      }
    }
  }

  void drawOverlay(DebugDraw& draw) override {
    const std::vector<Vec2f> trail(trail_.begin(), trail_.end());
    draw.polyline(trail, palette::trajectory.withAlpha(0.6f));
    const Transform2f xf = world().transform(craft_->body());
    std::vector<Vec2f> outline;
    for (const Vec2f& p : craft_->outline()) {
      outline.push_back(transformPoint(xf, p));
    }
    // The book's drawing order: bow-starboard corner, around the hull, the pointed bow last.
    const std::vector<Vec2f> hull{outline[0], outline[1], outline[2], outline[3], outline[4]};
    draw.polygon(hull, palette::awake);
    const HovercraftParams& p = craft_->params();
    const float scale = 1.5f; // m per N: the forces to scale
    const Vec2f stern = transformPoint(xf, Vec2f{-0.5f * p.length, 0.0f});
    draw.arrow(stern, stern - rotate(xf.q, Vec2f{craft_->thrust() * scale, 0.0f}), palette::warning);
    const Vec2f drag = transformPoint(xf, p.centreOfDrag);
    draw.arrow(drag, drag + loads_.dragForce * scale, palette::particle);
    if (controls_.portThruster) {
      const Vec2f at = transformPoint(xf, p.portThrusterPoint);
      draw.arrow(at, at + rotate(xf.q, Vec2f{0.0f, p.steeringForce * scale}), palette::reference);
    }
    if (controls_.starboardThruster) {
      const Vec2f at = transformPoint(xf, p.starboardThrusterPoint);
      draw.arrow(at, at - rotate(xf.q, Vec2f{0.0f, p.steeringForce * scale}), palette::reference);
    }
    draw.point(drag, 5.0f, palette::particle);
    draw.text(drag + rotate(xf.q, Vec2f{0.0f, -2.0f}), "CD", palette::particle);
  }

  void parameters() override {
    checkbox("autopilot slalom (without keys)", &autopilot_);
    bool rebuild = slider("max thrust", &params_.maxThrust, 1.0f, 50.0f, "%.1f N");
    rebuild |= slider("bow thrusters", &params_.steeringForce, 0.0f, 20.0f, "%.1f N");
    rebuild |= slider("drag coefficient", &params_.dragCoefficient, 0.1f, 5.0f, "%.2f");
    rebuild |= slider("centre of drag x", &params_.centreOfDrag.x, -10.0f, 5.0f, "%.1f m");
    if (rebuild) {
      setup();
    }
    textWrapped("drag aft of the centre of mass (x < 0) steadies the craft; ahead of it (x > 0) the "
                "craft spins round");
    speed_.plot("speed (m/s)", "%.2f m/s");
    thrust_.plot("propeller thrust (N)", "%.2f N", 45.0f, 0.0f, params_.maxThrust);
    sideslip_.plot("sideslip: heading minus track (deg)", "%.1f deg");
  }

private:
  vehicles::HovercraftParams params_;
  std::optional<vehicles::Hovercraft> craft_;
  HovercraftControls keyControls_;
  HovercraftControls controls_;
  HovercraftLoads loads_;
  bool keysHeld_ = false;
  bool autopilot_ = true;
  std::deque<Vec2f> trail_;
  float trailClock_ = 0.0f;
  History speed_;
  History thrust_;
  History sideslip_;
};

const SampleRegistrar registrar{"Book", "Hovercraft",
                                "The book's hovercraft (ch. 9): propeller, bow thrusters and drag aft of the "
                                "centre of mass; soft turns with sideslip. Arrow keys as in the book.",
                                [] { return std::make_unique<HovercraftSample>(); }};

} // namespace
} // namespace impetus::samples
