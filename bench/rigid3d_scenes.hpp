// The 3D rigid-body scenes of the side-by-side benchmark (bench/impetus_bench3d.cpp), checked by
// tests/bench/rigid3d_scenes_test.cpp. A scene is plain data (bodies, each with one box or sphere
// centred on its origin) with no engine in it: Impetus' rigid3d::World builds it in
// rigid3d_impetus_scene.hpp and Bullet 3.24 in bullet_scenes.hpp, so both get identical geometry.
// The quality figures here are computed from body poses alone, so they measure either engine the
// same way.
//
// Where a name is another engine's benchmark scene, the scene is that one, like for like:
// large_pyramid is Box3D's (shared/benchmarks.c, CreateLargePyramid), jolt_pyramid is Jolt's
// PerformanceTest `Pyramid` (PerformanceTest/PyramidScene.h), each with its own box size,
// spacing, ground, density and friction.
//
// Every scene: gravity (0, -10, 0) m/s^2, +y up, steps of 1/60 s, no restitution, no sleeping.
#pragma once

#include <impetus/math/quat.hpp>
#include <impetus/math/transform3.hpp>
#include <impetus/math/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace impetus::bench {

/// A body of a 3D scene with its one shape, a box or a sphere, centred on the body origin.
struct Scene3dBody {
  enum class Type { staticBody, dynamicBody };
  enum class Shape { box, sphere };
  Type type = Type::dynamicBody;
  Shape shape = Shape::box;
  Vec3f position;                     ///< body origin and shape centre, world, m
  Quatf rotation = Quatf::identity(); ///< body frame in the world
  Vec3f halfExtents;                  ///< box, body frame, m
  float radius = 0.0f;                ///< sphere, m
  float density = 1000.0f;            ///< kg/m^3 (static bodies: unused)
  float friction = 0.6f;              ///< Coulomb coefficient; a pair's is the geometric mean of its two
};

/// A scene as plain data: what every engine builds.
struct Rigid3dScene {
  std::string name;
  std::string origin; ///< whose scene it is, for the report
  std::vector<Scene3dBody> bodies;
  /// Bodies whose sinking is the quality figure (each pyramid's top box); may be empty.
  std::vector<std::uint32_t> tops;
  /// For each top, the height of its centre with every box resting on the ones below it, m (the
  /// starting height where the scene starts touching; lower where its layers start apart and fall).
  std::vector<float> topRestHeights;
  int defaultSteps = 500;            ///< steps of 1/60 s the benchmark runs by default
  Vec3f gravity{0.0f, -10.0f, 0.0f}; ///< m/s^2
};

inline constexpr float scene3dTimeStep = 1.0f / 60.0f; ///< s

/// "large_pyramid" (Box3D's benchmark): a pyramid of cubes of half-size 0.5 m in the plane z = 0,
/// `base` of them in the bottom row (base 100: 5050 boxes), rows touching and boxes side by side
/// touching: row i (from 0) holds base - i boxes at y = i + 0.5 m, centred on x = 0. Density
/// 100 kg/m^3, friction 0.6. The ground is a static box of half-extents 400 x 1 x 400 m centred
/// at (0, -1, 0), its top at y = 0. The top box is the quality figure. 200 steps (Box3D's own
/// count for it: a step of this scene is the slowest of the three).
inline constexpr int largePyramid3dBase = 100;
inline constexpr float largePyramid3dHalfSize = 0.5f;  ///< m
inline constexpr float largePyramid3dDensity = 100.0f; ///< kg/m^3
[[nodiscard]] Rigid3dScene largePyramid3dScene(int base = largePyramid3dBase);

/// "pyramid_20": large_pyramid's construction with a base of 20 (210 boxes), for quick runs and
/// tests. 500 steps.
[[nodiscard]] Rigid3dScene pyramid20Scene();

/// "jolt_pyramid" (Jolt's PerformanceTest `Pyramid`): a stepped pyramid of cubes of 2 m (half-size
/// 1 m), jolt3dPyramidLayers layers; layer i (from 0) is a square of (15 - i) x (15 - i) boxes side
/// by side touching, at x, z = -15 + 2 j (+ 1 on odd layers) for j from i / 2 to 15 - (i + 1) / 2
/// (exclusive), so each box of an odd layer stands on four; its centres at y = 1 + 2.5 i, so the
/// layers start 0.5 m apart and fall onto each other. 1240 boxes, density 1000 kg/m^3 and friction
/// 0.2 (Jolt's defaults). The floor is a static box of half-extents 50 x 1 x 50 m centred at
/// (0, -1, 0). The top box (at (-1, 36, -1), resting at y = 29) is the quality figure. 500 steps
/// (PerformanceTest's default).
inline constexpr int jolt3dPyramidLayers = 15;
inline constexpr float jolt3dPyramidHalfSize = 1.0f;   ///< m
inline constexpr float jolt3dPyramidSeparation = 0.5f; ///< m between layers at the start
inline constexpr float jolt3dPyramidFriction = 0.2f;   ///< Jolt's default
inline constexpr float jolt3dPyramidDensity = 1000.0f; ///< kg/m^3, Jolt's default
[[nodiscard]] Rigid3dScene joltPyramidScene();

/// "shape_rain" (Impetus' own): shapeRainColumns x shapeRainColumns columns of shapeRainLayers
/// bodies (1000) dropped at rest into a walled bin: by turns a sphere of radius 0.4 m, a cube of
/// half-size 0.4 m and a flat box of half-extents 0.6 x 0.2 x 0.4 m, each turned about its own
/// axis by its own angle (a fixed low-discrepancy sequence), shapeRainSpacing apart in x, y and z
/// with the lowest layer's centres at y = 2 m, shifted by up to 5 cm more so that no two land
/// squarely. Density 1000 kg/m^3, friction 0.6. The bin: a floor box (top at y = 0) and four walls
/// 4 m tall around an inner square of 18 m a side. No tops; 500 steps.
inline constexpr int shapeRainColumns = 10;
inline constexpr int shapeRainLayers = 10;
inline constexpr float shapeRainSpacing = 1.6f; ///< m, more than the widest shape's diameter (1.5 m)
[[nodiscard]] Rigid3dScene shapeRainScene();

/// Scene names, in the benchmark's order: large_pyramid, jolt_pyramid, pyramid_20, shape_rain.
[[nodiscard]] std::vector<std::string> rigid3dSceneNames();
/// The scene of that name; throws impetus::Error naming `scene` for an unknown one.
[[nodiscard]] Rigid3dScene makeRigid3dScene(std::string_view name);

// Quality figures, from body poses (the body origin's transform, in scene order) alone.

/// Every body at its starting pose.
[[nodiscard]] std::vector<Transform3f> startPoses(const Rigid3dScene& scene);
/// The largest sinking of the scene's tops below their rest heights, m (negative when every top
/// is above its rest height; 0 without tops).
[[nodiscard]] float topSink(const Rigid3dScene& scene, std::span<const Transform3f> poses);
/// The deepest overlap between the shapes of two bodies (at least one dynamic) at these poses, m
/// (0 when nothing overlaps): the penetration depth, the least distance that would part them,
/// exact for these shapes: for two boxes, the separating-axis test on their 15 axes (the
/// three face normals of each and the nine cross products of their edges); for a sphere, the
/// distance to the box's or the other sphere's surface. Pairs come from sweeping the bodies'
/// bounding boxes along x.
[[nodiscard]] float largestOverlap(const Rigid3dScene& scene, std::span<const Transform3f> poses);
/// The overlap of two boxes (half extents, poses), m: 0 or less when apart (then the negative of
/// the widest gap along one of the 15 axes, a lower bound of the distance).
[[nodiscard]] float boxOverlap(const Vec3f& halfA, const Transform3f& a, const Vec3f& halfB, const Transform3f& b);
/// Whether every pose is finite.
[[nodiscard]] bool allFinite(std::span<const Transform3f> poses);
/// Number of dynamic bodies.
[[nodiscard]] std::size_t dynamicBodyCount(const Rigid3dScene& scene);

} // namespace impetus::bench
