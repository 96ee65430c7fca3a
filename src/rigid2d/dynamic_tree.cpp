#include <impetus/error.hpp>
#include <impetus/rigid2d/dynamic_tree.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace impetus::rigid2d {

namespace {

/// The height of a node over two children of the given heights.
template <class N> std::int16_t heightOver(const N& a, const N& b) noexcept {
  return static_cast<std::int16_t>(1 + std::max(a.height, b.height));
}

/// Refuses, naming `box`, a box that is not finite or is inside out.
void requireValidBox(const AABB& box) {
  if (!isValid(box)) {
    throwInvalid("box", std::nan(""), "AABB must be finite with lower <= upper");
  }
}

} // namespace

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
  requireValidBox(box);
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
  requireValidBox(box);
  removeLeaf(proxy);
  node(proxy).box = box;
  insertLeaf(proxy);
}

void DynamicTree::enlargeProxy(std::int32_t proxy, const AABB& box) {
  requireValidBox(box);
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

void DynamicTree::rebuild(bool full) {
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
      buildUnits_.push_back({i, 0.5f * (n.box.lower + n.box.upper)});
      continue;
    }
    gatherStack_.push_back(n.child2);
    gatherStack_.push_back(n.child1);
    freeNode(i);
  }
  root_ = buildSubtree(static_cast<std::uint32_t>(buildUnits_.size()));
}

std::int32_t DynamicTree::buildSubtree(std::uint32_t count) {
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
      // Split at the middle of the centres' extent along its longer axis; all on one side
      // (coincident centres) splits the range in halves.
      const auto first = buildUnits_.begin() + r.begin;
      const auto last = buildUnits_.begin() + r.end;
      Vec2f lower = first->center;
      Vec2f upper = first->center;
      for (auto u = first; u != last; ++u) {
        lower = {std::min(lower.x, u->center.x), std::min(lower.y, u->center.y)};
        upper = {std::max(upper.x, u->center.x), std::max(upper.y, u->center.y)};
      }
      const bool alongX = upper.x - lower.x > upper.y - lower.y;
      const float pivot = alongX ? 0.5f * (lower.x + upper.x) : 0.5f * (lower.y + upper.y);
      const auto middle =
          std::partition(first, last, [&](const BuildUnit& u) { return (alongX ? u.center.x : u.center.y) < pivot; });
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

std::int32_t DynamicTree::findBestSibling(const AABB& box) const {
  // Greedy descent to a leaf with the surface area heuristic (perimeter in 2D), O(log n): at
  // each internal node, go to the child where the new box adds the least perimeter (for a leaf
  // child, the perimeter of the parent it would share with the new box; for an internal child,
  // the growth of its box). Always ending at a leaf keeps the rotations of insertLeaf able to
  // balance the path (making a tall internal node the sibling could not be fixed by one rotation).
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
    refit(i);
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

void DynamicTree::refit(std::int32_t i) {
  Node& n = node(i);
  const Node& c1 = node(n.child1);
  const Node& c2 = node(n.child2);
  n.box = merge(c1.box, c2.box);
  n.height = heightOver(c1, c2);
  // A node above a marked one is marked: rebuild reaches every marked node from the root.
  n.enlarged = n.enlarged || c1.enlarged || c2.enlarged;
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
  return c1.parent == i && c2.parent == i && n.height == heightOver(c1, c2) && contains(n.box, c1.box) &&
         contains(n.box, c2.box) && (n.enlarged || (!c1.enlarged && !c2.enlarged)) && validateNode(n.child1) &&
         validateNode(n.child2);
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
