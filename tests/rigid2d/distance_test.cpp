#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/distance.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace impetus::rigid2d {
namespace {

Transform2f at(float x, float y, float angle = 0.0f) { return {{x, y}, Rot2f::fromAngle(angle)}; }

// Float tolerances: coordinates here are below ~20 m, where a float ulp is ~2e-6 m; GJK does a
// handful of dot products and one barycentric division, so 1e-5 m covers round-off with margin.
constexpr float tol = 1e-5f;

void expectNear(const Vec2f& actual, const Vec2f& expected, float tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
}

/// Distance from p to the segment a-b (a == b allowed): the closed form the GJK answer must match.
float pointSegmentDistance(const Vec2f& p, const Vec2f& a, const Vec2f& b) {
  const Vec2f ab = b - a;
  const float ab2 = lengthSquared(ab);
  const float t = ab2 > 0.0f ? std::clamp(dot(p - a, ab) / ab2, 0.0f, 1.0f) : 0.0f;
  return distance(p, a + ab * t);
}

/// The distance between the cores (point hulls) of two separated proxies by brute force: for
/// disjoint convex polygons the closest pair is always a vertex of one against an edge of the
/// other. Edges are taken between all pairs of points, which includes the hull's edges.
float bruteCoreDistance(const ShapeProxy& a, const Transform2f& xfA, const ShapeProxy& b, const Transform2f& xfB) {
  std::vector<Vec2f> pa;
  std::vector<Vec2f> pb;
  for (int i = 0; i < a.count; ++i) {
    pa.push_back(transformPoint(xfA, a.points[static_cast<std::size_t>(i)]));
  }
  for (int i = 0; i < b.count; ++i) {
    pb.push_back(transformPoint(xfB, b.points[static_cast<std::size_t>(i)]));
  }
  float best = std::numeric_limits<float>::max();
  for (const Vec2f& p : pa) {
    for (std::size_t i = 0; i < pb.size(); ++i) {
      for (std::size_t j = i; j < pb.size(); ++j) {
        best = std::min(best, pointSegmentDistance(p, pb[i], pb[j]));
      }
    }
  }
  for (const Vec2f& p : pb) {
    for (std::size_t i = 0; i < pa.size(); ++i) {
      for (std::size_t j = i; j < pa.size(); ++j) {
        best = std::min(best, pointSegmentDistance(p, pa[i], pa[j]));
      }
    }
  }
  return best;
}

/// How far a world point is from a shape's rounded surface: its distance to the core minus the
/// radius (0 on the surface).
float offSurface(const Vec2f& p, const ShapeProxy& shape, const Transform2f& xf) {
  const std::array<Vec2f, 1> one{p};
  return shapeDistance(makeProxy(one, 0.0f), Transform2f::identity(), shape, xf, false).distance - shape.radius;
}

TEST(Distance, circles_match_centre_distance_minus_radii) {
  const ShapeProxy a = makeProxy(Circle{{0.1f, 0.0f}, 0.5f});
  const ShapeProxy b = makeProxy(Circle{{0.0f, 0.0f}, 0.3f});
  // World centres (1, 2) and (4, 6): 5 m apart along (0.6, 0.8).
  const DistanceOutput d = shapeDistance(a, at(0.9f, 2.0f), b, at(4.0f, 6.0f));
  EXPECT_NEAR(d.distance, 5.0f - 0.5f - 0.3f, tol);
  expectNear(d.normal, {0.6f, 0.8f}, tol);
  expectNear(d.pointA, Vec2f{1.0f, 2.0f} + Vec2f{0.6f, 0.8f} * 0.5f, tol);
  expectNear(d.pointB, Vec2f{4.0f, 6.0f} - Vec2f{0.6f, 0.8f} * 0.3f, tol);
  EXPECT_EQ(d.simplexCount, 1);
  // Without radii: the centre distance.
  EXPECT_NEAR(shapeDistance(a, at(0.9f, 2.0f), b, at(4.0f, 6.0f), false).distance, 5.0f, tol);
}

TEST(Distance, axis_aligned_boxes_face_to_face) {
  const ShapeProxy a = makeProxy(makeBox(0.5f, 0.5f));
  const ShapeProxy b = makeProxy(makeBox(1.0f, 0.25f));
  // B spans x in [2, 4], y in [0.05, 0.55]; A spans [-0.5, 0.5]^2: the gap is 1.5 m along x.
  const DistanceOutput d = shapeDistance(a, at(0, 0), b, at(3.0f, 0.3f));
  EXPECT_NEAR(d.distance, 1.5f, tol);
  expectNear(d.normal, {1.0f, 0.0f}, tol);
  EXPECT_NEAR(d.pointA.x, 0.5f, tol);
  EXPECT_NEAR(d.pointB.x, 2.0f, tol);
  EXPECT_NEAR(d.pointA.y, d.pointB.y, tol);
  EXPECT_GE(d.pointA.y, 0.05f - tol); // within the faces' overlap in y
  EXPECT_LE(d.pointA.y, 0.5f + tol);
}

TEST(Distance, rotated_box_vertex_to_face) {
  const ShapeProxy box = makeProxy(makeBox(0.5f, 0.5f));
  // B turned 45 degrees at (2, 0.1): its left vertex is at x = 2 - 0.5 sqrt(2), facing A's face x = 0.5.
  const float vertexX = 2.0f - 0.5f * std::sqrt(2.0f);
  const DistanceOutput d = shapeDistance(box, at(0, 0), box, at(2.0f, 0.1f, pi<float> / 4.0f));
  EXPECT_NEAR(d.distance, vertexX - 0.5f, tol);
  expectNear(d.pointA, {0.5f, 0.1f}, tol);
  expectNear(d.pointB, {vertexX, 0.1f}, tol);
  expectNear(d.normal, {1.0f, 0.0f}, tol);
  EXPECT_EQ(d.simplexCount, 2); // a vertex against an edge
}

TEST(Distance, point_to_segment_interior_and_end) {
  const ShapeProxy segment = makeProxy(Segment{{-1.0f, 0.0f}, {1.0f, 0.0f}});
  const Transform2f xf = at(2.0f, 3.0f, 0.5f);
  const auto pointProxy = [](const Vec2f& p) {
    const std::array<Vec2f, 1> one{p};
    return makeProxy(one, 0.0f);
  };
  // Above the interior: the perpendicular distance 0.7, foot at local (0.3, 0).
  const DistanceOutput inside = shapeDistance(segment, xf, pointProxy(transformPoint(xf, {0.3f, 0.7f})), at(0, 0));
  EXPECT_NEAR(inside.distance, 0.7f, tol);
  expectNear(inside.pointA, transformPoint(xf, {0.3f, 0.0f}), tol);
  // Past the end: the distance to the end point (1, 0), sqrt(2).
  const DistanceOutput beyond = shapeDistance(segment, xf, pointProxy(transformPoint(xf, {2.0f, -1.0f})), at(0, 0));
  EXPECT_NEAR(beyond.distance, std::sqrt(2.0f), tol);
  expectNear(beyond.pointA, transformPoint(xf, {1.0f, 0.0f}), tol);
  EXPECT_EQ(beyond.simplexCount, 1);
}

TEST(Distance, overlapping_shapes_give_zero) {
  const ShapeProxy box = makeProxy(makeBox(0.5f, 0.5f));
  const DistanceOutput d = shapeDistance(box, at(0, 0), box, at(0.7f, 0.2f, 0.3f));
  EXPECT_EQ(d.distance, 0.0f);
  EXPECT_EQ(d.simplexCount, 3); // the origin is inside the Minkowski difference
  EXPECT_EQ(d.pointA, d.pointB);
  EXPECT_EQ(d.normal, Vec2f{});
  EXPECT_EQ(shapeDistance(box, at(0, 0), box, at(0.7f, 0.2f, 0.3f), false).distance, 0.0f);

  // Rounded shapes whose surfaces overlap but cores do not: distance 0, points stay on the
  // surfaces (continuous in the motion) and the normal is still defined.
  const ShapeProxy a = makeProxy(Circle{{0, 0}, 0.5f});
  const DistanceOutput r = shapeDistance(a, at(0, 0), a, at(0.8f, 0.0f));
  EXPECT_EQ(r.distance, 0.0f);
  expectNear(r.pointA, {0.5f, 0.0f}, tol);
  expectNear(r.pointB, {0.3f, 0.0f}, tol);
  expectNear(r.normal, {1.0f, 0.0f}, tol);
  // Concentric: no direction at all.
  EXPECT_EQ(shapeDistance(a, at(1, 1), a, at(1, 1)).normal, Vec2f{});
}

/// Random separated pairs of every proxy kind (circle, capsule, segment, rounded polygon).
struct RandomPair {
  ShapeProxy a;
  Transform2f xfA;
  ShapeProxy b;
  Transform2f xfB;
};

ShapeProxy randomProxy(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::uniform_real_distribution<float> r(0.0f, 0.3f);
  switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
  case 0:
    return makeProxy(Circle{{u(rng), u(rng)}, 0.05f + r(rng)});
  case 1:
    return makeProxy(Capsule{{u(rng), u(rng)}, {u(rng), u(rng)}, r(rng)});
  case 2:
    return makeProxy(Segment{{u(rng), u(rng)}, {u(rng), u(rng)}});
  default: {
    std::array<Vec2f, 8> pts{};
    for (Vec2f& p : pts) {
      p = {u(rng), u(rng)};
    }
    return makeProxy(makePolygon(pts, r(rng)));
  }
  }
}

RandomPair randomSeparatedPair(std::mt19937& rng) {
  std::uniform_real_distribution<float> angle(-pi<float>, pi<float>);
  std::uniform_real_distribution<float> gap(0.05f, 3.0f);
  RandomPair p{randomProxy(rng), at(0, 0, angle(rng)), randomProxy(rng), {}};
  // Local points are within sqrt(2) of the origin, so bounding circles of sqrt(2) + radius keep
  // the shapes apart when the frames are farther apart than their sum.
  const float reach = 2.0f * std::sqrt(2.0f) + p.a.radius + p.b.radius;
  const float theta = angle(rng);
  const float dist = reach + gap(rng);
  p.xfB = at(dist * std::cos(theta), dist * std::sin(theta), angle(rng));
  p.xfA.p = {3.0f, -2.0f}; // away from the origin too
  p.xfB.p += p.xfA.p;
  return p;
}

TEST(Distance, random_pairs_match_brute_force_with_points_on_surfaces) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    const RandomPair p = randomSeparatedPair(rng);
    const DistanceOutput d = shapeDistance(p.a, p.xfA, p.b, p.xfB);
    const float expected = bruteCoreDistance(p.a, p.xfA, p.b, p.xfB) - p.a.radius - p.b.radius;
    ASSERT_NEAR(d.distance, expected, tol) << "trial " << trial;
    ASSERT_NEAR(distance(d.pointA, d.pointB), d.distance, tol);
    // The normal runs from A's witness point to B's, and is unit.
    ASSERT_NEAR(length(d.normal), 1.0f, tol);
    ASSERT_NEAR(dot(d.pointB - d.pointA, d.normal), d.distance, tol);
    // Witness points lie on the (rounded) surfaces.
    ASSERT_NEAR(offSurface(d.pointA, p.a, p.xfA), 0.0f, tol) << "trial " << trial;
    ASSERT_NEAR(offSurface(d.pointB, p.b, p.xfB), 0.0f, tol) << "trial " << trial;
  }
}

TEST(Distance, swapping_shapes_swaps_points_and_flips_normal) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 100; ++trial) {
    const RandomPair p = randomSeparatedPair(rng);
    const DistanceOutput ab = shapeDistance(p.a, p.xfA, p.b, p.xfB);
    const DistanceOutput ba = shapeDistance(p.b, p.xfB, p.a, p.xfA);
    ASSERT_NEAR(ab.distance, ba.distance, tol);
    expectNear(ab.normal, -ba.normal, 1e-4f); // normal of a >= 0.05 m gap: 1e-5 / 0.05 rad
    // Each witness point is on the other call's matching supporting line; vertex-vertex
    // witnesses are unique and must match exactly (parallel edges would not be).
    EXPECT_NEAR(dot(ab.pointA - ba.pointB, ab.normal), 0.0f, tol);
    EXPECT_NEAR(dot(ab.pointB - ba.pointA, ab.normal), 0.0f, tol);
    if (ab.simplexCount == 1 && ba.simplexCount == 1) {
      expectNear(ab.pointA, ba.pointB, tol);
      expectNear(ab.pointB, ba.pointA, tol);
    }
  }
}

TEST(Distance, simplex_cache_reused_gives_same_answer_in_no_more_iterations) {
  std::mt19937 rng(3);
  int savedIterations = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const RandomPair p = randomSeparatedPair(rng);
    SimplexCache cache;
    const DistanceOutput cold = shapeDistance(p.a, p.xfA, p.b, p.xfB, true, &cache);
    EXPECT_EQ(cache.count, cold.simplexCount);
    const DistanceOutput warm = shapeDistance(p.a, p.xfA, p.b, p.xfB, true, &cache);
    ASSERT_NEAR(warm.distance, cold.distance, tol);
    ASSERT_LE(warm.iterations, cold.iterations);
    savedIterations += cold.iterations - warm.iterations;
    // A small motion afterwards: the cache still gives the uncached answer.
    Transform2f moved = p.xfB;
    moved.p += Vec2f{0.01f, -0.02f};
    const DistanceOutput coherent = shapeDistance(p.a, p.xfA, p.b, moved, true, &cache);
    ASSERT_NEAR(coherent.distance, shapeDistance(p.a, p.xfA, p.b, moved).distance, tol);
  }
  EXPECT_GT(savedIterations, 0);

  // A cache from another pair, with indices past these proxies, is ignored rather than trusted.
  SimplexCache stale;
  stale.count = 3;
  stale.indexA = {7, 6, 5};
  stale.indexB = {7, 6, 5};
  const ShapeProxy circle = makeProxy(Circle{{0, 0}, 0.5f});
  EXPECT_NEAR(shapeDistance(circle, at(0, 0), circle, at(3, 0), true, &stale).distance, 2.0f, tol);
}

TEST(Distance, invalid_input_names_the_field) {
  const ShapeProxy box = makeProxy(makeBox(0.5f, 0.5f));
  const auto fieldOf = [](auto&& f) {
    try {
      f();
    } catch (const Error& e) {
      return e.field();
    }
    return std::string("(no throw)");
  };
  const std::array<Vec2f, 9> nine{};
  EXPECT_EQ(fieldOf([&] { (void)makeProxy(std::span<const Vec2f>(nine), 0.0f); }), "points.size");
  EXPECT_EQ(fieldOf([&] { (void)makeProxy(std::span<const Vec2f>(), 0.0f); }), "points.size");
  const std::array<Vec2f, 2> bad{Vec2f{0, 0}, Vec2f{1, std::nanf("")}};
  EXPECT_EQ(fieldOf([&] { (void)makeProxy(bad, 0.0f); }), "points[1].y");
  EXPECT_EQ(fieldOf([&] { (void)makeProxy(Circle{{0, 0}, -1.0f}); }), "radius");
  EXPECT_EQ(fieldOf([&] { (void)shapeDistance(ShapeProxy{}, at(0, 0), box, at(1, 0)); }), "a.count");
  ShapeProxy tooMany = box;
  tooMany.count = 9;
  EXPECT_EQ(fieldOf([&] { (void)shapeDistance(box, at(0, 0), tooMany, at(1, 0)); }), "b.count");
  Transform2f nanXf = at(0, 0);
  nanXf.p.x = std::numeric_limits<float>::infinity();
  EXPECT_EQ(fieldOf([&] { (void)shapeDistance(box, at(0, 0), box, nanXf); }), "xfB.p.x");
  ShapeCastInput cast{box, at(0, 0), box, at(3, 0), {-1, 0}, 2.0f};
  EXPECT_EQ(fieldOf([&] { (void)shapeCast(cast); }), "maxFraction");
  cast.maxFraction = 1.0f;
  cast.translationB.y = std::nanf("");
  EXPECT_EQ(fieldOf([&] { (void)shapeCast(cast); }), "translationB.y");
  Sweep sweep{{0, 0}, {0, 0}, {1, std::nanf("")}, {}, {}};
  EXPECT_EQ(fieldOf([&] { (void)timeOfImpact(box, sweep, box, Sweep{}); }), "sweepA.c2.y");
  EXPECT_EQ(fieldOf([&] { (void)timeOfImpact(box, Sweep{}, box, Sweep{}, -0.5f); }), "maxFraction");
}

TEST(ShapeCast, circle_moving_toward_box_hits_at_analytic_fraction) {
  const ShapeProxy box = makeProxy(makeBox(1.0f, 1.0f));
  const ShapeProxy ball = makeProxy(Circle{{0, 0}, 0.25f});
  const Vec2f translation{-8.0f, 0.0f};
  const CastOutput out = shapeCast({box, at(0, 0), ball, at(5.0f, 0.3f), translation, 1.0f});
  ASSERT_TRUE(out.hit);
  // The ball touches the face x = 1 when its centre is at x = 1.25: fraction 3.75 / 8. The cast
  // stops with the cores at the target 0.25 - linearSlop, +- linearSlop / 4: within
  // 1.25 linearSlop of touching along the 8 m translation.
  const float bound = 1.25f * linearSlop / length(translation) + 1e-6f;
  EXPECT_NEAR(out.fraction, 3.75f / 8.0f, bound);
  expectNear(out.normal, {1.0f, 0.0f}, tol);
  expectNear(out.point, {1.0f, 0.3f}, tol); // on the box face, under the ball's centre

  // The same in a moved and turned frame: a 4 x 1 box stood upright (turned 90 degrees) at
  // (10, -3), so its face toward the ball is x = 10.5.
  const ShapeProxy plank = makeProxy(makeBox(2.0f, 0.5f));
  const CastOutput turned =
      shapeCast({plank, at(10.0f, -3.0f, pi<float> / 2.0f), ball, at(15.0f, -2.6f), translation, 1.0f});
  ASSERT_TRUE(turned.hit);
  EXPECT_NEAR(turned.fraction, (15.0f - 10.75f) / 8.0f, bound);
  expectNear(turned.normal, {1.0f, 0.0f}, 1e-4f);
  EXPECT_NEAR(turned.point.x, 10.5f, 1e-4f);
}

TEST(ShapeCast, box_onto_box_corner_first) {
  // A box turned 45 degrees dropping onto a flat box: its lowest corner (0.5 sqrt(2) below the
  // centre) reaches the top face y = 0.5 after falling 2 - 0.5 - 0.5 sqrt(2). Sharp shapes stop
  // linearSlop short (the target), +- linearSlop / 4.
  const ShapeProxy box = makeProxy(makeBox(0.5f, 0.5f));
  const ShapeProxy ground = makeProxy(makeBox(5.0f, 0.5f));
  const Vec2f translation{0.0f, -4.0f};
  const CastOutput out = shapeCast({ground, at(0, 0), box, at(0.3f, 2.0f, pi<float> / 4.0f), translation, 1.0f});
  ASSERT_TRUE(out.hit);
  const float fall = 2.0f - 0.5f - 0.5f * std::sqrt(2.0f);
  EXPECT_NEAR(out.fraction, (fall - linearSlop) / 4.0f, 0.25f * linearSlop / 4.0f + 1e-6f);
  expectNear(out.normal, {0.0f, 1.0f}, tol);
  expectNear(out.point, {0.3f, 0.5f}, 1e-4f);
}

TEST(ShapeCast, misses_report_no_hit) {
  const ShapeProxy box = makeProxy(makeBox(1.0f, 1.0f));
  const ShapeProxy ball = makeProxy(Circle{{0, 0}, 0.25f});
  // Passing above the box (centre 0.5 m above its top face), moving away, and stopping short.
  EXPECT_FALSE(shapeCast({box, at(0, 0), ball, at(5.0f, 1.5f), {-10.0f, 0.0f}, 1.0f}).hit);
  EXPECT_FALSE(shapeCast({box, at(0, 0), ball, at(5.0f, 0.0f), {3.0f, 0.0f}, 1.0f}).hit);
  EXPECT_FALSE(shapeCast({box, at(0, 0), ball, at(5.0f, 0.0f), {-3.0f, 0.0f}, 1.0f}).hit);
  // maxFraction cuts the motion short of the box: 10 m * 0.3 = 3 m < 3.75 m.
  EXPECT_FALSE(shapeCast({box, at(0, 0), ball, at(5.0f, 0.0f), {-10.0f, 0.0f}, 0.3f}).hit);
  EXPECT_TRUE(shapeCast({box, at(0, 0), ball, at(5.0f, 0.0f), {-10.0f, 0.0f}, 0.4f}).hit);
}

TEST(ShapeCast, initially_overlapping_hits_at_zero) {
  const ShapeProxy box = makeProxy(makeBox(1.0f, 1.0f));
  const ShapeProxy ball = makeProxy(Circle{{0, 0}, 0.25f});
  const CastOutput out = shapeCast({box, at(0, 0), ball, at(1.1f, 0.0f), {5.0f, 0.0f}, 1.0f});
  EXPECT_TRUE(out.hit);
  EXPECT_EQ(out.fraction, 0.0f);
  EXPECT_NEAR(out.point.x, 1.0f - 0.5f * (1.0f - 0.85f), tol); // midway between box face and ball surface
  expectNear(out.normal, {1.0f, 0.0f}, tol);
}

/// The core distance (no radii) of the pair at fraction t of their sweeps.
float coreDistanceAt(const ShapeProxy& a, const Sweep& sa, const ShapeProxy& b, const Sweep& sb, float t) {
  return shapeDistance(a, sweepTransform(sa, t), b, sweepTransform(sb, t), false).distance;
}

float toiTarget(const ShapeProxy& a, const ShapeProxy& b) {
  return std::max(linearSlop, a.radius + b.radius - linearSlop);
}

TEST(TimeOfImpact, sweep_transform_interpolates_centre_and_rotation) {
  const Sweep s{{0.5f, 0.0f}, {1.0f, 1.0f}, {3.0f, 1.0f}, Rot2f::identity(), Rot2f::fromAngle(pi<float> / 2.0f)};
  const Transform2f start = sweepTransform(s, 0.0f);
  expectNear(start.p, {0.5f, 1.0f}, tol); // the origin is localCenter behind the centre of mass
  const Transform2f mid = sweepTransform(s, 0.5f);
  EXPECT_NEAR(mid.q.angle(), pi<float> / 4.0f, 1e-6f); // nlerp is exact at the midpoint
  expectNear(transformPoint(mid, s.localCenter), {2.0f, 1.0f}, tol);
  const Transform2f end = sweepTransform(s, 1.0f);
  expectNear(end.p, {3.0f, 0.5f}, tol);
}

TEST(TimeOfImpact, spinning_box_toward_wall_stops_at_target_without_overlap) {
  const ShapeProxy wall = makeProxy(makeBox(0.1f, 5.0f));
  const Sweep sweepWall{{0, 0}, {3.0f, 0.0f}, {3.0f, 0.0f}, Rot2f::identity(), Rot2f::identity()};
  // An off-centre box (centre of mass at its centroid (0.2, 0.1)) moving 4 m and turning 2.5 rad.
  const ShapeProxy box = makeProxy(makeOffsetBox(0.5f, 0.25f, {0.2f, 0.1f}, 0.0f));
  const Sweep sweepBox{{0.2f, 0.1f}, {0.0f, 0.0f}, {4.0f, 0.5f}, Rot2f::identity(), Rot2f::fromAngle(2.5f)};

  const TOIOutput out = timeOfImpact(wall, sweepWall, box, sweepBox);
  ASSERT_EQ(out.state, TOIOutput::State::hit);
  const float target = toiTarget(wall, box);
  const float tolerance = 0.25f * linearSlop;
  // Reported when GJK finds the cores within target +- tolerance; 1e-5 m for float round-off.
  const float atHit = coreDistanceAt(wall, sweepWall, box, sweepBox, out.fraction);
  EXPECT_GT(atHit, target - tolerance - tol);
  EXPECT_LT(atHit, target + tolerance + tol);

  // Brute force: sample the sweep finely. The shapes must not have come within the target before
  // the reported fraction (it is the first contact, not a later one), and sampling can only find
  // the crossing later than the truth, by at most a step.
  const int steps = 20000;
  float firstBelow = 1.0f;
  for (int i = 0; i <= steps; ++i) {
    const float t = static_cast<float>(i) / static_cast<float>(steps);
    if (coreDistanceAt(wall, sweepWall, box, sweepBox, t) < target - tolerance) {
      firstBelow = t;
      break;
    }
  }
  EXPECT_LT(firstBelow, 1.0f); // they do collide during the sweep
  EXPECT_LE(out.fraction, firstBelow);
  // ... and not much earlier: the box closes on the wall at no less than 4 - 2.5 * 0.56 > 2.5 m per
  // unit t (translation minus the fastest a corner can swing back), so the band target +-
  // tolerance is crossed within 2 tolerance / 2.5 < 4 tolerance in t.
  EXPECT_GT(out.fraction, firstBelow - 4.0f * tolerance);
}

TEST(TimeOfImpact, fast_thin_bullet_through_thin_wall_is_caught) {
  // A 1 cm wall and a 10 cm box crossing 10 m in one sweep: at t = 0 and t = 1 they are apart
  // (a discrete step would tunnel through), but the sweep meets the wall.
  const ShapeProxy wall = makeProxy(makeBox(0.005f, 2.0f));
  const Sweep still{{0, 0}, {0, 0}, {0, 0}, Rot2f::identity(), Rot2f::identity()};
  const ShapeProxy bullet = makeProxy(makeBox(0.05f, 0.05f));
  const Sweep fast{{0, 0}, {-5.0f, 0.2f}, {5.0f, 0.2f}, Rot2f::identity(), Rot2f::identity()};
  EXPECT_GT(coreDistanceAt(wall, still, bullet, fast, 0.0f), 1.0f);
  EXPECT_GT(coreDistanceAt(wall, still, bullet, fast, 1.0f), 1.0f);

  const TOIOutput out = timeOfImpact(wall, still, bullet, fast);
  ASSERT_EQ(out.state, TOIOutput::State::hit);
  // Sharp shapes stop linearSlop apart: the bullet's front face at x = -0.005 - linearSlop,
  // +- linearSlop / 4 over the 10 m travel.
  const float expected = (5.0f - 0.005f - 0.05f - linearSlop) / 10.0f;
  EXPECT_NEAR(out.fraction, expected, 0.25f * linearSlop / 10.0f + 1e-6f);
  EXPECT_GT(coreDistanceAt(wall, still, bullet, fast, out.fraction), 0.0f);

  // A small round bullet (2 cm) stops just into the slop: cores at 0.02 - linearSlop.
  const ShapeProxy pellet = makeProxy(Circle{{0, 0}, 0.02f});
  const TOIOutput round = timeOfImpact(wall, still, pellet, fast);
  ASSERT_EQ(round.state, TOIOutput::State::hit);
  EXPECT_NEAR(round.fraction, (5.0f - 0.005f - (0.02f - linearSlop)) / 10.0f, 0.25f * linearSlop / 10.0f + 1e-6f);
}

TEST(TimeOfImpact, random_translations_find_the_first_contact_and_agree_with_shape_cast) {
  // Pure translations (any shapes, any turned but fixed orientation): the separation along any
  // fixed axis is then concave in time, so the algorithm is exact: no sweep reported separated
  // may come within the target, and a hit is the first time it does. Sampling the sweep can only
  // find the crossing late (never early), so these checks cannot fail spuriously.
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::uniform_real_distribution<float> angle(-pi<float>, pi<float>);
  const float tolerance = 0.25f * linearSlop;
  int hits = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const ShapeProxy a = randomProxy(rng);
    const ShapeProxy b = randomProxy(rng);
    const Transform2f xfA{{u(rng) * 2.0f, u(rng) * 2.0f}, Rot2f::fromAngle(angle(rng))};
    const Transform2f xfB{{u(rng) * 5.0f, u(rng) * 5.0f}, Rot2f::fromAngle(angle(rng))};
    const Vec2f translation{u(rng) * 8.0f, u(rng) * 8.0f};
    const Sweep sweepA{{0, 0}, xfA.p, xfA.p, xfA.q, xfA.q};
    const Sweep sweepB{{0, 0}, xfB.p, xfB.p + translation, xfB.q, xfB.q};
    const TOIOutput toi = timeOfImpact(a, sweepA, b, sweepB);
    if (toi.state == TOIOutput::State::overlapped) {
      continue;
    }
    ASSERT_TRUE(toi.state == TOIOutput::State::hit || toi.state == TOIOutput::State::separated) << trial;
    const float target = toiTarget(a, b);
    float firstBelow = 2.0f; // past the sweep: never below
    for (int i = 0; i <= 1000; ++i) {
      const float t = static_cast<float>(i) / 1000.0f;
      if (coreDistanceAt(a, sweepA, b, sweepB, t) < target - tolerance) {
        firstBelow = t;
        break;
      }
    }
    ASSERT_LE(toi.fraction, firstBelow) << "trial " << trial;
    if (toi.state == TOIOutput::State::hit && toi.fraction > 0.0f) {
      const float d = coreDistanceAt(a, sweepA, b, sweepB, toi.fraction);
      ASSERT_GT(d, target - tolerance - tol) << "trial " << trial;
      ASSERT_LT(d, target + tolerance + tol) << "trial " << trial;
    }

    // The shape cast of the same motion uses the same target: same verdict, and fractions
    // within the shared tolerance band (2 linearSlop / 4 of travel) of each other.
    const CastOutput cast = shapeCast({a, xfA, b, xfB, translation, 1.0f});
    ASSERT_EQ(cast.hit, toi.state == TOIOutput::State::hit) << "trial " << trial;
    if (cast.hit) {
      ++hits;
      EXPECT_NEAR(cast.fraction, toi.fraction, 0.5f * linearSlop / length(translation) + 1e-6f) << "trial " << trial;
    }
  }
  EXPECT_GT(hits, 10); // the random set does exercise hits
}

TEST(TimeOfImpact, separated_sweeps_and_initial_overlap) {
  const ShapeProxy box = makeProxy(makeBox(0.5f, 0.5f));
  const Sweep still{{0, 0}, {0, 0}, {0, 0}, Rot2f::identity(), Rot2f::identity()};
  // Sliding past above, spinning: never within the target.
  const Sweep past{{0, 0}, {-5.0f, 2.0f}, {5.0f, 2.0f}, Rot2f::identity(), Rot2f::fromAngle(1.0f)};
  const TOIOutput apart = timeOfImpact(box, still, box, past);
  EXPECT_EQ(apart.state, TOIOutput::State::separated);
  EXPECT_EQ(apart.fraction, 1.0f);
  // Moving away.
  const Sweep away{{0, 0}, {2.0f, 0.0f}, {6.0f, 0.0f}, Rot2f::identity(), Rot2f::identity()};
  EXPECT_EQ(timeOfImpact(box, still, box, away).state, TOIOutput::State::separated);
  // Would hit at t ~ 0.25, but the sweep is cut at 0.2.
  const Sweep toward{{0, 0}, {2.0f, 0.0f}, {-2.0f, 0.0f}, Rot2f::identity(), Rot2f::identity()};
  const TOIOutput cut = timeOfImpact(box, still, box, toward, 0.2f);
  EXPECT_EQ(cut.state, TOIOutput::State::separated);
  EXPECT_EQ(cut.fraction, 0.2f);
  EXPECT_EQ(timeOfImpact(box, still, box, toward).state, TOIOutput::State::hit);
  // Overlapping from the start.
  const Sweep inside{{0, 0}, {0.5f, 0.0f}, {3.0f, 0.0f}, Rot2f::identity(), Rot2f::identity()};
  const TOIOutput overlap = timeOfImpact(box, still, box, inside);
  EXPECT_EQ(overlap.state, TOIOutput::State::overlapped);
  EXPECT_EQ(overlap.fraction, 0.0f);
}

} // namespace
} // namespace impetus::rigid2d
