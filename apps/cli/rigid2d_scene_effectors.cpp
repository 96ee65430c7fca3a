// The rigid2d scene loader's force effectors (docs/scene-format-2d.md, "effectors"): each one's
// settings, checked with the JSON path of each value, and the time window it runs in.
#include "json_fields.hpp"
#include "rigid2d_scene_loader.hpp"

#include <impetus/error.hpp>
#include <impetus/rigid2d/effectors.hpp>

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>

namespace impetus::cli {

namespace {

using json_fields::at;
using json_fields::fail;
using json_fields::Fields;
using json_fields::requiredVec2;
using json_fields::typeOf;
using json_fields::vec2;
using nlohmann::json;
using namespace rigid2d;

// Effectors: every effector runs only in its time window [start, stop). ---------------------

class Scheduled final : public ForceEffector {
public:
  Scheduled(std::unique_ptr<ForceEffector> inner, double start, double stop)
      : inner_(std::move(inner)), start_(start), stop_(stop) {}
  void apply(World& world, float dt) override {
    if (time_ >= start_ && time_ < stop_) {
      inner_->apply(world, dt);
    }
    ++steps_;
    time_ = static_cast<double>(steps_) * static_cast<double>(dt);
  }

private:
  std::unique_ptr<ForceEffector> inner_;
  double start_;
  double stop_;
  double time_ = 0.0;
  std::int64_t steps_ = 0;
};

} // namespace

namespace rigid2d_loader {

template <class E, class S> void Loader::addEffector(Fields& f, const std::string& where, const S& settings) {
  const double start = f.nonNegative("start", 0.0);
  double stop = std::numeric_limits<double>::infinity();
  if (f.has("stop")) {
    stop = f.nonNegative("stop", 0.0);
    if (stop < start) {
      throwInvalid(f.path("stop"), stop, "must be >= start");
    }
  }
  f.done();
  auto effector = at(where, [&] { return std::make_unique<E>(settings); });
  scene_.effectors.add(Scheduled(std::move(effector), start, stop));
}

void Loader::effector(const json& j, const std::string& where) {
  Fields f(j, where);
  const std::string type =
      typeOf(f, {"gravity_field", "point_attractor", "wind_drag", "thruster", "spring_damper", "explosion", "buoyancy"},
             "effector type");
  World& world = scene_.world;
  if (type == "gravity_field") {
    GravityFieldSettings s;
    s.acceleration = requiredVec2(f, "acceleration");
    if (const json* r = f.find("region")) {
      Fields rf(*r, f.path("region"));
      const Vec2f lo = requiredVec2(rf, "min");
      const Vec2f hi = requiredVec2(rf, "max");
      rf.done();
      if (!(hi.x >= lo.x && hi.y >= lo.y)) {
        fail(rf.path("max"), "must be >= min in both components");
      }
      s.region = AABB{lo, hi};
    }
    addEffector<GravityField>(f, where, s);
  } else if (type == "point_attractor") {
    PointAttractorSettings s;
    s.center = requiredVec2(f, "center");
    s.mu = f.requiredReal("mu");
    s.softening = f.nonNegative("softening", s.softening);
    if (f.has("max_radius")) {
      s.maxRadius = f.positive("max_radius", 1.0);
    }
    addEffector<PointAttractor>(f, where, s);
  } else if (type == "wind_drag") {
    WindDragSettings s;
    s.body = bodyNamed(f, "body");
    s.airVelocity = vec2(f, "air_velocity", s.airVelocity);
    s.airDensity = f.nonNegative("air_density", s.airDensity);
    s.dragArea = f.nonNegative("drag_area", s.dragArea);
    s.linearDrag = f.nonNegative("linear_drag", s.linearDrag);
    s.localCenterOfPressure = vec2(f, "local_center_of_pressure", s.localCenterOfPressure);
    addEffector<WindDrag>(f, where, s);
  } else if (type == "thruster") {
    ThrusterSettings s;
    s.body = bodyNamed(f, "body");
    s.localPoint = vec2(f, "local_point", s.localPoint);
    s.localDirection = vec2(f, "local_direction", s.localDirection);
    if (!(length(s.localDirection) > 1e-6f)) {
      fail(f.path("local_direction"), "must be non-zero");
    }
    s.thrust = f.requiredReal("thrust");
    addEffector<Thruster>(f, where, s);
  } else if (type == "spring_damper") {
    SpringDamperSettings s;
    s.bodyA = bodyNamed(f, "body_a");
    s.localAnchorA = anchor(f, s.bodyA, "a", false);
    Vec2f worldB;
    if (f.has("body_b")) {
      s.bodyB = bodyNamed(f, "body_b");
      if (s.bodyB == s.bodyA) {
        fail(f.path("body_b"), "a spring needs two different bodies (or a world point: leave out body_b)");
      }
      s.localAnchorB = anchor(f, s.bodyB, "b", false);
      worldB = transformPoint(world.transform(s.bodyB), s.localAnchorB);
    } else {
      s.localAnchorB = requiredVec2(f, "anchor_b");
      worldB = s.localAnchorB;
    }
    s.stiffness = f.nonNegative("stiffness", s.stiffness);
    s.damping = f.nonNegative("damping", s.damping);
    s.restLength = f.has("rest_length") ? f.nonNegative("rest_length", 0.0)
                                        : distance(transformPoint(world.transform(s.bodyA), s.localAnchorA), worldB);
    addEffector<SpringDamper>(f, where, s);
  } else if (type == "explosion") {
    ExplosionSettings s;
    s.center = requiredVec2(f, "center");
    s.radius = f.requiredPositive("radius");
    s.impulse = f.nonNegative("impulse", s.impulse);
    addEffector<Explosion>(f, where, s);
  } else {
    BuoyancySettings s;
    s.surfaceHeight = f.requiredReal("surface_height");
    if (f.has("x_min")) {
      s.xMin = f.real("x_min", 0.0);
    }
    if (f.has("x_max")) {
      s.xMax = f.real("x_max", 0.0);
    }
    if (s.xMax < s.xMin) {
      throwInvalid(f.path("x_max"), s.xMax, "must be >= x_min");
    }
    s.fluidDensity = f.positive("fluid_density", s.fluidDensity);
    s.gravity = gravity_;
    s.fluidVelocity = vec2(f, "fluid_velocity", s.fluidVelocity);
    s.linearDrag = f.nonNegative("linear_drag", s.linearDrag);
    s.angularDrag = f.nonNegative("angular_drag", s.angularDrag);
    addEffector<Buoyancy>(f, where, s);
  }
}

} // namespace rigid2d_loader

} // namespace impetus::cli
