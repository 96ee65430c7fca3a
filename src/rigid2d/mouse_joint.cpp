// The mouse joint in the soft step. (Placeholder: no constraint yet; see mouse_joint.hpp.)
#include "rigid2d/mouse_joint.hpp"

namespace impetus::rigid2d::detail {

void prepareJoint(MouseJoint&, const JointFrame&, const StepContext&) {}

void warmStartJoint(MouseJoint&, const JointFrame&, std::vector<BodyState>&, std::uint32_t) {}

void solveJoint(MouseJoint&, const JointFrame&, std::vector<BodyState>&, std::uint32_t, const StepContext&, bool) {}

JointReaction jointReaction(const MouseJoint&, const JointFrame&, float) { return {}; }

} // namespace impetus::rigid2d::detail
