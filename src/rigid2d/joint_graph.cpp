// The joints in the soft step's constraint graph: coloured before the contacts, their solver
// copies (JointSim) kept in colour order from step to step while neither the joints nor the
// moving bodies change (as Box2D v3 keeps its joint sims in the graph's colours), prepared and
// finished on threads. While a joint has a copy, the copy holds its data (jointDataOf).
#include "rigid2d/constraint_graph.hpp"

#include <algorithm>
#include <span>

namespace impetus::rigid2d::detail {

/// Collects this step's joints (WorldState::solvedJoints) and colours them in the graph, before
/// the contacts (joints hold structures together: a colour of their own is worth more to them),
/// and makes their solver copies in colour order. A joint with no rows (a filter joint) takes
/// none. Done again only when the joints or the moving bodies changed (the same colouring would
/// come out); otherwise the copies, impulses and settings in them, stay where they are (true).
bool colourJoints(WorldState& w, ContactSolverData& d) {
  const std::uint32_t staticIndex = w.staticIndex();
  // The joints to solve are last step's while the awake joint set and the moving bodies are (a
  // joint's bodies never change, and destroying one makes the colours invalid): then the
  // joints' records are not read to collect them again.
  w.awakeJointSet.compact();
  const std::span<const std::uint32_t> awakeJoints = w.awakeJointSet.items();
  const bool sameBodies = d.jointColoursValid && d.colouredBodies == w.awakeBodies;
  if (!sameBodies ||
      !std::equal(awakeJoints.begin(), awakeJoints.end(), d.colouredAwakeJoints.begin(), d.colouredAwakeJoints.end())) {
    collectSolvedJoints(w);
    d.colouredAwakeJoints.assign(awakeJoints.begin(), awakeJoints.end());
  }
  if (sameBodies && d.colouredJoints == w.solvedJoints) {
    return true;
  }
  returnJointSims(w);
  d.bodyColours.assign(staticIndex, 0);
  for (std::vector<std::uint32_t>& list : d.colourJoints) {
    list.clear();
  }
  d.overflowJoints.clear();
  for (const std::uint32_t slot : w.solvedJoints) {
    const Joint& joint = w.joints[slot];
    if (joint.type() == JointType::filter) {
      continue;
    }
    const auto [ia, ib] = jointSolverIndices(w, joint);
    const bool withStatic = ia == staticIndex || ib == staticIndex;
    const int colour = findColour(d, ia, ib, staticIndex, withStatic ? allColours : dynamicColours);
    if (colour < 0) {
      d.overflowJoints.push_back(slot);
    } else {
      d.colourJoints[static_cast<std::size_t>(colour)].push_back(slot);
    }
  }
  // The solver's copies, in solve order.
  std::size_t count = d.overflowJoints.size();
  for (const std::vector<std::uint32_t>& list : d.colourJoints) {
    count += list.size();
  }
  d.jointSims.resize(count);
  d.simOfJoint.resize(w.joints.size(), noJointSim);
  std::uint32_t at = 0;
  const auto copy = [&](const std::vector<std::uint32_t>& list) {
    w.parallelFor(static_cast<std::uint32_t>(list.size()), minJointsPerTask,
                  [&](std::uint32_t begin, std::uint32_t end) {
                    for (std::uint32_t k = begin; k < end; ++k) {
                      JointSim& sim = d.jointSims[at + k];
                      sim.data = w.joints[list[k]].data;
                      sim.slot = list[k];
                      d.simOfJoint[list[k]] = at + k;
                    }
                  });
    at += static_cast<std::uint32_t>(list.size());
  };
  copy(d.overflowJoints);
  for (std::size_t c = 0; c < colourCount; ++c) {
    d.jointColourStart[c] = at;
    copy(d.colourJoints[c]);
  }
  d.jointColourStart[colourCount] = at;
  d.breakableJoints.clear();
  for (const std::uint32_t slot : w.solvedJoints) {
    if (d.simOfJoint[slot] != noJointSim && breakable(w.joints[slot])) {
      d.breakableJoints.push_back(slot);
    }
  }
  d.colouredJoints.assign(w.solvedJoints.begin(), w.solvedJoints.end());
  d.colouredBodies.assign(w.awakeBodies.begin(), w.awakeBodies.end());
  d.jointColoursValid = true;
  return false;
}

namespace {

/// How many joint copies ahead the prepare asks the cache for the joint's record (and, half as
/// far ahead, for its bodies, read from the record by then): the copies are in colour order, so
/// their joints and bodies lie anywhere in the pools, and each is a chain of dependent loads.
constexpr std::uint32_t jointPrefetchDistance = 8;

/// Asks the cache for the bytes of a joint that the prepare reads (its bodies, anchors and
/// stiffness; not its data, which the copy holds, nor the book's solver's frame). Always inlined:
/// GCC 12 deletes calls of a function of nothing but prefetches.
[[gnu::always_inline]] inline void prefetchJoint(const Joint& joint) {
  const auto* end = reinterpret_cast<const char*>(&joint.frame);
  for (const auto* bytes = reinterpret_cast<const char*>(&joint.bodyA); bytes < end; bytes += 64) {
    __builtin_prefetch(bytes);
  }
}

[[gnu::always_inline]] inline void prefetchJointBodies(const WorldState& w, const Joint& joint) {
  __builtin_prefetch(&w.bodies[joint.bodyA]);
  __builtin_prefetch(&w.bodies[joint.bodyB]);
}

/// The same for a kept copy, whose solver indices are known: its moving bodies' poses.
[[gnu::always_inline]] inline void prefetchJointPoses(const WorldState& w, const JointFrame& f) {
  if (f.indexA < w.jointPoses.size()) {
    __builtin_prefetch(&w.jointPoses[f.indexA]);
  }
  if (f.indexB < w.jointPoses.size()) {
    __builtin_prefetch(&w.jointPoses[f.indexB]);
  }
}

} // namespace

void prepareJointSims(WorldState& w, ContactSolverData& d, const StepContext& context, bool kept) {
  w.parallelFor(
      static_cast<std::uint32_t>(d.jointSims.size()), minJointsPerTask, [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t k = begin; k < end; ++k) {
          if (k + jointPrefetchDistance < end && d.jointSims[k + jointPrefetchDistance].slot != noJointSim) {
            prefetchJoint(w.joints[d.jointSims[k + jointPrefetchDistance].slot]);
          }
          if (k + jointPrefetchDistance / 2 < end && d.jointSims[k + jointPrefetchDistance / 2].slot != noJointSim) {
            const JointSim& ahead = d.jointSims[k + jointPrefetchDistance / 2];
            if (kept) {
              prefetchJointPoses(w, ahead.frame);
            } else {
              prefetchJointBodies(w, w.joints[ahead.slot]);
            }
          }
          JointSim& sim = d.jointSims[k];
          prepareJoint(w, w.joints[sim.slot], sim.data, sim.frame, context, kept);
        }
      });
}

void finishJointSims(WorldState& w, const StepContext& context) {
  w.lastInverseH = context.inverseH;
  // Only breakable joints are looked at (the reactions are read when asked); their copies are
  // in colour order, their events go out in slot order.
  ContactSolverData& d = *w.contactSolver;
  for (const std::uint32_t slot : d.breakableJoints) {
    Joint& joint = w.joints[slot];
    const JointReaction reaction = reactionOf(d.jointSims[d.simOfJoint[slot]].data, context.inverseH);
    if (updateBreak(joint, reaction)) {
      raiseBreak(w, joint, reaction);
    }
  }
}

JointData& jointDataOf(WorldState& w, std::uint32_t slot) {
  if (w.contactSolver && slot < w.contactSolver->simOfJoint.size()) {
    if (const std::uint32_t k = w.contactSolver->simOfJoint[slot]; k != noJointSim) {
      return w.contactSolver->jointSims[k].data;
    }
  }
  return w.joints[slot].data;
}

const JointData& jointDataOf(const WorldState& w, std::uint32_t slot) {
  return jointDataOf(const_cast<WorldState&>(w), slot);
}

void forgetJointSim(WorldState& w, std::uint32_t slot) {
  if (!w.contactSolver) {
    return;
  }
  ContactSolverData& d = *w.contactSolver;
  if (slot < d.simOfJoint.size()) {
    if (std::uint32_t& k = d.simOfJoint[slot]; k != noJointSim) {
      d.jointSims[k].slot = noJointSim;
      k = noJointSim;
    }
  }
  // Coloured again next step, whether or not the joint had a copy (a filter joint has none):
  // a new joint in its slot would make the same list of solved joints.
  d.jointColoursValid = false;
}

void returnJointSims(WorldState& w) {
  if (!w.contactSolver) {
    return;
  }
  ContactSolverData& d = *w.contactSolver;
  for (const JointSim& sim : d.jointSims) {
    if (sim.slot != noJointSim) {
      w.joints[sim.slot].data = sim.data;
      d.simOfJoint[sim.slot] = noJointSim;
    }
  }
  dropJointSims(w);
}

void dropJointSims(WorldState& w) {
  if (!w.contactSolver) {
    return;
  }
  ContactSolverData& d = *w.contactSolver;
  d.jointSims.clear();
  std::fill(d.simOfJoint.begin(), d.simOfJoint.end(), noJointSim);
  d.colouredJoints.clear();
  d.colouredBodies.clear();
  d.colouredAwakeJoints.clear();
  d.jointColoursValid = false;
}

} // namespace impetus::rigid2d::detail
