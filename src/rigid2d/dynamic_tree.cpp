#include <impetus/error.hpp>
#include <impetus/rigid2d/dynamic_tree.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace impetus::rigid2d {

std::int32_t DynamicTree::allocateNode() {
  if (freeList_ == nullNode) {
    nodes_.emplace_back();
    return static_cast<std::int32_t>(nodes_.size() - 1);
  }
  const std::int32_t i = freeList_;
  freeList_ = node(i).parent;
  node(i) = Node{};
  return i;
}

void DynamicTree::freeNode(std::int32_t i) {
  node(i) = Node{};
  node(i).parent = freeList_;
  freeList_ = i;
}

std::int32_t DynamicTree::createProxy(const AABB& box, std::uint64_t userData) {
  if (!isValid(box)) {
    throwInvalid("box", std::nan(""), "AABB must be finite with lower <= upper");
  }
  const std::int32_t leaf = allocateNode();
  node(leaf).box = box;
  node(leaf).userData = userData;
  node(leaf).height = 0;
  insertLeaf(leaf);
  ++proxyCount_;
  return leaf;
}

void DynamicTree::destroyProxy(std::int32_t proxy) {
  if (proxy < 0 || static_cast<std::size_t>(proxy) >= nodes_.size() || !node(proxy).isLeaf() ||
      node(proxy).height != 0) {
    throwInvalid("proxy", proxy, "not a live proxy of this tree");
  }
  removeLeaf(proxy);
  freeNode(proxy);
  --proxyCount_;
}

void DynamicTree::moveProxy(std::int32_t proxy, const AABB& box) {
  if (!isValid(box)) {
    throwInvalid("box", std::nan(""), "AABB must be finite with lower <= upper");
  }
  removeLeaf(proxy);
  node(proxy).box = box;
  insertLeaf(proxy);
}

void DynamicTree::enlargeProxy(std::int32_t proxy, const AABB& box) {
  node(proxy).box = box;
  for (std::int32_t p = node(proxy).parent; p != nullNode; p = node(p).parent) {
    if (contains(node(p).box, box)) {
      break;
    }
    node(p).box = merge(node(p).box, box);
  }
}

std::int32_t DynamicTree::findBestSibling(const AABB& box) const {
  // Greedy descent to a leaf with the surface area heuristic (perimeter in 2D), O(log n): at
  // each internal node, go to the child where the new box adds the least perimeter (for a leaf
  // child, the perimeter of the parent it would share with the new box; for an internal child,
  // the growth of its box). Always ending at a leaf keeps the AVL rotations of insertLeaf able to
  // restore balance (making a tall internal node the sibling could not be fixed by one rotation).
  std::int32_t index = root_;
  while (!node(index).isLeaf()) {
    const Node& n = node(index);
    const auto growth = [&](std::int32_t child) {
      const Node& c = node(child);
      const float merged = perimeter(merge(c.box, box));
      return c.isLeaf() ? merged : merged - perimeter(c.box);
    };
    index = growth(n.child2) < growth(n.child1) ? n.child2 : n.child1;
  }
  return index;
}

void DynamicTree::insertLeaf(std::int32_t leaf) {
  if (root_ == nullNode) {
    root_ = leaf;
    node(leaf).parent = nullNode;
    return;
  }
  const std::int32_t sibling = findBestSibling(node(leaf).box);
  const std::int32_t oldParent = node(sibling).parent;
  const std::int32_t newParent = allocateNode();
  node(newParent).parent = oldParent;
  node(newParent).box = merge(node(leaf).box, node(sibling).box);
  node(newParent).height = node(sibling).height + 1;
  node(newParent).child1 = sibling;
  node(newParent).child2 = leaf;
  node(sibling).parent = newParent;
  node(leaf).parent = newParent;
  if (oldParent == nullNode) {
    root_ = newParent;
  } else if (node(oldParent).child1 == sibling) {
    node(oldParent).child1 = newParent;
  } else {
    node(oldParent).child2 = newParent;
  }
  // Walk back up, refitting boxes and heights and rebalancing.
  for (std::int32_t i = node(leaf).parent; i != nullNode; i = node(i).parent) {
    i = balance(i);
    const Node& n = node(i);
    node(i).height = 1 + std::max(node(n.child1).height, node(n.child2).height);
    node(i).box = merge(node(n.child1).box, node(n.child2).box);
  }
}

void DynamicTree::removeLeaf(std::int32_t leaf) {
  if (leaf == root_) {
    root_ = nullNode;
    return;
  }
  const std::int32_t parent = node(leaf).parent;
  const std::int32_t grandParent = node(parent).parent;
  const std::int32_t sibling = node(parent).child1 == leaf ? node(parent).child2 : node(parent).child1;
  if (grandParent == nullNode) {
    root_ = sibling;
    node(sibling).parent = nullNode;
    freeNode(parent);
    return;
  }
  if (node(grandParent).child1 == parent) {
    node(grandParent).child1 = sibling;
  } else {
    node(grandParent).child2 = sibling;
  }
  node(sibling).parent = grandParent;
  freeNode(parent);
  for (std::int32_t i = grandParent; i != nullNode; i = node(i).parent) {
    i = balance(i);
    const Node& n = node(i);
    node(i).box = merge(node(n.child1).box, node(n.child2).box);
    node(i).height = 1 + std::max(node(n.child1).height, node(n.child2).height);
  }
}

// A single left or right rotation when a subtree is more than one level deeper than its
// sibling (AVL-style). Returns the index of the node now at a's place.
std::int32_t DynamicTree::balance(std::int32_t a) {
  Node& A = node(a);
  if (A.isLeaf() || A.height < 2) {
    return a;
  }
  const std::int32_t b = A.child1;
  const std::int32_t c = A.child2;
  const std::int32_t difference = node(c).height - node(b).height;
  // Rotate the deeper child up; `up` is that child, `other` the shallower one.
  const auto rotate = [&](std::int32_t up, bool upIsChild2) {
    Node& U = node(up);
    const std::int32_t f = U.child1;
    const std::int32_t g = U.child2;
    U.child1 = a;
    U.parent = node(a).parent;
    node(a).parent = up;
    if (U.parent != nullNode) {
      if (node(U.parent).child1 == a) {
        node(U.parent).child1 = up;
      } else {
        node(U.parent).child2 = up;
      }
    } else {
      root_ = up;
    }
    const std::int32_t other = upIsChild2 ? b : c;
    // Keep the taller grandchild under `up`, hand the shorter one to a.
    const bool keepF = node(f).height > node(g).height;
    const std::int32_t kept = keepF ? f : g;
    const std::int32_t given = keepF ? g : f;
    U.child2 = kept;
    if (upIsChild2) {
      node(a).child2 = given;
    } else {
      node(a).child1 = given;
    }
    node(given).parent = a;
    node(a).box = merge(node(other).box, node(given).box);
    node(a).height = 1 + std::max(node(other).height, node(given).height);
    U.box = merge(node(a).box, node(kept).box);
    U.height = 1 + std::max(node(a).height, node(kept).height);
    return up;
  };
  if (difference > 1) {
    return rotate(c, true);
  }
  if (difference < -1) {
    return rotate(b, false);
  }
  return a;
}

int DynamicTree::height() const noexcept { return root_ == nullNode ? -1 : node(root_).height; }

float DynamicTree::areaRatio() const noexcept {
  if (root_ == nullNode) {
    return 0.0f;
  }
  const float rootArea = perimeter(node(root_).box);
  float total = 0.0f;
  for (const Node& n : nodes_) {
    if (n.height > 0) {
      total += perimeter(n.box);
    }
  }
  return rootArea > 0.0f ? total / rootArea : 0.0f;
}

bool DynamicTree::validateNode(std::int32_t i) const {
  const Node& n = node(i);
  if (n.isLeaf()) {
    return n.height == 0 && n.child2 == nullNode;
  }
  const Node& c1 = node(n.child1);
  const Node& c2 = node(n.child2);
  return c1.parent == i && c2.parent == i && n.height == 1 + std::max(c1.height, c2.height) &&
         std::abs(c1.height - c2.height) <= 1 && contains(n.box, c1.box) && contains(n.box, c2.box) &&
         validateNode(n.child1) && validateNode(n.child2);
}

bool DynamicTree::validate() const {
  if (root_ == nullNode) {
    return proxyCount_ == 0;
  }
  int leaves = 0;
  for (const Node& n : nodes_) {
    leaves += n.height == 0 ? 1 : 0;
  }
  return node(root_).parent == nullNode && leaves == proxyCount_ && validateNode(root_);
}

} // namespace impetus::rigid2d
