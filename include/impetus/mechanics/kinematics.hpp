// Kinematics (ch. 2): constant acceleration, quadratic drag, plane rigid-body kinematics.
#pragma once

namespace impetus {} // namespace impetus
