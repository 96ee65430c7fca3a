// The 2D world's dynamic tree: the shared template's one instantiation over rigid2d::AABB.
#include "core/dynamic_tree_impl.hpp"

#include <impetus/rigid2d/dynamic_tree.hpp>

namespace impetus {
template class DynamicTree<rigid2d::AABB>;
} // namespace impetus
