// Internal state of the 2D world, shared by world.cpp (bookkeeping, broadphase, collide,
// finalize), world_bodies.cpp (bodies and shapes), world_joints.cpp, solver.cpp (the soft step),
// contact_solver.cpp (the contact constraints), joint.cpp and the joints' files, island.cpp
// (sleeping), continuous.cpp, world_queries.cpp and snapshot.cpp.
#pragma once

#include "solver/colour_graph.hpp"
#include "solver/islands.hpp"
#include "solver/slot_list.hpp"
#include "solver/softness.hpp"
#include <impetus/core/id_pool.hpp>
#include <impetus/core/task_runner.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/rigid2d/chain.hpp>
#include <impetus/rigid2d/constants.hpp>
#include <impetus/rigid2d/distance.hpp>
#include <impetus/rigid2d/dynamic_tree.hpp>
#include <impetus/rigid2d/joint.hpp>
#include <impetus/rigid2d/manifold.hpp>
#include <impetus/rigid2d/world.hpp>

#include "rigid2d/pair_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace impetus::rigid2d::detail {

using Geometry = ShapeGeometry;

/// Shapes without area (segments and chain segments): no mass, nothing inside.
[[nodiscard]] inline bool isLine(const Geometry& g) {
  return std::holds_alternative<Segment>(g) || std::holds_alternative<ChainSegment>(g);
}

struct Shape {
  Geometry geometry;
  // What the finalize reads beside the geometry, next to it (the variant's index ends it).
  std::int32_t proxy = DynamicTree::nullNode;
  float margin = 0.0f;       ///< how far a moving shape's fat box reaches past its box, m (fatBoxMargin)
  bool inStaticTree = false; ///< which broadphase tree holds the proxy (fat box: WorldState::fatBoxes)
  bool fatBoxGrown = false;  ///< the finalize gave it a new fat box that its tree does not hold yet
  /// The narrowphase's view of a capsule, segment or polygon (circles have none): made once
  /// when the shape is created, so collision never converts or copies it in the step.
  Polygon collisionPolygon;
  std::uint32_t body = 0; ///< body slot
  float density = 1.0f;
  float friction = 0.6f;
  float restitution = 0.0f;
  /// Rolling resistance torque per unit normal force, m: the coefficient times the radius the
  /// shape rolls on (0 for shapes that do not roll).
  float rollingResistance = 0.0f;
  float tangentSpeed = 0.0f; ///< m/s, the surface's (ShapeDef::tangentSpeed)
  Filter filter;
  bool customFiltering = false; ///< ShapeDef::enableCustomFiltering
  bool preSolve = false;        ///< ShapeDef::enablePreSolveEvents
  bool sensor = false;
  std::uint64_t userData = 0;
  ShapeId id;
  bool alive = false;
};

struct Body {
  BodyType type = BodyType::staticBody;
  Transform2f transform; ///< of the body origin
  Vec2f localCenter;     ///< centre of mass in the body frame
  Vec2f center;          ///< centre of mass, world
  Vec2f linearVelocity;
  float angularVelocity = 0.0f;
  Vec2f force;
  float torque = 0.0f;
  float mass = 0.0f, inverseMass = 0.0f;
  float inertia = 0.0f, inverseInertia = 0.0f;
  float linearDamping = 0.0f, angularDamping = 0.0f, gravityScale = 1.0f;
  bool fixedRotation = false;
  bool bullet = false;
  bool allowFastRotation = false; ///< BodyDef::allowFastRotation
  bool enableSleep = true;
  bool awake = true;
  float sleepTime = 0.0f; ///< s spent slower than the sleep tolerances
  /// How fast the last step moved and turned the body (its displacement and turn over dt, m/s
  /// and rad/s): at rest means not moving, whatever the end velocity says (a joint being mended
  /// moves its bodies by bias velocity that the relax pass then takes back).
  float stepSpeed = 0.0f;
  float stepSpin = 0.0f;
  float coreRadius = 0.0f;           ///< continuous collision's swept circle, m (computeCoreRadius)
  std::uint32_t solverIndex = 0;     ///< this step's index into the solver arrays (moving bodies)
  std::vector<std::uint32_t> shapes; ///< shape slots
  std::vector<std::uint32_t> joints; ///< joint slots of the joints attached to this body
  /// The first of the body's contacts, as a contact edge key (contactEdgeKey); noContactEdge:
  /// none. The contacts link through their edges (Contact::next, prev): no allocation.
  std::uint32_t contactHead = 0xffffffffU;
  std::uint64_t userData = 0;
  BodyId id;
  bool alive = false;

  /// Simulated this step: alive, not static, awake.
  [[nodiscard]] bool moving() const noexcept { return alive && type != BodyType::staticBody && awake; }
};

/// The contact index's key of a shape pair: (lower slot << 32) | higher slot.
[[nodiscard]] inline std::uint64_t pairKey(std::uint32_t a, std::uint32_t b) noexcept {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

/// A touching manifold as it was computed, fixed in the two bodies: each point's core point on A
/// (in A's frame) and on B (in B's frame), the cores' separation and the normal then, and the
/// bodies' relative rotation then. A core point is the surface point moved in by the shape's
/// rounding radius along the normal (a circle's: its centre): it is a material point of the
/// body, where a round surface's contact point is not. While the bodies move less than the
/// world's reuse tolerances relative to each other, the manifold is carried along with them
/// instead of computed again (manifold_reuse.cpp).
///
/// A pair apart (no points) is noted too: B's pose in A's frame and the manifold's
/// separationBound then. While B's shape has moved less than the bound less speculativeDistance
/// relative to A, the pair cannot touch, and is not collided again (manifold_reuse.cpp).
struct ManifoldFrame {
  std::array<Vec2f, 2> localA{}, localB{};
  std::array<float, 2> coreSeparation{}; ///< m
  Vec2f localNormal;                     ///< A's frame
  Rot2f relativeRotation = Rot2f::identity();
  float radiusA = 0.0f, radiusB = 0.0f; ///< the shapes' rounding radii (a circle's radius), m
  /// How far B's shape reaches from B's origin, m: the most any of its points moves when B
  /// turns by an angle t relative to A is this times the chord 2 sin(t / 2).
  float reachB = 0.0f;
  Vec2f relativePosition;       ///< apart: B's origin in A's frame then, m
  float separationBound = 0.0f; ///< apart: the manifold's separationBound then, m
};

/// A pair of shapes whose fat boxes overlap: touching when its manifold has points.
///
/// Laid out by cache line (the record starts on one): the first holds what the pair update, the
/// islands and the colouring read (slots, flags) with the material; the second holds exactly the
/// manifold's points' impulses and its point count, all the store after the solve writes; the
/// third the rest of what the prepare reads; the collide pass's frame and the lists follow.
struct alignas(64) Contact {
  std::uint32_t shapeA = 0; ///< the lower shape slot
  std::uint32_t shapeB = 0;
  std::uint32_t bodyA = 0; ///< body slots
  std::uint32_t bodyB = 0;
  bool sensor = false;   ///< either shape is a sensor: events only, no response
  bool preSolve = false; ///< either shape asks the pre-solve callback
  bool reusable = false; ///< no pre-solve callback: the manifold may be carried (manifold_reuse.cpp)
  bool alive = false;
  float friction = 0.0f;
  float restitution = 0.0f;
  float rollingResistance = 0.0f; ///< m (torque per unit normal force)
  float tangentSpeed = 0.0f;      ///< the surfaces' sliding speed friction drives toward, m/s
  Manifold manifold;
  float rollingImpulse = 0.0f; ///< solver state, N m s (warm start)
  /// The solver's fastest impact this step, m/s, and the point that met it: hit events. Written
  /// only where the step may raise one (maybeHit), and read only then.
  float approachSpeed = 0.0f;
  int fastestPoint = 0;
  ManifoldFrame frame; ///< cold: read by the collide pass only (after the solver's fields)
  /// The contact's place in each body's list of contacts (edge 0: bodyA's, 1: bodyB's), as edge
  /// keys of the neighbours (contactEdgeKey), noContactEdge at the ends.
  std::array<std::uint32_t, 2> next{0xffffffffU, 0xffffffffU};
  std::array<std::uint32_t, 2> prev{0xffffffffU, 0xffffffffU};
};
/// The offset of the record's store line: from the first point's normal impulse to the
/// manifold's point count.
inline constexpr std::size_t contactStoreLine = 64;
static_assert(offsetof(Contact, manifold) + offsetof(Manifold, points) + offsetof(ManifoldPoint, normalImpulse) ==
              contactStoreLine);
static_assert(offsetof(Contact, manifold) + offsetof(Manifold, pointCount) + sizeof(int) <= contactStoreLine + 64);

/// The end of a body's contact list.
inline constexpr std::uint32_t noContactEdge = 0xffffffffU;
/// A contact's edge in one body's list: (slot << 1) | edge, edge 0 for bodyA and 1 for bodyB.
[[nodiscard]] constexpr std::uint32_t contactEdgeKey(std::uint32_t slot, std::uint32_t edge) noexcept {
  return (slot << 1) | edge;
}

/// A hit event needs an approach faster than this (and the world's hitEventThreshold): a resting
/// contact approaches at a few um/s of round-off. m/s.
inline constexpr float restingApproachSpeed = 1e-3f;

/// Whether a contact's fastest approach this step may raise a hit event.
[[nodiscard]] inline bool approachMayHit(float approachSpeed, float hitEventThreshold) noexcept {
  return approachSpeed > restingApproachSpeed && approachSpeed >= hitEventThreshold;
}

/// The rolling impulse a contact's solve starts from: zero without warm starting, and without
/// rolling resistance (its row holds none), where the record's third line is not read.
[[nodiscard]] inline float rollingImpulseToWarmStart(const Contact& contact, bool warmStarting) {
  return warmStarting && contact.rollingResistance > 0.0f ? contact.rollingImpulse : 0.0f;
}

/// The bytes the prepare reads of a contact without rolling resistance (whose rolling impulse,
/// after them, is always zero): its first two cache lines.
inline constexpr std::size_t contactPrepareBytes = contactStoreLine + 64;
static_assert(offsetof(Contact, manifold) + offsetof(Manifold, pointCount) + sizeof(int) <= contactPrepareBytes);

/// The solver's per-body state for one step: velocities and the position and rotation deltas
/// accumulated over the substeps (anchors stay fixed in the bodies, so separations follow from
/// the deltas without recomputing the manifolds). Eight floats: the wide solver loads a body
/// as two rows of four.
struct alignas(16) BodyState {
  Vec2f v;
  float w = 0.0f;
  float unused = 0.0f;
  Vec2f dp;
  Rot2f dq = Rot2f::identity();
};
static_assert(sizeof(BodyState) == 8 * sizeof(float));

/// What integrating a moving body needs, packed for the solver: accelerations from gravity and
/// the applied force and torque, and damping.
struct BodySim {
  Vec2f acceleration;             ///< m/s^2
  float angularAcceleration = 0;  ///< rad/s^2
  float linearDamping = 0;        ///< 1/s
  float angularDamping = 0;       ///< 1/s
  bool dynamic = false;           ///< kinematic bodies keep their velocity
  bool allowFastRotation = false; ///< BodyDef::allowFastRotation: no cap on the spin
};

/// The solver index of a body not in this step's solve (static or asleep).
inline constexpr std::uint32_t noSolverIndex = 0xffffffffU;

/// The most blocks the pair update splits its move buffer into, each queried as one task with
/// its own list of new pairs (more blocks than threads keeps the threads evenly loaded).
inline constexpr std::uint32_t pairQueryBlocks = 32;
/// The fewest moved shapes a block of the pair update holds: below it, a task costs more to
/// hand out than its queries (a query is about a microsecond).
inline constexpr std::uint32_t minPairQueryBlock = 64;

/// What the contact solver reads of a body each step, packed: the Body itself is large and cold,
/// and preparing thousands of contacts would otherwise pull two of them into the cache apiece.
struct SolverBodyInfo {
  /// Into `states`, for an awake body (refreshed each step); noSolverIndex for a static or
  /// sleeping one (solverIndexOf maps it to the static state).
  std::uint32_t solverIndex = noSolverIndex;
  float inverseMass = 0.0f;    ///< 1/kg
  float inverseInertia = 0.0f; ///< 1/(kg m^2)
  Vec2f centerOffset;          ///< centre of mass minus origin, world axes, m
};

/// What a joint's prepare reads of a body, packed (by solver index for the moving bodies, built
/// with `states`): its pose and inverse masses, without the Body's cold lines.
struct JointBodyPose {
  Rot2f q = Rot2f::identity();
  Vec2f center;      ///< centre of mass, world, m
  Vec2f localCenter; ///< centre of mass in the body frame, m
  float inverseMass = 0.0f;
  float inverseInertia = 0.0f;
};

[[nodiscard]] inline JointBodyPose jointBodyPose(const Body& b) {
  return {b.transform.q, b.center, b.localCenter, b.inverseMass, b.inverseInertia};
}

struct ContactSolverData; // contact_solver.cpp
struct Joint;             // joints.hpp

/// A body's one shape whose fat box the finalize grew, noted by the parallel pass for the
/// serial one: it reaches the tree without reading the body and its shape again.
struct GrownProxy {
  std::uint32_t shape = 0; ///< shape slot
  std::int32_t proxy = 0;  ///< in the moving tree
};

/// Where a bullet started the step, for its sweep.
struct BulletStart {
  std::uint32_t body = 0;
  Vec2f center;
  Rot2f rotation;
};

/// items[id.index] when `id` is live in `pool`, else an impetus::Error naming `field`.
template <class T, class Tag>
T& checkedSlot(const IdPool& pool, std::vector<T>& items, Id<Tag> id, const char* field, const char* what) {
  pool.requireValid(id, field, what);
  return items[id.index];
}

struct WorldState {
  WorldState();
  ~WorldState();
  WorldState(WorldState&&) noexcept;
  WorldState& operator=(WorldState&&) noexcept;

  WorldDef def;
  IdPool bodyIds;
  std::vector<Body> bodies; ///< by id slot
  IdPool shapeIds;
  std::vector<Shape> shapes; ///< by id slot
  /// Each shape's fat box as its tree holds it, by shape slot: apart from the shapes because
  /// every contact reads two of them every step.
  std::vector<AABB> fatBoxes;
  /// Broadphase: static shapes apart from moving ones, so a static world is never re-queried
  /// against itself and continuous collision searches static shapes only.
  DynamicTree staticTree;
  DynamicTree movingTree;
  std::vector<std::uint32_t> moveBuffer; ///< shapes whose fat box changed since the last pair update
  /// By shape slot, 1 while the pair update runs for a shape in the move buffer: a pair of two
  /// moved shapes is recorded by the query of one of them only.
  std::vector<std::uint8_t> movedShapes;
  /// The pair update's new pairs: one list per block of the move buffer (blocks are queried on
  /// threads), then all of them, sorted.
  std::array<std::vector<std::uint64_t>, pairQueryBlocks> pairBlocks;
  std::vector<std::uint64_t> newPairs;

  /// Contacts in a pool (slots reused last-in first-out, so the order is deterministic), found
  /// by their shape pair.
  std::vector<Contact> contacts;
  std::vector<std::uint32_t> freeContacts;
  std::vector<std::uint32_t> bodyContactScratch; ///< bodyContacts' list for the API's body changes
  PairMap contactByPair;                         ///< (shapeA << 32 | shapeB) -> slot

  IdPool jointIds;
  std::vector<Joint> joints; ///< by id slot
  JointEvents jointEvents;
  StepProfile profile;                    ///< the last step's (World::profile)
  float lastInverseH = 0.0f;              ///< the last step's substep rate, 1/s (impulses to forces)
  std::vector<std::uint8_t> touchChanges; ///< scratch of the collide pass (TouchChange)
  /// Scratch of the solve, per contact slot: 1 where the contact approached fast enough this
  /// step for a hit event (approachMayHit), so the events need not read every contact again.
  std::vector<std::uint8_t> maybeHit;

  /// The awake set: the bodies, contacts and joints the step walks (a contact or joint while
  /// either of its bodies is awake). A sleeping island's are out of them (island.cpp).
  solver::SlotList awakeBodySet;
  solver::SlotList awakeContactSet;
  solver::SlotList awakeJointSet;
  std::vector<std::uint32_t> solvedJoints; ///< this step's joints (the awake set's, compacted)
  solver::Islands islands;                 ///< every non-static body's island
  /// The contacts the soft step solves, in colours kept from step to step (updateContactColour),
  /// by contact slot and body slot.
  solver::ColourGraph contactGraph;
  std::vector<std::uint32_t> islandPieces; ///< scratch of a split
  /// This step's moving bodies in solver order (the awake set's, compacted), their solver state (plus, at
  /// staticIndex(), a never written state standing for every static body, and after it a never read one that takes the
  /// wide solver's writes to static lanes) and integration data.
  std::vector<std::uint32_t> awakeBodies;
  std::vector<BodyState> states;
  std::vector<BodySim> sims;
  std::vector<JointBodyPose> jointPoses; ///< by solver index, this step's (buildSolverBodies)
  std::vector<SolverBodyInfo> bodyInfo;  ///< by body slot, rebuilt each step with `states`
  std::unique_ptr<ContactSolverData> contactSolver;
  std::vector<BulletStart> bullets;      ///< scratch of the finalize pass
  std::vector<std::uint8_t> finishMarks; ///< the finalize's, by solver index: what the serial pass does
  std::vector<GrownProxy> grownProxies;  ///< the finalize's, by solver index: a one-shape body's grown proxy
  std::vector<float> islandRest;         ///< scratch of the sleep pass (least rest time per island)

  ContactEvents contactEvents;
  SensorEvents sensorEvents;
  ContactEvents pendingEvents; ///< raised between steps (destroyed bodies): reported by the next step
  SensorEvents pendingSensorEvents;
  std::vector<BodyMoveEvent> bodyMoveEvents;
  CustomFilterFcn customFilter;
  PreSolveFcn preSolve;

  // The item a live id names; an id that was destroyed or never made is an impetus::Error
  // naming "body id", "shape id" or "joint id".
  Body& body(BodyId id) { return checkedSlot(bodyIds, bodies, id, "body id", "body"); }
  [[nodiscard]] const Body& body(BodyId id) const { return const_cast<WorldState*>(this)->body(id); }
  Shape& shape(ShapeId id) { return checkedSlot(shapeIds, shapes, id, "shape id", "shape"); }
  [[nodiscard]] const Shape& shape(ShapeId id) const { return const_cast<WorldState*>(this)->shape(id); }
  Joint& joint(JointId id); // world_joints.cpp, where Joint is complete
  [[nodiscard]] const Joint& joint(JointId id) const;
  /// Whether a joint between the two bodies (slots) turns their collision off.
  [[nodiscard]] bool jointBlocksCollision(std::uint32_t bodyA, std::uint32_t bodyB) const;
  [[nodiscard]] DynamicTree& treeOf(const Shape& s) { return s.inStaticTree ? staticTree : movingTree; }
  /// The solver index standing for static bodies (a state that stays at rest).
  [[nodiscard]] std::uint32_t staticIndex() const noexcept { return static_cast<std::uint32_t>(awakeBodies.size()); }
  /// A body's index into `states` this step: the static state for a body not solved.
  [[nodiscard]] std::uint32_t solverIndexOf(const SolverBodyInfo& info) const noexcept {
    return std::min(info.solverIndex, staticIndex());
  }
  /// Runs task over [0, count) in ranges of at least minRange, on the task runner if any.
  void parallelFor(std::uint32_t count, std::uint32_t minRange, const TaskRunner::RangeTask& task) const;
};

using solver::makeSoft;
using solver::Softness;

/// The constants of one step's solve.
struct StepContext {
  float dt = 0.0f;
  float h = 0.0f;        ///< substep, s
  float inverseH = 0.0f; ///< 1/s
  int substeps = 1;
  Softness jointSoftness;       ///< the stiffness that holds joints together (jointHertz, jointDampingRatio)
  bool warmStarting = true;     ///< WorldDef::enableWarmStarting
  float maxLinearSpeed = 0.0f;  ///< m/s (WorldDef::maxLinearSpeed)
  float maxAngularSpeed = 0.0f; ///< rad/s: the largest turn per substep (a quarter turn) over h
};

/// A joint's soft rows at `hertz` and damping ratio `zeta`: stiffer than a quarter of the substep
/// rate cannot be resolved by the substeps (as the contacts' cap).
[[nodiscard]] inline Softness jointSoftnessFor(float hertz, float zeta, const StepContext& context) {
  return makeSoft(std::min(hertz, 0.25f * context.inverseH), zeta, context.h);
}

/// The one cap on how fast a dynamic body moves: at most maxLinearSpeed, and at most a quarter
/// turn a substep unless it allows fast rotation (a rotation delta integrated from a larger turn
/// no longer follows the spin). Applied where positions are integrated, so that no position step
/// is taken at a faster speed, whatever the constraints asked for.
[[gnu::always_inline]] inline void capVelocity(BodyState& s, const StepContext& context, bool allowFastRotation) {
  const float maxSpeed = context.maxLinearSpeed;
  // Each component first, so that an overflowed (infinite) velocity still has a direction.
  s.v = {std::clamp(s.v.x, -maxSpeed, maxSpeed), std::clamp(s.v.y, -maxSpeed, maxSpeed)};
  if (lengthSquared(s.v) > maxSpeed * maxSpeed) {
    s.v = normalize(s.v) * maxSpeed;
  }
  if (!allowFastRotation) {
    s.w = std::clamp(s.w, -context.maxAngularSpeed, context.maxAngularSpeed);
  }
}

using impetus::shouldCollide;

/// The shape as GJK sees it (its core points and radius), in the body frame.
[[nodiscard]] ShapeProxy shapeProxy(const Shape& s);

/// Frees a contact; one that touched reports its end to `events` (or `sensors`).
void destroyContact(WorldState& w, std::uint32_t slot, ContactEvents& events, SensorEvents& sensors);
/// The slots of a body's contacts, in slot order, into `out` (cleared first): what is touched
/// when the body alone changes, without a pass over every contact (world.cpp).
void bodyContacts(const WorldState& w, std::uint32_t body, std::vector<std::uint32_t>& out);

/// Notes a freshly computed manifold's points in its bodies' frames (Contact::frame).
void recordManifoldFrame(Contact& contact, const Transform2f& xfA, const Transform2f& xfB);
/// Notes a pair apart (its manifold has no points) at (xfA, xfB), for staysApart.
void recordSeparation(Contact& contact, const Transform2f& xfA, const Transform2f& xfB);
/// Whether a pair apart when noted is still farther apart than speculativeDistance at (xfA, xfB)
/// (B moved less than the noted bound allows, relative to A): colliding it would find nothing.
[[nodiscard]] bool staysApart(const Contact& contact, const Transform2f& xfA, const Transform2f& xfB);
/// Carries the contact's manifold along with its bodies when, since it was computed, each point's
/// surfaces moved less than `maxDistance` (m) relative to each other and the bodies turned
/// relative to each other by an angle whose sine is under `maxTurnSine`: new points, anchors,
/// separations and normal, the same feature ids and impulses. False (manifold untouched)
/// otherwise: collide again.
[[nodiscard]] bool carryManifold(Contact& contact, const Transform2f& xfA, const Transform2f& xfB, float maxDistance,
                                 float maxTurnSine);

/// A shape's world bounding box.
[[nodiscard]] AABB shapeBox(const Shape& s, const Transform2f& xf);
/// The box a moving shape's fat box must hold: its bounds grown by the speculative distance, so
/// that a shape within speculative reach of another always has a pair with it (as Box2D v3).
/// Without it a 6 mm ball stopped by the static sweep half a millimetre above the floor, its
/// fat box 0.2 mm short of the floor's, had no contact: it hung there while gravity wound its
/// velocity up.
/// A moving shape's fat-box margin: aabbMargin, or aabbMarginFraction of its extent (the
/// farthest its outline reaches from its centre) when that is less, m.
[[nodiscard]] float fatBoxMargin(const Geometry& g);

[[nodiscard]] inline AABB reachBox(const Shape& s, const Transform2f& xf) {
  return enlarge(shapeBox(s, xf), speculativeDistance);
}

// solver.cpp
/// The substepped soft-step solve of every moving body and touching contact: builds `states`
/// from the awake bodies and leaves the step's velocities and position deltas in them.
void solve(WorldState& w, float dt);
/// The step's constants for `substeps` substeps of dt / substeps: the speed limits and the
/// joints' softness.
[[nodiscard]] StepContext makeStepContext(const WorldState& w, float dt, int substeps);
/// Gives every moving body a solver index and loads `states` and `sims` from the bodies.
void buildSolverBodies(WorldState& w);
/// Semi-implicit Euler over one (sub)step of context.h: velocities from accelerations and
/// damping, then position deltas from the new velocities.
void integrateVelocities(WorldState& w, const StepContext& context);
void integratePositions(WorldState& w, const StepContext& context);
// book_impulse.cpp
/// The book's collision response (ch. 9-10, errata fixed): one step of semi-implicit Euler and
/// one impulse per touching contact.
void solveBookImpulse(WorldState& w, float dt);

// contact_solver.cpp: the constraint graph, contacts and joints coloured so that each colour's
// constraints share no moving body; a colour's contacts are solved several at a time in SIMD
// lanes, and its joints and contact batches on several threads. prepareConstraints colours the
// joints prepared by prepareJoints with the contacts and prepares the contacts.
void prepareConstraints(WorldState& w, const StepContext& context);
void warmStartConstraints(WorldState& w);
void solveConstraints(WorldState& w, const StepContext& context, bool useBias);
/// Throws impetus::Error naming the first invalid field of the world's settings
/// (world_settings.cpp).
void validateWorldDef(const WorldDef& def);

/// A body's place: finite and within maxWorldCoordinate of the origin on each axis (Error
/// naming position.x or position.y).
inline void requireWorldPosition(const Vec2f& p) {
  requireFinite(p, "position");
  for (const auto& [field, value] : {std::pair{"position.x", p.x}, std::pair{"position.y", p.y}}) {
    if (std::abs(value) > maxWorldCoordinate) {
      throw Error(field,
                  std::string(field) + " = " + formatFloat(value) + ": must be within 1e6 m of the world origin");
    }
  }
}

/// A velocity the world can carry: finite and no faster than its maxLinearSpeed (the step would
/// cap it without a word). The speed in double: 1e30 m/s squares past a float.
inline void requireWithinSpeedLimit(const Vec2f& v, float maxLinearSpeed) {
  requireFinite(v, "linearVelocity");
  const double speed = std::hypot(static_cast<double>(v.x), static_cast<double>(v.y));
  if (speed > maxLinearSpeed) {
    throw Error("linearVelocity", "linearVelocity = " + formatFloat(static_cast<float>(speed)) +
                                      " m/s: must be at most the world's maxLinearSpeed, " +
                                      formatFloat(maxLinearSpeed) + " m/s");
  }
}
/// Throws impetus::Error naming constraintHertz or constraintDampingRatio when invalid
/// (world_joints.cpp).
void validateConstraintTuning(float hertz, float dampingRatio);
void storeImpulses(WorldState& w);
/// The lane width and instruction set the world's def.simd selects on this CPU.
[[nodiscard]] int contactLanes(const WorldState& w);
[[nodiscard]] const char* contactSimd(const WorldState& w);
[[nodiscard]] ConstraintGraphCounts constraintGraph(const WorldState& w);

// island.cpp
/// Wakes the body's island (a static body: nothing) and restarts the body's rest time.
void wakeBody(WorldState& w, std::uint32_t slot);
/// Wakes every body of the island: they and their contacts join the awake set.
void wakeIsland(WorldState& w, std::uint32_t island);
/// Puts every body of the island to sleep (at rest): they and the contacts that no awake body
/// has leave the awake set.
void sleepIsland(WorldState& w, std::uint32_t island);
/// Puts the body's island to sleep, split first when it may have come apart (so that only the
/// body's piece sleeps).
void sleepBodyIsland(WorldState& w, std::uint32_t slot);
/// Whether the soft step solves the contact: alive, touching, not a sensor, a body moving (the
/// contacts in WorldState::contactGraph).
[[nodiscard]] inline bool solvedByStep(const WorldState& w, const Contact& c) noexcept {
  return c.alive && !c.sensor && c.manifold.pointCount > 0 &&
         (w.bodies[c.bodyA].moving() || w.bodies[c.bodyB].moving());
}
/// A body as the constraint graph knows it: by slot, a static one as none (it takes no colour).
/// By type, not state: a sleeping body keeps its colours (its island wakes whole).
[[nodiscard]] inline std::uint32_t graphBodyOf(const WorldState& w, std::uint32_t body) noexcept {
  return w.bodies[body].type == BodyType::staticBody ? solver::ColourGraph::noBody : body;
}
/// Puts the contact in the constraint graph when the step solves it (alive, touching, not a
/// sensor, a body moving), else takes it out: called when one of these may have changed (it
/// began or stopped touching, its island woke or fell asleep, it was destroyed).
void updateContactColour(WorldState& w, std::uint32_t slot);
/// Whether a touching contact joins its bodies' islands (not a sensor, neither body static).
[[nodiscard]] bool joinsIslands(const WorldState& w, const Contact& c);
/// Accumulates rest time and puts islands to sleep that have rested long enough.
void updateSleep(WorldState& w, float dt);

// finalize.cpp
/// Gives the body's shapes whose boxes left their fat boxes new ones, in their trees and the
/// move buffer (a teleport, a bullet after its sweep).
void synchronizeShapes(WorldState& w, const Body& b);
/// The step's end for the awake bodies: velocities and poses from the solver's state, forces
/// cleared, the broadphase told what moved, bullets swept.
void finalizeBodies(WorldState& w, float dt);

// continuous.cpp
/// The radius of the largest circle about the body's centre of mass inside all its shapes that
/// contain it (0 if none): cached in Body::coreRadius whenever the shapes or mass change.
[[nodiscard]] float computeCoreRadius(const WorldState& w, const Body& b);
/// Where a fast body may go from `start` toward `end` without passing a static shape.
[[nodiscard]] Vec2f sweepAgainstStatic(const WorldState& w, const Body& b, const Vec2f& start, const Vec2f& end);
/// Continuous collision of a bullet body that moved from (startCenter, startRotation) to where
/// it is now against every non-bullet shape at its end-of-step place: the bullet is moved back
/// to its first time of impact. Returns whether it was.
bool sweepBullet(WorldState& w, Body& b, const Vec2f& startCenter, const Rot2f& startRotation);

} // namespace impetus::rigid2d::detail

namespace impetus::rigid2d {
struct World::Impl : detail::WorldState {};
} // namespace impetus::rigid2d
