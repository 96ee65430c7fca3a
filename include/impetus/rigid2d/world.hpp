// The 2D world: bodies with shapes, stepped by a soft-step solver in the manner of Box2D v3.
//
// Each step: the broadphase finds shape pairs whose fattened boxes overlap; each pair's contact
// manifold is computed once (with speculative points, so contacts act before shapes meet); then
// `substeps` times: integrate velocities (gravity, damping, forces), warm start, solve the soft
// contact constraints with bias (they push overlap apart at a bounded speed, springy at
// contactHertz with contactDampingRatio), integrate positions, and relax (solve again without
// bias, removing the energy the bias added; friction and rolling resistance are solved here
// only, as in Box2D v3.2). Restitution acts within those passes, as an
// impact at each point that meets faster than restitutionThreshold (so a struck row of touching
// bodies passes the impulse along, Newton's cradle). Everything runs in a fixed order:
// the same inputs give bit-identical results.
//
// Contacts are coloured so that a colour's constraints share no moving body: they are solved
// four (SSE2) or eight (AVX2, where the CPU has it) at a time in SIMD lanes and, with a WorldDef::taskRunner, on
// several threads, with bit-identical results either way. docs/rigid2d.md explains the step and its tuning.
#pragma once

#include <impetus/math/transform2.hpp>
#include <impetus/rigid2d/chain.hpp>
#include <impetus/rigid2d/distance.hpp>
#include <impetus/rigid2d/geometry.hpp>
#include <impetus/rigid2d/joint.hpp>
#include <impetus/rigid2d/manifold.hpp>
#include <impetus/rigid2d/types.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

namespace impetus::rigid2d {

/// Any shape's geometry, in its body's frame.
using ShapeGeometry = std::variant<Circle, Capsule, Polygon, Segment, ChainSegment>;

/// Two shapes started touching (their manifold gained points) this step.
struct ContactBeginEvent {
  ShapeId shapeA;
  ShapeId shapeB;
};
/// Two shapes stopped touching this step (or one was destroyed).
struct ContactEndEvent {
  ShapeId shapeA;
  ShapeId shapeB;
};
/// Two shapes met at least as fast as hitEventThreshold: for impact sounds and damage.
struct ContactHitEvent {
  ShapeId shapeA;
  ShapeId shapeB;
  Vec2f point;                ///< world, m
  Vec2f normal;               ///< from A to B
  float approachSpeed = 0.0f; ///< m/s, > 0
};
/// A body that moved this step (awake, not static), or fell asleep at its end: where to draw it.
struct BodyMoveEvent {
  BodyId body;
  Transform2f transform; ///< of the body origin, at the end of the step
  bool fellAsleep = false;
  std::uint64_t userData = 0; ///< the body's (BodyDef::userData)
};

/// Game rules for which shapes collide, beyond their filters (Box2D v3's custom filter): asked
/// when the broadphase finds a new pair (a shape's fattened box moved onto the other's), their
/// filters let them collide and either shape enables it (ShapeDef::enableCustomFiltering);
/// false: no contact, until the broadphase finds the pair again. A pair already in contact is
/// not asked again. Called on the stepping thread, the lower shape slot first.
using CustomFilterFcn = std::function<bool(ShapeId shapeA, ShapeId shapeB)>;
/// Asked each step, before the solve, for every touching contact of a shape that enables it
/// (ShapeDef::enablePreSolveEvents), with the contact's fresh manifold (normal from A to B);
/// false: not solved this step, and not touching (a one-way platform lets a body through from
/// below). Called from the step's worker threads, for several contacts at once: it must be
/// thread-safe, and it may read the world but not change it.
using PreSolveFcn = std::function<bool(ShapeId shapeA, ShapeId shapeB, const Manifold& manifold)>;

struct ContactEvents {
  std::vector<ContactBeginEvent> begins;
  std::vector<ContactEndEvent> ends;
  std::vector<ContactHitEvent> hits;
};
/// A shape began or stopped overlapping a sensor shape.
struct SensorEvent {
  ShapeId sensor;
  ShapeId visitor;
};
struct SensorEvents {
  std::vector<SensorEvent> begins;
  std::vector<SensorEvent> ends;
};

struct RayHit {
  ShapeId shape;
  Vec2f point;
  Vec2f normal;
  float fraction = 0.0f;
};

/// A touching contact for inspection (debug draw, tools): its shapes, in the order the world
/// keeps them, and its manifold as of the last step (points and normal when the step began,
/// the impulses the solver applied over the step).
struct ContactData {
  ShapeId shapeA;
  ShapeId shapeB;
  Manifold manifold;
};

/// The dynamic state of a World, saved for rollback (World::saveState, World::restoreState):
/// bodies' motion, forces and sleep, the broadphase's fat boxes, the contacts with their
/// warm-start impulses, and the joints (settings and accumulated impulses). Not the world's
/// structure: it restores into the world it came from, with the same bodies, shapes and joints.
class WorldSnapshot {
public:
  /// Bytes the snapshot holds.
  [[nodiscard]] std::size_t sizeBytes() const noexcept { return bytes_.size(); }
  [[nodiscard]] bool empty() const noexcept { return bytes_.empty(); }

private:
  friend class World;
  std::vector<std::byte> bytes_;
};

namespace detail {
struct WorldAccess; // src/rigid2d/world_joints.cpp
} // namespace detail

class World {
public:
  explicit World(const WorldDef& def = {});
  ~World();
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Advances by dt seconds (0 < dt <= 1).
  void step(float dt);

  BodyId createBody(const BodyDef& def);
  void destroyBody(BodyId id);
  [[nodiscard]] bool isValid(BodyId id) const noexcept;
  [[nodiscard]] std::size_t bodyCount() const noexcept;

  ShapeId createShape(BodyId body, const ShapeDef& def, const Circle& circle);
  ShapeId createShape(BodyId body, const ShapeDef& def, const Capsule& capsule);
  ShapeId createShape(BodyId body, const ShapeDef& def, const Polygon& polygon);
  ShapeId createShape(BodyId body, const ShapeDef& def, const Segment& segment);
  /// A chain of one-sided segments (terrain; see chain.hpp for which side is solid): one shape
  /// per segment, in order, with no ghost collisions at the joins. Throws impetus::Error naming
  /// `points` for fewer than 2 points (3 for a loop), non-finite or repeated points.
  std::vector<ShapeId> createChain(BodyId body, const ShapeDef& def, const ChainDef& chain);
  [[nodiscard]] std::size_t shapeCount() const noexcept;
  [[nodiscard]] std::size_t contactCount() const noexcept; ///< touching contacts

  // Joints (joint.hpp). Both bodies must exist; a joint keeps both awake together and, unless
  // collideConnected, stops them colliding. Destroying a body destroys its joints.
  RevoluteJointId createJoint(const RevoluteJointDef& def);
  PrismaticJointId createJoint(const PrismaticJointDef& def);
  DistanceJointId createJoint(const DistanceJointDef& def);
  WeldJointId createJoint(const WeldJointDef& def);
  WheelJointId createJoint(const WheelJointDef& def);
  MotorJointId createJoint(const MotorJointDef& def);
  MouseJointId createJoint(const MouseJointDef& def);
  FilterJointId createJoint(const FilterJointDef& def);
  void destroyJoint(JointId id);
  [[nodiscard]] bool isValid(JointId id) const noexcept;
  [[nodiscard]] std::size_t jointCount() const noexcept;
  [[nodiscard]] JointType jointType(JointId id) const;
  /// Every live joint's id, in slot order, into `out` (cleared first; its capacity is reused).
  void jointIds(std::vector<JointId>& out) const;
  /// The joint's anchors on bodies A and B, world, m.
  [[nodiscard]] Vec2f jointAnchorA(JointId id) const;
  [[nodiscard]] Vec2f jointAnchorB(JointId id) const;
  [[nodiscard]] BodyId jointBodyA(JointId id) const;
  [[nodiscard]] BodyId jointBodyB(JointId id) const;
  /// The force (N) and torque (N m) the joint applied to body B over the last step.
  [[nodiscard]] Vec2f jointReactionForce(JointId id) const;
  [[nodiscard]] float jointReactionTorque(JointId id) const;
  // Each joint type's own readouts and settings are free functions of its typed id
  // (joint_functions.hpp, as Box2D v3's b2RevoluteJoint_*): the world's interface does not grow
  // with the joint types.
  /// Joints whose reaction crossed their break limits in the last step.
  [[nodiscard]] const JointEvents& jointEvents() const noexcept;

  // Body state.
  [[nodiscard]] Transform2f transform(BodyId id) const;
  [[nodiscard]] Vec2f position(BodyId id) const; ///< body origin, m
  [[nodiscard]] float angle(BodyId id) const;
  [[nodiscard]] Vec2f worldCenterOfMass(BodyId id) const;
  [[nodiscard]] Vec2f linearVelocity(BodyId id) const; ///< of the centre of mass
  [[nodiscard]] float angularVelocity(BodyId id) const;
  [[nodiscard]] float mass(BodyId id) const;
  [[nodiscard]] float rotationalInertia(BodyId id) const; ///< about the centre of mass
  /// Overrides a dynamic body's mass (kg, > 0), centre of mass (body frame) and rotational inertia
  /// about it (kg m^2, > 0; ignored with fixedRotation), e.g. to match a model's published
  /// values; until the next shape is added to the body, which recomputes them from densities.
  void setMassData(BodyId id, const MassData& massData);
  /// Sleeping: bodies whose whole island (bodies joined by touching contacts) has been slower
  /// than the sleep tolerances for timeToSleep fall asleep, and are neither moved nor solved
  /// until something touches them or the API changes them.
  [[nodiscard]] bool isAwake(BodyId id) const;
  void setAwake(BodyId id, bool awake);
  [[nodiscard]] std::size_t awakeBodyCount() const noexcept;
  /// Every API change below wakes the body.
  void setTransform(BodyId id, const Vec2f& position, float angle);
  void setLinearVelocity(BodyId id, const Vec2f& v);
  void setAngularVelocity(BodyId id, float av);
  /// A force (N) at a world point, acting during the next step.
  void applyForce(BodyId id, const Vec2f& force, const Vec2f& point);
  void applyTorque(BodyId id, float torque);
  /// An instant impulse (N s) at a world point.
  void applyLinearImpulse(BodyId id, const Vec2f& impulse, const Vec2f& point);

  /// The closest shape the ray origin -> origin + translation hits, if any (sensors excluded).
  [[nodiscard]] std::optional<RayHit> castRayClosest(const Vec2f& origin, const Vec2f& translation) const;
  /// Every shape the ray hits (sensors excluded), nearest first.
  [[nodiscard]] std::vector<RayHit> castRayAll(const Vec2f& origin, const Vec2f& translation) const;
  /// The first shape that `proxy` (placed by `transform`, moved by `translation`) touches, if
  /// any (sensors excluded): fraction of the translation, the point on the hit shape and its
  /// normal (toward the cast shape). A proxy that starts touching a shape hits it at 0.
  [[nodiscard]] std::optional<RayHit> castShape(const ShapeProxy& proxy, const Transform2f& transform,
                                                const Vec2f& translation) const;
  /// Shapes whose bounding boxes overlap `box`, in a fixed order.
  [[nodiscard]] std::vector<ShapeId> queryAABB(const AABB& box) const;
  /// Shapes that contain the world point (sensors included).
  [[nodiscard]] std::vector<ShapeId> queryPoint(const Vec2f& point) const;
  /// The body a shape belongs to.
  [[nodiscard]] BodyId shapeBody(ShapeId shape) const;

  /// A hash of the exact state of every live body, in slot order: origin position, rotation,
  /// linear and angular velocity, awake flag (StateHash: FNV-1a over the bits). Equal hashes:
  /// identical states; what the determinism tests and `impetus run --hash` compare.
  [[nodiscard]] std::uint64_t stateHash() const;

  /// Saves the world's dynamic state into `out` (its capacity is reused: no allocation once it
  /// has held a snapshot of this size). Restoring it and stepping again gives bit-identical
  /// results (same stateHash after the same steps), for rollback and replays.
  void saveState(WorldSnapshot& out) const;
  /// Puts the world back in the state `snapshot` saved, and clears this step's events. Throws
  /// impetus::Error naming "snapshot" if it is empty or was saved from a world whose bodies,
  /// shapes or joints differ from this one's (created or destroyed since).
  void restoreState(const WorldSnapshot& snapshot);

  // Inspection (for effectors, tools, renderers).
  /// Every live body's id, in slot order, into `out` (cleared first; its capacity is reused).
  void bodyIds(std::vector<BodyId>& out) const;
  /// A body's shapes, in creation order, into `out` (cleared first).
  void bodyShapes(BodyId body, std::vector<ShapeId>& out) const;
  [[nodiscard]] BodyType bodyType(BodyId id) const;
  [[nodiscard]] bool isBullet(BodyId id) const;
  [[nodiscard]] bool isSleepEnabled(BodyId id) const;
  [[nodiscard]] bool isValid(ShapeId id) const noexcept;
  /// Every touching, non-sensor contact, in slot order, into `out` (cleared first).
  void contacts(std::vector<ContactData>& out) const;
  /// A shape's geometry in its body's frame, and its material.
  [[nodiscard]] ShapeGeometry shapeGeometry(ShapeId shape) const;
  [[nodiscard]] float shapeDensity(ShapeId shape) const;
  [[nodiscard]] float shapeFriction(ShapeId shape) const;
  [[nodiscard]] bool isSensor(ShapeId shape) const;

  /// Events of the last step, in a fixed order (valid until the next step).
  [[nodiscard]] const ContactEvents& contactEvents() const noexcept;
  [[nodiscard]] const SensorEvents& sensorEvents() const noexcept;
  /// The bodies that moved in the last step (and those that fell asleep at its end), in body
  /// slot order: what a game copies into its renderer's transforms (Box2D v3's move events).
  [[nodiscard]] const std::vector<BodyMoveEvent>& bodyMoveEvents() const noexcept;

  /// The custom filter (CustomFilterFcn) and the pre-solve callback (PreSolveFcn); an empty
  /// function removes one. Neither may throw.
  void setCustomFilter(CustomFilterFcn filter);
  void setPreSolve(PreSolveFcn preSolve);

  [[nodiscard]] const WorldDef& settings() const noexcept;
  /// Run-time changes of the settings, each validated as at creation (impetus::Error naming the
  /// field; the world is unchanged then). Gravity changes wake nothing: sleeping bodies stay
  /// asleep until touched or woken, as in Box2D v3.
  void setGravity(const Vec2f& gravity);
  void setContactTuning(float hertz, float dampingRatio, float pushSpeed);
  void setJointTuning(float hertz, float dampingRatio);
  void setRestitutionThreshold(float speed);
  void setHitEventThreshold(float speed);
  void enableWarmStarting(bool enable);
  /// A joint's own stiffness (JointDefBase::constraintHertz; 0: the world's) and damping ratio.
  void setJointConstraintTuning(JointId id, float hertz, float dampingRatio);
  /// How many contacts the soft step solves at once (8 with AVX2, 4 with SSE2) and the name of
  /// the instruction set ("avx2", "sse2" or "scalar"): what WorldDef::simd chose on this CPU.
  [[nodiscard]] int contactLanes() const noexcept;
  [[nodiscard]] const char* contactSimd() const noexcept;
  /// Where the last step's time went (StepProfile).
  [[nodiscard]] const StepProfile& profile() const noexcept;
  /// The constraint graph of the last step (all zero before the first soft step).
  [[nodiscard]] ConstraintGraphCounts constraintGraph() const noexcept;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  friend struct detail::WorldAccess; // the joint types' functions (joint_functions.hpp)
};

} // namespace impetus::rigid2d

#include <impetus/rigid2d/joint_functions.hpp>
