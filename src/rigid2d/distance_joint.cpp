// The distance joint in the soft step. (Placeholder: no constraint yet; see distance_joint.hpp.)
#include "rigid2d/distance_joint.hpp"

namespace impetus::rigid2d::detail {

void prepareJoint(DistanceJoint&, const JointFrame&, const StepContext&) {}

void warmStartJoint(DistanceJoint&, const JointFrame&, std::vector<BodyState>&, std::uint32_t) {}

void solveJoint(DistanceJoint&, const JointFrame&, std::vector<BodyState>&, std::uint32_t, const StepContext&, bool) {}

JointReaction jointReaction(const DistanceJoint&, const JointFrame&, float) { return {}; }

} // namespace impetus::rigid2d::detail
