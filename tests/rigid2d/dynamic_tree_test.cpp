#include <impetus/rigid2d/dynamic_tree.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

namespace impetus::rigid2d {
namespace {

struct Fixture {
  DynamicTree tree;
  std::vector<std::int32_t> proxies;
  std::vector<AABB> boxes;
  std::mt19937 rng{3};

  AABB randomBox() {
    std::uniform_real_distribution<float> pos(-50.0f, 50.0f);
    std::uniform_real_distribution<float> size(0.1f, 3.0f);
    const Vec2f p{pos(rng), pos(rng)};
    return {p, p + Vec2f{size(rng), size(rng)}};
  }

  std::vector<std::uint64_t> query(const AABB& box) const {
    std::vector<std::uint64_t> hits;
    tree.query(box, [&](std::int32_t, std::uint64_t user) {
      hits.push_back(user);
      return true;
    });
    std::sort(hits.begin(), hits.end());
    return hits;
  }

  /// Removes proxy i unless it is gone already.
  void destroy(std::size_t i) {
    if (proxies[i] >= 0) {
      tree.destroyProxy(proxies[i]);
      proxies[i] = -1;
    }
  }

  /// `count` random queries, each against brute force.
  void expectQueriesMatchBruteForce(int count) {
    for (int q = 0; q < count; ++q) {
      const AABB box = enlarge(randomBox(), 5.0f);
      EXPECT_EQ(query(box), bruteForce(box));
    }
  }

  std::vector<std::uint64_t> bruteForce(const AABB& box) const {
    std::vector<std::uint64_t> hits;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      if (proxies[i] >= 0 && overlaps(boxes[i], box)) {
        hits.push_back(i);
      }
    }
    return hits;
  }
};

TEST(DynamicTree, queries_match_brute_force_through_inserts_moves_and_removals) {
  Fixture f;
  for (std::uint64_t i = 0; i < 1000; ++i) {
    f.boxes.push_back(f.randomBox());
    f.proxies.push_back(f.tree.createProxy(f.boxes.back(), i));
  }
  ASSERT_TRUE(f.tree.validate());
  // An AVL-balanced tree of 1000 leaves is at most ~1.44 log2(1000) ~ 14 deep.
  EXPECT_LE(f.tree.height(), 16);
  for (int round = 0; round < 3; ++round) {
    for (std::size_t i = 0; i < f.boxes.size(); i += 3) {
      if (f.proxies[i] >= 0) {
        f.boxes[i] = f.randomBox();
        f.tree.moveProxy(f.proxies[i], f.boxes[i]);
      }
    }
    for (std::size_t i = static_cast<std::size_t>(round); i < f.boxes.size(); i += 7) {
      f.destroy(i);
    }
    ASSERT_TRUE(f.tree.validate());
    f.expectQueriesMatchBruteForce(50);
  }
}

TEST(DynamicTree, ray_cast_visits_every_box_the_segment_crosses) {
  Fixture f;
  for (std::uint64_t i = 0; i < 500; ++i) {
    f.boxes.push_back(f.randomBox());
    f.proxies.push_back(f.tree.createProxy(f.boxes.back(), i));
  }
  std::uniform_real_distribution<float> pos(-60.0f, 60.0f);
  for (int r = 0; r < 50; ++r) {
    const Vec2f p1{pos(f.rng), pos(f.rng)};
    const Vec2f p2{pos(f.rng), pos(f.rng)};
    std::vector<std::uint64_t> visited;
    f.tree.rayCast(p1, p2, [&](std::int32_t, std::uint64_t user, const Vec2f&, const Vec2f&) {
      visited.push_back(user);
      return 1.0f; // keep going
    });
    std::sort(visited.begin(), visited.end());
    std::vector<std::uint64_t> expected;
    for (std::size_t i = 0; i < f.boxes.size(); ++i) {
      if (segmentOverlaps(f.boxes[i], p1, p2)) {
        expected.push_back(i);
      }
    }
    EXPECT_EQ(visited, expected);
  }
}

TEST(DynamicTree, same_operations_give_the_same_tree) {
  Fixture a;
  Fixture b;
  for (std::uint64_t i = 0; i < 300; ++i) {
    const AABB box = a.randomBox();
    (void)b.randomBox();
    a.tree.createProxy(box, i);
    b.tree.createProxy(box, i);
  }
  std::vector<std::uint64_t> orderA, orderB;
  const AABB all{{-100, -100}, {100, 100}};
  a.tree.query(all, [&](std::int32_t, std::uint64_t u) { return orderA.push_back(u), true; });
  b.tree.query(all, [&](std::int32_t, std::uint64_t u) { return orderB.push_back(u), true; });
  EXPECT_EQ(orderA, orderB);
  EXPECT_EQ(orderA.size(), 300U);
  EXPECT_EQ(a.tree.areaRatio(), b.tree.areaRatio());
}

TEST(DynamicTree, queries_are_reentrant_and_may_run_on_several_threads_at_once) {
  Fixture f;
  for (int i = 0; i < 2000; ++i) {
    f.boxes.push_back(f.randomBox());
    f.proxies.push_back(f.tree.createProxy(f.boxes.back(), static_cast<std::uint64_t>(i)));
  }
  const AABB outer{{-10.0f, -10.0f}, {10.0f, 10.0f}};
  const AABB inner{{-30.0f, 20.0f}, {-20.0f, 30.0f}};
  const std::vector<std::uint64_t> innerAlone = f.query(inner);
  ASSERT_FALSE(innerAlone.empty());
  // A visitor that queries the tree again, for every proxy the outer query visits: the outer
  // query must go on where it was (it kept its traversal to itself).
  std::vector<std::uint64_t> outerHits;
  bool nestedMatched = true;
  f.tree.query(outer, [&](std::int32_t, std::uint64_t user) {
    outerHits.push_back(user);
    nestedMatched = nestedMatched && f.query(inner) == innerAlone;
    return true;
  });
  EXPECT_TRUE(nestedMatched);
  std::sort(outerHits.begin(), outerHits.end());
  EXPECT_EQ(outerHits, f.query(outer));
  // Two threads querying at once see what one thread sees.
  std::vector<std::uint64_t> a;
  std::vector<std::uint64_t> b;
  std::thread other([&] {
    for (int i = 0; i < 200; ++i) {
      a = f.query(outer);
    }
  });
  for (int i = 0; i < 200; ++i) {
    b = f.query(inner);
  }
  other.join();
  EXPECT_EQ(a, f.query(outer));
  EXPECT_EQ(b, innerAlone);
}

TEST(DynamicTree, enlarged_in_place_and_rebuilt_it_stays_exact_and_shallow) {
  // The broadphase's per-step path: proxies given new boxes in place (enlargeProxy), new ones
  // inserted and old ones removed in between, then the marked part rebuilt. Queries must match
  // brute force at every stage, and the rebuilt tree must be as shallow as a median split makes
  // it (about log2 of the proxy count; a degenerate rebuild is a list, 1000 deep).
  Fixture f;
  std::uniform_real_distribution<float> drift(-2.0f, 2.0f);
  for (std::uint64_t i = 0; i < 1000; ++i) {
    f.boxes.push_back(f.randomBox());
    f.proxies.push_back(f.tree.createProxy(f.boxes.back(), i));
  }
  for (int round = 0; round < 6; ++round) {
    for (std::size_t i = static_cast<std::size_t>(round % 2); i < f.boxes.size(); i += 2) {
      if (f.proxies[i] >= 0) {
        const Vec2f shift{drift(f.rng), drift(f.rng)};
        f.boxes[i] = {f.boxes[i].lower + shift, f.boxes[i].upper + shift};
        f.tree.enlargeProxy(f.proxies[i], f.boxes[i]);
      }
    }
    // Inserts and removals while parts of the tree are marked keep it valid.
    f.boxes.push_back(f.randomBox());
    f.proxies.push_back(f.tree.createProxy(f.boxes.back(), f.boxes.size() - 1));
    f.destroy(static_cast<std::size_t>(round) * 97);
    ASSERT_TRUE(f.tree.validate());
    f.expectQueriesMatchBruteForce(20);
    f.tree.rebuild(round == 5);
    ASSERT_TRUE(f.tree.validate());
    EXPECT_EQ(f.tree.proxyCount(), static_cast<int>(std::count_if(f.proxies.begin(), f.proxies.end(),
                                                                  [](std::int32_t p) { return p >= 0; })));
    EXPECT_LE(f.tree.height(), 20) << "round " << round;
    f.expectQueriesMatchBruteForce(20);
  }
  // A full median-split build packs the boxes no worse than the incremental one did: the sum of
  // internal perimeters over the root's (the SAH cost) within 10% of an incremental tree's.
  DynamicTree incremental;
  for (std::size_t i = 0; i < f.boxes.size(); ++i) {
    if (f.proxies[i] >= 0) {
      incremental.createProxy(f.boxes[i], i);
    }
  }
  EXPECT_LE(f.tree.areaRatio(), 1.1f * incremental.areaRatio());
}

TEST(DynamicTree, rejects_invalid_boxes) {
  DynamicTree tree;
  EXPECT_ANY_THROW(tree.createProxy({{1, 1}, {0, 0}}, 0));
  EXPECT_ANY_THROW(tree.createProxy({{std::nanf(""), 0}, {1, 1}}, 0));
  EXPECT_ANY_THROW(tree.destroyProxy(5));
  const std::int32_t proxy = tree.createProxy({{0, 0}, {1, 1}}, 0);
  EXPECT_ANY_THROW(tree.enlargeProxy(proxy, {{0, 0}, {std::nanf(""), 1}}));
}

} // namespace
} // namespace impetus::rigid2d
