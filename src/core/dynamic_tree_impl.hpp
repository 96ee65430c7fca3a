// The member functions of impetus::DynamicTree (include/impetus/core/dynamic_tree.hpp), for the
// one translation unit per box type that instantiates them: src/rigid2d/dynamic_tree.cpp for
// rigid2d::AABB, src/rigid3d/dynamic_tree.cpp for rigid3d::AABB. The box's free functions
// (TreeBox) are found beside the box by argument-dependent lookup.
#pragma once

#include <impetus/core/dynamic_tree.hpp>
#include <impetus/error.hpp>

#include <algorithm>

namespace impetus {

template <TreeBox Box> std::int16_t DynamicTree<Box>::heightOver(const Node& a, const Node& b) noexcept {
  return static_cast<std::int16_t>(1 + std::max(a.height, b.height));
}

template <TreeBox Box> std::int32_t DynamicTree<Box>::allocateNode() {
  if (freeList_ == nullNode) {
    nodes_.emplace_back();
    return static_cast<std::int32_t>(nodes_.size() - 1);
  }
  const std::int32_t i = freeList_;
  freeList_ = node(i).parent;
  node(i) = Node{};
  return i;
}

template <TreeBox Box> void DynamicTree<Box>::freeNode(std::int32_t i) {
  node(i) = Node{};
  node(i).parent = freeList_;
  freeList_ = i;
}

template <TreeBox Box> std::int32_t DynamicTree<Box>::createProxy(const Box& box, std::uint64_t userData) {
  requireValid(box, "box");
  const std::int32_t leaf = allocateNode();
  node(leaf).box = box;
  node(leaf).userData = userData;
  node(leaf).height = 0;
  insertLeaf(leaf);
  ++proxyCount_;
  return leaf;
}

template <TreeBox Box> void DynamicTree<Box>::destroyProxy(std::int32_t proxy) {
  if (proxy < 0 || static_cast<std::size_t>(proxy) >= nodes_.size() || !node(proxy).isLeaf() ||
      node(proxy).height != 0) {
    throwInvalid("proxy", proxy, "not a live proxy of this tree");
  }
  removeLeaf(proxy);
  freeNode(proxy);
  --proxyCount_;
}

template <TreeBox Box> void DynamicTree<Box>::moveProxy(std::int32_t proxy, const Box& box) {
  requireValid(box, "box");
  removeLeaf(proxy);
  node(proxy).box = box;
  insertLeaf(proxy);
}

template <TreeBox Box> void DynamicTree<Box>::enlargeProxy(std::int32_t proxy, const Box& box) {
  requireValid(box, "box");
  node(proxy).box = box;
  for (std::int32_t p = node(proxy).parent; p != nullNode; p = node(p).parent) {
    Node& n = node(p);
    const bool holds = contains(n.box, box);
    if (holds && n.enlarged) {
      break; // marked before: so are its ancestors, and they hold its box
    }
    if (!holds) {
      n.box = merge(n.box, box);
    }
    n.enlarged = true;
  }
}

template <TreeBox Box> void DynamicTree<Box>::rebuild(bool full) {
  if (root_ == nullNode || (!full && !node(root_).enlarged)) {
    return;
  }
  // Gather the units (proxies, and unmarked subtrees unless full) and free the marked nodes.
  buildUnits_.clear();
  gatherStack_.clear();
  gatherStack_.push_back(root_);
  while (!gatherStack_.empty()) {
    const std::int32_t i = gatherStack_.back();
    gatherStack_.pop_back();
    Node& n = node(i);
    if (n.isLeaf() || (!n.enlarged && !full)) {
      n.parent = nullNode;
      buildUnits_.push_back({i, center(n.box)});
      continue;
    }
    gatherStack_.push_back(n.child2);
    gatherStack_.push_back(n.child1);
    freeNode(i);
  }
  root_ = buildSubtree(static_cast<std::uint32_t>(buildUnits_.size()));
}

template <TreeBox Box> std::int32_t DynamicTree<Box>::buildSubtree(std::uint32_t count) {
  if (count == 1) {
    return buildUnits_[0].node;
  }
  // Top down: each range of two or more units gets a node and is split in two; a range of one
  // is that unit. Boxes and heights are filled in afterwards, children before parents.
  builtNodes_.clear();
  buildRanges_.clear();
  buildRanges_.push_back({0, count, nullNode, true});
  std::int32_t top = nullNode;
  while (!buildRanges_.empty()) {
    const BuildRange r = buildRanges_.back();
    buildRanges_.pop_back();
    std::int32_t made = nullNode;
    if (r.end - r.begin == 1) {
      made = buildUnits_[r.begin].node;
    } else {
      made = allocateNode();
      builtNodes_.push_back(made);
      // Split at the middle of the centres' extent across its longest axis (splitAxis); all on
      // one side (coincident centres) splits the range in halves.
      const auto first = buildUnits_.begin() + r.begin;
      const auto last = buildUnits_.begin() + r.end;
      Box centres{first->center, first->center};
      for (auto u = first; u != last; ++u) {
        centres = merge(centres, Box{u->center, u->center});
      }
      const int axis = splitAxis(centres);
      const float pivot = center(centres)[axis];
      const auto middle = std::partition(first, last, [&](const BuildUnit& u) { return u.center[axis] < pivot; });
      auto split = static_cast<std::uint32_t>(middle - buildUnits_.begin());
      if (split == r.begin || split == r.end) {
        split = r.begin + (r.end - r.begin) / 2;
      }
      buildRanges_.push_back({split, r.end, made, false});
      buildRanges_.push_back({r.begin, split, made, true});
    }
    node(made).parent = r.parent;
    if (r.parent == nullNode) {
      top = made;
    } else if (r.isChild1) {
      node(r.parent).child1 = made;
    } else {
      node(r.parent).child2 = made;
    }
  }
  for (auto i = builtNodes_.rbegin(); i != builtNodes_.rend(); ++i) {
    Node& n = node(*i);
    n.box = merge(node(n.child1).box, node(n.child2).box);
    n.height = heightOver(node(n.child1), node(n.child2));
  }
  return top;
}

template <TreeBox Box> std::int32_t DynamicTree<Box>::findBestSibling(const Box& box) const {
  // Greedy descent to a leaf with the surface area heuristic (sahCost: perimeter in 2D, surface
  // area in 3D), O(log n): at each internal node, go to the child where the new box adds the
  // least cost (for a leaf child, the cost of the parent it would share with the new box; for an
  // internal child, the growth of its box). Always ending at a leaf keeps the rotations of
  // insertLeaf able to balance the path (making a tall internal node the sibling could not be
  // fixed by one rotation).
  std::int32_t index = root_;
  while (!node(index).isLeaf()) {
    const Node& n = node(index);
    const auto growth = [&](std::int32_t child) {
      const Node& c = node(child);
      const float merged = sahCost(merge(c.box, box));
      return c.isLeaf() ? merged : merged - sahCost(c.box);
    };
    index = growth(n.child2) < growth(n.child1) ? n.child2 : n.child1;
  }
  return index;
}

template <TreeBox Box> void DynamicTree<Box>::insertLeaf(std::int32_t leaf) {
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
  node(newParent).height = static_cast<std::int16_t>(node(sibling).height + 1);
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
    refit(i);
  }
}

template <TreeBox Box> void DynamicTree<Box>::removeLeaf(std::int32_t leaf) {
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
    refit(i);
  }
}

// A single left or right rotation when a subtree is more than one level deeper than its
// sibling (AVL-style). Returns the index of the node now at a's place.
template <TreeBox Box> std::int32_t DynamicTree<Box>::balance(std::int32_t a) {
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
    refit(a);
    refit(up);
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

template <TreeBox Box> void DynamicTree<Box>::refit(std::int32_t i) {
  Node& n = node(i);
  const Node& c1 = node(n.child1);
  const Node& c2 = node(n.child2);
  n.box = merge(c1.box, c2.box);
  n.height = heightOver(c1, c2);
  // A node above a marked one is marked: rebuild reaches every marked node from the root.
  n.enlarged = n.enlarged || c1.enlarged || c2.enlarged;
}

template <TreeBox Box> int DynamicTree<Box>::height() const noexcept {
  return root_ == nullNode ? -1 : node(root_).height;
}

template <TreeBox Box> float DynamicTree<Box>::areaRatio() const noexcept {
  if (root_ == nullNode) {
    return 0.0f;
  }
  const float rootArea = sahCost(node(root_).box);
  float total = 0.0f;
  for (const Node& n : nodes_) {
    if (n.height > 0) {
      total += sahCost(n.box);
    }
  }
  return rootArea > 0.0f ? total / rootArea : 0.0f;
}

template <TreeBox Box> bool DynamicTree<Box>::validateNode(std::int32_t i) const {
  const Node& n = node(i);
  if (n.isLeaf()) {
    return n.height == 0 && n.child2 == nullNode;
  }
  const Node& c1 = node(n.child1);
  const Node& c2 = node(n.child2);
  return c1.parent == i && c2.parent == i && n.height == heightOver(c1, c2) && contains(n.box, c1.box) &&
         contains(n.box, c2.box) && (n.enlarged || (!c1.enlarged && !c2.enlarged)) && validateNode(n.child1) &&
         validateNode(n.child2);
}

template <TreeBox Box> bool DynamicTree<Box>::validate() const {
  if (root_ == nullNode) {
    return proxyCount_ == 0;
  }
  int leaves = 0;
  for (const Node& n : nodes_) {
    leaves += n.height == 0 ? 1 : 0;
  }
  return node(root_).parent == nullNode && leaves == proxyCount_ && validateNode(root_);
}

} // namespace impetus
