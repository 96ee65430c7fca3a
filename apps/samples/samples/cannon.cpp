// Book/Cannon (ch. 2): the book's cannon program. A shell leaves a barrel of length L, pivoted Yb
// above the ground, at the muzzle speed Vm, the barrel at alpha from the vertical and gamma in the
// ground plane from +x toward +z, and flies in vacuum at a target box (mechanics/cannon.hpp: the
// shell's closed-form flight, tested against the target along each chord so a fast shell cannot
// skip through it, and the ground impact found by root-finding). The gun and target are the
// `impetus demo cannon` ones.
//
// The view shows the flight from the side (x, y) and from above (x, z, below the ground line).
// Plots: the shell's height over the shot; and the range against alpha, fired to the ground by the
// library, with its difference from the closed form of ch. 6 (table 6-3: vacuumFlight from the
// muzzle's height, R = v0 cos(phi) T, plus the barrel's reach L sin(alpha)): they agree to
// rounding.
#include "sample.hpp"

#include "plot.hpp"
#include "ui.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/mechanics/aiming.hpp>
#include <impetus/mechanics/cannon.hpp>
#include <impetus/mechanics/projectile.hpp>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace impetus::samples {
namespace {

constexpr double gravity = 9.81; // m/s^2, the book's ch. 2 value
constexpr float planY = -100.0f; // the plan view (x, z) is drawn at y = planY + z
constexpr double holdTime = 1.5; // s the outcome stays on screen before the next shot

Vec2f side(const Vec3d& p) { return {static_cast<float>(p.x), static_cast<float>(p.y)}; }
Vec2f plan(const Vec3d& p) { return {static_cast<float>(p.x), planY + static_cast<float>(p.z)}; }

class Cannon final : public Sample {
public:
  void setup() override {
    fire();
    rangeKey_.clear();
  }

  void step(float dt) override {
    t_ += dt;
    if (t_ <= result_.time) {
      height_.push(static_cast<float>(flight_->at(t_).position.y));
    } else if (autoFire_ && t_ > result_.time + holdTime) {
      fire();
    }
  }

  [[nodiscard]] bool finite() const override {
    const ShellState s = flight_->at(std::min(t_, result_.time));
    return std::isfinite(s.position.x) && std::isfinite(s.position.y) && std::isfinite(s.position.z) &&
           std::isfinite(s.velocity.x) && std::isfinite(s.velocity.y) && std::isfinite(s.velocity.z);
  }

  [[nodiscard]] CameraView initialView() const override { return {{260.0f, 10.0f}, 130.0f, 290.0f}; }

  void draw(DebugDraw& draw) override {
    // Ground lines of both views, the target and the gun.
    draw.segment({-30.0f, 0.0f}, {600.0f, 0.0f}, palette::staticBody);
    draw.segment({-30.0f, planY}, {600.0f, planY}, palette::grid.scaled(2.0f));
    draw.text({0.0f, -3.0f}, "side view (x, y)", palette::text);
    draw.text({0.0f, planY - 3.0f}, "from above (x, z)", palette::text);
    const Vec3d half = target_.size * 0.5;
    const Color targetColor =
        result_.outcome == ShotOutcome::hit && t_ >= result_.time ? palette::warning : palette::reference;
    draw.box(side(target_.center - half), side(target_.center + half), targetColor);
    draw.box(plan(target_.center - half), plan(target_.center + half), targetColor);
    const Vec3d pivot{0.0, gun_.baseHeight, 0.0};
    const Vec3d muzzle = muzzlePosition(gun_);
    draw.segment({0.0f, 0.0f}, side(pivot), palette::staticBody);
    draw.segment(side(pivot), side(muzzle), palette::awake);
    draw.segment(plan(pivot), plan(muzzle), palette::awake);
    // The whole flight, then the shell where it is now.
    std::vector<Vec2f> sidePath;
    std::vector<Vec2f> planPath;
    for (const ShellState& s : result_.trajectory) {
      sidePath.push_back(side(s.position));
      planPath.push_back(plan(s.position));
    }
    draw.polyline(sidePath, palette::trajectory.withAlpha(0.35f));
    draw.polyline(planPath, palette::trajectory.withAlpha(0.35f));
    const ShellState now = flight_->at(std::min(t_, result_.time));
    draw.point(side(now.position), 7.0f, palette::bullet);
    draw.point(plan(now.position), 7.0f, palette::bullet);
    if (t_ >= result_.time) {
      const char* outcome = result_.outcome == ShotOutcome::hit ? "HIT" : "ground";
      char text[96];
      std::snprintf(text, sizeof text, "%s at t = %.2f s, x = %.1f m", outcome, result_.time, result_.position.x);
      draw.text(side(result_.position) + Vec2f{5.0f, 25.0f}, text, palette::text);
    }
  }

  void ui() override {
    bool changed = false;
    float speed = static_cast<float>(gun_.muzzleSpeed);
    float alpha = static_cast<float>(radToDeg(gun_.altitude));
    float gamma = static_cast<float>(radToDeg(gun_.azimuth));
    float barrel = static_cast<float>(gun_.barrelLength);
    float base = static_cast<float>(gun_.baseHeight);
    changed |= slider("muzzle speed Vm", &speed, 10.0f, 150.0f, "%.1f m/s");
    changed |= slider("alpha (from vertical)", &alpha, 0.0f, 90.0f, "%.1f deg");
    changed |= slider("gamma (toward +z)", &gamma, -45.0f, 45.0f, "%.1f deg");
    changed |= slider("barrel length L", &barrel, 0.0f, 20.0f, "%.1f m");
    changed |= slider("base height Yb", &base, 0.0f, 30.0f, "%.1f m");
    float tx = static_cast<float>(target_.center.x);
    float ty = static_cast<float>(target_.center.y);
    float tz = static_cast<float>(target_.center.z);
    changed |= slider("target x", &tx, 20.0f, 580.0f, "%.0f m");
    changed |= slider("target y", &ty, 0.0f, 100.0f, "%.0f m");
    changed |= slider("target z", &tz, -60.0f, 80.0f, "%.0f m");
    if (changed) {
      gun_ = {speed, degToRad(static_cast<double>(alpha)), degToRad(static_cast<double>(gamma)), barrel, base};
      target_.center = {tx, ty, tz};
      fire();
    }
    if (ImGui::Button("fire")) {
      fire();
    }
    ImGui::SameLine();
    if (ImGui::Button("aim (library)")) {
      // mechanics/aiming.hpp: the low solution from the pivot to the target's centre.
      if (const std::optional<Aim3> aim =
              aimAt({0.0, gun_.baseHeight, 0.0}, target_.center, gun_.muzzleSpeed, gravity)) {
        gun_.altitude = std::acos(aim->lowDirection.y);
        gun_.azimuth = std::atan2(aim->lowDirection.z, aim->lowDirection.x);
        fire();
      }
    }
    ImGui::SameLine();
    checkbox("auto", &autoFire_);
    textWrapped("%s at t = %.2f s: (%.1f, %.1f, %.1f) m", result_.outcome == ShotOutcome::hit ? "hit" : "ground",
                result_.time, result_.position.x, result_.position.y, result_.position.z);
    height_.plot("shell height y (m)", "%.1f m");
    updateRangeCurve();
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "max %.0f m at alpha %.0f deg", maxRange_, maxRangeAlpha_);
    plotCurve("range to the ground vs alpha, 0-90 deg (m)", rangeCurve_, overlay, 70.0f, 0.0f,
              static_cast<float>(maxRange_ * 1.1));
    std::snprintf(overlay, sizeof overlay, "largest |difference| %.2g mm", maxDifference_);
    plotCurve("library minus closed form (mm)", differenceCurve_, overlay, 50.0f, 0.0f, 0.0f, 1.0f);
  }

private:
  void fire() {
    flight_.emplace(gun_, 1.0, Atmosphere{gravity});
    result_ = fireAtTarget(*flight_, target_, 0.01, 120.0);
    t_ = 0.0;
    height_.clear();
  }

  /// The range curve depends on Vm, L and Yb only: recomputed when they change.
  void updateRangeCurve() {
    const std::vector<double> key{gun_.muzzleSpeed, gun_.barrelLength, gun_.baseHeight};
    if (key == rangeKey_) {
      return;
    }
    rangeKey_ = key;
    rangeCurve_.clear();
    differenceCurve_.clear();
    maxRange_ = 0.0;
    maxDifference_ = 0.0;
    const TargetBox nowhere{{1e9, 0.0, 0.0}, {0.0, 0.0, 0.0}};
    for (int a = 0; a <= 90; ++a) {
      CannonSetup gun = gun_;
      gun.altitude = degToRad(static_cast<double>(a));
      gun.azimuth = 0.0;
      const ShotResult shot = fireAtTarget(ShellFlight(gun, 1.0, Atmosphere{gravity}), nowhere, 0.01, 120.0);
      const double library = std::hypot(shot.position.x, shot.position.z);
      // Closed form: a vacuum flight from the muzzle at elevation 90 - alpha, plus the barrel's reach.
      const VacuumLaunch launch{gun.muzzleSpeed, pi<double> / 2.0 - gun.altitude,
                                gun.baseHeight + gun.barrelLength * std::cos(gun.altitude), gravity};
      const double closed = vacuumFlight(launch, 0.0).range + gun.barrelLength * std::sin(gun.altitude);
      rangeCurve_.push_back(static_cast<float>(library));
      differenceCurve_.push_back(static_cast<float>(1000.0 * (library - closed)));
      maxDifference_ = std::max(maxDifference_, std::abs(1000.0 * (library - closed)));
      if (library > maxRange_) {
        maxRange_ = library;
        maxRangeAlpha_ = a;
      }
    }
  }

  CannonSetup gun_{70.0, degToRad(45.0), degToRad(8.5), 5.0, 2.0};
  TargetBox target_{{400.0, 10.0, 60.0}, {20.0, 20.0, 20.0}};
  std::optional<ShellFlight> flight_;
  ShotResult result_;
  double t_ = 0.0;
  bool autoFire_ = true;
  History height_;
  std::vector<double> rangeKey_;
  std::vector<float> rangeCurve_;
  std::vector<float> differenceCurve_;
  double maxRange_ = 0.0;
  double maxRangeAlpha_ = 0.0;
  double maxDifference_ = 0.0;
};

const SampleRegistrar registrar{"Book", "Cannon",
                                "The book's cannon (ch. 2): a shell fired in vacuum at a target box, seen from "
                                "the side and from above; its range against the closed form.",
                                [] { return std::make_unique<Cannon>(); }};

} // namespace
} // namespace impetus::samples
