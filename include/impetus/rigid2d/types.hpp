// Definitions for the 2D world: ids, body and shape definitions, world settings.
#pragma once

#include <impetus/core/collision_filter.hpp>
#include <impetus/core/id_pool.hpp>
#include <impetus/core/task_runner.hpp>
#include <impetus/math/vec2.hpp>

#include <array>
#include <cstdint>

namespace impetus::rigid2d {

using BodyId = Id<struct BodyTag>;
using ShapeId = Id<struct ShapeTag>;

enum class BodyType {
  staticBody,    ///< never moves, infinite mass
  kinematicBody, ///< moves at its set velocity, unaffected by forces and contacts
  dynamicBody,   ///< moved by forces and contacts
};

struct BodyDef {
  BodyType type = BodyType::staticBody;
  Vec2f position;               ///< body origin, m
  float angle = 0.0f;           ///< rad
  Vec2f linearVelocity;         ///< of the centre of mass, m/s
  float angularVelocity = 0.0f; ///< rad/s
  float linearDamping = 0.0f;   ///< 1/s: dv/dt = -c v
  float angularDamping = 0.0f;  ///< 1/s
  float gravityScale = 1.0f;
  bool fixedRotation = false;
  bool bullet = false; ///< continuous collision against dynamic bodies too (time of impact)
  /// Lets the body spin faster than a quarter turn a substep (a wheel, a rotor, a thrown bolo);
  /// otherwise its spin is capped there, where the rotation deltas stop meaning what they say.
  bool allowFastRotation = false;
  bool enableSleep = true; ///< may fall asleep when at rest
  bool isAwake = true;
  std::uint64_t userData = 0;
};

/// Which shapes collide (impetus::CollisionFilter, the same rule in every world).
using Filter = CollisionFilter;

struct ShapeDef {
  float density = 1.0f;     ///< kg/m^2
  float friction = 0.6f;    ///< Coulomb coefficient
  float restitution = 0.0f; ///< 0 to 1
  /// Rolling resistance coefficient (dimensionless, as c_rr in F = c_rr N): a circle or capsule
  /// rolling on this shape feels a torque c_rr N r against its rolling (r its radius). Typical:
  /// 0.001 (steel on steel) to 0.3 (tyre on sand). The pair uses the larger of the two.
  float rollingResistance = 0.0f;
  /// The speed of the shape's surface along itself, m/s, as a conveyor belt's (Box2D v3's
  /// tangentSpeed): friction drives what touches it toward this relative sliding speed. Positive
  /// runs clockwise around the shape, so a belt lying on the ground carries bodies toward +x.
  /// The soft step only; the pair's speeds add.
  float tangentSpeed = 0.0f;
  Filter filter;
  /// Ask the world's custom filter (World::setCustomFilter) whether this shape's new pairs
  /// collide. Either shape of a pair asking is enough.
  bool enableCustomFiltering = false;
  /// Ask the world's pre-solve callback (World::setPreSolve) before each step's solve whether
  /// this shape's touching contacts are solved (one-way platforms). Either shape asking is enough;
  /// such contacts are collided afresh every step (their manifolds are never carried).
  bool enablePreSolveEvents = false;
  bool isSensor = false; ///< detects overlap (sensor events), no collision response
  std::uint64_t userData = 0;
};

/// How the world resolves contacts.
enum class SolverKind {
  /// The soft step (Box2D v3's): substeps, soft contacts, warm starting, relax, restitution,
  /// friction. Stable stacks and piles. The default.
  softStep,
  /// The book's response (ch. 9-10, errata fixed): one semi-implicit Euler step and one impulse
  /// per touching pair. For reproducing the book's programs; stacks do not rest well.
  bookImpulse,
};

/// The instruction set of the soft step's wide contact solve.
enum class SimdLevel {
  /// The widest the CPU runs: AVX2 (eight contacts at once) where the CPU has it, else the
  /// baseline. The default.
  widest,
  /// The baseline of the build: SSE2 on x86-64 (four at once), plain floats elsewhere.
  baseline,
};

/// How the last soft step laid out its constraints in the constraint graph: per colour, the joints
/// and contacts that share no moving body (solved together, on threads), and the overflow solved
/// one by one first (a body in more constraints than there are colours). As Box2D v3's counters.
struct ConstraintGraphCounts {
  static constexpr int colours = 24;
  std::array<std::uint32_t, colours> colourJoints{};
  std::array<std::uint32_t, colours> colourContacts{};
  std::uint32_t overflowJoints = 0;
  std::uint32_t overflowContacts = 0;
};

/// Where the last step's time went, ms of wall time (as Box2D v3's b2Profile): the broadphase's new
/// pairs, the narrowphase, the solve by stage (summed over the substeps), and the finalize
/// (positions written back, continuous collision, sleep). Measured, not simulated: it differs
/// from run to run and never changes a result.
struct StepProfile {
  float step = 0.0f;
  float pairs = 0.0f;
  float collide = 0.0f;
  float solve = 0.0f;
  float prepare = 0.0f; ///< solver bodies, joints, the constraint graph and the contacts
  float integrateVelocities = 0.0f;
  float warmStart = 0.0f;
  float solveConstraints = 0.0f;
  float integratePositions = 0.0f;
  float relax = 0.0f;
  float storeImpulses = 0.0f; ///< and the joints' break events
  float finalize = 0.0f;
};

struct WorldDef {
  Vec2f gravity{0.0f, -10.0f}; ///< m/s^2
  SolverKind solver = SolverKind::softStep;
  int substeps = 4;           ///< solver substeps per step (soft step)
  float contactHertz = 30.0f; ///< contact stiffness, Hz (capped at a quarter of the substep rate)
  float contactDampingRatio = 10.0f;
  float maxContactPushSpeed = 3.0f; ///< m/s: how fast overlap is resolved
  /// Joint stiffness, Hz (capped at a quarter of the substep rate): how firmly a joint pulled
  /// apart is brought back together, and its damping ratio.
  float jointHertz = 60.0f;
  float jointDampingRatio = 2.0f;
  /// The fastest a joint's error is taken back (m/s along a direction, rad/s about an angle row:
  /// a metre's lever), as maxContactPushSpeed is for overlap: a joint torn metres apart (an
  /// impact at 100 m/s) is mended over several steps instead of in one violent push, whose
  /// velocity the relax pass cannot wholly take back when the bodies turn fast. It also bounds
  /// what a soft joint can hold (its force is its bias at the row's effective mass): 100 m/s
  /// holds some 2,000 times the weight of the row's effective mass; 10 m/s tore the 100-row
  /// cloth of the joint_grid benchmark at its top.
  float maxJointPushSpeed = 100.0f;
  float restitutionThreshold = 1.0f; ///< m/s: slower impacts do not bounce
  /// Start each step's contacts and joints from the impulses they ended the last with (what
  /// lets stacks and chains converge in a few iterations). Off: from zero (for study and tests).
  bool enableWarmStarting = true;
  float maxLinearSpeed = 400.0f;  ///< m/s
  float hitEventThreshold = 1.0f; ///< m/s: impacts at least this fast (and over 1 mm/s) raise a hit event
  /// Manifold reuse (as Jolt's body-pair cache): a touching pair whose shapes' cores (a
  /// round shape's surface moved in by its radius: a ball's centre) have moved less than this
  /// relative to each other since its manifold was computed, and turned less than
  /// contactReuseAngle, keeps that manifold's features and clipping, its points carried along
  /// with the bodies (separations exact), instead of colliding again: most of a resting pile's
  /// narrowphase. m; 0 collides every touching pair every step (as Box2D).
  float contactReuseDistance = 0.001f;
  float contactReuseAngle = 0.0087f;    ///< rad (half a degree)
  bool enableSleep = true;              ///< islands at rest fall asleep and cost (almost) nothing
  float timeToSleep = 0.5f;             ///< s an island must stay slow to fall asleep
  float sleepLinearTolerance = 0.05f;   ///< m/s
  float sleepAngularTolerance = 0.035f; ///< rad/s (2 degrees per second)
  /// Runs the step's parallel loops (not owned; must outlive the world). Null: everything on
  /// the calling thread. Results are bit-identical with or without, at any thread count.
  TaskRunner* taskRunner = nullptr;
  /// Lane width of the contact solve. Results are bit-identical at any width (every lane does
  /// the scalar solver's arithmetic, without fused multiply-add); only the speed differs.
  SimdLevel simd = SimdLevel::widest;
};

} // namespace impetus::rigid2d
