#include "bench_scene_sample.hpp"

#include <imgui.h>

#include <algorithm>
#include <limits>
#include <utility>

namespace impetus::samples {

void BenchSceneSample::buildScene(bench::Rigid2dScene scene) {
  scene_ = std::move(scene);
  bench::ImpetusScene built = bench::buildImpetusScene(scene_);
  bodies_ = std::move(built.bodies);
  adoptWorld(std::move(built.world));
  // The builder makes the scene's revolute joints in order in a fresh world, which hands out
  // JointId {i, 1} for the i-th (the world has no call that lists its joints). Each guess is
  // checked against the bodies it must join; a mismatch just leaves that joint undrawn.
  for (std::size_t i = 0; i < scene_.joints.size(); ++i) {
    const bench::SceneJoint& j = scene_.joints[i];
    const rigid2d::JointId id{static_cast<std::uint32_t>(i), 1};
    if (!world().isValid(id) || world().jointBodyA(id) != bodies_[j.bodyA] ||
        world().jointBodyB(id) != bodies_[j.bodyB]) {
      continue;
    }
    // Scene bodies start unrotated, so a local anchor is the world anchor minus the origin.
    recordJoint({id, j.anchor - scene_.bodies[j.bodyA].position, j.anchor - scene_.bodies[j.bodyB].position});
  }
  view_ = fitView();
}

std::vector<Transform2f> BenchSceneSample::transforms() const {
  std::vector<Transform2f> out;
  out.reserve(bodies_.size());
  for (const rigid2d::BodyId body : bodies_) {
    out.push_back(world().transform(body));
  }
  return out;
}

CameraView BenchSceneSample::fitView() const {
  Vec2f lower{std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
  Vec2f upper = -lower;
  for (const bench::SceneShape& s : scene_.shapes) {
    const bench::SceneBody& body = scene_.bodies[s.body];
    if (body.type == rigid2d::BodyType::staticBody) {
      continue; // grounds are far wider than the action
    }
    const float r = s.kind == bench::SceneShape::Kind::circle ? s.radius : std::max(s.halfWidth, s.halfHeight) * 1.5f;
    lower = min(lower, body.position + s.center - Vec2f{r, r});
    upper = max(upper, body.position + s.center + Vec2f{r, r});
  }
  if (!(lower.x <= upper.x)) {
    return {};
  }
  const Vec2f half = (upper - lower) * 0.5f;
  return {(lower + upper) * 0.5f, half.y * 1.15f + 0.5f, half.x * 1.1f + 0.5f};
}

void BenchSceneSample::sceneInfo() const {
  ImGui::Text("%zu bodies (%zu dynamic), %zu joints", scene_.bodies.size(), bench::dynamicBodyCount(scene_),
              scene_.joints.size());
}

} // namespace impetus::samples
