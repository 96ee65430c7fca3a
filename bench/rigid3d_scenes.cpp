// Builders of the 3D rigid-body benchmark scenes and their quality figures (see
// rigid3d_scenes.hpp for what each one is).
#include "rigid3d_scenes.hpp"

#include <impetus/error.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

namespace impetus::bench {
namespace {

using Type = Scene3dBody::Type;

std::uint32_t addBox(Rigid3dScene& scene, Type type, const Vec3f& position, const Vec3f& halfExtents, float density,
                     float friction) {
  Scene3dBody b;
  b.type = type;
  b.shape = Scene3dBody::Shape::box;
  b.position = position;
  b.halfExtents = halfExtents;
  b.density = density;
  b.friction = friction;
  scene.bodies.push_back(b);
  return static_cast<std::uint32_t>(scene.bodies.size() - 1);
}

/// Box3D's plane pyramid (CreateLargePyramid) of `base` cubes at the bottom on its ground box.
Rigid3dScene planePyramid(std::string name, int base) {
  if (base < 1) {
    throwInvalid("base", base, "must be at least 1");
  }
  Rigid3dScene scene;
  scene.name = std::move(name);
  scene.origin = "Box3D's benchmark large_pyramid (shared/benchmarks.c)";
  constexpr float h = largePyramid3dHalfSize;
  constexpr float friction = 0.6f; // Box3D's default surface material
  addBox(scene, Type::staticBody, {0.0f, -1.0f, 0.0f}, {400.0f, 1.0f, 400.0f}, 0.0f, friction);
  for (int i = 0; i < base; ++i) {
    const float y = (2.0f * static_cast<float>(i) + 1.0f) * h;
    for (int j = i; j < base; ++j) {
      // Box3D's own expression: the row's first box half a box further in than the row below's.
      const float x =
          (static_cast<float>(i) + 1.0f) * h + 2.0f * static_cast<float>(j - i) * h - h * static_cast<float>(base);
      const std::uint32_t id =
          addBox(scene, Type::dynamicBody, {x, y, 0.0f}, {h, h, h}, largePyramid3dDensity, friction);
      if (i == base - 1) {
        scene.tops.push_back(id);
        scene.topRestHeights.push_back(y);
      }
    }
  }
  return scene;
}

/// The fractional part of i times an irrational: an evenly spread sequence in [0, 1).
float goldenFraction(std::size_t i, double irrational) {
  const double x = static_cast<double>(i) * irrational;
  return static_cast<float>(x - std::floor(x));
}

Vec3d toDouble(const Vec3f& v) { return {v.x, v.y, v.z}; }

/// A box's axes (its body frame's, in the world) and centre, in double.
struct Box {
  std::array<Vec3d, 3> axes;
  Vec3d half;
  Vec3d center;
};

Box boxOf(const Vec3f& half, const Transform3f& pose) {
  return {{toDouble(rotate(pose.q, Vec3f{1.0f, 0.0f, 0.0f})), toDouble(rotate(pose.q, Vec3f{0.0f, 1.0f, 0.0f})),
           toDouble(rotate(pose.q, Vec3f{0.0f, 0.0f, 1.0f}))},
          toDouble(half),
          toDouble(pose.p)};
}

/// The box's extent along a unit axis from its centre, m.
double radiusAlong(const Box& b, const Vec3d& axis) {
  return b.half.x * std::abs(dot(b.axes[0], axis)) + b.half.y * std::abs(dot(b.axes[1], axis)) +
         b.half.z * std::abs(dot(b.axes[2], axis));
}

double sphereBoxOverlap(const Vec3f& center, float radius, const Vec3f& half, const Transform3f& pose) {
  const Vec3d local = toDouble(inverseRotate(pose.q, center - pose.p));
  const Vec3d h = toDouble(half);
  const Vec3d clamped{std::clamp(local.x, -h.x, h.x), std::clamp(local.y, -h.y, h.y), std::clamp(local.z, -h.z, h.z)};
  if (clamped != local) {
    return radius - length(local - clamped);
  }
  // The centre inside: out through the nearest face.
  return radius + std::min({h.x - std::abs(local.x), h.y - std::abs(local.y), h.z - std::abs(local.z)});
}

double overlapOf(const Scene3dBody& a, const Transform3f& pa, const Scene3dBody& b, const Transform3f& pb) {
  using Shape = Scene3dBody::Shape;
  if (a.shape == Shape::sphere && b.shape == Shape::sphere) {
    return double{a.radius} + double{b.radius} - length(toDouble(pb.p) - toDouble(pa.p));
  }
  if (a.shape == Shape::sphere) {
    return sphereBoxOverlap(pa.p, a.radius, b.halfExtents, pb);
  }
  if (b.shape == Shape::sphere) {
    return sphereBoxOverlap(pb.p, b.radius, a.halfExtents, pa);
  }
  return boxOverlap(a.halfExtents, pa, b.halfExtents, pb);
}

/// A body's bounding box at a pose: lower and upper corners.
std::array<Vec3f, 2> boundsOf(const Scene3dBody& body, const Transform3f& pose) {
  Vec3f extent{body.radius, body.radius, body.radius};
  if (body.shape == Scene3dBody::Shape::box) {
    const Mat33f r = toMat33(pose.q);
    extent = abs(r.cx) * body.halfExtents.x + abs(r.cy) * body.halfExtents.y + abs(r.cz) * body.halfExtents.z;
  }
  return {pose.p - extent, pose.p + extent};
}

} // namespace

Rigid3dScene largePyramid3dScene(int base) {
  Rigid3dScene scene = planePyramid("large_pyramid", base);
  scene.defaultSteps = 200;
  return scene;
}

Rigid3dScene pyramid20Scene() {
  Rigid3dScene scene = planePyramid("pyramid_20", 20);
  scene.origin = "Box3D's large_pyramid with a base of 20";
  scene.defaultSteps = 500;
  return scene;
}

Rigid3dScene joltPyramidScene() {
  Rigid3dScene scene;
  scene.name = "jolt_pyramid";
  scene.origin = "Jolt's PerformanceTest Pyramid (PerformanceTest/PyramidScene.h)";
  constexpr int n = jolt3dPyramidLayers;
  constexpr float h = jolt3dPyramidHalfSize;
  constexpr float size = 2.0f * h;
  addBox(scene, Type::staticBody, {0.0f, -1.0f, 0.0f}, {50.0f, 1.0f, 50.0f}, 0.0f, jolt3dPyramidFriction);
  for (int i = 0; i < n; ++i) {
    const float shift = (i & 1) != 0 ? h : 0.0f; // odd layers: each box on four below
    const float y = 1.0f + (size + jolt3dPyramidSeparation) * static_cast<float>(i);
    for (int j = i / 2; j < n - (i + 1) / 2; ++j) {
      for (int k = i / 2; k < n - (i + 1) / 2; ++k) {
        const Vec3f p{static_cast<float>(-n) + size * static_cast<float>(j) + shift, y,
                      static_cast<float>(-n) + size * static_cast<float>(k) + shift};
        const std::uint32_t id =
            addBox(scene, Type::dynamicBody, p, {h, h, h}, jolt3dPyramidDensity, jolt3dPyramidFriction);
        if (i == n - 1) {
          scene.tops.push_back(id);
          scene.topRestHeights.push_back(h + size * static_cast<float>(i)); // layers stacked, no gaps
        }
      }
    }
  }
  scene.defaultSteps = 500;
  return scene;
}

Rigid3dScene shapeRainScene() {
  Rigid3dScene scene;
  scene.name = "shape_rain";
  scene.origin = "Impetus' own: spheres, cubes and flat boxes dropped into a bin";
  constexpr float inner = 9.0f;      // m, the bin's inner half-width
  constexpr float wallHalf = 0.5f;   // m, half a wall's thickness
  constexpr float wallHeight = 4.0f; // m
  addBox(scene, Type::staticBody, {0.0f, -1.0f, 0.0f}, {inner + 2.0f * wallHalf, 1.0f, inner + 2.0f * wallHalf}, 0.0f,
         0.6f);
  const Vec3f alongZ{wallHalf, 0.5f * wallHeight, inner + 2.0f * wallHalf};
  const Vec3f alongX{inner, 0.5f * wallHeight, wallHalf};
  addBox(scene, Type::staticBody, {-inner - wallHalf, 0.5f * wallHeight, 0.0f}, alongZ, 0.0f, 0.6f);
  addBox(scene, Type::staticBody, {inner + wallHalf, 0.5f * wallHeight, 0.0f}, alongZ, 0.0f, 0.6f);
  addBox(scene, Type::staticBody, {0.0f, 0.5f * wallHeight, -inner - wallHalf}, alongX, 0.0f, 0.6f);
  addBox(scene, Type::staticBody, {0.0f, 0.5f * wallHeight, inner + wallHalf}, alongX, 0.0f, 0.6f);
  const float first = -0.5f * shapeRainSpacing * static_cast<float>(shapeRainColumns - 1);
  std::size_t n = 0;
  for (int layer = 0; layer < shapeRainLayers; ++layer) {
    for (int i = 0; i < shapeRainColumns; ++i) {
      for (int k = 0; k < shapeRainColumns; ++k, ++n) {
        // A shift of up to 5 cm in x and z, and a turn about an axis spread over the sphere.
        const float u = goldenFraction(n, 0.6180339887498949);
        const float v = goldenFraction(n, 0.7548776662466927);
        const float w = goldenFraction(n, 0.5698402909980532);
        const Vec3f position{first + shapeRainSpacing * static_cast<float>(i) + 0.1f * (u - 0.5f),
                             2.0f + shapeRainSpacing * static_cast<float>(layer),
                             first + shapeRainSpacing * static_cast<float>(k) + 0.1f * (v - 0.5f)};
        const float polar = std::acos(1.0f - 2.0f * v);
        const float azimuth = 2.0f * std::numbers::pi_v<float> * u;
        const Vec3f axis{std::sin(polar) * std::cos(azimuth), std::cos(polar), std::sin(polar) * std::sin(azimuth)};
        Scene3dBody b;
        b.position = position;
        b.rotation = Quatf::fromAxisAngle(axis, 2.0f * std::numbers::pi_v<float> * w);
        b.density = 1000.0f;
        b.friction = 0.6f;
        switch (n % 3) {
        case 0:
          b.shape = Scene3dBody::Shape::sphere;
          b.radius = 0.4f;
          break;
        case 1:
          b.halfExtents = {0.4f, 0.4f, 0.4f};
          break;
        default:
          b.halfExtents = {0.6f, 0.2f, 0.4f};
          break;
        }
        scene.bodies.push_back(b);
      }
    }
  }
  scene.defaultSteps = 500;
  return scene;
}

std::vector<std::string> rigid3dSceneNames() { return {"large_pyramid", "jolt_pyramid", "pyramid_20", "shape_rain"}; }

Rigid3dScene makeRigid3dScene(std::string_view name) {
  if (name == "large_pyramid") {
    return largePyramid3dScene();
  }
  if (name == "jolt_pyramid") {
    return joltPyramidScene();
  }
  if (name == "pyramid_20") {
    return pyramid20Scene();
  }
  if (name == "shape_rain") {
    return shapeRainScene();
  }
  throw Error("scene", "unknown 3D benchmark scene '" + std::string(name) +
                           "' (known: large_pyramid, jolt_pyramid, pyramid_20, shape_rain)");
}

std::vector<Transform3f> startPoses(const Rigid3dScene& scene) {
  std::vector<Transform3f> poses;
  poses.reserve(scene.bodies.size());
  for (const Scene3dBody& b : scene.bodies) {
    poses.push_back({b.position, b.rotation});
  }
  return poses;
}

float topSink(const Rigid3dScene& scene, std::span<const Transform3f> poses) {
  if (scene.tops.empty()) {
    return 0.0f;
  }
  float sink = -std::numeric_limits<float>::infinity();
  for (std::size_t k = 0; k < scene.tops.size(); ++k) {
    sink = std::max(sink, scene.topRestHeights[k] - poses[scene.tops[k]].p.y);
  }
  return sink;
}

float boxOverlap(const Vec3f& halfA, const Transform3f& a, const Vec3f& halfB, const Transform3f& b) {
  const Box ba = boxOf(halfA, a);
  const Box bb = boxOf(halfB, b);
  const Vec3d d = bb.center - ba.center;
  double depth = std::numeric_limits<double>::infinity();
  const auto along = [&](const Vec3d& axis) {
    depth = std::min(depth, radiusAlong(ba, axis) + radiusAlong(bb, axis) - std::abs(dot(d, axis)));
  };
  for (int i = 0; i < 3; ++i) {
    along(ba.axes[static_cast<std::size_t>(i)]);
    along(bb.axes[static_cast<std::size_t>(i)]);
  }
  // Edge against edge; nearly parallel edges give no axis the face normals do not.
  for (const Vec3d& ea : ba.axes) {
    for (const Vec3d& eb : bb.axes) {
      const Vec3d c = cross(ea, eb);
      const double len = length(c);
      if (len > 1.0e-6) {
        along(c / len);
      }
    }
  }
  return static_cast<float>(depth);
}

float largestOverlap(const Rigid3dScene& scene, std::span<const Transform3f> poses) {
  const std::size_t n = scene.bodies.size();
  std::vector<std::array<Vec3f, 2>> bounds;
  bounds.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    bounds.push_back(boundsOf(scene.bodies[i], poses[i]));
  }
  // Sort and sweep along x: each body meets the bodies that start before it ends.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return bounds[a][0].x != bounds[b][0].x ? bounds[a][0].x < bounds[b][0].x : a < b;
  });
  double deepest = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = order[k];
    for (std::size_t m = k + 1; m < n && bounds[order[m]][0].x <= bounds[a][1].x; ++m) {
      const std::size_t b = order[m];
      const bool bothStatic = scene.bodies[a].type == Type::staticBody && scene.bodies[b].type == Type::staticBody;
      if (bothStatic || bounds[b][0].y > bounds[a][1].y || bounds[a][0].y > bounds[b][1].y ||
          bounds[b][0].z > bounds[a][1].z || bounds[a][0].z > bounds[b][1].z) {
        continue;
      }
      deepest = std::max(deepest, overlapOf(scene.bodies[a], poses[a], scene.bodies[b], poses[b]));
    }
  }
  return static_cast<float>(deepest);
}

bool allFinite(std::span<const Transform3f> poses) {
  return std::all_of(poses.begin(), poses.end(), [](const Transform3f& p) { return isFinite(p.p) && isFinite(p.q); });
}

std::size_t dynamicBodyCount(const Rigid3dScene& scene) {
  return static_cast<std::size_t>(std::count_if(scene.bodies.begin(), scene.bodies.end(),
                                                [](const Scene3dBody& b) { return b.type == Type::dynamicBody; }));
}

} // namespace impetus::bench
