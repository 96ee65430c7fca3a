// Engine/Chain bridge: planks pinned end to end by revolute joints between two posts, loaded by a
// few boxes and balls. The joints carry the load as tension along the chain, which hangs in a
// catenary-like sag; the plots show how far the middle plank hangs below the posts (m) and the
// largest joint reaction force (N per metre of depth), which grows as the sag shrinks (a tauter
// chain needs more tension to hold the same weight). Joint friction damps the swinging.
#include "rigid2d_sample.hpp"
#include "ui.hpp"

#include <imgui.h>

#include <algorithm>

namespace impetus::samples {
namespace {

using namespace impetus::rigid2d;

class ChainBridge final : public Rigid2dSample {
public:
  void setup() override {
    resetWorld({});
    const BodyId ground = world().createBody({});
    world().createShape(ground, {}, makeOffsetBox(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    const float plank = 1.0f; // m, each plank's length
    const float span = plank * static_cast<float>(planks_);
    const float x0 = -0.5f * span;
    const float height = 6.0f;
    world().createShape(ground, {}, makeOffsetBox(0.5f, 0.5f * height, {x0 - 0.5f, 0.5f * height}, 0.0f));
    world().createShape(ground, {}, makeOffsetBox(0.5f, 0.5f * height, {-x0 + 0.5f, 0.5f * height}, 0.0f));
    ShapeDef plankShape;
    plankShape.density = density_;
    plankShape.friction = 0.6f;
    BodyId previous = ground;
    Vec2f previousAnchor{x0, height}; // in the ground's frame (its origin is the world origin)
    planksIds_.clear();
    for (int i = 0; i < planks_; ++i) {
      BodyDef def;
      def.type = BodyType::dynamicBody;
      def.position = {x0 + plank * (static_cast<float>(i) + 0.5f), height - 0.125f};
      const BodyId body = world().createBody(def);
      world().createShape(body, plankShape, makeBox(0.5f * plank, 0.125f));
      RevoluteJointDef joint;
      joint.bodyA = previous;
      joint.bodyB = body;
      joint.localAnchorA = previousAnchor;
      joint.localAnchorB = {-0.5f * plank, 0.125f};
      joint.frictionTorque = friction_;
      world().createJoint(joint);
      previous = body;
      previousAnchor = {0.5f * plank, 0.125f};
      planksIds_.push_back(body);
    }
    RevoluteJointDef last;
    last.bodyA = previous;
    last.bodyB = ground;
    last.localAnchorA = previousAnchor;
    last.localAnchorB = {-x0, height};
    last.frictionTorque = friction_;
    world().createJoint(last);
    // The load: a few boxes and balls dropped on the deck.
    for (int i = 0; i < loads_; ++i) {
      BodyDef def;
      def.type = BodyType::dynamicBody;
      def.position = {x0 + span * (static_cast<float>(i) + 0.5f) / static_cast<float>(loads_), height + 3.0f};
      const BodyId body = world().createBody(def);
      ShapeDef load;
      load.density = 2.0f;
      if (i % 2 == 0) {
        world().createShape(body, load, makeBox(0.6f, 0.6f));
      } else {
        world().createShape(body, load, Circle{{}, 0.6f});
      }
    }
    postHeight_ = height;
    sag_.clear();
    force_.clear();
  }
  [[nodiscard]] CameraView initialView() const override {
    return {{0.0f, 4.0f}, 6.0f, 0.5f * static_cast<float>(planks_) + 3.0f};
  }

protected:
  void afterStep(float /*dt*/) override {
    const BodyId middle = planksIds_[planksIds_.size() / 2];
    sag_.push(postHeight_ - world().position(middle).y);
    float largest = 0.0f;
    world().jointIds(joints_);
    for (const JointId joint : joints_) {
      if (world().jointType(joint) == JointType::revolute) { // not the mouse's
        largest = std::max(largest, length(world().jointReactionForce(joint)));
      }
    }
    force_.push(largest);
  }

  void parameters() override {
    slider("planks of 1 m", &planks_, 4, 60);
    bool rebuild = ImGui::IsItemDeactivatedAfterEdit();
    slider("loads", &loads_, 0, 12);
    rebuild |= ImGui::IsItemDeactivatedAfterEdit();
    slider("plank density", &density_, 0.1f, 10.0f, "%.1f kg/m^2");
    rebuild |= ImGui::IsItemDeactivatedAfterEdit();
    slider("joint friction", &friction_, 0.0f, 50.0f, "%.1f N m");
    rebuild |= ImGui::IsItemDeactivatedAfterEdit();
    if (rebuild) {
      setup();
    }
    sag_.plot("sag of the middle plank below the posts (m)", "%.3f m");
    force_.plot("largest joint reaction force (N per m of depth)", "%.1f N");
  }

private:
  int planks_ = 20;
  int loads_ = 4;
  float density_ = 1.0f;  // kg/m^2
  float friction_ = 2.0f; // N m
  float postHeight_ = 6.0f;
  std::vector<BodyId> planksIds_;
  std::vector<JointId> joints_; // scratch, reused every step
  History sag_;
  History force_;
};

const SampleRegistrar registrar{"Engine", "Chain bridge",
                                "Planks on revolute joints between two posts sag under a load; the joints' "
                                "reaction forces carry it as tension.",
                                [] { return std::make_unique<ChainBridge>(); }};

} // namespace
} // namespace impetus::samples
