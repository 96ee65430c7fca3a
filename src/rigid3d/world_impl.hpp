// The 3D world's internals: the bodies' records, the solver's per-body state, the world's state.
#pragma once

#include "rigid3d/contact.hpp"
#include "solver/colour_graph.hpp"
#include "solver/islands.hpp"
#include "solver/slot_list.hpp"
#include "solver/softness.hpp"

#include <impetus/core/id_pool.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/transform3.hpp>
#include <impetus/rigid3d/geometry.hpp>
#include <impetus/rigid3d/types.hpp>
#include <impetus/rigid3d/world.hpp>

#include <cstdint>
#include <utility>
#include <vector>

namespace impetus::rigid3d::detail {

/// A shape's record.
struct Shape {
  ShapeGeometry geometry;
  std::uint32_t body = 0; ///< body slot
  float density = 0.0f;
  float friction = 0.0f;
  float restitution = 0.0f;
  float rollingResistance = 0.0f;
  CollisionFilter filter;
  bool sensor = false;
  std::uint64_t userData = 0;
  ShapeId id;
  bool alive = false;
};

/// A body's record (the cold side: what the game reads and sets between steps).
struct Body {
  BodyType type = BodyType::staticBody;
  Transform3f transform; ///< of the body origin
  Vec3f localCenter;     ///< centre of mass in the body frame, m
  Vec3f center;          ///< centre of mass, world, m
  Vec3f linearVelocity;  ///< m/s
  Vec3f angularVelocity; ///< world, rad/s
  Vec3f force;           ///< N, at the centre of mass, until the step's end
  Vec3f torque;          ///< N m, world
  float mass = 0.0f, inverseMass = 0.0f;
  Mat33f inertia;        ///< about the centre, body frame, kg m^2 (zero for static and kinematic)
  Mat33f inverseInertia; ///< body frame, 1/(kg m^2)
  float linearDamping = 0.0f, angularDamping = 0.0f, gravityScale = 1.0f;
  AxisLocks locks;
  bool allowFastRotation = false;
  bool isBullet = false;
  bool enableSleep = true;
  bool awake = true;      ///< moving bodies: in the awake set (static bodies: always)
  float sleepTime = 0.0f; ///< s it has been slower than the sleep tolerances
  /// The farthest any point of the body's shapes lies from its centre of mass, m, and the least
  /// half-thickness of any of them (a sphere's or capsule's radius; a hull's least distance
  /// from its centroid to a face), m: what continuous collision reads (updateExtents).
  float reach = 0.0f, thinnest = 0.0f;
  std::uint32_t solverIndex = 0;     ///< this step's index into the solver arrays (moving bodies)
  std::vector<std::uint32_t> shapes; ///< shape slots, in creation order
  std::uint64_t userData = 0;
  BodyId id;
  bool alive = false;

  [[nodiscard]] bool moving() const noexcept { return alive && type != BodyType::staticBody; }
};

/// A moving body in the solver: what the substeps read and write (the hot side).
struct BodyState {
  Vec3f v;                      ///< m/s
  Vec3f w;                      ///< world, rad/s
  Vec3f dp;                     ///< the centre's move so far this step, m
  Quatf dq = Quatf::identity(); ///< the turn so far this step (world)
  /// Half of what the gyroscopic torque changed w by this substep, world, rad/s: the body turns
  /// at w - gyroscopicLag, the substep's mean spin (the implicit midpoint rule's), so that the
  /// orientation and the body-frame spin advance together and a torque-free body's angular
  /// momentum stays fixed in the world (turning at the end spin, it wobbles by h |w|).
  Vec3f gyroscopicLag;
};

/// What the velocity integration reads of a moving body, fixed for the step.
struct BodySim {
  Quatf rotation = Quatf::identity(); ///< at the step's start
  Mat33f inertia;                     ///< body frame, kg m^2
  Mat33f inverseInertia;              ///< body frame
  Vec3f acceleration;                 ///< gravity and force over mass, m/s^2
  Vec3f torque;                       ///< world, N m
  float linearDamping = 0.0f, angularDamping = 0.0f;
  AxisLocks locks;
  bool dynamic = false;
  bool allowFastRotation = false;
};

/// The step's constants.
struct StepContext {
  float dt = 0.0f;
  int substeps = 1;
  float h = 0.0f;        ///< substep, s
  float inverseH = 0.0f; ///< 1/s
  float maxLinearSpeed = 0.0f;
  float maxAngularSpeed = 0.0f;           ///< rad/s: a quarter turn a substep
  float maxContactPushSpeed = 0.0f;       ///< m/s
  solver::Softness contactSoftness;       ///< between moving bodies
  solver::Softness staticContactSoftness; ///< against a static or kinematic body: twice as stiff
};

struct WorldState {
  WorldDef def;
  IdPool bodyIds;
  IdPool shapeIds;
  std::vector<Body> bodies;  ///< by slot
  std::vector<Shape> shapes; ///< by slot
  solver::SlotList awakeBodySet;
  std::vector<std::uint32_t> awakeBodies; ///< this step's moving bodies, in solver order
  /// The moving bodies' solver states, and one more at rest for the static bodies
  /// (staticIndex(): contacts with a static body read it and never write it).
  std::vector<BodyState> states;
  std::vector<BodySim> sims;
  /// The contacts, in the order of their keys (A's shape key, then B's): the pairs of shapes
  /// whose boxes overlap, kept from step to step with their impulses.
  std::vector<Contact> contacts;
  /// This step's contact constraints: the touching contacts, in the constraint graph's colour
  /// order (orderByColour).
  std::vector<ContactConstraint> constraints;
  std::vector<ContactConstraint> orderedConstraints; ///< scratch of the colour order
  solver::ColourGraph contactColours;
  /// Scratch of the pair update, kept to spare allocations.
  std::vector<Contact> nextContacts;
  ContactEvents contactEvents; ///< the last step's
  SensorEvents sensorEvents;   ///< the last step's
  /// The dynamic bodies joined by touching contacts (the sleeping unit).
  solver::Islands islands;
  std::vector<std::uint32_t> sleepCandidates; ///< scratch of updateSleep: islands in order

  explicit WorldState(const WorldDef& d);
  [[nodiscard]] std::uint32_t staticIndex() const noexcept { return static_cast<std::uint32_t>(awakeBodies.size()); }
  /// The id of the shape a contact's key part names (stale once the shape is destroyed).
  [[nodiscard]] ShapeId shapeIdOf(std::uint64_t key) const noexcept {
    return {static_cast<std::uint32_t>(key >> 32U), static_cast<std::uint32_t>(key), shapeIds.world()};
  }
  Body& body(BodyId id);
  [[nodiscard]] const Body& body(BodyId id) const;
  Shape& shape(ShapeId id);
  [[nodiscard]] const Shape& shape(ShapeId id) const;
};

/// Gives `record` a new id from `ids` and keeps it in the id's slot of `pool` (grown as needed):
/// the records live where their ids say.
template <class Tag, class Record> Id<Tag> placeRecord(IdPool& ids, std::vector<Record>& pool, Record record) {
  const Id<Tag> id = ids.allocateId<Tag>();
  record.id = id;
  record.alive = true;
  if (id.index >= pool.size()) {
    pool.resize(id.index + 1);
  }
  pool[id.index] = std::move(record);
  return id;
}

/// v with the components along the locked world axes removed.
[[nodiscard]] inline Vec3f withoutLockedLinear(Vec3f v, const AxisLocks& locks) {
  v.x = locks.linearX ? 0.0f : v.x;
  v.y = locks.linearY ? 0.0f : v.y;
  v.z = locks.linearZ ? 0.0f : v.z;
  return v;
}
[[nodiscard]] inline Vec3f withoutLockedAngular(Vec3f w, const AxisLocks& locks) {
  w.x = locks.angularX ? 0.0f : w.x;
  w.y = locks.angularY ? 0.0f : w.y;
  w.z = locks.angularZ ? 0.0f : w.z;
  return w;
}

/// The inverse inertia a body turns with in the world for the rotation q (inertia and its
/// inverse in the body frame): R I^-1 R^T, or, with axes locked, the inverse of the world
/// inertia's block on the free axes (the locks' constraint torques hold the locked spin at zero,
/// so a torque on the free axes meets the free block of I alone), zero on the locked axes.
[[nodiscard]] inline Mat33f worldInverseInertia(const Quatf& q, const Mat33f& inertia, const Mat33f& inverseInertia,
                                                const AxisLocks& locks) {
  const Mat33f r = toMat33(q);
  if (!locks.angularX && !locks.angularY && !locks.angularZ) {
    return r * inverseInertia * transpose(r);
  }
  const Mat33f world = r * inertia * transpose(r);
  int free[3];
  int count = 0;
  const bool locked[3] = {locks.angularX, locks.angularY, locks.angularZ};
  for (int i = 0; i < 3; ++i) {
    if (!locked[i]) {
      free[count++] = i;
    }
  }
  Mat33f m;
  if (count == 1) {
    const int i = free[0];
    m(i, i) = world(i, i) > 0.0f ? 1.0f / world(i, i) : 0.0f;
  } else if (count == 2) {
    const int i = free[0];
    const int j = free[1];
    const float det = world(i, i) * world(j, j) - world(i, j) * world(j, i);
    if (det > 0.0f) {
      m(i, i) = world(j, j) / det;
      m(j, j) = world(i, i) / det;
      m(i, j) = -world(i, j) / det;
      m(j, i) = -world(j, i) / det;
    }
  }
  return m;
}

/// The most a body turns in a substep unless it allows fast rotation, rad: a quarter turn.
inline constexpr float maxRotationPerSubstep = 0.25f * pi<float>;

// integrate.cpp
/// The step's solve: the bodies' velocities (gravity, forces, torques, gyroscopic, damping),
/// the contacts, the speed caps and positions, substep after substep; writes the results back.
void solve(WorldState& w, float dt);

// collide.cpp
/// The broadphase's pairs of shapes whose boxes (grown by the speculative distance) overlap,
/// as contacts (kept with their impulses where the pair was already touching), and each
/// contact's manifold at the bodies' present poses.
void updateContacts(WorldState& w);

// sleep.cpp
/// Wakes a body and its island (everything touching it, transitively).
void wakeBody(WorldState& w, std::uint32_t slot);
void wakeIsland(WorldState& w, std::uint32_t island);
/// Puts an island's bodies to sleep: out of the awake set, at rest.
void sleepIsland(WorldState& w, std::uint32_t island);
/// A touching contact between two dynamic bodies began (joins their islands) or ended.
void linkContact(WorldState& w, const Contact& c, bool began);
/// The bodies' rest times after a step, and the islands at rest put to sleep.
void updateSleep(WorldState& w, float dt);

// continuous.cpp
/// Sweeps the bodies that moved more than half their thinnest extent this step (and bullets)
/// from their start to their end poses against the static shapes (bullets: and the dynamic
/// bodies' end poses), and stops each at its first time of impact.
void sweepFastBodies(WorldState& w);
/// The body's reach and thinnest extent from its shapes and centre of mass.
void updateExtents(const WorldState& w, Body& b);

// contact_solver.cpp
/// The constraints from the contacts with points, at the step's start: anchors, effective
/// masses, warm-start impulses.
void prepareContacts(WorldState& w, const StepContext& context);
void warmStartContacts(WorldState& w);
/// One pass over the contacts: with bias (overlap pushed apart softly) or without (relax: the
/// push taken back; friction solved here only).
void solveContacts(WorldState& w, const StepContext& context, bool useBias);
/// Newton's law of restitution for the points that were approaching faster than the threshold
/// and pushed: their normal velocity becomes e times the approach.
void applyRestitution(WorldState& w);
/// The impulses back into the contacts, for the next step's warm start; a hit event for each
/// contact whose fastest point that pushed approached at least at the hit threshold.
void storeImpulses(WorldState& w);
/// A substep of torque-free rotation (Euler's equations I dw/dt = -w x (I w) in the body frame)
/// by the implicit midpoint rule, which keeps both of the torque-free body's quadratic
/// invariants, its kinetic energy w.(I w)/2 and |I w|^2, exactly up to the solve (the backward
/// Euler step loses energy every substep, the forward one gains it), with the body turning at
/// the substep's mean spin, so that its angular momentum also stays fixed in the world.
struct GyroscopicStep {
  Vec3f change; ///< of the world spin, rad/s
  Vec3f lag;    ///< the new world spin less the mean spin the body turns at (BodyState::gyroscopicLag)
};
/// `rotation`: the body's now; `inertia`: in the body frame; h: the substep.
[[nodiscard]] GyroscopicStep gyroscopicStep(const Quatf& rotation, const Mat33f& inertia, const Vec3f& worldSpin,
                                            float h);

// bodies.cpp
/// Validates mass data for a dynamic body; throws impetus::Error naming the field.
void requireValidMassData(const MassData& data);
/// Gives the body its mass properties (dynamic) or none (static, kinematic).
void applyMassData(Body& b, const MassData& data);

// shapes.cpp
/// A dynamic body's mass properties from its shapes (the default MassData while they have no
/// mass), applied.
void updateMassFromShapes(WorldState& w, Body& b);

} // namespace impetus::rigid3d::detail

namespace impetus::rigid3d {

struct World::Impl : detail::WorldState {
  using WorldState::WorldState;
};

} // namespace impetus::rigid3d
