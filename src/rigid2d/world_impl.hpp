// Internal state of the 2D world, shared by world.cpp (bookkeeping, broadphase, collide,
// finalize) and contact_solver.cpp (the soft-step solve).
#pragma once

#include <impetus/core/id_pool.hpp>
#include <impetus/rigid2d/dynamic_tree.hpp>
#include <impetus/rigid2d/manifold.hpp>
#include <impetus/rigid2d/world.hpp>

#include <map>
#include <variant>
#include <vector>

namespace impetus::rigid2d::detail {

using Geometry = std::variant<Circle, Capsule, Polygon, Segment>;

struct Shape {
  Geometry geometry;
  /// The narrowphase's view of a capsule, segment or polygon (circles have none): made once
  /// when the shape is created, so collision never converts or copies it in the step.
  Polygon collisionPolygon;
  std::uint32_t body = 0; ///< body slot
  float density = 1.0f;
  float friction = 0.6f;
  float restitution = 0.0f;
  Filter filter;
  bool sensor = false;
  std::uint64_t userData = 0;
  std::int32_t proxy = DynamicTree::nullNode;
  AABB fatBox;
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
  bool enableSleep = true;
  bool awake = true;
  float sleepTime = 0.0f;            ///< s spent slower than the sleep tolerances
  std::vector<std::uint32_t> shapes; ///< shape slots
  std::uint64_t userData = 0;
  BodyId id;
  bool alive = false;

  /// Simulated this step: alive, not static, awake.
  [[nodiscard]] bool moving() const noexcept { return alive && type != BodyType::staticBody && awake; }
  void wake() noexcept {
    awake = true;
    sleepTime = 0.0f;
  }
};

struct Contact {
  std::uint32_t shapeA = 0; ///< the lower shape slot
  std::uint32_t shapeB = 0;
  Manifold manifold;
  float friction = 0.0f;
  float restitution = 0.0f;
  float approachSpeed = 0.0f; ///< the solver's fastest impact this step, m/s (for hit events)
  int fastestPoint = 0;
};

/// The solver's per-body state for one step: velocities and the position and rotation deltas
/// accumulated over the substeps (anchors stay fixed in the bodies, so separations follow from
/// the deltas without recomputing the manifolds).
struct BodyState {
  Vec2f v;
  float w = 0.0f;
  Vec2f dp;
  Rot2f dq = Rot2f::identity();
};

struct WorldState {
  WorldDef def;
  IdPool bodyIds;
  std::vector<Body> bodies; ///< by id slot
  IdPool shapeIds;
  std::vector<Shape> shapes; ///< by id slot
  DynamicTree tree;
  std::vector<std::uint32_t> moveBuffer;     ///< shapes whose fat box was (re)inserted
  std::map<std::uint64_t, Contact> contacts; ///< by (shapeA << 32 | shapeB): a fixed order
  std::vector<BodyState> states;             ///< by body slot, rebuilt each step
  ContactEvents contactEvents;
  SensorEvents sensorEvents;
  ContactEvents pendingEvents; ///< raised between steps (destroyed bodies): reported by the next step
  SensorEvents pendingSensorEvents;

  Body& body(BodyId id);
  [[nodiscard]] const Body& body(BodyId id) const;
};

/// A shape's world bounding box.
[[nodiscard]] AABB shapeBox(const Shape& s, const Transform2f& xf);

// contact_solver.cpp
/// The substepped soft contact solve over every touching contact; updates `states`.
void solveContacts(WorldState& w, float dt);

// island.cpp
/// A sleeping body touched by a moving one wakes up (before the solve, so it takes part).
void wakeTouched(WorldState& w);
/// Accumulates rest time and puts islands to sleep that have rested long enough.
void updateSleep(WorldState& w, float dt);

// continuous.cpp
/// Where a fast body may go from `start` toward `end` without passing a static shape.
[[nodiscard]] Vec2f sweepAgainstStatic(const WorldState& w, const Body& b, const Vec2f& start, const Vec2f& end);

} // namespace impetus::rigid2d::detail

namespace impetus::rigid2d {
struct World::Impl : detail::WorldState {};
} // namespace impetus::rigid2d
