#include "rigid2d_sample.hpp"
#include "ui.hpp"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <utility>

namespace impetus::samples {

using namespace impetus::rigid2d;

void Rigid2dSample::resetWorld(const WorldDef& def) { adoptWorld(World(def)); }

void Rigid2dSample::adoptWorld(World&& world) {
  world_ = std::move(world);
  drag_.reset();
  time_ = 0.0f;
  lastDt_ = 0.0f;
}

void Rigid2dSample::step(float dt) {
  beforeStep(dt);
  world_.step(dt);
  time_ += dt;
  lastDt_ = dt;
  afterStep(dt);
}

void Rigid2dSample::draw(DebugDraw& draw) {
  BodyColorFn colorOf = [this](BodyId body) { return bodyColorOf(body); };
  drawWorld(world_, draw, drawOptions_, lastDt_, colorOf);
  if (drag_ && world_.isValid(drag_->joint)) {
    const Transform2f xf = world_.transform(drag_->body);
    draw.segment(transformPoint(xf, drag_->localAnchor), drag_->target, palette::joint);
    draw.point(drag_->target, 6.0f, palette::joint);
  }
  drawOverlay(draw);
}

void Rigid2dSample::ui() {
  parameters();
  if (ImGui::CollapsingHeader("Debug draw")) {
    drawOptionsUi(drawOptions_);
    textWrapped("%zu bodies (%zu awake), %zu joints, %zu contacts", world_.bodyCount(), world_.awakeBodyCount(),
                world_.jointCount(), world_.contactCount());
  }
}

bool Rigid2dSample::finite() const {
  world_.bodyIds(bodyScratch_);
  for (const BodyId body : bodyScratch_) {
    const Transform2f xf = world_.transform(body);
    if (!isFinite(xf.p) || !std::isfinite(xf.q.c) || !std::isfinite(xf.q.s) || !isFinite(world_.linearVelocity(body)) ||
        !std::isfinite(world_.angularVelocity(body))) {
      return false;
    }
  }
  return true;
}

std::string Rigid2dSample::summary() const {
  char text[160];
  std::snprintf(text, sizeof text,
                "%zu bodies (%zu awake), %zu joints, %zu touching contacts, kinetic energy %.3g J per metre of depth",
                world_.bodyCount(), world_.awakeBodyCount(), world_.jointCount(), world_.contactCount(),
                static_cast<double>(kineticEnergy()));
  return text;
}

float Rigid2dSample::kineticEnergy() const {
  world_.bodyIds(bodyScratch_);
  float energy = 0.0f;
  for (const BodyId body : bodyScratch_) {
    if (world_.bodyType(body) != BodyType::dynamicBody) {
      continue;
    }
    const float w = world_.angularVelocity(body);
    energy += 0.5f * world_.mass(body) * lengthSquared(world_.linearVelocity(body)) +
              0.5f * world_.rotationalInertia(body) * w * w;
  }
  return energy;
}

bool Rigid2dSample::mouseDown(const Vec2f& p, MouseButton button) {
  if (button != MouseButton::left || drag_) {
    return false;
  }
  for (const ShapeId shape : world_.queryPoint(p)) {
    const BodyId body = world_.shapeBody(shape);
    if (world_.bodyType(body) != BodyType::dynamicBody || world_.isSensor(shape)) {
      continue;
    }
    // Pull hard enough to lift the body against gravity (1000 m g), softly (5 Hz, damped), so
    // the drag is felt through contacts and joints instead of teleporting the body.
    const float g = std::max(length(world_.settings().gravity), 10.0f);
    MouseJointDef def;
    def.bodyA = body; // ignored by the mouse joint: it pulls toward the world
    def.bodyB = body;
    def.localAnchorB = inverseTransformPoint(world_.transform(body), p);
    def.target = p;
    def.hertz = 5.0f;
    def.dampingRatio = 0.7f;
    def.maxForce = 1000.0f * world_.mass(body) * g;
    drag_ = Drag{world_.createJoint(def), body, def.localAnchorB, p};
    world_.setAwake(body, true);
    return true;
  }
  return false;
}

void Rigid2dSample::mouseMove(const Vec2f& p) {
  if (drag_ && world_.isValid(drag_->joint)) {
    drag_->target = p;
    setMouseTarget(world_, drag_->joint, p);
  }
}

void Rigid2dSample::mouseUp(const Vec2f& /*p*/, MouseButton button) {
  if (button != MouseButton::left || !drag_) {
    return;
  }
  if (world_.isValid(drag_->joint)) {
    world_.destroyJoint(drag_->joint);
  }
  drag_.reset();
}

} // namespace impetus::samples
