// Builders of the 2D rigid-body benchmark scenes (see rigid2d_scenes.hpp for what each one is).
#include "rigid2d_scenes.hpp"

#include "rigid2d_scene_parts.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace impetus::bench {
using namespace parts;
namespace {

/// Fractional part of i times the golden ratio: an evenly spread sequence in [0, 1).
float goldenFraction(std::size_t i) {
  const double x = static_cast<double>(i) * 0.6180339887498949;
  return static_cast<float>(x - std::floor(x));
}

} // namespace

Rigid2dScene largePyramidScene(int base) {
  Rigid2dScene scene;
  scene.name = "large_pyramid";
  const std::uint32_t ground = addBody(scene, BodyType::staticBody, {0.0f, -1.0f});
  addBox(scene, ground, 100.0f, 1.0f);
  addPyramid(scene, base, 0.0f);
  scene.defaultSteps = 500;
  return scene;
}

Rigid2dScene pyramidRowScene(int count, int base) {
  Rigid2dScene scene;
  scene.name = "pyramid_row";
  constexpr float h = pyramidBoxHalfSize;
  const float pitch = static_cast<float>(base + 1) * 2.0f * h; // one box of space between pyramids
  const float rowWidth = static_cast<float>(count) * pitch;
  const std::uint32_t ground = addBody(scene, BodyType::staticBody, {0.0f, -1.0f});
  addBox(scene, ground, 0.5f * rowWidth + 10.0f, 1.0f);
  for (int k = 0; k < count; ++k) {
    addPyramid(scene, base, (static_cast<float>(k) + 0.5f) * pitch - 0.5f * rowWidth);
  }
  scene.defaultSteps = 500;
  return scene;
}

Rigid2dScene circleRainScene(std::size_t count) {
  Rigid2dScene scene;
  scene.name = "circle_rain_" + (count % 1000 == 0 ? std::to_string(count / 1000) + "k" : std::to_string(count));
  const std::size_t columns = std::max<std::size_t>(1, (count + rainRows - 1) / rainRows);
  const float halfInner = 0.5f * static_cast<float>(columns) * rainColumnSpacing + 0.5f * rainColumnSpacing;
  const std::uint32_t ground = addBody(scene, BodyType::staticBody, {0.0f, 0.0f});
  addBox(scene, ground, halfInner + 1.0f, 1.0f, {0.0f, -1.0f}); // floor, top at y = 0
  addBox(scene, ground, 0.5f, 5.0f, {-halfInner - 0.5f, 5.0f}); // walls, 10 m tall
  addBox(scene, ground, 0.5f, 5.0f, {halfInner + 0.5f, 5.0f});
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t row = i / columns;
    const std::size_t column = i % columns;
    const float shift = (row % 2 == 1 ? 0.5f * rainColumnSpacing : 0.0f) + 0.05f * (goldenFraction(i) - 0.5f);
    const float x = (static_cast<float>(column) - 0.5f * static_cast<float>(columns - 1)) * rainColumnSpacing + shift;
    const float y = 1.0f + static_cast<float>(row) * rainRowSpacing;
    const std::uint32_t b = addBody(scene, BodyType::dynamicBody, {x, y});
    addCircle(scene, b, rainRadius);
  }
  scene.defaultSteps = 300;
  return scene;
}

Rigid2dScene kinematicTumblerScene(int grid) {
  Rigid2dScene scene;
  scene.name = "kinematic_tumbler";
  const std::uint32_t drum = addBody(scene, BodyType::kinematicBody, {0.0f, 10.0f}, tumblerSpeed);
  addBox(scene, drum, 0.5f, 10.0f, {10.0f, 0.0f});
  addBox(scene, drum, 0.5f, 10.0f, {-10.0f, 0.0f});
  addBox(scene, drum, 10.0f, 0.5f, {0.0f, 10.0f});
  addBox(scene, drum, 10.0f, 0.5f, {0.0f, -10.0f});
  const float start = -0.2f * static_cast<float>(grid);
  for (int i = 0; i < grid; ++i) {
    for (int j = 0; j < grid; ++j) {
      const Vec2f p{start + 0.4f * static_cast<float>(j), start + 10.0f + 0.4f * static_cast<float>(i)};
      const std::uint32_t b = addBody(scene, BodyType::dynamicBody, p);
      addBox(scene, b, 0.125f, 0.125f);
    }
  }
  scene.defaultSteps = 500;
  return scene;
}

Rigid2dScene smashAwakeScene(int grid) {
  Rigid2dScene scene;
  scene.name = "smash_awake";
  scene.gravity = {};
  constexpr float h = 0.1f;
  const float half = static_cast<float>(grid) * h;
  for (int i = 0; i < grid; ++i) {
    for (int j = 0; j < grid; ++j) {
      const Vec2f p{(static_cast<float>(2 * j) + 1.0f) * h, (static_cast<float>(2 * i) + 1.0f) * h - half};
      addBox(scene, addBody(scene, BodyType::dynamicBody, p), h, h);
    }
  }
  const std::uint32_t projectile = addBody(scene, BodyType::dynamicBody, {-12.0f, 0.0f});
  scene.bodies[projectile].linearVelocity = {40.0f, 0.0f};
  scene.bodies[projectile].bullet = true;
  addBox(scene, projectile, 2.0f, 2.0f);
  scene.defaultSteps = 300;
  return scene;
}

Rigid2dScene jointGridScene(int grid) {
  Rigid2dScene scene;
  scene.name = "joint_grid";
  constexpr float shift = 1.0f;
  constexpr float radius = 0.4f;
  const auto index = [&](int row, int column) { return static_cast<std::uint32_t>(row * grid + column); };
  for (int row = 0; row < grid; ++row) {
    for (int column = 0; column < grid; ++column) {
      const bool pinned = row == 0 && std::abs(column - grid / 2) <= 3;
      const Vec2f p{static_cast<float>(column - grid / 2) * shift, -static_cast<float>(row) * shift};
      const std::uint32_t b = addBody(scene, pinned ? BodyType::staticBody : BodyType::dynamicBody, p);
      addCircle(scene, b, radius, -1);
      if (row > 0) {
        addJoint(scene, index(row - 1, column), b, {p.x, p.y + 0.5f * shift});
      }
      if (column > 0) {
        addJoint(scene, index(row, column - 1), b, {p.x - 0.5f * shift, p.y});
      }
    }
  }
  scene.defaultSteps = 500;
  return scene;
}

namespace {

/// One ragdoll standing with its feet at `feet`: torso, head, upper and lower arms and legs.
void addRagdoll(Rigid2dScene& scene, const Vec2f& feet) {
  constexpr float pi = impetus::pi<float>;
  const auto part = [&](const Vec2f& center, float hx, float hy) {
    const std::uint32_t b = addBody(scene, BodyType::dynamicBody, feet + center);
    addBox(scene, b, hx, hy);
    return b;
  };
  const std::uint32_t torso = part({0.0f, 1.15f}, 0.15f, 0.3f);
  const std::uint32_t head = addBody(scene, BodyType::dynamicBody, feet + Vec2f{0.0f, 1.6f});
  addCircle(scene, head, 0.13f);
  addJoint(scene, torso, head, feet + Vec2f{0.0f, 1.47f}, -0.4f, 0.4f);
  for (const float side : {-1.0f, 1.0f}) {
    const std::uint32_t upperLeg = part({0.08f * side, 0.65f}, 0.07f, 0.2f);
    const std::uint32_t lowerLeg = part({0.08f * side, 0.225f}, 0.06f, 0.2f);
    addJoint(scene, torso, upperLeg, feet + Vec2f{0.08f * side, 0.85f}, -0.5f * pi, 0.25f * pi);
    addJoint(scene, upperLeg, lowerLeg, feet + Vec2f{0.08f * side, 0.44f}, -0.05f, 0.8f * pi);
    const std::uint32_t upperArm = part({0.22f * side, 1.25f}, 0.05f, 0.16f);
    const std::uint32_t lowerArm = part({0.22f * side, 0.92f}, 0.045f, 0.16f);
    addJoint(scene, torso, upperArm, feet + Vec2f{0.22f * side, 1.4f}, -pi, pi);
    addJoint(scene, upperArm, lowerArm, feet + Vec2f{0.22f * side, 1.08f}, -0.8f * pi, 0.05f);
  }
}

} // namespace

Rigid2dScene ragdollScene(int columns, int rows) {
  Rigid2dScene scene;
  scene.name = "ragdolls";
  constexpr float pitch = 1.0f;  // m between ragdolls in a row
  constexpr float height = 2.2f; // m between rows
  const float halfInner = 0.5f * static_cast<float>(columns) * pitch + 0.5f;
  const std::uint32_t ground = addBody(scene, BodyType::staticBody, {0.0f, 0.0f});
  addBox(scene, ground, halfInner + 1.0f, 1.0f, {0.0f, -1.0f});
  addBox(scene, ground, 0.5f, 20.0f, {-halfInner - 0.5f, 20.0f});
  addBox(scene, ground, 0.5f, 20.0f, {halfInner + 0.5f, 20.0f});
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      const float shift = row % 2 == 1 ? 0.3f : 0.0f;
      addRagdoll(scene, {(static_cast<float>(column) - 0.5f * static_cast<float>(columns - 1)) * pitch + shift,
                         0.5f + static_cast<float>(row) * height});
    }
  }
  scene.defaultSteps = 500;
  return scene;
}

std::vector<std::string> rigid2dSceneNames() {
  return {"large_pyramid",   "many_pyramids", "tumbler",           "smash",       "joint_grid",     "rain",
          "ragdolls",        "pyramid_row",   "kinematic_tumbler", "smash_awake", "circle_rain_1k", "circle_rain_10k",
          "circle_rain_100k"};
}

Rigid2dScene makeRigid2dScene(std::string_view name) {
  if (name == "large_pyramid") {
    return largePyramidScene();
  }
  if (name == "many_pyramids") {
    return manyPyramidsScene();
  }
  if (name == "tumbler") {
    return tumblerScene();
  }
  if (name == "smash") {
    return smashScene();
  }
  if (name == "joint_grid") {
    return jointGridScene();
  }
  if (name == "rain") {
    return rainScene();
  }
  if (name == "ragdolls") {
    return ragdollScene();
  }
  if (name == "pyramid_row") {
    return pyramidRowScene();
  }
  if (name == "kinematic_tumbler") {
    return kinematicTumblerScene();
  }
  if (name == "smash_awake") {
    return smashAwakeScene();
  }
  // circle_rain_N or circle_rain_Nk: N (thousand) circles.
  constexpr std::string_view rain = "circle_rain_";
  if (name.starts_with(rain) && name.size() > rain.size()) {
    std::string_view digits = name.substr(rain.size());
    std::size_t scale = 1;
    if (digits.ends_with('k')) {
      digits.remove_suffix(1);
      scale = 1000;
    }
    std::size_t count = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), count);
    if (error == std::errc{} && end == digits.data() + digits.size() && count > 0 && count <= 10000000 / scale) {
      return circleRainScene(count * scale);
    }
  }
  throw Error("scene", "unknown 2D benchmark scene '" + std::string(name) +
                           "' (large_pyramid, many_pyramids, tumbler, smash, joint_grid, rain, ragdolls, pyramid_row, "
                           "kinematic_tumbler, smash_awake, circle_rain_N or circle_rain_Nk: circle_rain_1k, "
                           "circle_rain_10k, circle_rain_100k)");
}

} // namespace impetus::bench
