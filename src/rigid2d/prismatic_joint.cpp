// The prismatic joint in the soft step. (Placeholder: no constraint yet; see prismatic_joint.hpp.)
#include "rigid2d/prismatic_joint.hpp"

namespace impetus::rigid2d::detail {

void prepareJoint(PrismaticJoint&, const JointFrame&, const StepContext&) {}

void warmStartJoint(PrismaticJoint&, const JointFrame&, std::vector<BodyState>&, std::uint32_t) {}

void solveJoint(PrismaticJoint&, const JointFrame&, std::vector<BodyState>&, std::uint32_t, const StepContext&, bool) {}

JointReaction jointReaction(const PrismaticJoint&, const JointFrame&, float) { return {}; }

} // namespace impetus::rigid2d::detail
