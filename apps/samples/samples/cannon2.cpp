// Book/Cannon2 (ch. 4): the cannon with air. The shell of mass m feels linear drag F = -C v
// relative to the air and a wind; per axis m dv/dt = -C v + F with constant F, so the velocity
// relaxes exponentially, v(t) = v_inf + (v1 - v_inf) e^(-C t / m), toward the terminal velocity
// v_inf = F / C (mechanics/cannon.hpp, closed form). The wind is moving air by default (the drag
// acts on v - w); the book's separate constant wind force -Cw vw is kept as an option: it is the
// same physics only when Cw = C, and with Cw = 2 C the shell drifts at twice the wind speed, which
// no air can do. The setup is `impetus demo cannon2`'s.
//
// The view shows the shot in vacuum (faint) and with air; the plots show the horizontal velocity
// relaxing toward its terminal value and the speed over the flight.
#include "sample.hpp"

#include "plot.hpp"
#include "ui.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/mechanics/cannon.hpp>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace impetus::samples {
namespace {

constexpr double holdTime = 1.5; // s the landing stays on screen before the next shot

Vec2f side(const Vec3d& p) { return {static_cast<float>(p.x), static_cast<float>(p.y)}; }

class Cannon2 final : public Sample {
public:
  void setup() override { fire(); }

  void step(float dt) override {
    t_ += dt;
    if (t_ <= shot_.time) {
      const ShellState s = flight_->at(t_);
      vx_.push(static_cast<float>(s.velocity.x));
      speed_.push(static_cast<float>(length(s.velocity)));
    } else if (t_ > shot_.time + holdTime) {
      fire();
    }
  }

  [[nodiscard]] bool finite() const override {
    const ShellState s = flight_->at(std::min(t_, shot_.time));
    return std::isfinite(s.position.x) && std::isfinite(s.position.y) && std::isfinite(s.velocity.x) &&
           std::isfinite(s.velocity.y);
  }

  [[nodiscard]] CameraView initialView() const override { return {{250.0f, 60.0f}, 90.0f, 280.0f}; }

  void draw(DebugDraw& draw) override {
    draw.segment({-30.0f, 0.0f}, {650.0f, 0.0f}, palette::staticBody);
    const Vec3d half = target_.size * 0.5;
    draw.box(side(target_.center - half), side(target_.center + half), palette::reference);
    const auto path = [&](const ShotResult& r, const Color& c) {
      std::vector<Vec2f> points;
      for (const ShellState& s : r.trajectory) {
        points.push_back(side(s.position));
      }
      draw.polyline(points, c);
    };
    path(vacuumShot_, palette::reference.withAlpha(0.4f));
    path(shot_, palette::trajectory.withAlpha(0.6f));
    draw.text(side(vacuumShot_.position) + Vec2f{-40.0f, 14.0f}, "vacuum", palette::reference);
    const ShellState now = flight_->at(std::min(t_, shot_.time));
    draw.point(side(now.position), 7.0f, palette::bullet);
    // The velocity and the wind, to scale: 1 m/s = 1 m.
    draw.arrow(side(now.position), side(now.position + now.velocity), palette::trajectory);
    const Vec3d wind = windVelocity();
    draw.arrow({300.0f, 150.0f}, Vec2f{300.0f, 150.0f} + side(wind) * 3.0f, palette::particle);
    char text[64];
    std::snprintf(text, sizeof text, "wind %.0f m/s (x3)", static_cast<double>(windSpeed_));
    draw.text({300.0f, 160.0f}, text, palette::particle);
  }

  void ui() override {
    bool changed = false;
    changed |= slider("shell mass m", &mass_, 1.0f, 50.0f, "%.1f kg");
    changed |= slider("drag C", &drag_, 0.0f, 5.0f, "%.2f kg/s");
    changed |= slider("wind speed vw", &windSpeed_, 0.0f, 40.0f, "%.1f m/s");
    changed |= slider("wind from gw", &windFrom_, -180.0f, 180.0f, "%.0f deg");
    changed |= checkbox("the book's wind force -Cw vw (not moving air)", &bookWind_);
    if (bookWind_) {
      changed |= slider("Cw", &windCoefficient_, 0.0f, 5.0f, "%.2f kg/s");
    }
    changed |= slider("alpha (from vertical)", &alpha_, 5.0f, 85.0f, "%.1f deg");
    if (changed) {
      fire();
    }
    const Vec3d terminal = flight_->terminalVelocity();
    textWrapped("%s at t = %.2f s, x = %.1f m (vacuum %.1f m)", shot_.outcome == ShotOutcome::hit ? "hit" : "ground",
                shot_.time, shot_.position.x, vacuumShot_.position.x);
    if (drag_ > 0.0f) {
      textWrapped("terminal vx = F/C = %.2f m/s; relaxes in m/C = %.1f s", terminal.x,
                  static_cast<double>(mass_ / drag_));
    }
    vx_.plot("horizontal velocity vx (m/s)", "%.2f m/s");
    speed_.plot("speed |v| (m/s)", "%.2f m/s");
  }

private:
  [[nodiscard]] Atmosphere air() const {
    Atmosphere a;
    a.dragCoefficient = drag_;
    a.windSpeed = windSpeed_;
    a.windDirection = degToRad(static_cast<double>(windFrom_));
    a.windModel = bookWind_ ? WindModel::bookConstantForce : WindModel::movingAir;
    a.windCoefficient = windCoefficient_;
    return a;
  }

  /// Where the air moves: from gw, so toward gw + 180 degrees (gw = 0 blows toward -x).
  [[nodiscard]] Vec3d windVelocity() const {
    const double g = degToRad(static_cast<double>(windFrom_));
    return Vec3d{-std::cos(g), 0.0, -std::sin(g)} * static_cast<double>(windSpeed_);
  }

  void fire() {
    gun_.altitude = degToRad(static_cast<double>(alpha_));
    flight_.emplace(gun_, mass_, air());
    shot_ = fireAtTarget(*flight_, target_, 0.01, 120.0);
    vacuumShot_ = fireAtTarget(ShellFlight(gun_, mass_, Atmosphere{}), target_, 0.01, 120.0);
    t_ = 0.0;
    vx_.clear();
    speed_.clear();
  }

  CannonSetup gun_{70.0, degToRad(45.0), 0.0, 5.0, 2.0};
  TargetBox target_{{460.0, 10.0, 0.0}, {20.0, 20.0, 20.0}};
  float mass_ = 10.0f;      // kg
  float drag_ = 0.5f;       // kg/s
  float windSpeed_ = 15.0f; // m/s
  float windFrom_ = 180.0f; // deg: from -x, a tail wind
  bool bookWind_ = false;
  float windCoefficient_ = 1.0f; // kg/s
  float alpha_ = 45.0f;          // deg
  std::optional<ShellFlight> flight_;
  ShotResult shot_;
  ShotResult vacuumShot_;
  double t_ = 0.0;
  History vx_;
  History speed_;
};

const SampleRegistrar registrar{"Book", "Cannon2",
                                "The book's Cannon2 (ch. 4): the shell with linear drag and wind, its velocity "
                                "relaxing to the terminal velocity; moving air vs the book's wind force.",
                                [] { return std::make_unique<Cannon2>(); }};

} // namespace
} // namespace impetus::samples
