// Book/Integrators (ch. 7): the same spring and mass, m x'' = -k x - c x', stepped side by side by
// explicit Euler, semi-implicit (symplectic) Euler, Heun, RK4 and velocity Verlet (the steppers of
// integrate/steppers.hpp), from x = 1 m at rest, with the exact solution beside them. With
// w = sqrt(k/m) and z = w h, one step multiplies an undamped oscillation's amplitude by the
// method's amplification (steppers.hpp's table): explicit Euler sqrt(1 + z^2) > 1 always (the
// book's Fig. 7-5 blow-up), Heun sqrt(1 + z^4/4), RK4 slightly below 1, the two symplectic
// methods exactly 1 while z < 2. The plots are each method's relative energy error (E - E0)/E0,
// E = 1/2 m v^2 + 1/2 k x^2 (with damping, against the exact solution's energy). A method whose
// energy passes 10^6 E0 is stopped and marked "blew up".
#include "sample.hpp"

#include "plot.hpp"
#include "ui.hpp"

#include <impetus/integrate/steppers.hpp>

#include <imgui.h>

#include <array>
#include <cmath>
#include <cstdio>

namespace impetus::samples {
namespace {

using State = PhaseState<double, double>;

enum Method { explicitEuler, semiImplicit, heun, rk4, verlet, methodCount };
constexpr const char* methodNames[methodCount] = {"explicit Euler", "semi-implicit Euler", "Heun", "RK4",
                                                  "velocity Verlet"};

class Integrators final : public Sample {
public:
  void setup() override {
    for (int i = 0; i < methodCount; ++i) {
      states_[static_cast<std::size_t>(i)] = {1.0, 0.0};
      blownUp_[static_cast<std::size_t>(i)] = false;
      errors_[static_cast<std::size_t>(i)].clear();
    }
    verletAcceleration_ = acceleration(0.0, 1.0, 0.0);
    t_ = 0.0;
  }

  [[nodiscard]] float timeStep() const override { return h_; }

  void step(float dt) override {
    const double h = dt;
    const auto a = [this](double t, double x, double v) { return acceleration(t, x, v); };
    const auto f = firstOrderRate(a);
    for (int i = 0; i < methodCount; ++i) {
      auto& s = states_[static_cast<std::size_t>(i)];
      if (blownUp_[static_cast<std::size_t>(i)]) {
        continue;
      }
      switch (i) {
      case explicitEuler:
        s = explicitEulerStep2(a, t_, s, h);
        break;
      case semiImplicit:
        s = semiImplicitEulerStep(a, t_, s, h);
        break;
      case heun:
        s = heunStep(f, t_, s, h);
        break;
      case rk4:
        s = rk4Step(f, t_, s, h);
        break;
      default:
        s = velocityVerletStep(a, t_, s, h, verletAcceleration_);
        break;
      }
    }
    t_ += h;
    const double reference = energy(exact(t_));
    for (int i = 0; i < methodCount; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const double e = energy(states_[k]);
      if (!blownUp_[k] && (!std::isfinite(e) || e > 1e6 * energy(State{1.0, 0.0}))) {
        blownUp_[k] = true; // frozen where it was: the plot shows the run-away
      }
      errors_[k].push(static_cast<float>((e - reference) / energy(State{1.0, 0.0})));
    }
  }

  [[nodiscard]] bool finite() const override {
    for (int i = 0; i < methodCount; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (!blownUp_[k] && (!std::isfinite(states_[k].position) || !std::isfinite(states_[k].velocity))) {
        return false;
      }
    }
    return true;
  }

  [[nodiscard]] CameraView initialView() const override { return {{7.5f, -0.5f}, 4.0f, 9.5f}; }

  void draw(DebugDraw& draw) override {
    // One column per method, 3 m apart: the spring hangs from an anchor at y = 2.6 m and the mass
    // sits at its displacement x (m) about y = 0, the rest position; the exact solution last.
    const auto column = [&](int i, double x, const Color& c, const char* name, bool dead) {
      const float cx = 3.0f * static_cast<float>(i);
      const float labelY = i % 2 == 0 ? -2.7f : -3.1f; // staggered: the names are wider than a column
      const float y = static_cast<float>(std::clamp(x, -2.4, 2.4));
      draw.segment({cx - 0.4f, 2.6f}, {cx + 0.4f, 2.6f}, palette::staticBody);
      std::array<Vec2f, 14> coil{};
      for (std::size_t j = 0; j < coil.size(); ++j) {
        const float s = static_cast<float>(j) / static_cast<float>(coil.size() - 1);
        coil[j] = {cx + (j == 0 || j + 1 == coil.size() ? 0.0f : (j % 2 == 0 ? 0.2f : -0.2f)),
                   2.6f + (y + 0.3f - 2.6f) * s};
      }
      draw.polyline(coil, c.withAlpha(0.6f));
      draw.solidPolygon(std::array<Vec2f, 4>{Vec2f{cx - 0.3f, y - 0.3f}, Vec2f{cx + 0.3f, y - 0.3f},
                                             Vec2f{cx + 0.3f, y + 0.3f}, Vec2f{cx - 0.3f, y + 0.3f}},
                        c.scaled(0.5f).withAlpha(0.7f), c);
      draw.text({cx - 1.2f, labelY}, name, c);
      if (dead) {
        draw.text({cx - 1.2f, labelY - 0.9f}, "blew up", palette::warning);
      }
    };
    draw.segment({-1.5f, 0.0f}, {16.5f, 0.0f}, palette::grid.scaled(1.8f));
    for (int i = 0; i < methodCount; ++i) {
      const auto k = static_cast<std::size_t>(i);
      column(i, states_[k].position, palette::series[k], methodNames[i], blownUp_[k]);
    }
    column(methodCount, exact(t_).position, palette::reference, "exact", false);
  }

  void ui() override {
    bool changed = slider("stiffness k", &k_, 1.0f, 400.0f, "%.0f N/m");
    changed |= slider("mass m", &m_, 0.1f, 10.0f, "%.2f kg");
    changed |= slider("damping c", &c_, 0.0f, 5.0f, "%.2f N s/m");
    changed |= slider("step h", &h_, 0.002f, 0.25f, "%.3f s", ImGuiSliderFlags_Logarithmic);
    if (changed) {
      setup();
    }
    const double w = std::sqrt(static_cast<double>(k_ / m_));
    textWrapped("w = %.2f rad/s, z = w h = %.3f, t = %.2f s", w, w * static_cast<double>(h_), t_);
    for (int i = 0; i < methodCount; ++i) {
      const auto k = static_cast<std::size_t>(i);
      char label[96];
      std::snprintf(label, sizeof label, "%s: (E - E0)/E0%s", methodNames[i], blownUp_[k] ? " - blew up" : "");
      ImGui::PushStyleColor(ImGuiCol_PlotLines,
                            ImVec4(palette::series[k].r, palette::series[k].g, palette::series[k].b, 1.0f));
      errors_[k].plot(label, "%.2e", 38.0f);
      ImGui::PopStyleColor();
    }
  }

private:
  [[nodiscard]] double acceleration(double /*t*/, double x, double v) const {
    return (-static_cast<double>(k_) * x - static_cast<double>(c_) * v) / static_cast<double>(m_);
  }
  [[nodiscard]] double energy(const State& s) const {
    return 0.5 * static_cast<double>(m_) * s.velocity * s.velocity +
           0.5 * static_cast<double>(k_) * s.position * s.position;
  }
  /// The exact solution from x = 1, v = 0: under-, critically or over-damped.
  [[nodiscard]] State exact(double t) const {
    const double m = m_;
    const double w0 = std::sqrt(static_cast<double>(k_) / m);
    const double zeta = static_cast<double>(c_) / (2.0 * std::sqrt(static_cast<double>(k_) * m));
    if (zeta < 1.0) {
      const double wd = w0 * std::sqrt(1.0 - zeta * zeta);
      const double decay = std::exp(-zeta * w0 * t);
      const double b = zeta * w0 / wd;
      const double x = decay * (std::cos(wd * t) + b * std::sin(wd * t));
      const double v = -decay * (w0 * w0 / wd) * std::sin(wd * t);
      return {x, v};
    }
    if (zeta == 1.0) {
      const double decay = std::exp(-w0 * t);
      return {decay * (1.0 + w0 * t), -decay * w0 * w0 * t};
    }
    const double r = w0 * std::sqrt(zeta * zeta - 1.0);
    const double r1 = -zeta * w0 + r;
    const double r2 = -zeta * w0 - r;
    const double a1 = -r2 / (r1 - r2);
    const double a2 = r1 / (r1 - r2);
    return {a1 * std::exp(r1 * t) + a2 * std::exp(r2 * t), a1 * r1 * std::exp(r1 * t) + a2 * r2 * std::exp(r2 * t)};
  }

  float k_ = 100.0f; // N/m: w = 10 rad/s with m = 1 kg (the spec's spring-mass demo)
  float m_ = 1.0f;   // kg
  float c_ = 0.0f;   // N s/m
  float h_ = 0.02f;  // s: z = 0.2
  double t_ = 0.0;
  std::array<State, methodCount> states_{};
  std::array<bool, methodCount> blownUp_{};
  std::array<History, methodCount> errors_;
  double verletAcceleration_ = 0.0;
};

const SampleRegistrar registrar{"Book", "Integrators",
                                "The book's integrators (ch. 7) side by side on a spring: explicit Euler gains "
                                "energy, the symplectic methods keep it, RK4 loses a little.",
                                [] { return std::make_unique<Integrators>(); }};

} // namespace
} // namespace impetus::samples
