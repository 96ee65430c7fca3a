// The joints' part of the step: the common frame of each joint, then its type's prepare, warm
// start and solve, in joint slot order (a fixed order: results are deterministic), and after
// the substeps the reaction readouts and break events.
#include "rigid2d/joints.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace impetus::rigid2d::detail {

void prepareJoints(WorldState& w, const StepContext& context) {
  const std::uint32_t staticIndex = w.staticIndex();
  for (Joint& joint : w.joints) {
    joint.solved = false;
    if (!joint.alive) {
      continue;
    }
    const Body& a = w.bodies[joint.bodyA];
    const Body& b = w.bodies[joint.bodyB];
    if (!a.moving() && !b.moving()) {
      continue; // asleep or static (a sleeper joined to a moving body is woken before the solve)
    }
    JointFrame& f = joint.frame;
    // A joint to the world (the mouse joint: bodyA is bodyB) sees a static body A.
    const bool aMoves = a.moving() && joint.bodyA != joint.bodyB;
    f.indexA = aMoves ? a.solverIndex : staticIndex;
    f.indexB = b.moving() ? b.solverIndex : staticIndex;
    f.mA = aMoves ? a.inverseMass : 0.0f;
    f.mB = b.moving() ? b.inverseMass : 0.0f;
    f.iA = aMoves ? a.inverseInertia : 0.0f;
    f.iB = b.moving() ? b.inverseInertia : 0.0f;
    f.frameA = rotate(a.transform.q, joint.localAnchorA - a.localCenter);
    f.frameB = rotate(b.transform.q, joint.localAnchorB - b.localCenter);
    f.deltaCenter = b.center - a.center;
    f.deltaAngle = relativeAngle(b.transform.q, a.transform.q);
    f.qA = a.transform.q;
    f.qB = b.transform.q;
    f.localCenterA = a.localCenter;
    f.localCenterB = b.localCenter;
    f.centerB = b.center;
    f.softness = context.jointSoftness;
    f.positionCorrection = context.positionCorrection;
    if (joint.constraintHertz > 0.0f) {
      // The joint's own stiffness, capped as the world's (jointSoftnessFor).
      f.softness = jointSoftnessFor(joint.constraintHertz, joint.constraintDampingRatio, context);
      f.positionCorrection = positionCorrectionFor(f.softness, context);
    }
    if (!context.warmStarting) {
      std::visit([](auto& data) { scaleImpulses(data, 0.0f, JointRows::all); }, joint.data);
    }
    std::visit([&](auto& data) { prepareJoint(data, f, context); }, joint.data);
    joint.solved = true;
  }
  buildJointGroups(w);
}

namespace {

/// How far past the speed limits a joint may leave a body within the solve before it is held
/// to them. Within it the solve runs untouched (the velocities are clamped where they are
/// integrated); beyond it the body is a runaway.
constexpr float runawayFactor = 1000.0f;

/// Keeps the joint's dynamic bodies within the speed limits after its solve: an ill-conditioned
/// joint (a light, small body on a long lever arm; anchors pulled metres apart) can hand its
/// bodies a runaway velocity that the next joint or contact would multiply into an overflow.
void clampJointBodies(WorldState& w, const JointFrame& f, const StepContext& context) {
  const float runawaySpeed = runawayFactor * context.maxLinearSpeed;
  const float runawaySpin = runawayFactor * context.maxAngularSpeed;
  const auto clampIfDynamic = [&](std::uint32_t index) {
    if (index < w.sims.size() && w.sims[index].dynamic) {
      BodyState& s = w.states[index];
      if (!(std::abs(s.v.x) + std::abs(s.v.y) <= runawaySpeed && std::abs(s.w) <= runawaySpin)) {
        clampVelocity(s, context);
      }
    }
  };
  clampIfDynamic(f.indexA);
  clampIfDynamic(f.indexB);
}

} // namespace

namespace {

/// The joint's rows that may do work on its bodies (JointRows): none, some (`working`: a motor,
/// a spring, a soft weld's rows) or all (the motor and mouse joints, which drive B to a target).
template <class JointData> JointRows rowsWithMotorOrSpring(const JointData& joint) {
  return joint.def.enableMotor || joint.def.enableSpring ? JointRows::working : JointRows::none;
}
JointRows workingRowsOf(const RevoluteJoint& joint) { return rowsWithMotorOrSpring(joint); }
JointRows workingRowsOf(const PrismaticJoint& joint) { return rowsWithMotorOrSpring(joint); }
JointRows workingRowsOf(const WheelJoint& joint) { return rowsWithMotorOrSpring(joint); }
JointRows workingRowsOf(const DistanceJoint& joint) {
  return isRigid(joint.def) ? JointRows::none : JointRows::working; // a rod has no motor either
}
JointRows workingRowsOf(const WeldJoint& joint) {
  return joint.def.linearHertz > 0.0f || joint.def.angularHertz > 0.0f ? JointRows::working : JointRows::none;
}
JointRows workingRowsOf(const MotorJoint&) { return JointRows::all; }
JointRows workingRowsOf(const MouseJoint&) { return JointRows::all; }
JointRows workingRowsOf(const FilterJoint&) { return JointRows::none; }

} // namespace

/// The jointed groups of this step (JointGroups), after the joints are prepared.
void buildJointGroups(WorldState& w) {
  JointGroups& g = w.jointGroups;
  g.members.clear();
  if (w.joints.empty()) {
    return;
  }
  const std::uint32_t n = w.staticIndex();
  g.parent.resize(n);
  g.isMember.assign(n, 0);
  g.memberMass.clear();
  g.memberInertia.clear();
  // At most two members a joint: reserved once, no allocation while the joints stay.
  g.members.reserve(2 * w.joints.size());
  g.memberMass.reserve(2 * w.joints.size());
  g.memberInertia.reserve(2 * w.joints.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    g.parent[i] = i;
  }
  const auto dynamicIndex = [&](std::uint32_t index, float inverseMass) { return index < n && inverseMass > 0.0f; };
  for (const Joint& joint : w.joints) {
    if (!joint.solved) {
      continue;
    }
    const JointFrame& f = joint.frame;
    const bool a = dynamicIndex(f.indexA, f.mA);
    const bool b = dynamicIndex(f.indexB, f.mB);
    for (const auto& [index, inverseMass, inverseInertia, dynamic] :
         {std::tuple{f.indexA, f.mA, f.iA, a}, std::tuple{f.indexB, f.mB, f.iB, b}}) {
      if (dynamic && g.isMember[index] == 0) {
        g.isMember[index] = 1;
        g.members.push_back(index);
        g.memberMass.push_back(1.0f / inverseMass);
        g.memberInertia.push_back(inverseInertia > 0.0f ? 1.0f / inverseInertia : 0.0f);
      }
    }
    if (a && b) {
      g.parent[findRoot(g.parent, f.indexA)] = findRoot(g.parent, f.indexB);
    }
  }
  g.memberGroup.resize(g.members.size());
  for (std::size_t k = 0; k < g.members.size(); ++k) {
    g.memberGroup[k] = findRoot(g.parent, g.members[k]);
  }
  g.jointGroup.resize(w.joints.size());
  for (std::size_t j = 0; j < w.joints.size(); ++j) {
    const Joint& joint = w.joints[j];
    const JointFrame& f = joint.frame;
    const bool a = joint.solved && dynamicIndex(f.indexA, f.mA);
    const bool b = joint.solved && dynamicIndex(f.indexB, f.mB);
    g.jointGroup[j] = a ? findRoot(g.parent, f.indexA) : (b ? findRoot(g.parent, f.indexB) : JointGroups::noGroup);
  }
  // Which rows of each joint may do work (all of a joint to a kinematic body, which moves as it is
  // told, or outside any group), and which groups hold a slider (a prismatic or wheel joint).
  g.workingRows.resize(w.joints.size());
  g.slider.resize(n);
  for (const std::uint32_t group : g.memberGroup) {
    g.slider[group] = 0;
  }
  for (std::size_t j = 0; j < w.joints.size(); ++j) {
    const Joint& joint = w.joints[j];
    const JointFrame& f = joint.frame;
    const bool kinematic = (f.indexA < n && f.mA == 0.0f) || (f.indexB < n && f.mB == 0.0f);
    const bool grouped = g.jointGroup[j] != JointGroups::noGroup;
    g.workingRows[j] = kinematic || !grouped
                           ? JointRows::all
                           : std::visit([](const auto& data) { return workingRowsOf(data); }, joint.data);
    if (grouped && (joint.type() == JointType::prismatic || joint.type() == JointType::wheel)) {
      g.slider[g.jointGroup[j]] = 1;
    }
  }
  g.before.resize(g.members.size());
  g.slope.resize(n);
  g.curvature.resize(n);
  g.energy.resize(n);
  g.share.resize(n);
}

namespace {

/// The most kinetic energy the warm start of a jointed group's passive rows may add, as a share
/// of the group's kinetic energy before it: a joint turning omega h rad a substep has a
/// centripetal pull whose warm start adds (omega h)^2 of it (the relax pass has already turned
/// the velocities along the joint at the substep's end, so J v = 0 when the warm start comes):
/// 0.25 at half a radian a substep, the fastest whirl left to the soft step (the position
/// correction has had such joints' errors from 0.2 rad a substep on, positionShare). Without it a
/// swinging cloth of 10,000 pinned discs (the `joint_grid` benchmark) stretched 0.66 m, with it
/// 0.17. Not for a group holding a prismatic or wheel joint: their line-and-angle rows lock the
/// bodies' relative turning, and a chain of them between bodies of little inertia is a block
/// one Gauss-Seidel pass does not converge, so that whatever its warm start adds stays (two
/// sliders between a 1.3 kg disc and bodies of 1.7 and 60 kg gain 1.3% of their energy scale in
/// half a second with 5% allowed a substep). Those keep no energy gain at all
/// (and their joints warm start with 0.8 of their impulses: sliderWarmStartFactor).
constexpr double maxWarmStartGain = 0.25;

/// The share (0 to 1) of a jointed group's passive warm start to keep: the whole of it unless it
/// adds more kinetic energy than `allowed` (J), else as much as adds that. Along the warm start's
/// direction the energy is E(s) = E0 + s slope + s^2 curvature / 2.
///
/// The warm start re-applies the last substep's impulses as a guess of this one's. Where the
/// joints carry a load (a weight, a motor's drive) the forces since have undone last substep's
/// impulses along them (J v = -K lambda), and the guess takes that energy out again; a turning
/// joint's centripetal pull adds a little (maxWarmStartGain). Where they were an impact that
/// stopped the bodies once, J v = 0 now, and applying them again throws the bodies back apart
/// for the solve to take back. A lone joint's solve does that exactly; in a chain, one
/// Gauss-Seidel pass does not, and the rest is energy from nowhere: a 7 mm, 5 kg disc thrown at
/// 189 m/s along a slider on a 3.6 kg disc pinned to a 107 kg block gains 500 kJ in its first
/// step without this, each warm start tripling the trio's energy; and chains of sliders between
/// 1 cm discs see their accumulated impulses drift apart, cancelling on the shared disc, until
/// one warm start spins it past 10^5 rad/s (docs/reliability.md). The test is over a group, not
/// each joint:
/// a hanging chain's links all fall together under gravity, so no one joint's guess takes
/// energy out alone (each link's J v is zero), only all of them together. And over the passive
/// rows only, the rows that may do work (motors, springs) applied whole before them: a motor
/// hoisting a chain adds energy by right, but a spring in a group once spared the group's rigid
/// rows too, and a wheel joint on a 1 kg disc of inverse inertia 577 gained 23 times its
/// group's energy in a substep.
float keptShare(double slope, double curvature, double allowed) {
  if (!(curvature > 0.0) || slope + 0.5 * curvature <= allowed) {
    return 1.0f; // nothing applied, or the whole of it is within the allowance
  }
  // The larger root of s slope + s^2 curvature / 2 = allowed (allowed >= 0: a root in [0, 1)),
  // in the form without cancellation for either sign of the slope.
  const double root = std::sqrt(slope * slope + 2.0 * curvature * allowed);
  const double s = slope <= 0.0 ? (root - slope) / curvature : 2.0 * allowed / (slope + root);
  return s >= 0.0 ? static_cast<float>(std::min(s, 1.0)) : 0.0f; // NaN (an infinite velocity): none
}

} // namespace

void warmStartJoints(WorldState& w, const StepContext& context) {
  const std::uint32_t staticIndex = w.staticIndex();
  JointGroups& g = w.jointGroups;
  // The rows that may do work first, whole: a motor's drive or a spring's push adds energy by
  // right (trimmed, a crane's motor raised its hook 0.12 m in 5 s instead of 2.5).
  for (std::size_t j = 0; j < w.joints.size(); ++j) {
    Joint& joint = w.joints[j];
    if (joint.solved) {
      std::visit(
          [&](auto& data) {
            beginWarmStart(data);
            if (g.workingRows[j] != JointRows::none) {
              warmStartJoint(data, joint.frame, w.states, staticIndex, g.workingRows[j]);
            }
          },
          joint.data);
    }
  }
  // Then the passive rows (rigid rows, limits, friction), along whose direction the energy is
  // measured.
  for (std::size_t k = 0; k < g.members.size(); ++k) {
    g.before[k] = w.states[g.members[k]];
    g.slope[g.memberGroup[k]] = 0.0;
    g.energy[g.memberGroup[k]] = 0.0;
    g.curvature[g.memberGroup[k]] = 0.0;
  }
  for (std::size_t j = 0; j < w.joints.size(); ++j) {
    Joint& joint = w.joints[j];
    if (joint.solved && g.workingRows[j] != JointRows::all) {
      std::visit([&](auto& data) { warmStartJoint(data, joint.frame, w.states, staticIndex, JointRows::passive); },
                 joint.data);
    }
  }
  for (std::size_t k = 0; k < g.members.size(); ++k) {
    const BodyState& s0 = g.before[k];
    const BodyState& s1 = w.states[g.members[k]];
    const double dvx = static_cast<double>(s1.v.x) - s0.v.x;
    const double dvy = static_cast<double>(s1.v.y) - s0.v.y;
    const double dw = static_cast<double>(s1.w) - s0.w;
    const double m = g.memberMass[k];
    const double inertia = g.memberInertia[k];
    const std::uint32_t group = g.memberGroup[k];
    g.slope[group] += m * (s0.v.x * dvx + s0.v.y * dvy) + inertia * s0.w * dw;
    g.curvature[group] += m * (dvx * dvx + dvy * dvy) + inertia * dw * dw;
    g.energy[group] += 0.5 * (m * (static_cast<double>(s0.v.x) * s0.v.x + static_cast<double>(s0.v.y) * s0.v.y) +
                              inertia * s0.w * s0.w);
  }
  for (std::size_t k = 0; k < g.members.size(); ++k) {
    const std::uint32_t group = g.memberGroup[k];
    const double allowed = g.slider[group] != 0 ? 0.0 : maxWarmStartGain * g.energy[group];
    const float share = g.share[group] = keptShare(g.slope[group], g.curvature[group], allowed);
    if (share < 1.0f) {
      const BodyState& s0 = g.before[k];
      BodyState& s = w.states[g.members[k]];
      s.v = s0.v + (s.v - s0.v) * share;
      s.w = s0.w + (s.w - s0.w) * share;
    }
  }
  for (std::size_t j = 0; j < w.joints.size(); ++j) {
    Joint& joint = w.joints[j];
    if (!joint.solved) {
      continue;
    }
    const std::uint32_t group = g.jointGroup[j];
    if (group != JointGroups::noGroup && g.share[group] < 1.0f && g.workingRows[j] != JointRows::all) {
      std::visit([&](auto& data) { scaleImpulses(data, g.share[group], JointRows::passive); }, joint.data);
    }
    // Held to the speed limits only now: the warm starts of joints sharing a body may cancel on
    // it, and a clamp between them would break that; the trim needs them unclamped
    // too, to stay linear in the share.
    clampJointBodies(w, joint.frame, context);
  }
}

void solveJoints(WorldState& w, const StepContext& context, bool useBias) {
  const std::uint32_t staticIndex = w.staticIndex();
  for (Joint& joint : w.joints) {
    if (joint.solved) {
      std::visit([&](auto& data) { solveJoint(data, joint.frame, w.states, staticIndex, context, useBias); },
                 joint.data);
      clampJointBodies(w, joint.frame, context);
    }
  }
}

namespace {
template <class JointData>
void correctJointPosition(JointData&, const JointFrame&, std::vector<BodyState>&, std::uint32_t, const StepContext&) {}
} // namespace

void correctJointPositions(WorldState& w, const StepContext& context) {
  const std::uint32_t staticIndex = w.staticIndex();
  for (Joint& joint : w.joints) {
    if (joint.solved) {
      std::visit([&](auto& data) { correctJointPosition(data, joint.frame, w.states, staticIndex, context); },
                 joint.data);
    }
  }
}

void finishJoints(WorldState& w, const StepContext& context) {
  w.lastInverseH = context.inverseH;
  for (Joint& joint : w.joints) {
    if (!joint.solved) {
      continue; // asleep: it still carries what it carried when it fell asleep
    }
    joint.reaction =
        std::visit([&](const auto& data) { return jointReaction(data, joint.frame, context.inverseH); }, joint.data);
    const float force = length(joint.reaction.force);
    const float torque = std::abs(joint.reaction.torque);
    const bool over = force > joint.breakForce || torque > joint.breakTorque;
    if (over && !joint.overBreakLimit) {
      w.jointEvents.breaks.push_back({joint.id, force, torque});
    }
    joint.overBreakLimit = over;
  }
}

} // namespace impetus::rigid2d::detail
