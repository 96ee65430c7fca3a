// Each joint type's own readouts and settings, as free functions of its typed id (after Box2D
// v3's b2RevoluteJoint_*, b2PrismaticJoint_*, ...): World keeps what every joint has (create,
// destroy, anchors, bodies, reaction), and a new joint type adds functions here, not members
// there. A setter validates its values (impetus::Error naming the field) and wakes the joint's
// bodies; a typed id of the wrong joint type is an impetus::Error naming "joint id".
#pragma once

#include <impetus/math/vec2.hpp>
#include <impetus/rigid2d/joint.hpp>

namespace impetus::rigid2d {

class World;

/// The joint's angle (angleB - angleA - referenceAngle, in (-pi, pi]), rad.
[[nodiscard]] float revoluteAngle(const World& world, RevoluteJointId joint);
/// The torque the motor applied over the last step, N m.
[[nodiscard]] float revoluteMotorTorque(const World& world, RevoluteJointId joint);
void setRevoluteMotor(World& world, RevoluteJointId joint, bool enable, float speed, float maxTorque);
void setRevoluteLimit(World& world, RevoluteJointId joint, bool enable, float lowerAngle, float upperAngle);

/// The translation of anchor B from anchor A along the axis, m.
[[nodiscard]] float prismaticTranslation(const World& world, PrismaticJointId joint);
/// The force the motor applied over the last step, N.
[[nodiscard]] float prismaticMotorForce(const World& world, PrismaticJointId joint);
void setPrismaticMotor(World& world, PrismaticJointId joint, bool enable, float speed, float maxForce);
void setPrismaticLimit(World& world, PrismaticJointId joint, bool enable, float lowerTranslation,
                       float upperTranslation);

/// The anchors' distance now, m.
[[nodiscard]] float distanceJointLength(const World& world, DistanceJointId joint);
/// The rest length, m (> 0).
void setDistanceJointLength(World& world, DistanceJointId joint, float length);

/// The torque the wheel's motor applied over the last step, N m.
[[nodiscard]] float wheelMotorTorque(const World& world, WheelJointId joint);
void setWheelMotor(World& world, WheelJointId joint, bool enable, float speed, float maxTorque);

/// Where the motor joint drives body B: its offset from A in A's frame (m) and angle (rad).
void setMotorJointTarget(World& world, MotorJointId joint, const Vec2f& linearOffset, float angularOffset);

/// The world point the mouse joint pulls its body's anchor toward, m.
void setMouseTarget(World& world, MouseJointId joint, const Vec2f& target);

} // namespace impetus::rigid2d
