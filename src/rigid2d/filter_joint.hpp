// A joint that only turns collision off between its two bodies (FilterJointDef): no parts, so
// every solver stage passes it by. It keeps the bodies in one island, as every joint does.
#pragma once

#include "rigid2d/joint_solver.hpp"

namespace impetus::rigid2d::detail {

struct FilterJoint {
  struct NoSettings {};
  NoSettings def; ///< a filter joint has no settings of its own
};

inline void prepareJoint(FilterJoint& /*joint*/, const JointFrame& /*frame*/, const JointPose& /*pose*/,
                         const StepContext& /*context*/) {}
inline void warmStartJoint(FilterJoint& /*joint*/, const JointFrame& /*frame*/, std::vector<BodyState>& /*states*/,
                           std::uint32_t /*staticIndex*/) {}
inline void solveJoint(FilterJoint& /*joint*/, const JointFrame& /*frame*/, std::vector<BodyState>& /*states*/,
                       std::uint32_t /*staticIndex*/, const StepContext& /*context*/, bool /*useBias*/) {}
[[nodiscard]] inline JointReaction jointReaction(const FilterJoint& /*joint*/, float /*inverseH*/) { return {}; }

} // namespace impetus::rigid2d::detail
