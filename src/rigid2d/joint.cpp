// The joints' part of the step: the common frame of each joint, then its type's prepare, warm
// start and solve (compositions of the solver's joint parts), for the awake set's joints in slot
// order (WorldState::solvedJoints; a fixed order: results are deterministic), and after the
// substeps the reaction readouts and break events.
#include "rigid2d/joints.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace impetus::rigid2d::detail {

void prepareJoints(WorldState& w, const StepContext& context) {
  const std::uint32_t staticIndex = w.staticIndex();
  w.awakeJointSet.compact();
  w.solvedJoints.clear();
  for (const std::uint32_t slot : w.awakeJointSet.items()) {
    Joint& joint = w.joints[slot];
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
          [](auto& data) {
            std::decay_t<decltype(data)> fresh{};
            fresh.def = data.def;
            data = fresh;
          },
          joint.data);
    }
    std::visit([&](auto& data) { prepareJoint(data, f, context); }, joint.data);
    w.solvedJoints.push_back(slot);
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

void finishJoints(WorldState& w, const StepContext& context) {
  w.lastInverseH = context.inverseH;
  // A sleeping joint still carries what it carried when it fell asleep.
  for (const std::uint32_t slot : w.solvedJoints) {
    Joint& joint = w.joints[slot];
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
