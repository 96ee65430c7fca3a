// The 3D world's dynamic tree: the shared template's one instantiation over rigid3d::AABB.
#include "core/dynamic_tree_impl.hpp"

#include <impetus/rigid3d/dynamic_tree.hpp>

namespace impetus {
template class DynamicTree<rigid3d::AABB>;
} // namespace impetus
