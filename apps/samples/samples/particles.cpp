// Book/Particles (ch. 8): the book's particle simulator, on the particle world (particles/). Balls
// of 1 kg and r = 0.1 m rain from an emitter through air (rho 1.23 kg/m^3, Cd 0.6: quadratic drag
// on the velocity relative to the wind, so they drift at the wind's speed, not at the 3.4 m/s the
// book's separate wind force gives) onto round obstacles and the ground, bouncing with
// restitution e (0.6, the book's) and Coulomb friction, and coming to rest instead of
// micro-bouncing for ever (contacts slower than 0.5 m/s do not bounce). Between two walls so the
// wind does not blow them away. Plots: the number of particles, the kinetic energy (J) and the
// mean horizontal velocity of the airborne ones (m/s), which approaches the wind's.
#include "sample.hpp"

#include "particle_draw.hpp"
#include "plot.hpp"
#include "ui.hpp"

#include <imgui.h>

#include <cmath>
#include <impetus/math/scalar.hpp>
#include <optional>
#include <vector>

namespace impetus::samples {
namespace {

constexpr const char* integratorNames[] = {"semi-implicit Euler", "explicit Euler", "velocity Verlet", "RK4"};

class Particles final : public Sample {
public:
  void setup() override {
    world_.emplace(settings());
    SurfaceMaterial material;
    material.restitution = restitution_;
    material.friction = friction_;
    world_->addObstacle(PlaneObstacle{{0.0f, 1.0f, 0.0f}, 0.0f}, material);
    world_->addObstacle(PlaneObstacle{{1.0f, 0.0f, 0.0f}, -wall_}, material);
    world_->addObstacle(PlaneObstacle{{-1.0f, 0.0f, 0.0f}, -wall_}, material);
    spheres_ = {{{-12.0f, 8.0f, 0.0f}, 2.0f}, {{-4.0f, 5.0f, 0.0f}, 2.5f},  {{5.0f, 9.0f, 0.0f}, 1.8f},
                {{13.0f, 4.0f, 0.0f}, 2.2f},  {{-8.0f, 14.0f, 0.0f}, 1.5f}, {{9.0f, 15.0f, 0.0f}, 1.5f}};
    for (const SphereObstacle& s : spheres_) {
      world_->addObstacle(s, material);
    }
    box_ = {{20.0f, 10.0f, 0.0f}, {3.0f, 0.4f, 1.0f}, Quatf::fromAxisAngle(Vec3f::unitZ(), -0.5f)};
    world_->addObstacle(box_, material);
    EmitterDef emitter;
    emitter.position = {-2.0f, 24.0f, 0.0f};
    emitter.direction = {0.0f, -1.0f, 0.0f};
    emitter.coneAngle = 1.2f;
    emitter.minSpeed = 0.0f;
    emitter.maxSpeed = 3.0f;
    emitter.rate = rate_;
    emitter.minLifetime = 25.0f;
    emitter.maxLifetime = 30.0f;
    emitter.mass = 1.0f;
    emitter.radius = 0.1f;
    emitter.planar = true; // the x-y plane: a 2D simulation, like the book's
    emitter.seed = 8;
    world_->addEmitter(emitter);
    count_.clear();
    energy_.clear();
    drift_.clear();
  }

  [[nodiscard]] float timeStep() const override { return 1.0f / 60.0f; }

  void step(float dt) override {
    world_->step(dt);
    count_.push(static_cast<float>(world_->particleCount()));
    energy_.push(static_cast<float>(world_->kineticEnergy()));
    float sum = 0.0f;
    int airborne = 0;
    const auto positions = world_->positions();
    const auto velocities = world_->velocities();
    for (std::size_t i = 0; i < positions.size(); ++i) {
      if (positions[i].y > 1.0f) {
        sum += velocities[i].x;
        ++airborne;
      }
    }
    drift_.push(airborne > 0 ? sum / static_cast<float>(airborne) : 0.0f);
  }

  [[nodiscard]] bool finite() const override {
    for (const Vec3f& p : world_->positions()) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        return false;
      }
    }
    return std::isfinite(world_->kineticEnergy());
  }

  [[nodiscard]] CameraView initialView() const override { return {{0.0f, 12.0f}, 14.0f, wall_ + 1.0f}; }

  void draw(DebugDraw& draw) override {
    drawObstacle(draw, PlaneObstacle{{0.0f, 1.0f, 0.0f}, 0.0f}, wall_);
    draw.segment({-wall_, 0.0f}, {-wall_, 30.0f}, palette::staticBody);
    draw.segment({wall_, 0.0f}, {wall_, 30.0f}, palette::staticBody);
    for (const SphereObstacle& s : spheres_) {
      drawObstacle(draw, s);
    }
    drawObstacle(draw, box_);
    drawParticles(*world_, draw, palette::particle);
    draw.arrow({-wall_ + 2.0f, 27.0f}, {-wall_ + 2.0f + 0.5f * wind_, 27.0f}, palette::particle);
    draw.text({-wall_ + 2.0f, 29.0f}, "wind", palette::particle);
  }

  void ui() override {
    bool live = slider("wind", &wind_, -20.0f, 20.0f, "%.1f m/s");
    live |= slider("drag coefficient Cd", &cd_, 0.0f, 2.0f, "%.2f");
    labelColumn("integrator");
    live |= ImGui::Combo("##integrator", &integrator_, integratorNames, 4);
    live |= checkbox("particles collide with each other", &collisions_);
    if (live) {
      world_->setSettings(settings());
    }
    bool rebuild = slider("restitution e", &restitution_, 0.0f, 1.0f, "%.2f");
    rebuild |= slider("friction mu", &friction_, 0.0f, 1.0f, "%.2f");
    rebuild |= slider("emission rate", &rate_, 1.0f, 200.0f, "%.0f /s");
    if (rebuild) {
      setup();
    }
    textWrapped("terminal speed in still air sqrt(2 m g / (rho Cd A)) = %.1f m/s",
                cd_ > 0.0f ? std::sqrt(2.0 * 9.81 / (1.23 * static_cast<double>(cd_) * pi<double> * 0.01)) : 0.0);
    count_.plot("particles", "%.0f");
    energy_.plot("kinetic energy (J)", "%.0f J");
    drift_.plot("mean horizontal velocity in the air (m/s)", "%.2f m/s");
  }

private:
  [[nodiscard]] ParticleWorldSettings settings() const {
    ParticleWorldSettings s;
    s.gravity = {0.0f, -9.81f, 0.0f};
    s.integrator = static_cast<ParticleIntegrator>(integrator_);
    s.wind = {wind_, 0.0f, 0.0f};
    s.dragCoefficient = cd_;
    s.airDensity = 1.23f; // the book's
    s.particleCollisions = collisions_;
    return s;
  }

  std::optional<ParticleWorld> world_;
  std::vector<SphereObstacle> spheres_;
  BoxObstacle box_;
  float wall_ = 26.0f;       // m, the walls' distance from the centre
  float wind_ = 10.0f;       // m/s: the book's V_w
  float cd_ = 0.6f;          // the book's C_d
  float restitution_ = 0.6f; // the book's e
  float friction_ = 0.4f;
  float rate_ = 40.0f; // particles per second
  int integrator_ = 0;
  bool collisions_ = false;
  History count_;
  History energy_;
  History drift_;
};

const SampleRegistrar registrar{"Book", "Particles",
                                "The book's particle simulator (ch. 8): balls raining through air with drag "
                                "and wind onto obstacles and the ground, bouncing and coming to rest.",
                                [] { return std::make_unique<Particles>(); }};

} // namespace
} // namespace impetus::samples
