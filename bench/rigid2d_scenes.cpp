// Builders of the 2D rigid-body benchmark scenes (see rigid2d_scenes.hpp for what each one is).
#include "rigid2d_scenes.hpp"

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/manifold.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numeric>
#include <variant>

namespace impetus::bench {
namespace {

using rigid2d::BodyType;

std::uint32_t addBody(Rigid2dScene& scene, BodyType type, const Vec2f& position, float angularVelocity = 0.0f) {
  scene.bodies.push_back({type, position, angularVelocity, {}, false});
  return static_cast<std::uint32_t>(scene.bodies.size() - 1);
}

void addBox(Rigid2dScene& scene, std::uint32_t body, float halfWidth, float halfHeight, const Vec2f& center = {},
            float angle = 0.0f) {
  SceneShape s;
  s.kind = SceneShape::Kind::box;
  s.body = body;
  s.center = center;
  s.halfWidth = halfWidth;
  s.halfHeight = halfHeight;
  s.angle = angle;
  scene.shapes.push_back(s);
}

void addCircle(Rigid2dScene& scene, std::uint32_t body, float radius, std::int32_t group = 0,
               const Vec2f& center = {}) {
  SceneShape s;
  s.kind = SceneShape::Kind::circle;
  s.body = body;
  s.radius = radius;
  s.group = group;
  s.center = center;
  scene.shapes.push_back(s);
}

void addJoint(Rigid2dScene& scene, std::uint32_t a, std::uint32_t b, const Vec2f& anchor, float lower = 0.0f,
              float upper = 0.0f) {
  scene.joints.push_back({a, b, anchor, lower != upper, lower, upper});
}

/// A pyramid of `base` boxes at the bottom, centred on x = centerX, standing on y = 0; its top
/// box is recorded in scene.tops.
void addPyramid(Rigid2dScene& scene, int base, float centerX) {
  constexpr float h = pyramidBoxHalfSize;
  for (int i = 0; i < base; ++i) {
    const int rowCount = base - i;
    const float y = static_cast<float>(2 * i + 1) * h;
    for (int j = 0; j < rowCount; ++j) {
      // Row i: boxes 2h apart, centred on centerX.
      const float x = centerX + (static_cast<float>(2 * j) - static_cast<float>(rowCount - 1)) * h;
      const std::uint32_t b = addBody(scene, BodyType::dynamicBody, {x, y});
      addBox(scene, b, h, h);
    }
  }
  scene.tops.push_back(static_cast<std::uint32_t>(scene.bodies.size() - 1));
}

/// Fractional part of i times the golden ratio: an evenly spread sequence in [0, 1).
float goldenFraction(std::size_t i) {
  const double x = static_cast<double>(i) * 0.6180339887498949;
  return static_cast<float>(x - std::floor(x));
}

using Geometry = std::variant<rigid2d::Polygon, rigid2d::Circle>;

Geometry geometryOf(const SceneShape& s) {
  if (s.kind == SceneShape::Kind::circle) {
    return rigid2d::Circle{s.center, s.radius};
  }
  return rigid2d::makeOffsetBox(s.halfWidth, s.halfHeight, s.center, s.angle);
}

/// The smallest separation of the manifold's points (positive when apart; large when none).
float separation(const rigid2d::Manifold& m) {
  float least = 1.0e30f;
  for (int i = 0; i < m.pointCount; ++i) {
    least = std::min(least, m.points[static_cast<std::size_t>(i)].separation);
  }
  return least;
}

float separation(const Geometry& a, const Transform2f& xfA, const Geometry& b, const Transform2f& xfB) {
  const auto* ca = std::get_if<rigid2d::Circle>(&a);
  const auto* cb = std::get_if<rigid2d::Circle>(&b);
  if (ca != nullptr && cb != nullptr) {
    return separation(rigid2d::collideCircles(*ca, xfA, *cb, xfB));
  }
  if (ca != nullptr) {
    return separation(rigid2d::collidePolygonAndCircle(std::get<rigid2d::Polygon>(b), xfB, *ca, xfA));
  }
  if (cb != nullptr) {
    return separation(rigid2d::collidePolygonAndCircle(std::get<rigid2d::Polygon>(a), xfA, *cb, xfB));
  }
  return separation(rigid2d::collidePolygons(std::get<rigid2d::Polygon>(a), xfA, std::get<rigid2d::Polygon>(b), xfB));
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

Rigid2dScene manyPyramidsScene(int count, int base) {
  Rigid2dScene scene;
  scene.name = "many_pyramids";
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

Rigid2dScene rainScene(std::size_t count) {
  Rigid2dScene scene;
  scene.name = "rain_" + (count % 1000 == 0 ? std::to_string(count / 1000) + "k" : std::to_string(count));
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

Rigid2dScene tumblerScene(int grid) {
  Rigid2dScene scene;
  scene.name = "tumbler";
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

Rigid2dScene smashScene(int grid) {
  Rigid2dScene scene;
  scene.name = "smash";
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

float largestJointGap(const Rigid2dScene& scene, std::span<const Transform2f> transforms) {
  float widest = 0.0f;
  for (const SceneJoint& j : scene.joints) {
    const Vec2f localA = j.anchor - scene.bodies[j.bodyA].position; // bodies start unrotated
    const Vec2f localB = j.anchor - scene.bodies[j.bodyB].position;
    widest = std::max(
        widest, distance(transformPoint(transforms[j.bodyA], localA), transformPoint(transforms[j.bodyB], localB)));
  }
  return widest;
}

std::vector<std::string> rigid2dSceneNames() {
  return {"large_pyramid", "many_pyramids", "tumbler",  "smash",    "joint_grid",
          "ragdolls",      "rain_1k",       "rain_10k", "rain_100k"};
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
  if (name == "ragdolls") {
    return ragdollScene();
  }
  // rain_N or rain_Nk: N (thousand) circles.
  if (name.starts_with("rain_") && name.size() > 5) {
    std::string_view digits = name.substr(5);
    std::size_t scale = 1;
    if (digits.ends_with('k')) {
      digits.remove_suffix(1);
      scale = 1000;
    }
    std::size_t count = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), count);
    if (error == std::errc{} && end == digits.data() + digits.size() && count > 0 && count <= 10000000 / scale) {
      return rainScene(count * scale);
    }
  }
  throw Error("scene", "unknown 2D benchmark scene '" + std::string(name) +
                           "' (large_pyramid, many_pyramids, tumbler, smash, joint_grid, ragdolls, rain_N or rain_Nk: "
                           "rain_1k, rain_10k, rain_100k)");
}

ImpetusScene buildImpetusScene(const Rigid2dScene& scene, const ImpetusSettings& settings) {
  rigid2d::WorldDef def;
  def.taskRunner = settings.runner;
  def.substeps = settings.substeps;
  def.contactHertz = settings.contactHertz;
  def.contactReuseDistance = settings.contactReuseDistance;
  def.simd = settings.simd;
  def.gravity = scene.gravity;
  def.enableSleep = settings.enableSleep;
  ImpetusScene built{rigid2d::World(def), {}};
  built.bodies.reserve(scene.bodies.size());
  for (const SceneBody& b : scene.bodies) {
    rigid2d::BodyDef bd;
    bd.type = b.type;
    bd.position = b.position;
    bd.angularVelocity = b.angularVelocity;
    bd.linearVelocity = b.linearVelocity;
    bd.bullet = b.bullet;
    built.bodies.push_back(built.world.createBody(bd));
  }
  rigid2d::ShapeDef sd;
  sd.density = sceneDensity;
  sd.friction = sceneFriction;
  for (const SceneShape& s : scene.shapes) {
    const rigid2d::BodyId body = built.bodies[s.body];
    sd.filter.group = s.group;
    if (s.kind == SceneShape::Kind::circle) {
      built.world.createShape(body, sd, rigid2d::Circle{s.center, s.radius});
    } else {
      built.world.createShape(body, sd, rigid2d::makeOffsetBox(s.halfWidth, s.halfHeight, s.center, s.angle));
    }
  }
  for (const SceneJoint& j : scene.joints) {
    rigid2d::RevoluteJointDef jd;
    jd.bodyA = built.bodies[j.bodyA];
    jd.bodyB = built.bodies[j.bodyB];
    jd.localAnchorA = j.anchor - scene.bodies[j.bodyA].position; // bodies start unrotated
    jd.localAnchorB = j.anchor - scene.bodies[j.bodyB].position;
    jd.enableLimit = j.enableLimit;
    jd.lowerAngle = j.lowerAngle;
    jd.upperAngle = j.upperAngle;
    built.world.createJoint(jd);
  }
  return built;
}

std::vector<Transform2f> bodyTransforms(const ImpetusScene& built) {
  std::vector<Transform2f> out;
  out.reserve(built.bodies.size());
  for (const rigid2d::BodyId id : built.bodies) {
    out.push_back(built.world.transform(id));
  }
  return out;
}

float topSink(const Rigid2dScene& scene, std::span<const Transform2f> transforms) {
  if (scene.tops.empty()) {
    return 0.0f;
  }
  float sink = -std::numeric_limits<float>::infinity();
  for (const std::uint32_t top : scene.tops) {
    sink = std::max(sink, scene.bodies[top].position.y - transforms[top].p.y);
  }
  return sink;
}

float largestOverlap(const Rigid2dScene& scene, std::span<const Transform2f> transforms) {
  const std::size_t n = scene.shapes.size();
  std::vector<Geometry> geometry;
  std::vector<rigid2d::AABB> boxes;
  geometry.reserve(n);
  boxes.reserve(n);
  for (const SceneShape& s : scene.shapes) {
    geometry.push_back(geometryOf(s));
    const Transform2f& xf = transforms[s.body];
    boxes.push_back(std::visit([&](const auto& g) { return rigid2d::computeAABB(g, xf); }, geometry.back()));
  }
  // Sort and sweep along x: each shape meets the shapes that start before it ends.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return boxes[a].lower.x != boxes[b].lower.x ? boxes[a].lower.x < boxes[b].lower.x : a < b;
  });
  float deepest = 0.0f;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = order[k];
    const SceneShape& sa = scene.shapes[a];
    for (std::size_t m = k + 1; m < n && boxes[order[m]].lower.x <= boxes[a].upper.x; ++m) {
      const std::size_t b = order[m];
      const SceneShape& sb = scene.shapes[b];
      if (sa.body == sb.body || boxes[b].lower.y > boxes[a].upper.y || boxes[a].lower.y > boxes[b].upper.y) {
        continue;
      }
      if (scene.bodies[sa.body].type != BodyType::dynamicBody && scene.bodies[sb.body].type != BodyType::dynamicBody) {
        continue;
      }
      deepest = std::max(deepest, -separation(geometry[a], transforms[sa.body], geometry[b], transforms[sb.body]));
    }
  }
  return deepest;
}

bool allFinite(std::span<const Transform2f> transforms) {
  return std::all_of(transforms.begin(), transforms.end(), [](const Transform2f& xf) {
    return std::isfinite(xf.p.x) && std::isfinite(xf.p.y) && std::isfinite(xf.q.c) && std::isfinite(xf.q.s);
  });
}

std::size_t dynamicBodyCount(const Rigid2dScene& scene) {
  return static_cast<std::size_t>(std::count_if(scene.bodies.begin(), scene.bodies.end(),
                                                [](const SceneBody& b) { return b.type == BodyType::dynamicBody; }));
}

} // namespace impetus::bench
