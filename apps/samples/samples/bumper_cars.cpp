// Book/Bumper cars (ch. 10): two of the book's hovercraft crash, side on, with restitution 0.5,
// in two worlds side by side: on the left the book's response (one semi-implicit Euler step and
// one impulse per touching pair: j = -(1 + e) v_rel.n / (1/m1 + 1/m2 + rotational terms)), on the
// right the engine's soft-step solver. The impulse is the same physics, so both conserve momentum
// and lose the same share of kinetic energy; the plots show each world's total momentum (kg m/s)
// and kinetic energy (J) through the crash. The setup is `impetus demo bumper-cars`'s with the
// craft starting closer, so that they meet within two seconds; the arrow keys drive the player's
// craft in both worlds at once; the crash repeats every 20 s.
#include "sample.hpp"

#include "plot.hpp"
#include "rigid2d_draw.hpp"
#include "ui.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/vehicles/hovercraft.hpp>

#include <imgui.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace impetus::samples {
namespace {

using namespace impetus::rigid2d;
using vehicles::Hovercraft;
using vehicles::HovercraftControls;

constexpr float separation = 120.0f; // m between the two worlds' drawings
constexpr float repeatTime = 20.0f;  // s

/// One world with its two craft. Built in place and never moved: the craft refer to the world.
struct Arena {
  explicit Arena(SolverKind solver) : world(worldDef(solver)) {
    player.emplace(world, vehicles::HovercraftParams{}, Vec2f{-20.0f, 4.0f}, 0.0f, 10.0f);
    other.emplace(world, vehicles::HovercraftParams{}, Vec2f{0.0f, 14.0f}, -0.5f * pi<float>, 5.0f);
    world.setLinearVelocity(player->body(), {8.0f, 0.0f});
    world.setLinearVelocity(other->body(), {0.0f, -2.0f});
  }
  static WorldDef worldDef(SolverKind solver) {
    WorldDef def;
    def.gravity = {};
    def.solver = solver;
    return def;
  }
  [[nodiscard]] Vec2f momentum() const {
    return world.linearVelocity(player->body()) * world.mass(player->body()) +
           world.linearVelocity(other->body()) * world.mass(other->body());
  }
  [[nodiscard]] float energy() const {
    float e = 0.0f;
    for (const BodyId b : {player->body(), other->body()}) {
      const float w = world.angularVelocity(b);
      e += 0.5f * world.mass(b) * lengthSquared(world.linearVelocity(b)) + 0.5f * world.rotationalInertia(b) * w * w;
    }
    return e;
  }

  World world;
  std::optional<Hovercraft> player;
  std::optional<Hovercraft> other;
  History momentumHistory;
  History energyHistory;
  std::string report;
};

class BumperCars final : public Sample {
public:
  void setup() override {
    arenas_[0].emplace(SolverKind::bookImpulse);
    arenas_[1].emplace(SolverKind::softStep);
    time_ = 0.0f;
  }

  void keys(const KeyState& keys) override {
    controls_ = {(keys.up ? 1 : 0) - (keys.down ? 1 : 0), keys.right, keys.left};
  }

  void step(float dt) override {
    time_ += dt;
    if (time_ > repeatTime) {
      setup();
    }
    for (auto& arena : arenas_) {
      Arena& a = *arena;
      const Vec2f p0 = a.momentum();
      const float e0 = a.energy();
      a.player->applyLoads(controls_, dt);
      a.other->applyLoads({}, dt);
      a.world.step(dt);
      a.momentumHistory.push(length(a.momentum()));
      a.energyHistory.push(a.energy());
      if (a.report.empty() && !a.world.contactEvents().hits.empty()) {
        char text[160];
        std::snprintf(text, sizeof text, "hit at %.2f s, %.2f m/s: |p| %.1f -> %.1f kg m/s, KE %.0f -> %.0f J",
                      static_cast<double>(time_),
                      static_cast<double>(a.world.contactEvents().hits.front().approachSpeed),
                      static_cast<double>(length(p0)), static_cast<double>(length(a.momentum())),
                      static_cast<double>(e0), static_cast<double>(a.energy()));
        a.report = text;
      }
    }
  }

  [[nodiscard]] bool finite() const override {
    for (const auto& arena : arenas_) {
      for (const BodyId b : {arena->player->body(), arena->other->body()}) {
        const Transform2f xf = arena->world.transform(b);
        if (!isFinite(xf.p) || !std::isfinite(xf.q.c) || !isFinite(arena->world.linearVelocity(b))) {
          return false;
        }
      }
    }
    return true;
  }

  /// Both worlds, from the player's start (x = -20 m) to past the other world's crash site.
  [[nodiscard]] CameraView initialView() const override { return {{0.5f * separation - 10.0f, 5.0f}, 30.0f, 85.0f}; }
  [[nodiscard]] std::string summary() const override {
    return "book's impulse: " + (arenas_[0]->report.empty() ? std::string("no hit yet") : arenas_[0]->report) +
           "; soft step: " + (arenas_[1]->report.empty() ? std::string("no hit yet") : arenas_[1]->report);
  }
  [[nodiscard]] std::string_view controls() const override {
    return "Arrow keys drive the player's craft (left in each world) in both worlds at once.";
  }

  void draw(DebugDraw& draw) override {
    static constexpr std::array<const char*, 2> titles{"book's impulse (ch. 10)", "soft step"};
    Rigid2dDrawOptions options;
    options.contacts = true;
    options.centersOfMass = true;
    for (std::size_t i = 0; i < arenas_.size(); ++i) {
      OffsetDraw shifted(draw, {separation * static_cast<float>(i), 0.0f});
      const Arena& a = *arenas_[i];
      drawWorld(a.world, shifted, options, timeStep(), [&](BodyId b) -> std::optional<Color> {
        return b == a.player->body() ? palette::series[0] : palette::series[2];
      });
      for (const Hovercraft* craft : {&*a.player, &*a.other}) {
        const Transform2f xf = a.world.transform(craft->body());
        std::array<Vec2f, 5> outline{};
        for (std::size_t k = 0; k < outline.size(); ++k) {
          outline[k] = transformPoint(xf, craft->outline()[k]);
        }
        shifted.polygon(outline, palette::text.withAlpha(0.6f));
      }
      shifted.text({-30.0f, 28.0f}, titles[i], palette::text);
    }
  }

  void ui() override {
    static constexpr std::array<const char*, 2> names{"book's impulse", "soft step"};
    textWrapped("t = %.2f s (repeats every %.0f s)", static_cast<double>(time_), static_cast<double>(repeatTime));
    for (std::size_t i = 0; i < arenas_.size(); ++i) {
      Arena& a = *arenas_[i];
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.9f, 0.9f, 0.6f, 1.0f));
      textWrapped("%s: %s", names[i], a.report.empty() ? "no hit yet" : a.report.c_str());
      ImGui::PopStyleColor();
      const std::string m = std::string(names[i]) + ": total momentum (kg m/s)";
      const std::string e = std::string(names[i]) + ": kinetic energy (J)";
      a.momentumHistory.plot(m.c_str(), "%.1f kg m/s", 45.0f);
      a.energyHistory.plot(e.c_str(), "%.0f J", 45.0f);
    }
  }

private:
  std::array<std::optional<Arena>, 2> arenas_;
  HovercraftControls controls_;
  float time_ = 0.0f;
};

const SampleRegistrar registrar{"Book", "Bumper cars",
                                "The book's bumper cars (ch. 10): two hovercraft crash, with the book's "
                                "single-impulse response beside the soft-step solver.",
                                [] { return std::make_unique<BumperCars>(); }};

} // namespace
} // namespace impetus::samples
