// The 3D broadphase: the dynamic tree both worlds share, over 3D boxes, against brute force
// (queries and ray casts through inserts, moves, in-place enlargements, rebuilds and removals),
// its quality on a regular grid, and its refusal of invalid boxes.
#include <impetus/rigid3d/dynamic_tree.hpp>

#include "support/error_field.hpp"
#include "test_random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace impetus::rigid3d {
namespace {

struct Fixture {
  DynamicTree tree;
  std::vector<std::int32_t> proxies; ///< -1 once destroyed
  std::vector<AABB> boxes;
  Lcg random{0x9e3779b97f4a7c15ULL};

  /// A point in [-50, 50)^3 m.
  Vec3f randomPoint() { return {50.0f * random.next(), 50.0f * random.next(), 50.0f * random.next()}; }
  /// A box with its lower corner in [-50, 50)^3 m and sides from 0.1 to 3 m.
  AABB randomBox() {
    const Vec3f p = randomPoint();
    const auto side = [&] { return 1.55f + 1.45f * random.next(); };
    return {p, p + Vec3f{side(), side(), side()}};
  }
  void create() {
    boxes.push_back(randomBox());
    proxies.push_back(tree.createProxy(boxes.back(), boxes.size() - 1));
  }
  void destroy(std::size_t i) {
    if (proxies[i] >= 0) {
      tree.destroyProxy(proxies[i]);
      proxies[i] = -1;
    }
  }
  [[nodiscard]] int liveCount() const {
    return static_cast<int>(std::count_if(proxies.begin(), proxies.end(), [](std::int32_t p) { return p >= 0; }));
  }

  [[nodiscard]] std::vector<std::uint64_t> query(const AABB& box) const {
    std::vector<std::uint64_t> hits;
    tree.query(box, [&](std::int32_t, std::uint64_t user) {
      hits.push_back(user);
      return true;
    });
    std::sort(hits.begin(), hits.end());
    return hits;
  }
  [[nodiscard]] std::vector<std::uint64_t> bruteForceQuery(const AABB& box) const {
    std::vector<std::uint64_t> hits;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      if (proxies[i] >= 0 && overlaps(boxes[i], box)) {
        hits.push_back(i);
      }
    }
    return hits;
  }

  /// Every proxy the segment crosses, the visitor never clipping the ray.
  [[nodiscard]] std::vector<std::uint64_t> rayCast(const Vec3f& p1, const Vec3f& p2) const {
    std::vector<std::uint64_t> visited;
    tree.rayCast(p1, p2, [&](std::int32_t, std::uint64_t user, const Vec3f&, const Vec3f&) {
      visited.push_back(user);
      return 1.0f;
    });
    std::sort(visited.begin(), visited.end());
    return visited;
  }
  [[nodiscard]] std::vector<std::uint64_t> bruteForceRay(const Vec3f& p1, const Vec3f& p2) const {
    std::vector<std::uint64_t> hits;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      if (proxies[i] >= 0 && segmentOverlaps(boxes[i], p1, p2)) {
        hits.push_back(i);
      }
    }
    return hits;
  }

  /// The tree holds exactly the live boxes: `count` random queries (boxes grown by 5 m, so that
  /// they hold some tens of boxes) and ray casts (from 60 m on either side of the cloud) give the
  /// brute-force sets.
  void expectMatchesBruteForce(int count) {
    ASSERT_TRUE(tree.validate());
    ASSERT_EQ(tree.proxyCount(), liveCount());
    for (int q = 0; q < count; ++q) {
      const AABB box = enlarge(randomBox(), 5.0f);
      EXPECT_EQ(query(box), bruteForceQuery(box));
      const Vec3f p1 = 1.2f * randomPoint();
      const Vec3f p2 = 1.2f * randomPoint();
      EXPECT_EQ(rayCast(p1, p2), bruteForceRay(p1, p2));
    }
  }
};

TEST(Rigid3dDynamicTree, the_box_functions_match_hand_computed_values) {
  const AABB a{{0.0f, 0.0f, 0.0f}, {1.0f, 2.0f, 3.0f}};
  const AABB touching{{1.0f, 2.0f, 3.0f}, {4.0f, 4.0f, 4.0f}};
  const AABB apartAlongZ{{0.0f, 0.0f, 3.5f}, {1.0f, 2.0f, 4.0f}};
  EXPECT_TRUE(overlaps(a, touching));
  EXPECT_FALSE(overlaps(a, apartAlongZ));
  EXPECT_EQ(merge(a, apartAlongZ), (AABB{{0.0f, 0.0f, 0.0f}, {1.0f, 2.0f, 4.0f}}));
  EXPECT_TRUE(contains(merge(a, touching), a));
  EXPECT_FALSE(contains(a, touching));
  EXPECT_EQ(surfaceArea(a), 22.0f); // 2 (1 x 2 + 2 x 3 + 3 x 1) m^2
  EXPECT_EQ(sahCost(a), surfaceArea(a));
  EXPECT_EQ(center(a), (Vec3f{0.5f, 1.0f, 1.5f}));
  EXPECT_EQ(enlarge(a, 0.5f), (AABB{{-0.5f, -0.5f, -0.5f}, {1.5f, 2.5f, 3.5f}}));
  EXPECT_EQ(splitAxis(a), 2);
  EXPECT_EQ(splitAxis({{0.0f, 0.0f, 0.0f}, {3.0f, 2.0f, 1.0f}}), 0);
  EXPECT_EQ(splitAxis({{0.0f, 0.0f, 0.0f}, {3.0f, 3.0f, 1.0f}}), 1); // of equal extents the later
  EXPECT_EQ(splitAxis({{0.0f, 0.0f, 0.0f}, {2.0f, 2.0f, 2.0f}}), 2);
  // Along x from x = -1 to 3 through the box's middle: enters a quarter of the way.
  float entry = -1.0f;
  EXPECT_TRUE(segmentOverlaps(a, {-1.0f, 1.0f, 1.5f}, {3.0f, 1.0f, 1.5f}, &entry));
  EXPECT_EQ(entry, 0.25f);
  EXPECT_TRUE(segmentOverlaps(a, {0.5f, 1.0f, 1.5f}, {3.0f, 1.0f, 1.5f}, &entry)); // starts inside
  EXPECT_EQ(entry, 0.0f);
  EXPECT_FALSE(segmentOverlaps(a, {-1.0f, 1.0f, 3.5f}, {3.0f, 1.0f, 3.5f}));  // parallel, above
  EXPECT_FALSE(segmentOverlaps(a, {-3.0f, 1.0f, 1.5f}, {-1.0f, 1.0f, 1.5f})); // stops short
  EXPECT_FALSE(segmentOverlaps(a, {-1.0f, 1.0f, 2.9f}, {0.5f, 1.0f, 4.9f}));  // passes over a corner edge
  // Against marching along random segments in steps of 1/4000 of their length (3 mm at most): a
  // segment with a point in the box crosses it, and one that crosses it has a point in it unless
  // it only clips an edge or a corner between two steps (rare).
  Lcg random{11};
  int crossing = 0;
  int clipsBetweenSteps = 0;
  for (int r = 0; r < 300; ++r) {
    const Vec3f p1{3.0f * random.next(), 3.0f * random.next(), 4.0f * random.next()};
    const Vec3f p2{3.0f * random.next(), 3.0f * random.next(), 4.0f * random.next()};
    bool inside = false;
    for (int i = 0; i <= 4000 && !inside; ++i) {
      const Vec3f q = p1 + (p2 - p1) * (static_cast<float>(i) / 4000.0f);
      inside = contains(a, {q, q});
    }
    float at = -1.0f;
    const bool crosses = segmentOverlaps(a, p1, p2, &at);
    EXPECT_TRUE(crosses || !inside) << "segment " << r;
    clipsBetweenSteps += crosses && !inside ? 1 : 0;
    if (crosses) {
      ++crossing;
      const Vec3f q = p1 + (p2 - p1) * at;
      EXPECT_TRUE(contains(enlarge(a, 1e-4f), {q, q})) << "segment " << r; // it enters on the box
    }
  }
  EXPECT_LE(clipsBetweenSteps, 3);
  EXPECT_GT(crossing, 50);
  EXPECT_LT(crossing, 250);
}

TEST(Rigid3dDynamicTree, queries_and_ray_casts_match_brute_force_through_every_kind_of_change) {
  Fixture f;
  for (int i = 0; i < 1000; ++i) {
    f.create();
  }
  f.expectMatchesBruteForce(30);
  // An AVL-balanced tree of 1000 leaves is at most ~1.44 log2(1000) ~ 14 deep.
  EXPECT_LE(f.tree.height(), 16);
  for (int round = 0; round < 6; ++round) {
    const auto r = static_cast<std::size_t>(round);
    // Re-inserted elsewhere (the static tree's path).
    for (std::size_t i = r; i < f.boxes.size(); i += 5) {
      if (f.proxies[i] >= 0) {
        f.boxes[i] = f.randomBox();
        f.tree.moveProxy(f.proxies[i], f.boxes[i]);
      }
    }
    // Drifted by up to 2 m and given the new box in place (the moving tree's path).
    for (std::size_t i = r % 2; i < f.boxes.size(); i += 2) {
      if (f.proxies[i] >= 0) {
        const Vec3f shift{2.0f * f.random.next(), 2.0f * f.random.next(), 2.0f * f.random.next()};
        f.boxes[i] = {f.boxes[i].lower + shift, f.boxes[i].upper + shift};
        f.tree.enlargeProxy(f.proxies[i], f.boxes[i]);
      }
    }
    // Inserts and removals while parts of the tree are marked.
    for (int i = 0; i < 20; ++i) {
      f.create();
    }
    for (std::size_t i = r * 3; i < f.boxes.size(); i += 11) {
      f.destroy(i);
    }
    f.expectMatchesBruteForce(20);
    f.tree.rebuild(round == 5);
    f.expectMatchesBruteForce(20);
    // The median split keeps it about log2(1000) ~ 10 deep (a degenerate one is a list).
    EXPECT_LE(f.tree.height(), 20) << "round " << round;
  }
  // Emptied, it is an empty tree again, and refilled it works.
  for (std::size_t i = 0; i < f.boxes.size(); ++i) {
    f.destroy(i);
  }
  EXPECT_EQ(f.tree.height(), -1);
  f.expectMatchesBruteForce(5);
  for (int i = 0; i < 100; ++i) {
    f.create();
  }
  f.expectMatchesBruteForce(20);
}

TEST(Rigid3dDynamicTree, a_ray_clipped_by_its_hits_finds_the_first_box_it_enters) {
  // The visitor returns the fraction where the segment enters each box it is given: the tree
  // then searches only the segment up to the nearest entry so far, and must still reach the box
  // the segment enters first (brute force), pruning others on the way.
  Fixture f;
  for (int i = 0; i < 2000; ++i) {
    f.create();
  }
  int clippedVisits = 0;
  int fullVisits = 0;
  for (int r = 0; r < 100; ++r) {
    const Vec3f p1 = 1.2f * f.randomPoint();
    const Vec3f p2 = 1.2f * f.randomPoint();
    float firstEntry = 2.0f; // brute force; 2: the segment crosses no box
    for (const AABB& box : f.boxes) {
      if (float entry = 0.0f; segmentOverlaps(box, p1, p2, &entry)) {
        firstEntry = std::min(firstEntry, entry);
      }
    }
    float clip = 1.0f;
    float found = 2.0f;
    f.tree.rayCast(p1, p2, [&](std::int32_t proxy, std::uint64_t user, const Vec3f& a, const Vec3f& b) {
      EXPECT_EQ(a, p1);
      EXPECT_EQ(b, p2);
      EXPECT_EQ(f.tree.fatBox(proxy), f.boxes[user]);
      // Given only boxes the segment, clipped at the nearest entry so far, crosses.
      EXPECT_TRUE(segmentOverlaps(f.boxes[user], p1, p1 + (p2 - p1) * clip));
      ++clippedVisits;
      float entry = 0.0f;
      EXPECT_TRUE(segmentOverlaps(f.boxes[user], p1, p2, &entry));
      found = std::min(found, entry);
      clip = std::min(clip, entry);
      return entry;
    });
    EXPECT_EQ(found, firstEntry) << "ray " << r;
    fullVisits += static_cast<int>(f.rayCast(p1, p2).size());
  }
  EXPECT_LT(clippedVisits, fullVisits);
  // A visitor returning 0 stops the cast at its first box.
  int visits = 0;
  f.tree.rayCast(Vec3f{-60.0f, 0.0f, 0.0f}, Vec3f{60.0f, 0.0f, 0.0f}, [&](auto, auto, const auto&, const auto&) {
    ++visits;
    return 0.0f;
  });
  EXPECT_EQ(visits, 1);
}

TEST(Rigid3dDynamicTree, same_operations_give_the_same_tree) {
  Fixture a;
  Fixture b;
  for (int i = 0; i < 300; ++i) {
    a.create();
    b.create();
  }
  a.tree.rebuild(true);
  b.tree.rebuild(true);
  std::vector<std::uint64_t> orderA;
  std::vector<std::uint64_t> orderB;
  const AABB all{{-100.0f, -100.0f, -100.0f}, {100.0f, 100.0f, 100.0f}};
  a.tree.query(all, [&](std::int32_t, std::uint64_t u) { return orderA.push_back(u), true; });
  b.tree.query(all, [&](std::int32_t, std::uint64_t u) { return orderB.push_back(u), true; });
  EXPECT_EQ(orderA, orderB);
  EXPECT_EQ(orderA.size(), 300U);
  EXPECT_EQ(a.tree.areaRatio(), b.tree.areaRatio());
}

/// The total surface, m^2, of the internal nodes of the ideal tree of k^3 unit cubes filling a
/// cube of side k m, each node's box grown by `grow` m along each axis: the tree that halves the
/// cube across its longest side, z, y, x in turn (of equal sides the later, as the median split).
float halvingTreeSurface(int k, float grow) {
  int sides[3] = {k, k, k};
  float nodes = 1.0f;
  float total = 0.0f;
  while (sides[0] > 1 || sides[1] > 1 || sides[2] > 1) {
    const float a = static_cast<float>(sides[0]) + grow;
    const float b = static_cast<float>(sides[1]) + grow;
    const float c = static_cast<float>(sides[2]) + grow;
    total += nodes * 2.0f * (a * b + b * c + c * a);
    const int axis = sides[0] > sides[1] && sides[0] > sides[2] ? 0 : (sides[1] > sides[2] ? 1 : 2);
    sides[axis] /= 2;
    nodes *= 2.0f;
  }
  return total;
}

TEST(Rigid3dDynamicTree, a_grid_of_cubes_packs_about_as_well_as_halving_it_along_each_axis_in_turn) {
  // k^3 unit cubes filling a cube of side L = k m. The tree that halves the cube along z, y and x
  // in turn has, three levels down, 8 cubes of side L/2, whose total surface is twice the root's
  // 6 L^2 (the levels between hold 8 L^2 and 10 L^2). A group of three levels at each depth j
  // (j = 0 .. log2 k - 1) holds 24 L^2 2^j, so its areaRatio is 24 (k - 1) / 6 = 4 (k - 1): 60
  // for k = 16, the `ideal` below. The median split builds exactly that tree (the centres' extents tie, and it
  // takes z, y, x in turn). Inserted one by one, greedily, in scan order, the tree is within twice
  // that (it is 1.53 times); one that ignored the heuristic, or a list, is many times worse (a
  // list's ratio grows with the proxy count, here thousands).
  constexpr int k = 16;
  const float ideal = halvingTreeSurface(k, 0.0f) / (6.0f * k * k);
  ASSERT_EQ(ideal, 4.0f * (k - 1));
  DynamicTree incremental;
  std::vector<std::int32_t> proxies;
  std::vector<AABB> cubes;
  for (int x = 0; x < k; ++x) {
    for (int y = 0; y < k; ++y) {
      for (int z = 0; z < k; ++z) {
        const Vec3f lower{static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
        cubes.push_back({lower, lower + Vec3f{1.0f, 1.0f, 1.0f}});
        proxies.push_back(incremental.createProxy(cubes.back(), cubes.size() - 1));
      }
    }
  }
  ASSERT_TRUE(incremental.validate());
  EXPECT_LE(incremental.areaRatio(), 2.0f * ideal);

  DynamicTree rebuilt = incremental;
  rebuilt.rebuild(true);
  ASSERT_TRUE(rebuilt.validate());
  EXPECT_NEAR(rebuilt.areaRatio(), ideal, 1e-4f * ideal);
  EXPECT_EQ(rebuilt.height(), 12); // log2(16^3)

  // Each cube shifted by up to 0.1 m along each axis and given a fat box 0.1 m larger on every
  // side, in place, then rebuilt: every node's box is at most 0.2 m wider on each side than in
  // the grid's ideal tree (0.4 m along each axis), and the root's is still at least k m wide.
  Lcg random{7};
  for (std::size_t i = 0; i < cubes.size(); ++i) {
    const Vec3f shift{0.1f * random.next(), 0.1f * random.next(), 0.1f * random.next()};
    rebuilt.enlargeProxy(proxies[i], enlarge({cubes[i].lower + shift, cubes[i].upper + shift}, 0.1f));
  }
  rebuilt.rebuild();
  ASSERT_TRUE(rebuilt.validate());
  EXPECT_LE(rebuilt.areaRatio(), halvingTreeSurface(k, 0.4f) / (6.0f * k * k)); // 85.2
}

TEST(Rigid3dDynamicTree, refuses_invalid_boxes_naming_the_bad_component) {
  DynamicTree tree;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  expectErrorField([&] { tree.createProxy({{0.0f, nan, 0.0f}, {1.0f, 1.0f, 1.0f}}, 0); }, "box.lower.y");
  expectErrorField([&] { tree.createProxy({{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, inf}}, 0); }, "box.upper.z");
  expectErrorField([&] { tree.createProxy({{0.0f, 0.0f, 2.0f}, {1.0f, 1.0f, 1.0f}}, 0); }, "box.upper.z");
  EXPECT_NE(thrownMessage([&] {
              tree.createProxy({{3.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}}, 0);
            }).find("box.upper.x = 1: must be >= box.lower.x"),
            std::string::npos);
  EXPECT_EQ(tree.proxyCount(), 0);
  const std::int32_t proxy = tree.createProxy({{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}}, 0);
  expectErrorField([&] { tree.moveProxy(proxy, {{nan, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}}); }, "box.lower.x");
  expectErrorField([&] { tree.enlargeProxy(proxy, {{0.0f, 2.0f, 0.0f}, {1.0f, 1.0f, 1.0f}}); }, "box.upper.y");
  expectErrorField([&] { tree.destroyProxy(proxy + 5); }, "proxy");
  // Refused, they changed nothing.
  EXPECT_EQ(tree.fatBox(proxy), (AABB{{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}}));
  EXPECT_TRUE(tree.validate());
}

} // namespace
} // namespace impetus::rigid3d
