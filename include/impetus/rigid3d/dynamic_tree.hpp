// The 3D world's broadphase: the dynamic AABB tree both worlds share (impetus::DynamicTree,
// core/dynamic_tree.hpp) over 3D boxes, its surface-area heuristic the surface area.
#pragma once

#include <impetus/core/dynamic_tree.hpp>
#include <impetus/rigid3d/aabb.hpp>

namespace impetus {
// Compiled once, in src/rigid3d/dynamic_tree.cpp.
extern template class DynamicTree<rigid3d::AABB>;
} // namespace impetus

namespace impetus::rigid3d {

using DynamicTree = impetus::DynamicTree<AABB>;

} // namespace impetus::rigid3d
