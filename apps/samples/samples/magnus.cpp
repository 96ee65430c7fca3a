// Book/Magnus (ch. 6): a spinning baseball. The book flies it with gravity and the idealized
// Magnus force F = C (w_hat x v), C = pi^2 rho r^3 w, evaluating a whole-flight formula at each
// time; that formula has the x force's sign wrong (so its "lift" does work) and divides by zero
// at t = m/C. Four flights of the same pitch (`impetus demo magnus`'s: 0.145 kg, r = 36.6 mm,
// 40 m/s and 5 m/s up from 1 m, 1800 rpm backspin):
//   the book's formula (until it blows up), the exact solution of the book's model (the velocity
//   circles the drift velocity g/Omega, Omega = C/m: the ball loops), the vacuum parabola without
//   spin, and what a library should fly: quadratic drag (Cd 0.35) with the measured lift
//   coefficient of Sawicki et al. (2003), integrated with RK4 (mechanics/aerodynamics.hpp).
// Plots: the mechanical energy of the book's formula minus the exact solution's (J; the exact
// solution keeps it, since the Magnus force is perpendicular to v), and the live speed of the
// drag + lift ball.
#include "sample.hpp"

#include "plot.hpp"
#include "ui.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/mechanics/aerodynamics.hpp>
#include <impetus/mechanics/projectile.hpp>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace impetus::samples {
namespace {

constexpr double g = 9.8;      // m/s^2, the book's chapter-6 value
constexpr double rho = 1.225;  // kg/m^3, the book's RHO
constexpr double window = 5.0; // s shown of each flight
constexpr double dtCurve = 0.01;

struct Curve {
  std::vector<Vec2f> points; ///< one every dtCurve seconds
  Color color;
  const char* name = "";
};

class Magnus final : public Sample {
public:
  void setup() override {
    compute();
    t_ = 0.0;
    speed_.clear();
  }

  void step(float dt) override {
    t_ += dt;
    if (t_ > window + 1.0) {
      t_ = 0.0;
      speed_.clear();
    }
    const std::size_t i = index(flight_.samples.size());
    if (i < flight_.samples.size()) {
      speed_.push(static_cast<float>(length(flight_.samples[i].velocity)));
    }
  }

  [[nodiscard]] bool finite() const override {
    for (const Curve& c : curves_) {
      for (const Vec2f& p : c.points) {
        if (!isFinite(p)) {
          return false;
        }
      }
    }
    return true;
  }

  [[nodiscard]] CameraView initialView() const override { return view_; }

  void draw(DebugDraw& draw) override {
    draw.segment({-10.0f, 0.0f}, {400.0f, 0.0f}, palette::staticBody);
    float labelY = view_.center.y + view_.halfHeight * 0.92f;
    for (const Curve& c : curves_) {
      draw.polyline(c.points, c.color.withAlpha(0.7f));
      if (!c.points.empty()) {
        const std::size_t i = std::min(index(std::numeric_limits<std::size_t>::max()), c.points.size() - 1);
        draw.point(c.points[i], 7.0f, c.color);
      }
      draw.text({view_.center.x - view_.halfWidth * 0.95f, labelY}, c.name, c.color);
      labelY -= 16.0f * draw.pixelSize();
    }
  }

  void ui() override {
    bool changed = slider("backspin", &rpm_, -3000.0f, 3000.0f, "%.0f rpm");
    changed |= slider("launch speed", &speed0_, 5.0f, 60.0f, "%.1f m/s");
    changed |= slider("launch angle", &angle_, -10.0f, 60.0f, "%.1f deg");
    if (changed) {
      setup();
    }
    textWrapped("C = pi^2 rho r^3 w = %.4f N s/m; lift/weight at launch %.2f", c_,
                c_ * static_cast<double>(speed0_) / (mass_ * g));
    if (std::isfinite(singular_)) {
      textWrapped("the book's formula divides by zero at t = m/C = %.2f s", singular_);
    }
    textWrapped("drag + lift: lands at x = %.1f m after %.2f s", flight_.range, flight_.flightTime);
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "up to %.3g J", energyGap_.empty() ? 0.0 : static_cast<double>(maxGap_));
    plotCurve("energy: book's formula minus exact (J), 0-5 s", energyGap_, overlay, 70.0f);
    speed_.plot("speed of the drag + lift ball (m/s)", "%.2f m/s");
  }

private:
  [[nodiscard]] std::size_t index(std::size_t size) const {
    return std::min(static_cast<std::size_t>(t_ / dtCurve), size == 0 ? 0 : size - 1);
  }

  void compute() {
    const double omega = static_cast<double>(rpm_) * 2.0 * pi<double> / 60.0; // rad/s
    const double a = degToRad(static_cast<double>(angle_));
    const Vec2d v0 = Vec2d{std::cos(a), std::sin(a)} * static_cast<double>(speed0_);
    c_ = idealMagnusCoefficient(rho, radius_, omega);
    const MagnusPlaneLaunch launch{{0.0, launchHeight_}, v0, mass_, c_, g};
    singular_ = bookMagnusSingularTime(launch);
    curves_.clear();
    energyGap_.clear();
    maxGap_ = 0.0f;
    const auto energy = [&](const MagnusPlaneState& s) {
      return 0.5 * mass_ * (s.velocity.x * s.velocity.x + s.velocity.y * s.velocity.y) + mass_ * g * s.position.y;
    };
    Curve exact{{}, palette::reference, "exact solution of the book's model"};
    Curve book{{}, palette::warning, "the book's formula"};
    Curve vacuum{{}, palette::grid.scaled(3.0f), "no spin, vacuum"};
    for (int i = 0; i * dtCurve <= window; ++i) {
      const double t = i * dtCurve;
      const MagnusPlaneState e = magnusClosedForm(launch, t);
      exact.points.push_back({static_cast<float>(e.position.x), static_cast<float>(e.position.y)});
      if (t < 0.97 * singular_) {
        const MagnusPlaneState b = bookMagnusFormula(launch, t);
        if (std::abs(b.position.x) < 1e4 && std::abs(b.position.y) < 1e4) {
          book.points.push_back({static_cast<float>(b.position.x), static_cast<float>(b.position.y)});
          const auto gap = static_cast<float>(energy(b) - energy(e));
          energyGap_.push_back(gap);
          maxGap_ = std::max(maxGap_, std::abs(gap));
        }
      }
      const ProjectilePoint p = vacuumPointAt({static_cast<double>(speed0_), a, launchHeight_, g}, t);
      if (p.position.y >= 0.0) {
        vacuum.points.push_back({static_cast<float>(p.position.x), static_cast<float>(p.position.y)});
      }
    }
    // The flight a library should compute: drag and measured lift, RK4.
    FlightConditions conditions;
    conditions.airDensity = rho;
    conditions.gravity = g;
    conditions.spin = {0.0, 0.0, omega};
    FlightSettings settings;
    settings.timeStep = dtCurve;
    settings.maxTime = window;
    flight_ = simulateBallFlight(baseball(), conditions, {0.0, launchHeight_, 0.0}, {v0.x, v0.y, 0.0}, settings);
    Curve real{{}, palette::trajectory, "drag + measured lift (Sawicki 2003)"};
    for (const FlightSample& s : flight_.samples) {
      real.points.push_back({static_cast<float>(s.position.x), static_cast<float>(s.position.y)});
    }
    curves_ = {exact, book, vacuum, real};
    // The view: the drag + lift and vacuum flights, and the first 2.5 s of the exact solution of
    // the book's model (it loops far higher later).
    Vec2f upper{1.0f, 1.0f};
    for (const Curve* c : {&real, &vacuum}) {
      for (const Vec2f& p : c->points) {
        upper = max(upper, p);
      }
    }
    for (std::size_t i = 0; i < exact.points.size() && static_cast<double>(i) * dtCurve <= 2.5; ++i) {
      upper = max(upper, exact.points[i]);
    }
    upper.y *= 1.25f; // room for the labels
    view_ = {{0.5f * upper.x, 0.5f * upper.y - 2.0f}, 0.55f * upper.y + 3.0f, 0.55f * upper.x + 5.0f};
  }

  float rpm_ = 1800.0f;  // backspin
  float speed0_ = 40.3f; // m/s: the demo's (40, 5) m/s
  float angle_ = 7.1f;   // deg
  double mass_ = 0.145;  // kg, baseball
  double radius_ = 0.0366;
  double launchHeight_ = 1.0; // m
  double c_ = 0.0;
  double singular_ = 0.0;
  double t_ = 0.0;
  BallFlight flight_;
  std::vector<Curve> curves_;
  std::vector<float> energyGap_;
  float maxGap_ = 0.0f;
  CameraView view_;
  History speed_;
};

const SampleRegistrar registrar{"Book", "Magnus",
                                "The book's Magnus curve ball (ch. 6): its formula against the exact solution "
                                "of its model, the vacuum parabola, and drag with measured lift.",
                                [] { return std::make_unique<Magnus>(); }};

} // namespace
} // namespace impetus::samples
