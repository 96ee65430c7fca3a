// The 2D rigid-body scenes of the side-by-side benchmark (bench/impetus_bench.cpp), checked by
// tests/bench/rigid2d_scenes_test.cpp. A scene is first described as plain data (bodies and their
// boxes and circles), then built in an engine: here in Impetus' rigid2d::World, and in Box2D 2.4.1
// by bench/box2d_scenes.hpp from the same description, so both engines get identical geometry.
//
// Every scene: gravity (0, -10) m/s^2 (the smash: none), density 1 kg/m^2, friction 0.6, no restitution, sleeping
// off in both engines (what is timed is the solver at work), steps of 1/60 s.
#pragma once

#include <impetus/math/scalar.hpp>
#include <impetus/math/transform2.hpp>
#include <impetus/rigid2d/world.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace impetus::bench {

/// A shape of a scene body, in the body frame: a box (half-widths, centre, angle) or a circle.
struct SceneShape {
  enum class Kind { box, circle };
  Kind kind = Kind::box;
  std::uint32_t body = 0; ///< index into Rigid2dScene::bodies
  Vec2f center;           ///< box or circle centre in the body frame, m
  float halfWidth = 0.0f; ///< box, m
  float halfHeight = 0.0f;
  float angle = 0.0f;     ///< box rotation in the body frame, rad
  float radius = 0.0f;    ///< circle, m
  std::int32_t group = 0; ///< collision group (negative: shapes of the group never collide)
};

/// A revolute joint between two bodies at a world point (the scene's initial pose), with
/// optional angle limits.
struct SceneJoint {
  std::uint32_t bodyA = 0;
  std::uint32_t bodyB = 0;
  Vec2f anchor; ///< world, m, at the start
  bool enableLimit = false;
  float lowerAngle = 0.0f; ///< rad
  float upperAngle = 0.0f; ///< rad
};

struct SceneBody {
  rigid2d::BodyType type = rigid2d::BodyType::staticBody;
  Vec2f position;               ///< body origin, m
  float angularVelocity = 0.0f; ///< rad/s (the tumbler's kinematic drum)
  Vec2f linearVelocity;         ///< m/s (the smash's projectile)
  bool bullet = false;          ///< continuous collision against dynamic bodies (the smash's projectile)
};

/// A scene as plain data: what both engines build.
struct Rigid2dScene {
  std::string name;
  std::vector<SceneBody> bodies;
  std::vector<SceneShape> shapes; ///< grouped by body, in body order
  std::vector<SceneJoint> joints;
  /// Bodies whose sinking is the quality figure (the top box of each pyramid); may be empty.
  std::vector<std::uint32_t> tops;
  int defaultSteps = 500;      ///< steps of 1/60 s the benchmark runs by default
  Vec2f gravity{0.0f, -10.0f}; ///< m/s^2 (zero for the smash)
};

inline constexpr float sceneTimeStep = 1.0f / 60.0f; ///< s
inline constexpr float sceneDensity = 1.0f;          ///< kg/m^2
inline constexpr float sceneFriction = 0.6f;
inline constexpr Vec2f sceneGravity{0.0f, -10.0f}; ///< m/s^2

/// Half-size of the pyramids' boxes, m.
inline constexpr float pyramidBoxHalfSize = 0.5f;

/// "large_pyramid" (as Box2D v3's benchmark): a pyramid of `base` boxes at the bottom (base 100:
/// 5050 boxes) of half-size 0.5 m, rows touching, standing on a static ground box of half-extents
/// 100 x 1 m whose top is y = 0 (its centre at (0, -1)). Row i (from 0) holds base - i boxes at
/// y = i + 0.5, centred on x = 0. The top box is the quality figure.
[[nodiscard]] Rigid2dScene largePyramidScene(int base = 100);

/// "many_pyramids": `count` pyramids of base `base` (default 10 of base 20: 2100 boxes), side by
/// side one box apart on one ground box (top at y = 0, 10 m wider than the row on each side).
inline constexpr int manyPyramidsCount = 10;
inline constexpr int manyPyramidsBase = 20;
[[nodiscard]] Rigid2dScene manyPyramidsScene(int count = manyPyramidsCount, int base = manyPyramidsBase);

/// "rain_N": `count` circles of radius 0.25 m dropped at rest into a wide open box: a floor
/// (top at y = 0) and two walls 10 m tall. The circles stand in rainRows rows (rainRowSpacing apart,
/// the lowest at y = 1 m) and ceil(count / rainRows) columns (rainColumnSpacing apart); every other
/// row is shifted by half a column, and every circle by up to 5 cm more (a fixed low-discrepancy
/// sequence), so that they do not land in perfect towers. The box is as wide as the columns,
/// so the pile is equally deep (about 8 circles) at every count: the work per circle is the
/// same at every size, and the cost should grow linearly (n log n at worst, for the broadphase).
inline constexpr float rainRadius = 0.25f;
inline constexpr std::size_t rainRows = 10;
inline constexpr float rainRowSpacing = 0.75f;   ///< m
inline constexpr float rainColumnSpacing = 0.6f; ///< m
[[nodiscard]] Rigid2dScene rainScene(std::size_t count);

/// "tumbler" (as Box2D v3's benchmark): a kinematic drum at (0, 10) m, a hollow square of four
/// boxes (inner side 19 m, walls 1 m thick) turning at 25 degrees per second, holding a grid of
/// grid x grid (default 45 x 45 = 2025) boxes of half-size 0.125 m 0.4 m apart. Box2D v3 turns
/// a dynamic drum with a revolute motor; a kinematic body with an angular velocity is the same
/// motion without joints (which Impetus does not have yet).
inline constexpr int tumblerGrid = 45;
inline constexpr float tumblerSpeed = 25.0f * pi<float> / 180.0f; ///< rad/s
[[nodiscard]] Rigid2dScene tumblerScene(int grid = tumblerGrid);

/// "smash" (after Box2D v3's): in zero gravity, a block of smashGrid x smashGrid boxes of
/// half-size 0.1 m, touching, its left face at x = 0 and centred on y = 0, is hit at 40 m/s by a
/// 4 x 4 m box of the same density (a bullet in both engines) starting 10 m to its left. 300 steps.
inline constexpr int smashGrid = 60;
[[nodiscard]] Rigid2dScene smashScene(int grid = smashGrid);

/// "joint_grid" (after Box2D v3's): grid x grid circles of radius 0.4 m, 1 m apart, each joined
/// by revolute joints to its neighbours above and to the left; seven circles in the middle of the
/// top row are static, so the net hangs and swings. The circles do not collide (one negative
/// group). 500 steps. Quality: the widest gap between a joint's two anchors at the end.
inline constexpr int jointGridSize = 100;
[[nodiscard]] Rigid2dScene jointGridScene(int grid = jointGridSize);

/// "ragdolls": `columns` x `rows` ragdolls of 9 boxes and a circle head joined by 9 revolute
/// joints with limits (elbows, knees, shoulders, hips, neck), dropped into an open box. 500 steps.
inline constexpr int ragdollColumns = 20;
inline constexpr int ragdollRows = 15;
[[nodiscard]] Rigid2dScene ragdollScene(int columns = ragdollColumns, int rows = ragdollRows);

/// Scene names, in the benchmark's order: large_pyramid, many_pyramids, tumbler, rain_1k,
/// rain_10k, rain_100k.
[[nodiscard]] std::vector<std::string> rigid2dSceneNames();
/// The scene of that name (also rain_N and rain_Nk for N or N thousand circles); throws
/// impetus::Error naming `scene` for an unknown one.
[[nodiscard]] Rigid2dScene makeRigid2dScene(std::string_view name);

/// The scene built in Impetus (the default WorldDef, gravity (0, -10) and 4 substeps, with
/// sleeping off); `bodies[i]` is the id of the scene's body i.
struct ImpetusScene {
  rigid2d::World world;
  std::vector<rigid2d::BodyId> bodies;
};
/// Solver settings a benchmark run may change (the defaults are WorldDef's) and the task runner
/// (optional, not owned) for the world's parallel loops. Sleeping is off unlike WorldDef's
/// default: the benchmark times the solver, and a scene that falls asleep would cost almost
/// nothing; the samples app switches it on to show sleeping in the same scenes.
struct ImpetusSettings {
  int substeps = rigid2d::WorldDef{}.substeps;
  float contactHertz = rigid2d::WorldDef{}.contactHertz;
  float contactReuseDistance = rigid2d::WorldDef{}.contactReuseDistance; ///< m; 0: collide every pair every step
  rigid2d::SimdLevel simd = rigid2d::WorldDef{}.simd;
  bool enableSleep = false;
  TaskRunner* runner = nullptr;
};
[[nodiscard]] ImpetusScene buildImpetusScene(const Rigid2dScene& scene, const ImpetusSettings& settings = {});
/// Every body's transform, in scene order.
[[nodiscard]] std::vector<Transform2f> bodyTransforms(const ImpetusScene& built);

// Quality figures, computed from body transforms alone, so they measure either engine the same way.

/// The largest sinking of the scene's `tops`, m: initial minus current height, negative when every
/// top rose (0 without tops).
[[nodiscard]] float topSink(const Rigid2dScene& scene, std::span<const Transform2f> transforms);
/// The deepest overlap between any two shapes of different bodies (at least one dynamic) at these
/// transforms, m (0 when nothing overlaps): Impetus' manifold functions on the scene's exact
/// geometry, for pairs found by sweeping the shapes' bounding boxes along x.
[[nodiscard]] float largestOverlap(const Rigid2dScene& scene, std::span<const Transform2f> transforms);
/// The widest gap between a joint's two anchors at these transforms, m (0 without joints).
[[nodiscard]] float largestJointGap(const Rigid2dScene& scene, std::span<const Transform2f> transforms);
/// Whether every transform is finite.
[[nodiscard]] bool allFinite(std::span<const Transform2f> transforms);
/// Number of dynamic bodies.
[[nodiscard]] std::size_t dynamicBodyCount(const Rigid2dScene& scene);

} // namespace impetus::bench
