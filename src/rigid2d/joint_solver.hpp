// Joints inside the solver: the common part of every joint (bodies, anchors, the solver's
// per-step frames) and the per-type parts, one file per type (revolute_joint.cpp, ...). Each
// type provides prepare, warm start, solve (with or without bias, like the contacts) and its
// reaction, and is called in joint order: the solves before the contacts' of each stage (joints
// are few and hold structures together: solving them first lets the contacts see their result),
// the warm start after the contacts' (warmStartJoints measures it with their support in).
#pragma once

#include "rigid2d/world_impl.hpp"

#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/joint.hpp>

#include <algorithm>
#include <cmath>
#include <variant>

namespace impetus::rigid2d::detail {

/// A joint's force and torque on body B (N, N m).
struct JointReaction {
  Vec2f force;
  float torque = 0.0f;
};

/// The solver's view of a joint for one step, shared by every type.
struct JointFrame {
  std::uint32_t indexA = 0, indexB = 0; ///< solver indices (the static index for static bodies)
  float mA = 0.0f, mB = 0.0f;           ///< inverse masses, 1/kg
  float iA = 0.0f, iB = 0.0f;           ///< inverse rotational inertias, 1/(kg m^2)
  Vec2f frameA, frameB;                 ///< anchors relative to the centres of mass, world axes, at the step's start, m
  Vec2f deltaCenter;                    ///< cB - cA at the step's start, m
  float deltaAngle = 0.0f;              ///< angleB - angleA at the step's start (in (-pi, pi]), rad
  Rot2f qA, qB;                         ///< the bodies' rotations at the step's start
  Vec2f localCenterA, localCenterB;     ///< centres of mass in the body frames, m (origin = c - rotate(q, localCenter))
  Vec2f centerB;                        ///< B's centre of mass at the step's start, world, m (the mouse joint)
  Softness softness;                    ///< the rigid rows' stiffness (the joint's constraintHertz, or the world's)
  float positionCorrection = 0.0f;      ///< fraction of an error corrected on positions a substep (with softness)
};

/// Whether `rows` takes in the rows of `part` (JointRows::working or JointRows::passive).
[[nodiscard]] constexpr bool includes(JointRows rows, JointRows part) {
  return (static_cast<unsigned>(rows) & static_cast<unsigned>(part)) != 0;
}

/// `impulse` where `rows` includes `part`, else 0 (exactly: with every row picked, a sum of
/// picks rounds as the plain sum).
[[nodiscard]] constexpr float pick(JointRows rows, JointRows part, float impulse) {
  return includes(rows, part) ? impulse : 0.0f;
}

/// What a joint does before its warm start (beginWarmStart): nothing, unless its type says so.
template <class JointData> void beginWarmStart(JointData&) {}

/// The angle of qB relative to qA, in (-pi, pi].
[[nodiscard]] inline float relativeAngle(const Rot2f& qB, const Rot2f& qA) {
  const Rot2f q = invMul(qA, qB);
  return std::atan2(q.s, q.c);
}

/// An angle wrapped into (-pi, pi].
[[nodiscard]] inline float unwindAngle(float a) {
  constexpr float pi = impetus::pi<float>;
  if (a < -pi) {
    return a + 2.0f * pi;
  }
  if (a > pi) {
    return a - 2.0f * pi;
  }
  return a;
}

/// The anchors now: the step's frames turned by each body's rotation so far this step.
[[nodiscard]] inline Vec2f currentAnchor(const BodyState& s, const Vec2f& frame) { return rotate(s.dq, frame); }

/// Writes a body's new velocities back unless it is the static state.
inline void storeVelocity(std::vector<BodyState>& states, std::uint32_t index, std::uint32_t staticIndex,
                          const BodyState& s) {
  if (index != staticIndex) {
    states[index].v = s.v;
    states[index].w = s.w;
  }
}

/// The share (0 to 1) of a joint's position error corrected on the positions after the relax
/// pass instead of by bias velocity in the solve pass, from how far the joint's frame turns in a
/// substep (`turn`, rad: the faster of the bodies' spins, or the faster rotation the joint
/// follows, times the substep). The soft step's bias is taken back by the relax pass along the
/// joint's direction at the substep's end; the bias pushed along its direction at the start.
/// While the frame turns little that is the same direction, and the soft step keeps a pendulum's
/// energy to 0.3% over ten swings. Turning half a radian a substep (a whirl: 120 rad/s at 240
/// substeps a second), half the bias is left behind across the joint and speeds the whirl up:
/// a closed chain of three 1-2 cm discs, whirling on a revolute and a distance joint, gains
/// 2.9% of its energy scale in 1.5 s without this (and sliders likewise). A correction on the
/// positions adds no velocity at all (as Box2D 2.4's and Jolt's position solves); it is not used
/// throughout because the relax pass's projection then loses what the bias used to give back (a
/// pendulum swinging at 86 degrees loses 1.2% of its energy a second). In between, a blend.
[[nodiscard]] inline float positionShare(float turn) {
  constexpr float softBelow = 0.05f; // rad a substep: 12 rad/s at 240 substeps a second
  constexpr float positionsAbove = 0.2f;
  return std::clamp((turn - softBelow) / (positionsAbove - softBelow), 0.0f, 1.0f);
}

/// How far the faster of two bodies turns in a substep, rad.
[[nodiscard]] inline float substepTurn(const BodyState& a, const BodyState& b, const StepContext& context) {
  return std::max(std::abs(a.w), std::abs(b.w)) * context.h;
}

/// Writes a body's position and rotation deltas back (not for the shared static state).
inline void storePose(std::vector<BodyState>& states, std::uint32_t index, std::uint32_t staticIndex,
                      const BodyState& s) {
  if (index != staticIndex) {
    states[index].dp = s.dp;
    states[index].dq = s.dq;
  }
}

/// Turns a body's rotation delta by `angle` (rad), as the position integration does.
inline void turnBy(BodyState& s, float angle) {
  s.dq = normalize(Rot2f{s.dq.c - angle * s.dq.s, s.dq.s + angle * s.dq.c});
}

/// The share of their accumulated impulses the prismatic and wheel joints warm start with
/// (Bullet's warmstartingFactor, 0.85, does so for every constraint). Their line-and-angle rows
/// lock the bodies' relative turning, and chains of them between bodies of tiny inertia do not
/// converge in a Gauss-Seidel pass: accumulated impulses drift apart, cancelling on a shared
/// body, until one warm start spins it past 10^5 rad/s. Let go, that drift decays as 0.8^n; a
/// lone slider's solve is exact and needs no warm start. The trim of each group's passive warm
/// start (warmStartJoints, joint.cpp) keeps a group from gaining energy by it, but not a pair
/// from swinging: without this factor a 46 kg, 2 cm disc carrying a wheel joint's line, its
/// wheel 54 m out along it, spins at 10^5 rad/s within a step and flings the wheel at the speed
/// limit through the floor; with it, it holds (docs/reliability.md tells the history).
constexpr float sliderWarmStartFactor = 0.8f;

/// The effective mass matrix of a point constraint at anchors rA, rB (the 2x2 K with
/// K v = relative velocity change per unit impulse).
[[nodiscard]] inline Mat22f pointMass(const JointFrame& f, const Vec2f& rA, const Vec2f& rB) {
  const float m = f.mA + f.mB;
  const float k11 = m + f.iA * rA.y * rA.y + f.iB * rB.y * rB.y;
  const float k12 = -f.iA * rA.x * rA.y - f.iB * rB.x * rB.y;
  const float k22 = m + f.iA * rA.x * rA.x + f.iB * rB.x * rB.x;
  return {k11, k12, k12, k22};
}

/// Solves K x = b for a 2x2 K; zero when K is singular (two immovable bodies).
[[nodiscard]] inline Vec2f solve22(const Mat22f& k, const Vec2f& b) {
  const float a11 = k.cx.x, a12 = k.cy.x, a21 = k.cx.y, a22 = k.cy.y;
  const float det = a11 * a22 - a12 * a21;
  if (det == 0.0f) {
    return {};
  }
  const float inv = 1.0f / det;
  return {inv * (a22 * b.x - a12 * b.y), inv * (a11 * b.y - a21 * b.x)};
}

/// A joint whose spring, motor or limits are switched off holds no impulse for them (it would be
/// warm started otherwise). For the joint types with those three parts.
template <class JointData> void clearSwitchedOffImpulses(JointData& joint) {
  if (!joint.def.enableSpring) {
    joint.springImpulse = 0.0f;
  }
  if (!joint.def.enableMotor) {
    joint.motorImpulse = 0.0f;
  }
  if (!joint.def.enableLimit) {
    joint.lowerImpulse = joint.upperImpulse = 0.0f;
  }
}

/// One row of a one-sided limit (C >= 0 allowed): the change of its accumulated impulse (kept
/// >= 0) for a constraint speed `cdot` (of C) and effective mass `mass`. While the limit is not
/// reached (C > 0) it is speculative: the row may close the gap this substep, no more; once
/// violated it is pushed back softly at the world's joint stiffness (with bias only).
[[nodiscard]] inline float limitImpulse(float& accumulated, float c, float cdot, float mass, const JointFrame& f,
                                        const StepContext& context, bool useBias) {
  float bias = 0.0f;
  float massScale = 1.0f;
  float impulseScale = 0.0f;
  if (c > 0.0f) {
    bias = c * context.inverseH;
  } else if (useBias) {
    bias = f.softness.biasRate * c;
    massScale = f.softness.massScale;
    impulseScale = f.softness.impulseScale;
  }
  const float impulse = -mass * massScale * (cdot + bias) - impulseScale * accumulated;
  const float total = std::max(accumulated + impulse, 0.0f);
  const float applied = total - accumulated;
  accumulated = total;
  return applied;
}

/// The point constraint (anchors together), as a 2x2 block on the accumulated impulse `linear`:
/// soft with `soft` when `applySoftness` (the position error then biases the target velocity),
/// rigid on the velocities otherwise.
inline void solvePointConstraint(Vec2f& linear, const JointFrame& f, BodyState& a, BodyState& b, const Softness& soft,
                                 bool applySoftness, float biasScale = 1.0f) {
  const Vec2f rA = currentAnchor(a, f.frameA);
  const Vec2f rB = currentAnchor(b, f.frameB);
  const Vec2f cdot = (b.v + cross(b.w, rB)) - (a.v + cross(a.w, rA));
  Vec2f bias;
  float massScale = 1.0f;
  float impulseScale = 0.0f;
  if (applySoftness) {
    const Vec2f separation = (b.dp - a.dp) + (rB - rA) + f.deltaCenter;
    bias = separation * (soft.biasRate * biasScale);
    massScale = soft.massScale;
    impulseScale = soft.impulseScale;
  }
  const Vec2f impulse = solve22(pointMass(f, rA, rB), cdot + bias) * -massScale - linear * impulseScale;
  linear += impulse;
  a.v -= impulse * f.mA;
  a.w -= f.iA * cross(rA, impulse);
  b.v += impulse * f.mB;
  b.w += f.iB * cross(rB, impulse);
}

/// The most one position correction may turn a body, rad (Box2D 2.4's maxAngularCorrection, 8
/// degrees). The correction is solved on the joint's linearization at the current pose: turning
/// a body by theta moves its anchor by theta x r. A pin pulled 0.3 m apart on a 3 cm, 0.6 kg disc
/// whose anchor is 5 cm from its centre (inverse inertia 3000: turning is the cheap way to move
/// the anchor) asks for a 6 rad turn, which moves the anchor nowhere near where the
/// linearization said, and flips the disc's other joints round: the next warm start then applies
/// their stored impulses in a geometry they were not found in: such a chain (a plank, the disc,
/// a slider to a disc thrown at 115 m/s) gains 60% of its energy in three steps uncapped.
/// Capped, the correction goes in steps the linearization holds for, and the next
/// substeps finish it.
constexpr float maxCorrectionTurn = 0.1396f;

/// Applies a position correction: linear impulse `p` (kg m: moves B by p/mB, A by -p/mA) and the
/// moments `momentA`, `momentB` it and any angular part exert on each body (kg m^2: turns B by
/// iB momentB, A by -iA momentA), scaled down as a whole so neither body turns more than
/// maxCorrectionTurn. Positions only: velocities are untouched, so no energy is added.
inline void applyPositionCorrection(const JointFrame& f, BodyState& a, BodyState& b, const Vec2f& p, float momentA,
                                    float momentB) {
  const float turn = std::max(std::abs(f.iA * momentA), std::abs(f.iB * momentB));
  const float scale = turn > maxCorrectionTurn ? maxCorrectionTurn / turn : 1.0f;
  a.dp -= p * (f.mA * scale);
  turnBy(a, -f.iA * momentA * scale);
  b.dp += p * (f.mB * scale);
  turnBy(b, f.iB * momentB * scale);
}

/// Moves the anchors of a point constraint `fraction` of the way together, on the positions only.
inline void correctPointPosition(const JointFrame& f, BodyState& a, BodyState& b, float fraction) {
  const Vec2f rA = currentAnchor(a, f.frameA);
  const Vec2f rB = currentAnchor(b, f.frameB);
  const Vec2f separation = (b.dp - a.dp) + (rB - rA) + f.deltaCenter;
  const Vec2f p = solve22(pointMass(f, rA, rB), separation) * -fraction;
  applyPositionCorrection(f, a, b, p, cross(rA, p), cross(rB, p));
}

} // namespace impetus::rigid2d::detail
