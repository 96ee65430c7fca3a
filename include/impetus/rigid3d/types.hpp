// Definitions for the 3D world: ids, body definitions, mass data, world settings. Frames are
// right-handed with +y up; SI units throughout (m, kg, s, rad).
#pragma once

#include <impetus/core/collision_filter.hpp>
#include <impetus/core/id_pool.hpp>
#include <impetus/math/mat33.hpp>
#include <impetus/math/quat.hpp>
#include <impetus/math/vec3.hpp>

#include <cstdint>
#include <optional>

namespace impetus::rigid3d {

using BodyId = Id<struct BodyTag>;
using ShapeId = Id<struct ShapeTag>;

enum class BodyType {
  staticBody,    ///< never moves, infinite mass
  kinematicBody, ///< moves at its set velocity, unaffected by forces
  dynamicBody,   ///< moved by forces, torques and impulses
};

/// A body's mass properties: its mass, its centre of mass in the body frame and its inertia
/// tensor about that centre, in the body frame (symmetric, positive definite, its principal
/// moments satisfying the triangle inequality I1 + I2 >= I3 as every real body's do).
struct MassData {
  float mass = 1.0f;                   ///< kg
  Vec3f center;                        ///< m, body frame
  Mat33f inertia = Mat33f::identity(); ///< kg m^2, about the centre, body frame
};

/// Motion a body may not have, along or about the world's axes (a body kept in a plane, a
/// character's capsule that never tips). A locked axis takes no velocity from forces, impulses
/// or gyroscopic torque; what the body's definition or setters give it along that axis is
/// removed at the next step.
struct AxisLocks {
  bool linearX = false, linearY = false, linearZ = false;
  bool angularX = false, angularY = false, angularZ = false;
};

struct BodyDef {
  BodyType type = BodyType::staticBody;
  Vec3f position;                     ///< body origin, m
  Quatf rotation = Quatf::identity(); ///< body frame in the world (a unit quaternion)
  Vec3f linearVelocity;               ///< of the centre of mass, world, m/s
  Vec3f angularVelocity;              ///< world, rad/s
  float linearDamping = 0.0f;         ///< 1/s: dv/dt = -c v
  float angularDamping = 0.0f;        ///< 1/s
  float gravityScale = 1.0f;
  AxisLocks locks;
  /// Lets the body spin faster than a quarter turn a substep (a wheel, a rotor); otherwise its
  /// spin is capped there, where the rotation deltas stop meaning what they say.
  bool allowFastRotation = false;
  /// Swept against the dynamic bodies too, not only the static ones (a projectile): a body
  /// moving more than half its thinnest extent in a step is always swept against the static
  /// shapes, so it cannot pass through a wall; a bullet cannot pass through a thin moving body
  /// either. It costs a sweep each step.
  bool isBullet = false;
  /// May fall asleep when it and everything touching it have been at rest for timeToSleep.
  bool enableSleep = true;
  /// Starts awake (false: asleep, until touched or changed).
  bool isAwake = true;
  /// A dynamic body's mass properties. Absent: its shapes' (World::createShape), or while it has
  /// none with mass, 1 kg at the body origin with a unit inertia tensor (1 kg m^2 about every
  /// axis). Setting them (here or World::setMassData) holds them until a shape is added or
  /// removed.
  std::optional<MassData> massData;
  std::uint64_t userData = 0;
};

/// A shape's material and mass. A contact's friction is the geometric mean of its shapes' (a
/// slippery shape is slippery against anything), its restitution the larger of the two.
struct ShapeDef {
  float density = 1000.0f;  ///< kg/m^3 (water's by default): the body's mass comes from its shapes'
  float friction = 0.6f;    ///< Coulomb coefficient
  float restitution = 0.0f; ///< 0 to 1: the ratio of separation to approach speed in an impact
  /// Rolling resistance coefficient (dimensionless, as c_rr in F = c_rr N): a sphere or capsule
  /// rolling on this shape feels a torque c_rr N r against its rolling (r its radius), so a
  /// rolling ball slows at (5/7) c_rr g. Typical: 0.001 (steel on steel) to 0.3 (tyre on sand).
  /// The pair uses the larger of the two.
  float rollingResistance = 0.0f;
  /// Which shapes it collides with (categories, masks, groups), and which queries see it.
  CollisionFilter filter;
  /// A sensor: it pushes nothing and is pushed by nothing, and reports the shapes that overlap
  /// it (World::sensorEvents: a trigger volume). Its density still counts toward its body's mass.
  /// Sensors see other bodies' shapes, not other sensors.
  bool isSensor = false;
  std::uint64_t userData = 0;
};

struct WorldDef {
  Vec3f gravity{0.0f, -10.0f, 0.0f}; ///< m/s^2
  int substeps = 4;                  ///< solver substeps per step
  float maxLinearSpeed = 400.0f;     ///< m/s
  /// Contact stiffness, Hz, capped at a quarter of the substep rate (a stiffer spring than the
  /// substep can follow would ring); twice this against static and kinematic bodies, which give
  /// nothing back.
  float contactHertz = 30.0f;
  /// Contact damping ratio: heavily overdamped, so an overlap is taken back without a bounce.
  float contactDampingRatio = 10.0f;
  float maxContactPushSpeed = 3.0f;  ///< m/s: the fastest an overlap is pushed apart
  float restitutionThreshold = 1.0f; ///< m/s: slower impacts do not bounce
  /// Start each step's contact solve from the last step's impulses (warm starting): a resting
  /// stack holds in a few iterations rather than sinking while they build up.
  bool enableWarmStarting = true;
  /// m/s: impacts at least this fast raise a hit event (World::contactEvents).
  float hitEventThreshold = 1.0f;
  /// Islands at rest fall asleep and cost the solver nothing until touched.
  bool enableSleep = true;
  float timeToSleep = 0.5f;             ///< s an island must stay slow to fall asleep
  float sleepLinearTolerance = 0.05f;   ///< m/s
  float sleepAngularTolerance = 0.035f; ///< rad/s (2 degrees per second)
};

} // namespace impetus::rigid3d
