// The joints' part of the step: the common frame of each joint, then its type's prepare, warm
// start and solve (compositions of the solver's joint parts), for the awake set's joints in slot
// order (WorldState::solvedJoints; a fixed order: results are deterministic), and after the
// substeps the reaction readouts and break events.
#include "rigid2d/joints.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <type_traits>

namespace impetus::rigid2d::detail {

void collectSolvedJoints(WorldState& w) {
  w.awakeJointSet.compact();
  w.solvedJoints.clear();
  for (const std::uint32_t slot : w.awakeJointSet.items()) {
    const Joint& joint = w.joints[slot];
    if (w.bodies[joint.bodyA].moving() || w.bodies[joint.bodyB].moving()) {
      w.solvedJoints.push_back(slot);
    } // else asleep or static (a sleeper joined to a moving body is woken before the solve)
  }
}

std::pair<std::uint32_t, std::uint32_t> jointSolverIndices(const WorldState& w, const Joint& joint) {
  const Body& a = w.bodies[joint.bodyA];
  const Body& b = w.bodies[joint.bodyB];
  // A joint to the world (the mouse joint: bodyA is bodyB) sees a static body A.
  const bool aMoves = a.moving() && joint.bodyA != joint.bodyB;
  return {aMoves ? a.solverIndex : w.staticIndex(), b.moving() ? b.solverIndex : w.staticIndex()};
}

namespace {

/// Whether a joint's rows read its bodies' relative angle at the step's start (the angle rows of
/// the weld, prismatic and motor joints, and a revolute joint's spring and limits): a pin alone
/// (joint_grid's 20,000) or its motor and friction act on the relative spin, and the distance,
/// wheel and mouse joints have no angle row.
bool readsStartAngle(const JointData& data) {
  if (const auto* revolute = std::get_if<RevoluteJoint>(&data)) {
    return revolute->def.enableSpring || revolute->def.enableLimit;
  }
  return std::holds_alternative<WeldJoint>(data) || std::holds_alternative<PrismaticJoint>(data) ||
         std::holds_alternative<MotorJoint>(data);
}

} // namespace

void prepareJoint(const WorldState& w, const Joint& joint, JointData& data, JointFrame& f, const StepContext& context,
                  bool indicesKnown) {
  const std::uint32_t staticIndex = w.staticIndex();
  if (!indicesKnown) {
    std::tie(f.indexA, f.indexB) = jointSolverIndices(w, joint);
  }
  const bool aMoves = f.indexA != staticIndex;
  const bool bMoves = f.indexB != staticIndex;
  const JointBodyPose a = aMoves ? w.jointPoses[f.indexA] : jointBodyPose(w.bodies[joint.bodyA]);
  const JointBodyPose b = bMoves ? w.jointPoses[f.indexB] : jointBodyPose(w.bodies[joint.bodyB]);
  f.mA = aMoves ? a.inverseMass : 0.0f;
  f.mB = bMoves ? b.inverseMass : 0.0f;
  f.iA = aMoves ? a.inverseInertia : 0.0f;
  f.iB = bMoves ? b.inverseInertia : 0.0f;
  f.frameA = rotate(a.q, joint.localAnchorA - a.localCenter);
  f.frameB = rotate(b.q, joint.localAnchorB - b.localCenter);
  f.deltaCenter = b.center - a.center;
  f.deltaAngle = readsStartAngle(data) ? relativeAngle(b.q, a.q) : 0.0f;
  f.softness = context.jointSoftness;
  f.maxSpeed = context.maxLinearSpeed;
  f.maxSpin = context.maxAngularSpeed;
  if (joint.constraintHertz > 0.0f) {
    // The joint's own stiffness, capped as the world's (jointSoftnessFor).
    f.softness = jointSoftnessFor(joint.constraintHertz, joint.constraintDampingRatio, context);
    f.softness.maxBias = context.jointSoftness.maxBias;
  }
  if (!context.warmStarting) {
    // Every part starts the step without an impulse: a fresh joint with the same settings.
    std::visit(
        [](auto& typed) {
          std::decay_t<decltype(typed)> fresh{};
          fresh.def = typed.def;
          typed = fresh;
        },
        data);
  }
  const JointPose pose{a.q, b.q, a.localCenter, b.localCenter, b.center};
  std::visit([&](auto& typed) { prepareJoint(typed, f, pose, context); }, data);
}

void prepareJoints(WorldState& w, const StepContext& context) {
  collectSolvedJoints(w);
  for (const std::uint32_t slot : w.solvedJoints) {
    Joint& joint = w.joints[slot];
    prepareJoint(w, joint, joint.data, joint.frame, context);
  }
}

void warmStartJoint(JointSim& joint, std::vector<BodyState>& states, std::uint32_t staticIndex) {
  std::visit([&](auto& data) { warmStartJoint(data, joint.frame, states, staticIndex); }, joint.data);
}

void solveJoint(JointSim& joint, std::vector<BodyState>& states, std::uint32_t staticIndex, const StepContext& context,
                bool useBias) {
  std::visit([&](auto& data) { solveJoint(data, joint.frame, states, staticIndex, context, useBias); }, joint.data);
}

void warmStartJoint(WorldState& w, std::uint32_t slot) {
  Joint& joint = w.joints[slot];
  std::visit([&](auto& data) { warmStartJoint(data, joint.frame, w.states, w.staticIndex()); }, joint.data);
}

void solveJoint(WorldState& w, std::uint32_t slot, const StepContext& context, bool useBias) {
  Joint& joint = w.joints[slot];
  std::visit([&](auto& data) { solveJoint(data, joint.frame, w.states, w.staticIndex(), context, useBias); },
             joint.data);
}

void warmStartJoints(WorldState& w) {
  for (const std::uint32_t slot : w.solvedJoints) {
    warmStartJoint(w, slot);
  }
}

void solveJoints(WorldState& w, const StepContext& context, bool useBias) {
  for (const std::uint32_t slot : w.solvedJoints) {
    solveJoint(w, slot, context, useBias);
  }
}

JointReaction reactionOf(const JointData& data, float inverseH) {
  return std::visit([&](const auto& typed) { return jointReaction(typed, inverseH); }, data);
}

bool breakable(const Joint& joint) {
  return joint.breakForce < std::numeric_limits<float>::infinity() ||
         joint.breakTorque < std::numeric_limits<float>::infinity();
}

bool updateBreak(Joint& joint, const JointReaction& reaction) {
  const bool over = length(reaction.force) > joint.breakForce || std::abs(reaction.torque) > joint.breakTorque;
  const bool crossed = over && !joint.overBreakLimit;
  joint.overBreakLimit = over;
  return crossed;
}

void raiseBreak(WorldState& w, const Joint& joint, const JointReaction& reaction) {
  w.jointEvents.breaks.push_back({joint.id, length(reaction.force), std::abs(reaction.torque)});
}

void finishJoints(WorldState& w, const StepContext& context) {
  w.lastInverseH = context.inverseH;
  for (const std::uint32_t slot : w.solvedJoints) {
    Joint& joint = w.joints[slot];
    if (!breakable(joint)) {
      continue;
    }
    const JointReaction reaction = reactionOf(joint.data, context.inverseH);
    if (updateBreak(joint, reaction)) {
      raiseBreak(w, joint, reaction);
    }
  }
}

} // namespace impetus::rigid2d::detail
