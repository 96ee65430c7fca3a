// The 3D world (ch. 11-12): rigid bodies with quaternion orientation and full inertia tensors,
// stepped in substeps as the 2D world is. Bodies move under gravity, forces, torques and
// impulses, with their mass from their shapes, and collide: soft contacts with friction and
// restitution. Joints come next (docs/rigid3d.md says what is there).
//
// Each step: find the pairs of shapes whose boxes overlap and their manifolds; then `substeps`
// times: integrate velocities (gravity, forces and torques; the gyroscopic torque -w x (I w)
// implicitly, by the implicit midpoint rule on Euler's equations in the body frame, so a body
// spun about its intermediate axis flips over and back with its energy bounded; damping,
// implicitly), warm start and solve the contacts (soft: overlap pushed apart at a bounded speed),
// hold the speeds within the world's caps, integrate positions (the orientation as
// q += h/2 (0, w) q, normalised), relax the contacts (friction); then restitution. Everything
// runs in a fixed order: the same inputs give bit-identical results.
#pragma once

#include <impetus/math/transform3.hpp>
#include <impetus/rigid3d/geometry.hpp>
#include <impetus/rigid3d/manifold.hpp>
#include <impetus/rigid3d/types.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace impetus::rigid3d {

/// A touching pair of shapes after a step: its manifold (the normal from A to B) and the
/// impulses the solver's last substep held at its points.
struct ContactData {
  ShapeId shapeA, shapeB;
  Manifold manifold;
  std::array<float, 4> normalImpulses{};  ///< N s, a substep's, by point
  std::array<Vec3f, 4> tangentImpulses{}; ///< N s, world, a substep's friction, by point
};

/// Two shapes started touching (their manifold gained points) this step.
struct ContactBeginEvent {
  ShapeId shapeA, shapeB;
};
/// Two shapes stopped touching this step (or one was destroyed: its id is then stale).
struct ContactEndEvent {
  ShapeId shapeA, shapeB;
};
/// Two shapes met at least as fast as WorldDef::hitEventThreshold: for impact sounds and damage.
struct ContactHitEvent {
  ShapeId shapeA, shapeB;
  Vec3f point;                ///< world, m: the point that approached fastest
  Vec3f normal;               ///< from A to B
  float approachSpeed = 0.0f; ///< m/s, > 0
};
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

/// Where a ray met a shape.
struct RayHit {
  ShapeId shape;
  Vec3f point;           ///< world, m
  Vec3f normal;          ///< the surface's outward normal there
  float fraction = 0.0f; ///< along the translation, 0 to 1
};

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

  /// Throws impetus::Error for a non-finite or out-of-range field (naming it), a zero
  /// rotation quaternion, or invalid mass data.
  BodyId createBody(const BodyDef& def);
  void destroyBody(BodyId id);
  [[nodiscard]] bool isValid(BodyId id) const noexcept;
  [[nodiscard]] std::uint32_t bodyCount() const noexcept;
  void bodyIds(std::vector<BodyId>& out) const;

  /// A shape on a body, in its frame. A dynamic body's mass properties become its shapes' (the
  /// composite about their common centre of mass). Throws impetus::Error for invalid geometry
  /// (requireValidGeometry) or a negative or non-finite density.
  ShapeId createShape(BodyId body, const ShapeDef& def, const ShapeGeometry& geometry);
  void destroyShape(ShapeId id);
  [[nodiscard]] bool isValid(ShapeId id) const noexcept;
  [[nodiscard]] BodyId shapeBody(ShapeId id) const;
  [[nodiscard]] ShapeGeometry shapeGeometry(ShapeId id) const;
  void bodyShapes(BodyId body, std::vector<ShapeId>& out) const;

  /// Whether the body is awake (static bodies: always). Islands at rest fall asleep (WorldDef::
  /// enableSleep); a contact beginning with an awake body, or any call that changes a body
  /// (its transform, velocities, mass, forces, impulses), wakes its island.
  [[nodiscard]] bool isAwake(BodyId id) const;
  /// Wakes the body's island, or puts it to sleep (the whole island: a body cannot sleep on
  /// what is still moving).
  void setAwake(BodyId id, bool awake);
  [[nodiscard]] BodyType bodyType(BodyId id) const;
  /// The body origin's frame in the world.
  [[nodiscard]] Transform3f transform(BodyId id) const;
  [[nodiscard]] Vec3f position(BodyId id) const;
  [[nodiscard]] Quatf rotation(BodyId id) const;
  /// The centre of mass, world, m.
  [[nodiscard]] Vec3f worldCenter(BodyId id) const;
  [[nodiscard]] Vec3f linearVelocity(BodyId id) const;
  /// World frame, rad/s.
  [[nodiscard]] Vec3f angularVelocity(BodyId id) const;
  /// The velocity of a point fixed to the body, given in the world, m/s.
  [[nodiscard]] Vec3f velocityAt(BodyId id, const Vec3f& worldPoint) const;
  [[nodiscard]] MassData massData(BodyId id) const;
  /// The inertia tensor about the centre of mass in world axes, kg m^2: R I R^T.
  [[nodiscard]] Mat33f worldInertia(BodyId id) const;
  /// Translational plus rotational kinetic energy, J (in double: for conservation checks).
  [[nodiscard]] double kineticEnergy(BodyId id) const;
  /// Angular momentum about the centre of mass, world, kg m^2/s (in double).
  [[nodiscard]] Vec3d angularMomentum(BodyId id) const;
  [[nodiscard]] std::uint64_t userData(BodyId id) const;

  /// Teleports the body (its velocities kept). Throws impetus::Error for a non-finite
  /// position or a zero or non-finite rotation (normalised otherwise).
  void setTransform(BodyId id, const Vec3f& position, const Quatf& rotation);
  void setLinearVelocity(BodyId id, const Vec3f& velocity);
  void setAngularVelocity(BodyId id, const Vec3f& velocity);
  /// A dynamic body's mass properties (MassData's rules; throws impetus::Error naming the
  /// field otherwise). The body frame's origin stays where it is; the centre of mass moves.
  void setMassData(BodyId id, const MassData& data);
  void setLinearDamping(BodyId id, float damping);
  void setAngularDamping(BodyId id, float damping);
  void setGravityScale(BodyId id, float scale);
  void setAxisLocks(BodyId id, const AxisLocks& locks);

  /// A force (N) at a point (world, m) until the end of the next step; it also turns the body
  /// by (point - centre) x force. Dynamic bodies only (others ignore it).
  void applyForce(BodyId id, const Vec3f& force, const Vec3f& worldPoint);
  void applyForceToCenter(BodyId id, const Vec3f& force);
  /// A torque (N m, world) until the end of the next step.
  void applyTorque(BodyId id, const Vec3f& torque);
  /// An impulse (N s) at a point (world, m): the velocities change at once.
  void applyLinearImpulse(BodyId id, const Vec3f& impulse, const Vec3f& worldPoint);
  /// An angular impulse (N m s, world).
  void applyAngularImpulse(BodyId id, const Vec3f& impulse);

  /// The first shape the ray from `origin` along `translation` (world, m) hits, of those whose
  /// filter passes `filter` (shouldCollide); none when it hits nothing. A ray starting inside a
  /// shape does not hit that shape (rayCast). Throws impetus::Error for non-finite input.
  [[nodiscard]] std::optional<RayHit> castRayClosest(const Vec3f& origin, const Vec3f& translation,
                                                     const CollisionFilter& filter = {}) const;
  /// Every shape the ray hits, nearest first (ties in shape order).
  [[nodiscard]] std::vector<RayHit> castRayAll(const Vec3f& origin, const Vec3f& translation,
                                               const CollisionFilter& filter = {}) const;
  /// The shapes a shape placed at `transform` overlaps (closer than touching: their surfaces
  /// cross), in shape order. Throws impetus::Error for invalid geometry or a non-finite position.
  [[nodiscard]] std::vector<ShapeId> overlapShape(const ShapeGeometry& shape, const Transform3f& transform,
                                                  const CollisionFilter& filter = {}) const;

  /// The contact events of the last step, in a fixed order (the contacts' keys: A's shape, then
  /// B's), valid until the next step.
  [[nodiscard]] const ContactEvents& contactEvents() const noexcept;
  /// The sensor events of the last step (begins and ends of overlaps), in the contacts' order.
  [[nodiscard]] const SensorEvents& sensorEvents() const noexcept;
  /// The contacts whose manifolds have points (touching, or about to), in a fixed order.
  void contacts(std::vector<ContactData>& out) const;
  [[nodiscard]] std::uint32_t contactCount() const noexcept;

  [[nodiscard]] Vec3f gravity() const noexcept;
  void setGravity(const Vec3f& gravity);
  /// Moves the world's origin to `newOrigin` (world, m): every body's position becomes relative
  /// to it, so a world far from its origin (a flight 100 km out) keeps the resolution of floats.
  void shiftOrigin(const Vec3f& newOrigin);

  /// A hash of every body's pose and velocities (bits, not values): equal for bit-identical
  /// states.
  [[nodiscard]] std::uint64_t stateHash() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace impetus::rigid3d
