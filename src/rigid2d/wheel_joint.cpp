// The wheel joint in the soft step. (Placeholder: no constraint yet; see wheel_joint.hpp.)
#include "rigid2d/wheel_joint.hpp"

namespace impetus::rigid2d::detail {

void prepareJoint(WheelJoint&, const JointFrame&, const StepContext&) {}

void warmStartJoint(WheelJoint&, const JointFrame&, std::vector<BodyState>&, std::uint32_t) {}

void solveJoint(WheelJoint&, const JointFrame&, std::vector<BodyState>&, std::uint32_t, const StepContext&, bool) {}

JointReaction jointReaction(const WheelJoint&, const JointFrame&, float) { return {}; }

} // namespace impetus::rigid2d::detail
