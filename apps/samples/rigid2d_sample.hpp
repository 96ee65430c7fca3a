// The base of every sample on the 2D rigid-body world: it owns the World, steps it, draws it
// (with the debug-draw switches in the panel), lets the mouse drag a dynamic body through a mouse
// joint (a soft spring of at most 1000 m g: the body follows the pointer but cannot be yanked
// through walls), and checks that the state stays finite.
#pragma once

#include "plot.hpp"
#include "rigid2d_draw.hpp"
#include "sample.hpp"

#include <impetus/rigid2d/world.hpp>

#include <optional>
#include <string>
#include <vector>

namespace impetus::samples {

class Rigid2dSample : public Sample {
public:
  void step(float dt) override;
  void draw(DebugDraw& draw) override;
  void ui() override;
  [[nodiscard]] bool finite() const override;
  /// Bodies (awake), joints, touching contacts and the kinetic energy.
  [[nodiscard]] std::string summary() const override;

  bool mouseDown(const Vec2f& world, MouseButton button) override;
  void mouseMove(const Vec2f& world) override;
  void mouseUp(const Vec2f& world, MouseButton button) override;

protected:
  [[nodiscard]] rigid2d::World& world() noexcept { return world_; }
  [[nodiscard]] const rigid2d::World& world() const noexcept { return world_; }
  /// Starts over with an empty world (drag and time forgotten).
  void resetWorld(const rigid2d::WorldDef& def);
  /// Starts over with a world built elsewhere (the benchmark scenes' builder).
  void adoptWorld(rigid2d::World&& world);

  /// Hooks around World::step: forces for the coming step, readouts after it.
  virtual void beforeStep(float /*dt*/) {}
  virtual void afterStep(float /*dt*/) {}
  /// The sample's own controls and plots (the debug-draw switches follow them).
  virtual void parameters() {}
  /// Drawn over the world (trajectories, rays, labels).
  virtual void drawOverlay(DebugDraw& /*draw*/) {}
  /// A colour for some bodies; none: by type and state.
  [[nodiscard]] virtual std::optional<Color> bodyColorOf(rigid2d::BodyId /*body*/) const { return std::nullopt; }

  /// Kinetic energy of the dynamic bodies, sum of 1/2 m v^2 + 1/2 I w^2, J (per metre of depth:
  /// the 2D world is a slab of unit depth).
  [[nodiscard]] float kineticEnergy() const;
  /// Seconds simulated since the last reset.
  [[nodiscard]] float time() const noexcept { return time_; }

  Rigid2dDrawOptions drawOptions_;

private:
  struct Drag {
    rigid2d::MouseJointId joint;
    rigid2d::BodyId body;
    Vec2f localAnchor; ///< the grabbed point, body frame, m
    Vec2f target;      ///< world, m
  };

  rigid2d::World world_;
  std::optional<Drag> drag_;
  float time_ = 0.0f;
  float lastDt_ = 0.0f; ///< s, the last step's: turns the solver's impulses into drawn forces
  mutable std::vector<rigid2d::BodyId> bodyScratch_;
};

} // namespace impetus::samples
