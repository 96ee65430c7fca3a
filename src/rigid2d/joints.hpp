// A joint of the 2D world: the common part and one of the per-type parts.
#pragma once

#include "rigid2d/distance_joint.hpp"
#include "rigid2d/filter_joint.hpp"
#include "rigid2d/motor_joint.hpp"
#include "rigid2d/mouse_joint.hpp"
#include "rigid2d/prismatic_joint.hpp"
#include "rigid2d/revolute_joint.hpp"
#include "rigid2d/weld_joint.hpp"
#include "rigid2d/wheel_joint.hpp"

#include <utility>
#include <variant>

namespace impetus::rigid2d::detail {

using JointData = std::variant<RevoluteJoint, PrismaticJoint, DistanceJoint, WeldJoint, WheelJoint, MotorJoint,
                               MouseJoint, FilterJoint>;

struct Joint {
  JointData data;
  std::uint32_t bodyA = 0; ///< body slots
  std::uint32_t bodyB = 0;
  Vec2f localAnchorA; ///< m, body A's frame (relative to its origin)
  Vec2f localAnchorB;
  bool collideConnected = false;
  float breakForce = 0.0f;      ///< N
  float breakTorque = 0.0f;     ///< N m
  float constraintHertz = 0.0f; ///< Hz (0: the world's jointHertz)
  float constraintDampingRatio = 2.0f;
  bool overBreakLimit = false; ///< the break event has been raised and the reaction is still above
  std::uint64_t userData = 0;
  JointId id;
  bool alive = false;
  JointFrame frame; ///< the book's solver's view this step (the soft step's is in the joint's JointSim)

  [[nodiscard]] JointType type() const noexcept { return static_cast<JointType>(data.index()); }
};
// Four cache lines: a type's data that grows the record past them makes every joint's prepare
// read a fifth, and grows the solver copy (JointSim) that every pass streams.
static_assert(sizeof(Joint) <= 256);

/// A joint as the soft step solves it: a copy of its per-type data and this step's frame, laid out
/// colour by colour in the constraint graph so that every pass over a colour walks memory in
/// order. The passes stream these copies, so their size is their cost: 184 bytes, against the
/// Joint's 256 with its cold bookkeeping. Kept from step to step while the joints and moving
/// bodies stay the same, holding the joint's data meanwhile (jointDataOf); returned to its slot
/// when the joints are coloured again.
struct JointSim {
  JointData data;
  JointFrame frame;
  std::uint32_t slot = 0;
};

void warmStartJoint(JointSim& joint, std::vector<BodyState>& states, std::uint32_t staticIndex);
void solveJoint(JointSim& joint, std::vector<BodyState>& states, std::uint32_t staticIndex, const StepContext& context,
                bool useBias);

// joint.cpp: the joints' part of the step. The soft step solves them in the constraint graph's
// colours with the contacts (contact_solver.cpp); the book's solver, in joint slot order.
/// This step's joints (WorldState::solvedJoints): the awake set's with a moving body, in slot order.
void collectSolvedJoints(WorldState& w);
/// The joint's bodies' solver indices this step (the static index for one not moving).
[[nodiscard]] std::pair<std::uint32_t, std::uint32_t> jointSolverIndices(const WorldState& w, const Joint& joint);
/// One joint's frame for this step and its type's prepare, into `data` and `f` (the Joint's own
/// or its solver copy's). With `indicesKnown`, f's solver indices are this step's already (a
/// copy kept from last step, whose bodies kept their indices): the moving bodies are read from
/// WorldState::jointPoses, not their records. Reads only the joint and its bodies: joints
/// prepare on threads.
void prepareJoint(const WorldState& w, const Joint& joint, JointData& data, JointFrame& f, const StepContext& context,
                  bool indicesKnown = false);
/// collectSolvedJoints, then each joint prepared in its slot (the book's solver).
void prepareJoints(WorldState& w, const StepContext& context);
/// One joint's warm start: its parts' accumulated impulses applied again.
void warmStartJoint(WorldState& w, std::uint32_t slot);
void solveJoint(WorldState& w, std::uint32_t slot, const StepContext& context, bool useBias);
/// Every joint's warm start and solve, in joint slot order (the book's solver).
void warmStartJoints(WorldState& w);
void solveJoints(WorldState& w, const StepContext& context, bool useBias);
/// The force and torque on body B over the last substep of the joint's last solve (N, N m):
/// its impulses times the world's last substep rate. Read when asked, as Box2D v3's: a sleeping
/// joint still carries the impulses it had when it fell asleep (read at the current rate, should
/// the steps have changed since).
[[nodiscard]] JointReaction reactionOf(const JointData& data, float inverseH);
/// Whether the joint has a finite break force or torque (only those are checked each step).
[[nodiscard]] bool breakable(const Joint& joint);
/// Notes whether the reaction is over the joint's break limits; true when it has just gone over
/// (a break event is due: raiseBreak, in slot order).
bool updateBreak(Joint& joint, const JointReaction& reaction);
void raiseBreak(WorldState& w, const Joint& joint, const JointReaction& reaction);
/// Break events after the substeps, of joints solved in their slots.
void finishJoints(WorldState& w, const StepContext& context);

// contact_solver.cpp: the soft step keeps its joints' solver copies (JointSim) in colour order
// from step to step while neither its joints nor its moving bodies change (as Box2D v3 keeps
// joint sims in the graph's colours). While a joint has a copy, the copy holds its data.
/// The joint's data, wherever it lives now.
[[nodiscard]] JointData& jointDataOf(WorldState& w, std::uint32_t slot);
[[nodiscard]] const JointData& jointDataOf(const WorldState& w, std::uint32_t slot);
/// A destroyed joint's copy, if any, forgotten, and the joints coloured again at the next step
/// (its slot may be reused before then, by a joint of another kind or with other bodies).
void forgetJointSim(WorldState& w, std::uint32_t slot);
/// Every copy's data back into its joint, and the copies gone (before the book's solver runs).
void returnJointSims(WorldState& w);
/// The copies dropped without a look (a snapshot just replaced every joint).
void dropJointSims(WorldState& w);
/// The soft step's break events, from the copies of breakable joints.
void finishJointSims(WorldState& w, const StepContext& context);

} // namespace impetus::rigid2d::detail
