// The weld joint in the soft step. (Placeholder: no constraint yet; see weld_joint.hpp.)
#include "rigid2d/weld_joint.hpp"

namespace impetus::rigid2d::detail {

void prepareJoint(WeldJoint&, const JointFrame&, const StepContext&) {}

void warmStartJoint(WeldJoint&, const JointFrame&, std::vector<BodyState>&, std::uint32_t) {}

void solveJoint(WeldJoint&, const JointFrame&, std::vector<BodyState>&, std::uint32_t, const StepContext&, bool) {}

JointReaction jointReaction(const WeldJoint&, const JointFrame&, float) { return {}; }

} // namespace impetus::rigid2d::detail
