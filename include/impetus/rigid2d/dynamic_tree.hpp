// The 2D world's broadphase: the dynamic AABB tree both worlds share (impetus::DynamicTree,
// core/dynamic_tree.hpp) over 2D boxes, its surface-area heuristic the perimeter.
#pragma once

#include <impetus/core/dynamic_tree.hpp>
#include <impetus/rigid2d/aabb.hpp>

namespace impetus {
// Compiled once, in src/rigid2d/dynamic_tree.cpp.
extern template class DynamicTree<rigid2d::AABB>;
} // namespace impetus

namespace impetus::rigid2d {

using DynamicTree = impetus::DynamicTree<AABB>;

} // namespace impetus::rigid2d
