// A slider: translation along an axis of A only, with limits, a motor and a spring.
// The solver's side (prismatic_joint.cpp); the definition is PrismaticJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

/// A block part for the line and the angle; spring, motor and limit parts along the axis.
struct PrismaticJoint {
  PrismaticJointSettings def; ///< the type's settings (axes as given; motor and limit settings change at run time)
  BlockPart<2> block;         ///< across the axis (N s) and in angle (N m s), per substep
  SpringPart spring;          ///< along the axis, N s per substep
  MotorPart motor;
  LimitPart limit;
  Vec2f axisA; ///< the axis in world axes at the step's start
  /// The axis in world axes as the last solve saw it (body A turned through the step): the
  /// direction of the reaction's axial part.
  Vec2f solvedAxis;
};

/// A point of B sliding on a line fixed in A (the prismatic and wheel joints), now: the line turns
/// with A, so the moment arms on A are taken about B's anchor (d + rA), not A's.
struct SliderGeometry {
  Vec2f rA, rB; ///< anchors relative to the centres of mass, world axes, m
  Vec2f d;      ///< anchor B minus anchor A, m
  Vec2f axis;   ///< the line's unit direction, world axes
  Vec2f normal; ///< perp(axis)
  [[nodiscard]] JointRow axialRow() const { return linearRow(axis, d + rA, rB); }
  [[nodiscard]] JointRow normalRow() const { return linearRow(normal, d + rA, rB); }
  [[nodiscard]] float translation() const { return dot(axis, d); }
};

/// The slider now; `axisAtStart` is the line's direction in world axes at the step's start.
[[nodiscard]] SliderGeometry sliderGeometry(const Vec2f& axisAtStart, const JointFrame& f, const BodyState& a,
                                            const BodyState& b);

void prepareJoint(PrismaticJoint& joint, const JointFrame& frame, const JointPose& pose, const StepContext& context);
void warmStartJoint(PrismaticJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex);
void solveJoint(PrismaticJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep (impulses times the substep rate).
[[nodiscard]] JointReaction jointReaction(const PrismaticJoint& joint, float inverseH);

} // namespace impetus::rigid2d::detail
