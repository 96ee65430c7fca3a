// The motor joint in the soft step. (Placeholder: no constraint yet; see motor_joint.hpp.)
#include "rigid2d/motor_joint.hpp"

namespace impetus::rigid2d::detail {

void prepareJoint(MotorJoint&, const JointFrame&, const StepContext&) {}

void warmStartJoint(MotorJoint&, const JointFrame&, std::vector<BodyState>&, std::uint32_t) {}

void solveJoint(MotorJoint&, const JointFrame&, std::vector<BodyState>&, std::uint32_t, const StepContext&, bool) {}

JointReaction jointReaction(const MotorJoint&, const JointFrame&, float) { return {}; }

} // namespace impetus::rigid2d::detail
