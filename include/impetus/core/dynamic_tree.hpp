// A dynamic AABB tree: the broadphase of both worlds, one template over the box type
// (rigid2d::DynamicTree over 2D boxes, rigid3d::DynamicTree over 3D ones). Leaves hold fattened
// boxes of shapes (proxies); internal nodes hold the union of their children. Insertion picks
// the sibling that least increases the total surface-area-heuristic cost (perimeter in 2D,
// surface area in 3D) and rotations keep the inserted path balanced. A proxy whose tight box
// leaves its fat box is re-inserted (moveProxy: the static tree) or grown in place and the grown
// part rebuilt by a median split (enlargeProxy and rebuild: the moving tree, whose proxies move
// every step); one that moves within its fat box costs nothing.
//
// The member functions are defined in src/core/dynamic_tree_impl.hpp and instantiated once per
// box type, in the world that owns the box (src/rigid2d/dynamic_tree.cpp,
// src/rigid3d/dynamic_tree.cpp), so the translation units that use a tree do not compile it.
// query and rayCast are templates on their visitor and stay here.
#pragma once

#include <array>
#include <concepts>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <vector>

namespace impetus {

/// A box's corner type (Vec2f, Vec3f): its `lower` member's.
template <class Box> using BoxPoint = std::remove_cvref_t<decltype(Box::lower)>;

/// What the tree needs of a box: an aggregate {lower, upper} of points (components p[i], and
/// +, -, * float for points along a segment) and these free functions, found by argument-
/// dependent lookup beside the box (rigid2d/aabb.hpp, rigid3d/aabb.hpp).
template <class Box>
concept TreeBox = requires(const Box& a, const BoxPoint<Box>& p, float margin, std::string_view field) {
  Box{p, p};
  { p[0] } -> std::convertible_to<float>;
  { p + (p - p) * margin } -> std::convertible_to<BoxPoint<Box>>;
  requireValid(a, field);                             // throws impetus::Error naming a bad component
  { overlaps(a, a) } -> std::same_as<bool>;           // share a point (touching counts)
  { contains(a, a) } -> std::same_as<bool>;           // the first holds the second
  { merge(a, a) } -> std::same_as<Box>;               // the smallest box holding both
  { enlarge(a, margin) } -> std::same_as<Box>;        // grown by margin on every side (fat boxes)
  { center(a) } -> std::same_as<BoxPoint<Box>>;       // the middle, the rebuild's sort key
  { sahCost(a) } -> std::same_as<float>;              // perimeter in 2D, surface area in 3D
  { splitAxis(a) } -> std::same_as<int>;              // the median rebuild's axis across a box of centres
  { segmentOverlaps(a, p, p) } -> std::same_as<bool>; // slab test of the segment p1 -> p2
};

/// The nodes a traversal has still to visit: on the caller's stack, so traversals share nothing.
/// A balanced tree of a million proxies is about 30 deep and its traversal holds about that many
/// nodes; past traversalStackSize (a degenerate tree) the rest spills to the heap.
class TraversalStack {
public:
  static constexpr std::size_t traversalStackSize = 256;

  void push(std::int32_t node) {
    if (size_ < fixed_.size()) {
      fixed_[size_] = node;
    } else {
      spill_.push_back(node);
    }
    ++size_;
  }
  std::int32_t pop() {
    --size_;
    if (size_ < fixed_.size()) {
      return fixed_[size_];
    }
    const std::int32_t node = spill_.back();
    spill_.pop_back();
    return node;
  }
  [[nodiscard]] bool empty() const noexcept { return size_ == 0; }

private:
  std::array<std::int32_t, traversalStackSize> fixed_; // NOLINT: filled before it is read (no 1 KB clear per query)
  std::vector<std::int32_t> spill_;
  std::size_t size_ = 0;
};

template <TreeBox Box> class DynamicTree {
public:
  using Point = BoxPoint<Box>;
  static constexpr std::int32_t nullNode = -1;

  /// Adds a proxy with the given (already fattened) box and a user value; returns its id.
  /// Throws impetus::Error for an invalid box.
  std::int32_t createProxy(const Box& box, std::uint64_t userData);
  void destroyProxy(std::int32_t proxy);
  /// Moves a proxy to a new fat box (removal and re-insertion).
  void moveProxy(std::int32_t proxy, const Box& box);
  /// Gives a proxy a new fat box in place, growing its ancestors to hold it and marking them
  /// for `rebuild` (no removal and re-insertion: much cheaper than moveProxy when many proxies
  /// move each step, as Box2D v3's broadphase does). Queries stay exact; the tree loosens
  /// until rebuilt.
  void enlargeProxy(std::int32_t proxy, const Box& box);
  /// Rebuilds what enlargeProxy marked (all of the tree with `full`): the proxies and the
  /// unmarked subtrees below the marked nodes are regrouped top down, each group split at the
  /// middle of its centres across their longest extent (Box2D v3's median split). Deterministic;
  /// allocation-free once its scratch has grown to the proxy count.
  void rebuild(bool full = false);

  /// Asks the cache for a proxy's leaf, and (prefetchParent, once the leaf is there) its parent:
  /// what enlargeProxy reads first. For callers that know the proxies they will enlarge ahead.
  void prefetchLeaf(std::int32_t proxy) const { __builtin_prefetch(&nodes_[static_cast<std::size_t>(proxy)]); }
  void prefetchParent(std::int32_t proxy) const {
    if (const std::int32_t parent = nodes_[static_cast<std::size_t>(proxy)].parent; parent != nullNode) {
      __builtin_prefetch(&nodes_[static_cast<std::size_t>(parent)]);
    }
  }

  [[nodiscard]] const Box& fatBox(std::int32_t proxy) const { return nodes_[static_cast<std::size_t>(proxy)].box; }
  [[nodiscard]] std::uint64_t userData(std::int32_t proxy) const {
    return nodes_[static_cast<std::size_t>(proxy)].userData;
  }
  [[nodiscard]] int proxyCount() const noexcept { return proxyCount_; }
  /// Height of the tree (0 for a single leaf, -1 when empty).
  [[nodiscard]] int height() const noexcept;
  /// Sum of the costs (sahCost) of the internal nodes over the root's: the quality of the tree.
  [[nodiscard]] float areaRatio() const noexcept;

  /// Calls `visit(proxy, userData)` for every proxy whose fat box overlaps `box`, in a fixed
  /// order; the visitor returns false to stop. Queries and ray casts keep no state in the tree:
  /// a visitor may query the tree again, and several threads may query it at once.
  template <class Visitor> void query(const Box& box, Visitor&& visit) const;

  /// Calls `visit(proxy, userData, p1, p2)` for proxies whose box the segment p1 -> p2 crosses;
  /// the visitor returns the new maximum fraction along the segment (0 stops, 1 or the previous
  /// value continues, a hit's fraction clips the ray), as Box2D's ray-cast callbacks do.
  template <class Visitor> void rayCast(const Point& p1, const Point& p2, Visitor&& visit) const;

  /// Checks the tree's invariants (parents, heights, boxes containing children); for tests.
  [[nodiscard]] bool validate() const;

private:
  struct Node {
    Box box;
    std::uint64_t userData = 0;
    std::int32_t parent = nullNode; ///< or the next free node
    std::int32_t child1 = nullNode;
    std::int32_t child2 = nullNode;
    std::int16_t height = -1; ///< 0 for leaves, -1 for free nodes
    /// An internal node grown by enlargeProxy since the last rebuild (its parent is marked too).
    bool enlarged = false;
    [[nodiscard]] bool isLeaf() const noexcept { return child1 == nullNode; }
  };
  /// What rebuild regroups: a proxy or an unmarked subtree, and its box's centre.
  struct BuildUnit {
    std::int32_t node;
    Point center;
  };
  /// A range of rebuild's units still to be split, and the node waiting for what it becomes.
  struct BuildRange {
    std::uint32_t begin, end;
    std::int32_t parent;
    bool isChild1;
  };

  /// The height of a node over two children.
  static std::int16_t heightOver(const Node& a, const Node& b) noexcept;
  std::int32_t allocateNode();
  void freeNode(std::int32_t i);
  void insertLeaf(std::int32_t leaf);
  void removeLeaf(std::int32_t leaf);
  std::int32_t balance(std::int32_t a);
  /// A node's box, height and mark from its children's.
  void refit(std::int32_t i);
  std::int32_t findBestSibling(const Box& box) const;
  Node& node(std::int32_t i) { return nodes_[static_cast<std::size_t>(i)]; }
  const Node& node(std::int32_t i) const { return nodes_[static_cast<std::size_t>(i)]; }
  bool validateNode(std::int32_t i) const;

  std::int32_t buildSubtree(std::uint32_t count);

  std::vector<Node> nodes_;
  std::vector<BuildUnit> buildUnits_;     ///< rebuild's scratch
  std::vector<BuildRange> buildRanges_;   ///< rebuild's scratch
  std::vector<std::int32_t> builtNodes_;  ///< rebuild's scratch: the internal nodes it made, parents first
  std::vector<std::int32_t> gatherStack_; ///< rebuild's scratch
  std::int32_t root_ = nullNode;
  std::int32_t freeList_ = nullNode;
  int proxyCount_ = 0;
};

template <TreeBox Box> template <class Visitor> void DynamicTree<Box>::query(const Box& box, Visitor&& visit) const {
  if (root_ == nullNode) {
    return;
  }
  TraversalStack stack;
  stack.push(root_);
  while (!stack.empty()) {
    const std::int32_t i = stack.pop();
    const Node& n = node(i);
    if (!overlaps(n.box, box)) {
      continue;
    }
    if (n.isLeaf()) {
      if (!visit(i, n.userData)) {
        return;
      }
    } else {
      stack.push(n.child2);
      stack.push(n.child1);
    }
  }
}

template <TreeBox Box> template <class Visitor>
void DynamicTree<Box>::rayCast(const Point& p1, const Point& p2, Visitor&& visit) const {
  if (root_ == nullNode) {
    return;
  }
  float maxFraction = 1.0f;
  TraversalStack stack;
  stack.push(root_);
  while (!stack.empty()) {
    const std::int32_t i = stack.pop();
    const Node& n = node(i);
    const Point end = p1 + (p2 - p1) * maxFraction;
    if (!segmentOverlaps(n.box, p1, end)) {
      continue;
    }
    if (n.isLeaf()) {
      const float value = visit(i, n.userData, p1, p2);
      if (value == 0.0f) {
        return;
      }
      if (value > 0.0f && value < maxFraction) {
        maxFraction = value;
      }
    } else {
      stack.push(n.child2);
      stack.push(n.child1);
    }
  }
}

} // namespace impetus
