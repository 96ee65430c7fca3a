// Joints of the 2D world: constraints between two bodies, solved in the soft-step solver with the
// contacts (book ch. 13, "connecting objects", done as Box2D v3 does it rather than with the
// book's stiff springs). Each joint type has a definition struct; World::createJoint(def) makes
// it and returns a JointId.
//
// Anchors are given in each body's local frame (m, relative to the body origin, not to its centre
// of mass). Angles are radians, counter-clockwise positive; the joint angle of a revolute or weld
// joint is angleB - angleA - referenceAngle. Springs are given by their frequency (Hz) and
// damping ratio (dimensionless; 1 = critical), which stay meaningful whatever the masses; a zero
// frequency means rigid. Motor limits are a torque (N m) or a force (N). Reaction forces and
// torques are what the joint applies to body B, averaged over the last step (N, N m).
//
// Every definition's `breakForce` (N) and `breakTorque` (N m) make a joint breakable: the step in
// which its reaction exceeds either raises a JointBreakEvent (once, until the joint is below it
// again); the joint keeps working until destroyed, so the game decides what breaking means.
#pragma once

#include <impetus/core/id_pool.hpp>
#include <impetus/rigid2d/types.hpp>

#include <limits>
#include <vector>

namespace impetus::rigid2d {

using JointId = Id<struct JointTag>;

enum class JointType { revolute, prismatic, distance, weld, wheel, motor, mouse, filter };

/// A joint id that knows its joint's type: what createJoint returns for each def, and what the
/// type's own functions take (joint_functions.hpp), so that a revolute joint's motor cannot be
/// set on a prismatic joint. It converts to JointId for what every joint has; a JointId of a
/// known type becomes one as `RevoluteJointId{id}` (a function given the wrong type throws
/// impetus::Error naming "joint id").
template <JointType Type> struct TypedJointId {
  JointId id;
  static constexpr JointType type = Type;
  constexpr operator JointId() const noexcept { return id; } // NOLINT(google-explicit-constructor)
  friend constexpr bool operator==(const TypedJointId&, const TypedJointId&) noexcept = default;
};
using RevoluteJointId = TypedJointId<JointType::revolute>;
using PrismaticJointId = TypedJointId<JointType::prismatic>;
using DistanceJointId = TypedJointId<JointType::distance>;
using WeldJointId = TypedJointId<JointType::weld>;
using WheelJointId = TypedJointId<JointType::wheel>;
using MotorJointId = TypedJointId<JointType::motor>;
using MouseJointId = TypedJointId<JointType::mouse>;
using FilterJointId = TypedJointId<JointType::filter>;

/// What every joint has. Each type's definition is this and the type's own settings
/// (RevoluteJointSettings, ...), which its solver keeps; this part the world keeps apart.
struct JointDefBase {
  BodyId bodyA;
  BodyId bodyB;
  Vec2f localAnchorA; ///< m, in body A's frame
  Vec2f localAnchorB; ///< m, in body B's frame
  /// Whether the two bodies' shapes still collide with each other (usually not: a hinge's parts
  /// overlap at the pin).
  bool collideConnected = false;
  float breakForce = std::numeric_limits<float>::infinity();  ///< N
  float breakTorque = std::numeric_limits<float>::infinity(); ///< N m
  /// How firmly the joint's rigid rows are held, Hz (Box2D v3's constraintHertz): a joint pulled
  /// apart by a load W settles W / k apart, k = m_eff (2 pi f)^2, and is brought back at that
  /// rate. 0: the world's jointHertz. Capped, like the world's, at a quarter of the substep rate.
  float constraintHertz = 0.0f;
  /// The rigid rows' damping ratio with constraintHertz (dimensionless; ignored without it).
  float constraintDampingRatio = 2.0f;
  std::uint64_t userData = 0;
};

/// A pin: the anchors stay together and the bodies turn freely about them, within optional
/// limits, driven by an optional motor, pulled by an optional torsional spring, and slowed by
/// joint friction (a torque of at most frictionTorque against the relative spin).
struct RevoluteJointSettings {
  float referenceAngle = 0.0f; ///< rad: angleB - angleA when the joint angle is zero
  bool enableLimit = false;
  float lowerAngle = 0.0f; ///< rad, in [-pi, pi] and <= upperAngle (the joint angle lives in (-pi, pi])
  float upperAngle = 0.0f; ///< rad, in [-pi, pi]
  bool enableMotor = false;
  float motorSpeed = 0.0f;     ///< rad/s of B relative to A
  float maxMotorTorque = 0.0f; ///< N m, >= 0
  bool enableSpring = false;
  float hertz = 0.0f;          ///< spring frequency, Hz (toward joint angle 0)
  float dampingRatio = 0.0f;   ///< of the spring
  float frictionTorque = 0.0f; ///< N m, >= 0: dry friction in the pin
};
struct RevoluteJointDef : JointDefBase, RevoluteJointSettings {};

/// A slider: B moves relative to A along `localAxisA` (body A's frame) only, without turning
/// relative to A; with limits on the translation, a motor and a spring.
struct PrismaticJointSettings {
  Vec2f localAxisA{1.0f, 0.0f}; ///< unit direction in A's frame (normalized on creation)
  float referenceAngle = 0.0f;  ///< rad
  bool enableLimit = false;
  float lowerTranslation = 0.0f; ///< m, <= upperTranslation
  float upperTranslation = 0.0f; ///< m
  bool enableMotor = false;
  float motorSpeed = 0.0f;    ///< m/s
  float maxMotorForce = 0.0f; ///< N, >= 0
  bool enableSpring = false;
  float hertz = 0.0f;        ///< spring frequency, Hz (toward translation 0)
  float dampingRatio = 0.0f; ///< of the spring
};
struct PrismaticJointDef : JointDefBase, PrismaticJointSettings {};

/// Keeps the anchors `length` apart, as a rod; or, with minLength < maxLength, lets the distance
/// range between them (a rope: minLength 0); with a spring, pulls toward `length` softly.
struct DistanceJointSettings {
  float length = 1.0f;                                      ///< m, > 0
  float minLength = 0.0f;                                   ///< m (used with enableLimit)
  float maxLength = std::numeric_limits<float>::infinity(); ///< m (used with enableLimit)
  bool enableLimit = false;
  bool enableSpring = false; ///< false: rigid at `length` (within the limits)
  float hertz = 0.0f;        ///< spring frequency, Hz
  float dampingRatio = 0.0f; ///< of the spring
  bool enableMotor = false;
  float motorSpeed = 0.0f;    ///< m/s, rate of change of the length
  float maxMotorForce = 0.0f; ///< N, >= 0
};
struct DistanceJointDef : JointDefBase, DistanceJointSettings {};

/// Glues B to A at the anchors and relative angle; soft with linearHertz / angularHertz > 0.
struct WeldJointSettings {
  float referenceAngle = 0.0f; ///< rad
  float linearHertz = 0.0f;    ///< 0: rigid
  float linearDampingRatio = 0.0f;
  float angularHertz = 0.0f; ///< 0: rigid
  float angularDampingRatio = 0.0f;
};
struct WeldJointDef : JointDefBase, WeldJointSettings {};

/// A vehicle wheel: B (the wheel) slides along `localAxisA` of A (the chassis) on a suspension
/// spring and turns freely about its anchor, driven by an optional motor.
struct WheelJointSettings {
  Vec2f localAxisA{0.0f, 1.0f}; ///< suspension direction in A's frame (normalized on creation)
  bool enableSpring = true;
  float hertz = 1.0f;        ///< suspension frequency, Hz
  float dampingRatio = 0.7f; ///< of the suspension
  bool enableLimit = false;
  float lowerTranslation = 0.0f; ///< m
  float upperTranslation = 0.0f; ///< m
  bool enableMotor = false;
  float motorSpeed = 0.0f;     ///< rad/s of the wheel relative to the chassis
  float maxMotorTorque = 0.0f; ///< N m, >= 0
};
struct WheelJointDef : JointDefBase, WheelJointSettings {};

/// Drives B toward a target position and angle relative to A (`linearOffset` in A's frame, m;
/// `angularOffset`, rad) with at most maxForce and maxTorque: for characters and top-down
/// friction. The anchors are not used. correctionFactor is per substep.
struct MotorJointSettings {
  Vec2f linearOffset;            ///< m, B's origin relative to A's, in A's frame
  float angularOffset = 0.0f;    ///< rad, angleB - angleA
  float maxForce = 1.0f;         ///< N, >= 0
  float maxTorque = 1.0f;        ///< N m, >= 0
  float correctionFactor = 0.3f; ///< fraction of the position error closed per substep, 0 to 1
};
struct MotorJointDef : JointDefBase, MotorJointSettings {};

/// Drags a point of B (localAnchorB) toward a world target with a soft spring of at most
/// maxForce: a mouse or a finger. bodyA is ignored: B is pulled toward the world.
struct MouseJointSettings {
  Vec2f target;       ///< m, world
  float hertz = 5.0f; ///< Hz
  float dampingRatio = 0.7f;
  float maxForce = 1000.0f; ///< N, >= 0
};
struct MouseJointDef : JointDefBase, MouseJointSettings {};

/// Only turns collision off between two bodies (Box2D v3's filter joint): no constraint, no
/// force; the bodies sleep and wake together, like any joined pair. The anchors are not used;
/// collideConnected must stay false (a filter joint that lets the bodies collide does nothing).
struct FilterJointDef : JointDefBase {};

/// A joint's reaction exceeded its breakForce or breakTorque this step.
struct JointBreakEvent {
  JointId joint;
  float force = 0.0f;  ///< N, the reaction force's magnitude
  float torque = 0.0f; ///< N m, the reaction torque's magnitude
};
struct JointEvents {
  std::vector<JointBreakEvent> breaks;
};

} // namespace impetus::rigid2d
