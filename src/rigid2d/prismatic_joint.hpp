// A slider: translation along an axis of A only, with limits, a motor and a spring.
// The solver's side (prismatic_joint.cpp); the definition is PrismaticJointDef in <impetus/rigid2d/joint.hpp>.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

struct PrismaticJoint {
  PrismaticJointDef def; ///< the settings (anchors and axes as given; motor and limit settings change at run time)
  // Accumulated impulses: solver state, kept from step to step for warm starting.
  Vec2f impulse;              ///< perpendicular (x, N s) and angular (y, N m s) constraint, per substep
  float springImpulse = 0.0f; ///< N s per substep, along the axis
  float motorImpulse = 0.0f;
  float lowerImpulse = 0.0f;
  float upperImpulse = 0.0f;
  /// The moments (N m s) of everything the joint applied to A and to B about their centres in
  /// the current substep, from its warm start on: what the end of the substep rebases the angular
  /// impulse on (correctJointPosition, which ends every substep).
  float torqueOnA = 0.0f;
  float torqueOnB = 0.0f;
  /// Their part from the passive rows' warm start (N m s): what trimming it takes off them.
  float passiveTorqueOnA = 0.0f;
  float passiveTorqueOnB = 0.0f;
  float positionShare = 0.0f; ///< of the block's error corrected on positions this substep (positionShare)
  // This step's constants.
  Vec2f axisA;            ///< the axis in world axes at the step's start
  float axialMass = 0.0f; ///< kg
  Softness springSoftness;
  /// The axis in world axes as the last solve saw it (body A turned through the step): the
  /// direction of the reaction's axial part.
  Vec2f solvedAxis;
};

/// A point of B sliding on a line fixed in A (the prismatic and wheel joints), now: the anchors
/// turned by each body's rotation so far this step and the line turned with A.
struct SliderGeometry {
  Vec2f rA, rB;    ///< anchors relative to the centres of mass, world axes, m
  Vec2f d;         ///< anchor B minus anchor A, m
  Vec2f axis;      ///< the line's unit direction, world axes
  Vec2f normal;    ///< perp(axis)
  float a1 = 0.0f; ///< moment arm of an axial impulse on A: cross(d + rA, axis), m (A's line turns with A)
  float a2 = 0.0f; ///< on B: cross(rB, axis), m
  float s1 = 0.0f; ///< moment arms of a normal impulse: cross(d + rA, normal), m
  float s2 = 0.0f; ///< cross(rB, normal), m
};

/// The slider now; `axisAtStart` is the line's direction in world axes at the step's start.
[[nodiscard]] SliderGeometry sliderGeometry(const Vec2f& axisAtStart, const JointFrame& f, const BodyState& a,
                                            const BodyState& b);
/// The rate of change of the translation dot(axis, d) (m/s): B's anchor's velocity relative to
/// A's along the axis, plus the turning of the axis with A.
[[nodiscard]] float axialSpeed(const SliderGeometry& g, const BodyState& a, const BodyState& b);
/// An impulse (N s) along the axis: -impulse on A, +impulse on B, with their moments.
void applyAxial(const SliderGeometry& g, const JointFrame& f, BodyState& a, BodyState& b, float impulse);
/// The effective mass along the axis at the step's start, kg (0 when neither body can move).
[[nodiscard]] float sliderAxialMass(const Vec2f& axis, const JointFrame& f);
/// The effective masses along the axis and across it in the current geometry, kg. The rigid rows
/// (limits, motors, the line) use these, not the step's-start values: a light body with little
/// inertia on a long arm turns far within a step, its effective mass along a row changes by
/// orders of magnitude, and an impulse from the stale mass overshoots, over and over: energy
/// without end. Springs keep the step's-start mass,
/// which defines their stiffness.
[[nodiscard]] float sliderAxialMassNow(const SliderGeometry& g, const JointFrame& f);
[[nodiscard]] float sliderNormalMassNow(const SliderGeometry& g, const JointFrame& f);
/// A one-sided translation limit (lower: direction +1, c = translation - lower; upper: -1,
/// c = upper - translation) keeping c >= 0 with an accumulated impulse >= 0: speculative while
/// inside (may close the gap this substep, no more), soft at the joint stiffness when violated.
void solveTranslationLimit(float& accumulated, float c, float direction, const SliderGeometry& g, const JointFrame& f,
                           BodyState& a, BodyState& b, float axialMass, const StepContext& context, bool useBias);

void prepareJoint(PrismaticJoint& joint, const JointFrame& frame, const StepContext& context);
/// Scales the accumulated impulses of `rows` (what the warm start applied) and their moments in
/// the tally: warmStartJoints' line search. The spring and motor may do work; the line-and-angle
/// block and the limits are passive.
inline void scaleImpulses(PrismaticJoint& joint, float scale, JointRows rows) {
  if (includes(rows, JointRows::passive)) {
    joint.impulse = joint.impulse * scale;
    joint.lowerImpulse = joint.lowerImpulse * scale;
    joint.upperImpulse = joint.upperImpulse * scale;
    joint.torqueOnA -= (1.0f - scale) * joint.passiveTorqueOnA;
    joint.torqueOnB -= (1.0f - scale) * joint.passiveTorqueOnB;
  }
  if (includes(rows, JointRows::working)) {
    joint.springImpulse = joint.springImpulse * scale;
    joint.motorImpulse = joint.motorImpulse * scale;
  }
}
/// Lets go of part of the accumulated impulses before the warm start (sliderWarmStartFactor) and
/// starts the substep's tally of moments.
inline void beginWarmStart(PrismaticJoint& joint) {
  scaleImpulses(joint, sliderWarmStartFactor, JointRows::all);
  joint.torqueOnA = joint.torqueOnB = 0.0f;
  joint.passiveTorqueOnA = joint.passiveTorqueOnB = 0.0f;
}
/// Applies the accumulated impulses of `rows` (the warm start: warmStartJoints).
void warmStartJoint(PrismaticJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex, JointRows rows);
void solveJoint(PrismaticJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias);
/// The block's error corrected on positions, after the relax pass (positionShare).
void correctJointPosition(PrismaticJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                          std::uint32_t staticIndex, const StepContext& context);
/// The force and torque on body B over the last substep (impulses times the substep rate).
[[nodiscard]] JointReaction jointReaction(const PrismaticJoint& joint, const JointFrame& frame, float inverseH);

} // namespace impetus::rigid2d::detail
