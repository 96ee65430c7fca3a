// The distance joint in the soft step (after Box2D v3's distance joint).
//
// One row along the axis u = (pB - pA) / |pB - pA| between the current world anchors:
// C = |pB - pA| - L, Cdot = u . (vB + wB x rB - vA - wA x rA), with the effective mass
// 1 / (1/mA + 1/mB + (rA x u)^2 / IA + (rB x u)^2 / IB). Impulses along u are positive when
// they push the anchors apart. The joint is
//  - rigid (a rod) without a spring: C = |pB - pA| - length = 0 as a hard row, soft at the
//    world's joint stiffness with bias and plain in the relax pass, like the revolute's pin;
//  - soft with a spring: a spring toward `length` at `hertz` and `dampingRatio` (hertz 0: no
//    spring force at all, so only the limits and the motor act; see springCoefficients for how
//    it is integrated and why it differs from Box2D's soft constraint), then the motor on
//    the length rate (clamped to maxMotorForce h per substep) and the two one-sided limits, last
//    so that they win: minLength (C = length - minLength >= 0, pushes) and maxLength
//    (C = maxLength - length >= 0, pulls), speculative while inside (they may close the gap in
//    this substep, no more) and soft at the joint stiffness when violated. A rope is the spring
//    mode with hertz 0 and the limits [0, L].
// The axis is recomputed from the current anchors at every solve. When the anchors coincide it
// has no direction: the joint then applies nothing (and forgets its impulses) until they part.
#include "rigid2d/distance_joint.hpp"

#include <algorithm>
#include <cmath>
#include <impetus/math/scalar.hpp>

namespace impetus::rigid2d::detail {
namespace {

/// Below this separation (m) the anchors count as coinciding: the axis is undefined.
constexpr float minAxisLength = 1e-5f;

/// The joint's geometry now: anchors relative to the centres, the distance and the unit axis.
struct AxisGeometry {
  Vec2f rA, rB;
  float length = 0.0f;
  Vec2f axis; ///< zero when the anchors coincide
};

AxisGeometry currentGeometry(const JointFrame& f, const BodyState& a, const BodyState& b) {
  AxisGeometry g;
  g.rA = currentAnchor(a, f.frameA);
  g.rB = currentAnchor(b, f.frameB);
  const Vec2f separation = (b.dp - a.dp) + (g.rB - g.rA) + f.deltaCenter;
  g.length = length(separation);
  if (g.length > minAxisLength) {
    g.axis = separation / g.length;
  }
  return g;
}

/// 1 / (inverse mass along the axis): kg; zero when neither body can move along it.
float axialMassOf(const JointFrame& f, const Vec2f& rA, const Vec2f& rB, const Vec2f& axis) {
  const float crA = cross(rA, axis);
  const float crB = cross(rB, axis);
  const float k = f.mA + f.mB + f.iA * crA * crA + f.iB * crB * crB;
  return k > 0.0f ? 1.0f / k : 0.0f;
}

/// The rate of change of the distance, m/s.
float lengthRate(const AxisGeometry& g, const BodyState& a, const BodyState& b) {
  return dot(g.axis, (b.v + cross(b.w, g.rB)) - (a.v + cross(a.w, g.rA)));
}

/// An impulse along the axis (N s; positive pushes the anchors apart).
void applyAxial(BodyState& a, BodyState& b, const JointFrame& f, const AxisGeometry& g, float impulse) {
  const Vec2f p = g.axis * impulse;
  a.v -= p * f.mA;
  a.w -= f.iA * cross(g.rA, p);
  b.v += p * f.mB;
  b.w += f.iB * cross(g.rB, p);
}

/// The spring's coefficients for a substep h. With k = m omega^2 and c = 2 zeta m omega for the
/// effective mass m along the axis, the spring's impulse over a substep is
///   lambda = -h k (x1 + theta h v2) - h c v2,   i.e.   lambda = -m (A v2 + B x1),
/// with x1 the stretch at the substep's start, v2 the stretch rate after it, B = h omega^2 and
/// A = 2 zeta omega h + theta (h omega)^2. With theta = 1, and applied again in the relax pass,
/// this is Box2D's soft spring (backward Euler), which is stable at any stiffness but, with the
/// position update x2 = x1 + h v2, removes a fraction of about A of the energy every substep:
/// an undamped 2 Hz spring at 4 substeps of 1/60 s lost half its energy per period. With
/// theta = 0, applied once, the stiffness is symplectic Euler, whose energy does not drift (the
/// damping stays implicit, exact to O(h omega)), but it is only stable for h omega < 2, less in
/// chains. So a soft spring (h omega <= 1/4: up to 9.5 Hz at 240 substeps per second) is
/// symplectic; from there theta rises to 1 at h omega = 1/2, and the relax share from 0 at 1/2 to
/// 1 at 3/4 (28.6 Hz at 240/s), beyond which it is exactly Box2D's. Measured on chains of six
/// springs with mass ratios 1 and 50: no energy gain at any frequency up to the world's 60 Hz cap,
/// like Box2D's (both become unstable near 200 Hz at that substep, where springs should be rods).
struct SpringCoefficients {
  float stiffness = 0.0f;  ///< B, 1/s
  float damping = 0.0f;    ///< A
  float relaxShare = 0.0f; ///< of the spring's impulse applied again in the relax pass
};

SpringCoefficients springCoefficients(float hertz, float dampingRatio, float h) {
  if (hertz <= 0.0f) {
    return {};
  }
  const float omega = 2.0f * pi<float> * hertz;
  const float hw = h * omega;
  const float theta = std::clamp((hw - 0.25f) / 0.25f, 0.0f, 1.0f);
  return {h * omega * omega, 2.0f * dampingRatio * hw + theta * hw * hw, std::clamp((hw - 0.5f) / 0.25f, 0.0f, 1.0f)};
}

/// A one-sided limit on c (+1: lower, c = length - minLength; -1: upper, c = maxLength - length).
void solveLimit(float& accumulated, float c, float direction, BodyState& a, BodyState& b, const JointFrame& f,
                const AxisGeometry& g, float mass, const StepContext& context, bool useBias) {
  const float applied = limitImpulse(accumulated, c, direction * lengthRate(g, a, b), mass, f, context, useBias);
  applyAxial(a, b, f, g, direction * applied);
}

} // namespace

bool isRigid(const DistanceJointDef& def) {
  return !def.enableSpring || (def.enableLimit && def.minLength >= def.maxLength);
}

void prepareJoint(DistanceJoint& joint, const JointFrame& frame, const StepContext& context) {
  const DistanceJointDef& def = joint.def;
  const Vec2f separation = frame.deltaCenter + frame.frameB - frame.frameA;
  const float len = length(separation);
  joint.axialMass = len > minAxisLength ? axialMassOf(frame, frame.frameA, frame.frameB, separation / len) : 0.0f;
  const SpringCoefficients spring = springCoefficients(def.hertz, def.dampingRatio, context.h);
  joint.springStiffness = spring.stiffness;
  joint.springDamping = spring.damping;
  joint.springRelaxShare = spring.relaxShare;
  // What is switched off holds no impulse (it would be warm started otherwise).
  const bool rigid = isRigid(def);
  if (!rigid && def.hertz == 0.0f) {
    joint.impulse = 0.0f;
  }
  if (rigid || !def.enableLimit) {
    joint.lowerImpulse = joint.upperImpulse = 0.0f;
  }
  if (rigid || !def.enableMotor) {
    joint.motorImpulse = 0.0f;
  }
}

void warmStartJoint(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                    std::uint32_t staticIndex, JointRows rows) {
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  const AxisGeometry g = currentGeometry(frame, a, b);
  applyAxial(a, b, frame, g,
             pick(rows, lengthRow(joint), joint.impulse) + pick(rows, JointRows::passive, joint.lowerImpulse) -
                 pick(rows, JointRows::passive, joint.upperImpulse) +
                 pick(rows, JointRows::working, joint.motorImpulse));
  storeVelocity(states, frame.indexA, staticIndex, a);
  storeVelocity(states, frame.indexB, staticIndex, b);
}

void solveJoint(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                std::uint32_t staticIndex, const StepContext& context, bool useBias) {
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  const DistanceJointDef& def = joint.def;
  const AxisGeometry g = currentGeometry(frame, a, b);
  joint.axis = g.axis;
  const float mass = g.length > minAxisLength ? axialMassOf(frame, g.rA, g.rB, g.axis) : 0.0f;
  if (mass == 0.0f) {
    // No direction (coinciding anchors) or nothing can move along it: no row to solve.
    joint.impulse = joint.lowerImpulse = joint.upperImpulse = joint.motorImpulse = 0.0f;
    return;
  }

  if (isRigid(def)) {
    // A rod at `length` (kept within the limits when they are on).
    const float target = def.enableLimit ? std::clamp(def.length, def.minLength, def.maxLength) : def.length;
    float bias = 0.0f;
    float massScale = 1.0f;
    float impulseScale = 0.0f;
    if (useBias) {
      // The rod turns with the anchors' relative motion across it, and with the bodies.
      const Vec2f relative = (b.v + cross(b.w, g.rB)) - (a.v + cross(a.w, g.rA));
      const float orbit = std::abs(cross(g.axis, relative)) / g.length * context.h;
      joint.positionShare = positionShare(std::max(orbit, substepTurn(a, b, context)));
      bias = frame.softness.biasRate * (1.0f - joint.positionShare) * (g.length - target);
      massScale = frame.softness.massScale;
      impulseScale = frame.softness.impulseScale;
    }
    const float impulse = -mass * massScale * (lengthRate(g, a, b) + bias) - impulseScale * joint.impulse;
    joint.impulse += impulse;
    applyAxial(a, b, frame, g, impulse);
  } else {
    if (def.hertz > 0.0f && (useBias || joint.springRelaxShare > 0.0f)) {
      // The spring: the impulse that makes lambda = -m (A v2 + B x) hold, where v2 moves by 1/m
      // per unit impulse, so the residual lambda + m (A v + B x) moves by (1 + A). In the solve
      // pass x is the substep's start x1; a stiff spring is corrected again in the relax pass
      // (from the integrated stretch, as Box2D does), a soft one is not (see springCoefficients).
      const float c = g.length - def.length;
      const float residual =
          joint.impulse + mass * (joint.springDamping * lengthRate(g, a, b) + joint.springStiffness * c);
      const float share = useBias ? 1.0f : joint.springRelaxShare;
      const float impulse = -share * residual / (1.0f + joint.springDamping);
      joint.impulse += impulse;
      applyAxial(a, b, frame, g, impulse);
    }
    if (def.enableMotor) {
      const float maxImpulse = context.h * def.maxMotorForce;
      const float old = joint.motorImpulse;
      joint.motorImpulse = std::clamp(old + mass * (def.motorSpeed - lengthRate(g, a, b)), -maxImpulse, maxImpulse);
      applyAxial(a, b, frame, g, joint.motorImpulse - old);
    }
    if (def.enableLimit) {
      // A minimum of (about) zero enforces nothing a length could break; acting on it would stop
      // a body passing through the other anchor (a rope's end swinging past its pin).
      if (def.minLength > linearSlop) {
        solveLimit(joint.lowerImpulse, g.length - def.minLength, 1.0f, a, b, frame, g, mass, context, useBias);
      } else {
        joint.lowerImpulse = 0.0f;
      }
      if (std::isfinite(def.maxLength)) { // the default infinity: no upper limit
        solveLimit(joint.upperImpulse, def.maxLength - g.length, -1.0f, a, b, frame, g, mass, context, useBias);
      }
    }
  }

  storeVelocity(states, frame.indexA, staticIndex, a);
  storeVelocity(states, frame.indexB, staticIndex, b);
}

void correctJointPosition(DistanceJoint& joint, const JointFrame& frame, std::vector<BodyState>& states,
                          std::uint32_t staticIndex, const StepContext& /*context*/) {
  const DistanceJointDef& def = joint.def;
  if (!isRigid(def) || joint.positionShare == 0.0f) {
    return;
  }
  BodyState a = states[frame.indexA];
  BodyState b = states[frame.indexB];
  const AxisGeometry g = currentGeometry(frame, a, b);
  const float mass = g.length > minAxisLength ? axialMassOf(frame, g.rA, g.rB, g.axis) : 0.0f;
  if (mass == 0.0f) {
    return;
  }
  const float target = def.enableLimit ? std::clamp(def.length, def.minLength, def.maxLength) : def.length;
  const Vec2f p = g.axis * (-mass * joint.positionShare * frame.positionCorrection * (g.length - target));
  applyPositionCorrection(frame, a, b, p, cross(g.rA, p), cross(g.rB, p));
  storePose(states, frame.indexA, staticIndex, a);
  storePose(states, frame.indexB, staticIndex, b);
}

JointReaction jointReaction(const DistanceJoint& joint, const JointFrame&, float inverseH) {
  const float axial = joint.impulse + joint.lowerImpulse - joint.upperImpulse + joint.motorImpulse;
  return {joint.axis * (axial * inverseH), 0.0f};
}

} // namespace impetus::rigid2d::detail
