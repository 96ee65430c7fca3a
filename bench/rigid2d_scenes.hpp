// The 2D rigid-body scenes of the side-by-side benchmark (bench/impetus_bench.cpp), checked by
// tests/bench/rigid2d_scenes_test.cpp. A scene is first described as plain data (bodies and their
// boxes, circles and segments, revolute joints), then built in an engine: here in Impetus'
// rigid2d::World, in Box2D 2.4.1 by bench/box2d_scenes.hpp and in Box2D v3 by
// bench/box2d3_scenes.hpp from the same description, so every engine gets identical geometry.
//
// Where a name is also a scene of Box2D v3's own benchmark (large_pyramid, many_pyramids,
// tumbler, smash, joint_grid, rain), the scene is v3's, like for like (box2d3_benchmark_scenes.cpp,
// rain_scene.cpp);
// Impetus' earlier variants are kept under names of their own (pyramid_row, kinematic_tumbler,
// smash_awake, circle_rain_N).
//
// Every scene: gravity (0, -10) m/s^2 (the smashes: none), density 1 kg/m^2 unless a shape says,
// friction 0.6, no restitution, steps of 1/60 s; sleeping off in every engine (what is timed is
// the solver at work) unless the scene says, as v3's smash and tumbler do.
#pragma once

#include <impetus/math/scalar.hpp>
#include <impetus/math/transform2.hpp>
#include <impetus/rigid2d/world.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace impetus::bench {

inline constexpr float sceneDensity = 1.0f;  ///< kg/m^2, unless a shape says otherwise
inline constexpr float sceneFriction = 0.6f; ///< unless a shape says otherwise

/// A shape of a scene body, in the body frame: a box (half-widths, centre, angle), a circle, a
/// segment, a capsule or a rounded convex polygon.
struct SceneShape {
  enum class Kind { box, circle, segment, capsule, polygon };
  Kind kind = Kind::box;
  std::uint32_t body = 0; ///< index into Rigid2dScene::bodies
  Vec2f center;           ///< box or circle centre in the body frame, m
  float halfWidth = 0.0f; ///< box, m
  float halfHeight = 0.0f;
  float angle = 0.0f;             ///< box rotation in the body frame, rad
  float radius = 0.0f;            ///< circle, capsule, polygon's rounding, m
  Vec2f point1, point2;           ///< segment (two-sided, on a static body) or the capsule's centres, body frame, m
  std::vector<Vec2f> points;      ///< polygon: its hull's points (3 to 8), body frame, m
  float density = sceneDensity;   ///< kg/m^2
  float friction = sceneFriction; ///< Coulomb coefficient
  std::int32_t group = 0;         ///< collision group (negative: shapes of the group never collide)
  std::uint64_t categoryBits = 1; ///< collision filter: A and B collide when each one's category is in the other's mask
  std::uint64_t maskBits = ~std::uint64_t{0};
};

/// A revolute joint between two bodies at a world point (the scene's initial pose), with
/// optional angle limits and motor.
struct SceneJoint {
  std::uint32_t bodyA = 0;
  std::uint32_t bodyB = 0;
  Vec2f anchor; ///< world, m, at the start
  bool enableLimit = false;
  float lowerAngle = 0.0f; ///< rad
  float upperAngle = 0.0f; ///< rad
  bool enableMotor = false;
  float motorSpeed = 0.0f;     ///< rad/s of B relative to A
  float maxMotorTorque = 0.0f; ///< N m (with motorSpeed 0: the pin's friction, as v3's ragdolls)
  float referenceAngle = 0.0f; ///< rad: angleB - angleA at joint angle 0 (v3: local frame A's rotation)
  bool enableSpring = false;   ///< toward joint angle 0
  float hertz = 0.0f;          ///< Hz
  float dampingRatio = 0.0f;
};

struct SceneBody {
  rigid2d::BodyType type = rigid2d::BodyType::staticBody;
  Vec2f position;               ///< body origin, m
  float angularVelocity = 0.0f; ///< rad/s (the tumbler's kinematic drum)
  Vec2f linearVelocity;         ///< m/s (the smash's projectile)
  bool bullet = false;          ///< continuous collision against dynamic bodies (the smash's projectile)
  bool awake = true;            ///< false: starts asleep (v3's smash), where the scene sleeps
  float linearDamping = 0.0f;   ///< 1/s
};

/// A scene body's type in a peer engine's own enumeration (Box2D 2.4.1's and v3's b2BodyType
/// name theirs alike but are different types).
template <class PeerType> [[nodiscard]] PeerType peerBodyType(rigid2d::BodyType type, PeerType staticType,
                                                              PeerType kinematicType, PeerType dynamicType) {
  switch (type) {
  case rigid2d::BodyType::staticBody:
    return staticType;
  case rigid2d::BodyType::kinematicBody:
    return kinematicType;
  case rigid2d::BodyType::dynamicBody:
    break;
  }
  return dynamicType;
}

/// Copies a scene joint's limit and motor into a revolute joint definition of any of the engines
/// (Impetus', Box2D 2.4.1's and v3's name these fields alike).
template <class RevoluteDef> void setLimitAndMotor(const SceneJoint& j, RevoluteDef& def) {
  def.enableLimit = j.enableLimit;
  def.lowerAngle = j.lowerAngle;
  def.upperAngle = j.upperAngle;
  def.enableMotor = j.enableMotor;
  def.motorSpeed = j.motorSpeed;
  def.maxMotorTorque = j.maxMotorTorque;
}

/// Bodies with their shapes and joints: a whole scene's, or a group a scene spawns while it runs
/// (a ragdoll), its indices its own.
struct SceneContent {
  std::vector<SceneBody> bodies;
  std::vector<SceneShape> shapes; ///< grouped by body, in body order
  std::vector<SceneJoint> joints;
};

/// What each engine offers a scene's script: spawn a group of bodies (its handle back) and
/// destroy one (its bodies, and their joints with them).
class SceneSpawner {
public:
  virtual ~SceneSpawner() = default;
  virtual std::uint32_t spawn(const SceneContent& group) = 0;
  virtual void destroy(std::uint32_t group) = 0;
};

/// A scene's doings between steps: called before step `step` (from 0) with the engine's spawner.
using SceneScript = std::function<void(int step, SceneSpawner& spawner)>;

/// A scene as plain data: what every engine builds.
struct Rigid2dScene : SceneContent {
  std::string name;
  /// Bodies whose sinking is the quality figure (the top box of each pyramid); may be empty.
  std::vector<std::uint32_t> tops;
  int defaultSteps = 500;       ///< steps of 1/60 s the benchmark runs by default
  Vec2f gravity{0.0f, -10.0f};  ///< m/s^2 (zero for the smashes)
  bool enableSleep = false;     ///< bodies may sleep, in every engine (v3's smash, tumbler and rain)
  float sleepThreshold = 0.05f; ///< m/s a body must stay under to sleep (v3's default; Impetus': sleepLinearTolerance)
  /// Makes the scene's script for one run (each run starts it afresh); empty: the scene runs as built.
  std::function<SceneScript()> makeScript;
  /// Whether Box2D 2.4.1 can build it (it has no capsules or rounded polygons).
  bool box2d241 = true;
};

inline constexpr float sceneTimeStep = 1.0f / 60.0f; ///< s
inline constexpr Vec2f sceneGravity{0.0f, -10.0f};   ///< m/s^2

/// Half-size of the pyramids' boxes, m.
inline constexpr float pyramidBoxHalfSize = 0.5f;

/// "large_pyramid" (as Box2D v3's benchmark): a pyramid of `base` boxes at the bottom (base 100:
/// 5050 boxes) of half-size 0.5 m, rows touching, standing on a static ground box of half-extents
/// 100 x 1 m whose top is y = 0 (its centre at (0, -1)). Row i (from 0) holds base - i boxes at
/// y = i + 0.5, centred on x = 0. The top box is the quality figure.
[[nodiscard]] Rigid2dScene largePyramidScene(int base = 100);

/// "pyramid_row": `count` pyramids of base `base` (default 10 of base 20: 2100 boxes), side by
/// side one box apart on one ground box (top at y = 0, 10 m wider than the row on each side).
inline constexpr int pyramidRowCount = 10;
inline constexpr int pyramidRowBase = 20;
[[nodiscard]] Rigid2dScene pyramidRowScene(int count = pyramidRowCount, int base = pyramidRowBase);

/// "many_pyramids" (Box2D v3's): `rows` x `columns` pyramids of base 10 (default 20 x 20: 22,000
/// boxes of half-size 0.5 m), each row of pyramids on a two-sided segment floor 220 m wide, the
/// floors 11 m apart; within a row the pyramids stand one box apart. 200 steps.
inline constexpr int manyPyramidsRows = 20;
inline constexpr int manyPyramidsColumns = 20;
inline constexpr int manyPyramidsBase = 10;
[[nodiscard]] Rigid2dScene manyPyramidsScene(int rows = manyPyramidsRows, int columns = manyPyramidsColumns);

/// "circle_rain_N": `count` circles of radius 0.25 m dropped at rest into a wide open box: a floor
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
[[nodiscard]] Rigid2dScene circleRainScene(std::size_t count);

/// "kinematic_tumbler": a kinematic drum at (0, 10) m, a hollow square of four boxes (inner
/// side 19 m, walls 1 m thick) turning at 25 degrees per second, holding a grid of grid x grid
/// (default 45 x 45 = 2025) boxes of half-size 0.125 m 0.4 m apart. 500 steps, no sleeping.
inline constexpr int tumblerGrid = 45;
inline constexpr float tumblerSpeed = 25.0f * pi<float> / 180.0f; ///< rad/s
[[nodiscard]] Rigid2dScene kinematicTumblerScene(int grid = tumblerGrid);

/// "tumbler" (Box2D v3's): the same drum and boxes, but the drum is dynamic (density 50 kg/m^2)
/// and turned by a revolute joint's motor (25 degrees per second, at most 10^8 N m) to a static
/// ground body; bodies may sleep. 750 steps.
inline constexpr float tumblerDrumDensity = 50.0f;  ///< kg/m^2
inline constexpr float tumblerMotorTorque = 1.0e8f; ///< N m: enough to keep the speed whatever the load
[[nodiscard]] Rigid2dScene tumblerScene(int grid = tumblerGrid);

/// "smash_awake": in zero gravity, a block of smashGrid x smashGrid boxes of half-size 0.1 m,
/// touching, its left face at x = 0 and centred on y = 0, is hit at 40 m/s by a 4 x 4 m box of
/// the same density (a bullet in every engine) starting 10 m to its left. 300 steps, no sleeping.
inline constexpr int smashGrid = 60;
[[nodiscard]] Rigid2dScene smashAwakeScene(int grid = smashGrid);

/// "smash" (Box2D v3's): in zero gravity, a block of `columns` x `rows` (default 120 x 80 =
/// 9,600) boxes of half-size 0.2 m, touching, asleep, its left face at x = 29.8 m and centred on
/// y = 0, is hit at 40 m/s by an 8 x 8 m box of density 8 kg/m^2 starting at x = -20 m (not a
/// bullet); bodies may sleep, so the block costs little until it is hit. 300 steps.
inline constexpr int smashColumns = 120;
inline constexpr int smashRows = 80;
[[nodiscard]] Rigid2dScene smashScene(int columns = smashColumns, int rows = smashRows);

/// "joint_grid" (after Box2D v3's): grid x grid circles of radius 0.4 m, 1 m apart, each joined
/// by revolute joints to its neighbours above and to the left; seven circles in the middle of the
/// top row are static, so the net hangs and swings. The circles do not collide (one negative
/// group). 500 steps. Quality: the widest gap between a joint's two anchors at the end.
inline constexpr int jointGridSize = 100;
[[nodiscard]] Rigid2dScene jointGridScene(int grid = jointGridSize);

/// "rain" (Box2D v3's): ragdolls rain onto five floors, each a row of 501 static boxes of
/// 0.5 m side (one static body), 45 m apart. Every 8 steps a column of five groups (one above
/// each floor) of rainGroupSize ragdolls 0.5 m apart is spawned 40 m above its floor; once
/// rainColumns columns stand, each new column destroys the oldest first. A ragdoll is v3's
/// human: 11 capsule bones (rounded-polygon feet) joined by revolute joints with limits, a
/// spring (5 Hz, damping ratio 0.5) and pin friction; the ragdolls of one group's same place
/// never collide with each other (v3's groups), nor do feet with ragdolls. Bodies may sleep
/// (0.1 m/s). 1000 steps. Box2D 2.4.1 has no capsules: not run there.
inline constexpr int rainColumns = 40;
inline constexpr int rainFloors = 5;
inline constexpr int rainGroupSize = 5;
inline constexpr int rainSpawnInterval = 8; ///< steps
[[nodiscard]] Rigid2dScene rainScene();
/// One of v3's ragdolls (its human at scale 1) with its feet at `feet`; its shapes in
/// collision group `group` (negative: the ragdoll's bones never collide).
[[nodiscard]] SceneContent humanRagdoll(const Vec2f& feet, std::int32_t group);

/// "ragdolls": `columns` x `rows` ragdolls of 9 boxes and a circle head joined by 9 revolute
/// joints with limits (elbows, knees, shoulders, hips, neck), dropped into an open box. 500 steps.
inline constexpr int ragdollColumns = 20;
inline constexpr int ragdollRows = 15;
[[nodiscard]] Rigid2dScene ragdollScene(int columns = ragdollColumns, int rows = ragdollRows);

/// Scene names, in the benchmark's order: Box2D v3's (large_pyramid, many_pyramids, tumbler,
/// smash, joint_grid, rain), then Impetus' own (ragdolls, pyramid_row, kinematic_tumbler,
/// smash_awake, circle_rain_1k, circle_rain_10k, circle_rain_100k).
[[nodiscard]] std::vector<std::string> rigid2dSceneNames();
/// The scene of that name (also circle_rain_N and circle_rain_Nk for N or N thousand circles);
/// throws impetus::Error naming `scene` for an unknown one.
[[nodiscard]] Rigid2dScene makeRigid2dScene(std::string_view name);

/// The scene built in Impetus (the default WorldDef, gravity (0, -10) and 4 substeps, with
/// sleeping off); `bodies[i]` is the id of the scene's body i.
struct ImpetusScene {
  rigid2d::World world;
  std::vector<rigid2d::BodyId> bodies;
};
/// A scene's script's spawner in an Impetus world.
class ImpetusSpawner final : public SceneSpawner {
public:
  explicit ImpetusSpawner(rigid2d::World& world) : world_(world) {}
  std::uint32_t spawn(const SceneContent& group) override;
  void destroy(std::uint32_t group) override;
  /// Bodies of the groups spawned and not destroyed.
  [[nodiscard]] std::size_t liveBodies() const;
  /// Every live spawned body, group after group.
  [[nodiscard]] std::vector<rigid2d::BodyId> bodies() const;

private:
  rigid2d::World& world_;
  std::vector<std::vector<rigid2d::BodyId>> groups_;
};
/// Adds bodies with their shapes and joints to an Impetus world (the scene's sleep threshold
/// applies to the world); their ids, in order.
std::vector<rigid2d::BodyId> addToImpetusWorld(rigid2d::World& world, const SceneContent& content);
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
