#include "bench_scene_sample.hpp"
#include "ui.hpp"

#include <imgui.h>

#include <algorithm>
#include <limits>
#include <utility>

namespace impetus::samples {

void BenchSceneSample::buildScene(bench::Rigid2dScene scene) {
  scene_ = std::move(scene);
  bench::ImpetusSettings settings;
  settings.enableSleep = sleep_;
  bench::ImpetusScene built = bench::buildImpetusScene(scene_, settings);
  bodies_ = std::move(built.bodies);
  adoptWorld(std::move(built.world));
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

void BenchSceneSample::sceneControls() {
  if (checkbox("sleeping", &sleep_)) {
    setup();
  }
  textWrapped("%zu bodies (%zu dynamic), %zu joints", scene_.bodies.size(), bench::dynamicBodyCount(scene_),
              scene_.joints.size());
}

} // namespace impetus::samples
