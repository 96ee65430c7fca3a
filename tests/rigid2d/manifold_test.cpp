#include <impetus/math/scalar.hpp>
#include <impetus/rigid2d/manifold.hpp>

#include "rigid2d/manifold_internal.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <span>
#include <vector>

namespace impetus::rigid2d {
namespace {

Transform2f at(float x, float y, float angle = 0.0f) { return {{x, y}, Rot2f::fromAngle(angle)}; }

// A face clip's point ids do not tell which face was the reference (they are A's vertex and B's,
// as Box2D v3's, the same either way), so the branches taken are read off the geometry: B's face
// was the reference when the normal is minus one of B's face normals and clearly none of A's; a
// point was clipped when it lies at none of the incident polygon's corners (an unclipped point
// lies midway between a corner and the reference face).
bool referenceIsB(const Manifold& m, const Polygon& a, const Transform2f& xa, const Polygon& b, const Transform2f& xb) {
  const auto nearest = [&](const Polygon& p, const Transform2f& x, float sign) {
    float best = 1e9f;
    for (int i = 0; i < p.count; ++i) {
      best = std::min(best, length(rotate(x.q, p.normals[static_cast<std::size_t>(i)]) * sign - m.normal));
    }
    return best;
  };
  return nearest(b, xb, -1.0f) < 1e-6f && nearest(a, xa, 1.0f) > 1e-4f;
}

bool atNoCorner(const ManifoldPoint& point, const Polygon& incident, const Transform2f& x, float tolerance) {
  for (int i = 0; i < incident.count; ++i) {
    const Vec2f corner = transformPoint(x, incident.vertices[static_cast<std::size_t>(i)]);
    if (length(point.point - corner) <= 0.5f * std::abs(point.separation) + tolerance) {
      return false;
    }
  }
  return true;
}

TEST(Manifold, circles_separation_normal_and_speculative_range) {
  const Circle unit{{0, 0}, 0.5f};
  const Manifold overlap = collideCircles(unit, at(0, 0), unit, at(0.9f, 0));
  ASSERT_EQ(overlap.pointCount, 1);
  EXPECT_NEAR(overlap.points[0].separation, -0.1f, 1e-6f);
  EXPECT_NEAR(overlap.normal.x, 1.0f, 1e-6f);
  EXPECT_NEAR(overlap.points[0].point.x, 0.45f, 1e-6f); // midway between the surfaces
  // Kept while closer than the speculative distance, dropped beyond.
  EXPECT_EQ(collideCircles(unit, at(0, 0), unit, at(1.0f + 0.5f * speculativeDistance, 0)).pointCount, 1);
  EXPECT_EQ(collideCircles(unit, at(0, 0), unit, at(1.0f + 2.0f * speculativeDistance, 0)).pointCount, 0);
}

TEST(Manifold, box_resting_on_box_has_two_points_along_the_face) {
  const Polygon ground = makeBox(5.0f, 0.5f);
  const Polygon box = makeBox(0.5f, 0.5f);
  const Manifold m = collidePolygons(ground, at(0, 0), box, at(1.0f, 0.99f)); // 1 cm overlap
  ASSERT_EQ(m.pointCount, 2);
  EXPECT_NEAR(m.normal.y, 1.0f, 1e-6f);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[static_cast<std::size_t>(i)].separation, -0.01f, 1e-5f);
    EXPECT_NEAR(m.points[static_cast<std::size_t>(i)].point.y, 0.495f, 1e-5f);
  }
  EXPECT_NEAR(std::abs(m.points[0].point.x - m.points[1].point.x), 1.0f, 1e-5f);
  EXPECT_NE(m.points[0].id, m.points[1].id);
  // The same features give the same ids a step later.
  const Manifold later = collidePolygons(ground, at(0, 0), box, at(1.02f, 0.985f));
  ASSERT_EQ(later.pointCount, 2);
  EXPECT_EQ(later.points[0].id, m.points[0].id);
  EXPECT_EQ(later.points[1].id, m.points[1].id);
}

// Two equal boxes stacked half a box apart (a pyramid's rows), the upper one turned by a hair
// either way: the reference face passes from one box to the other as the turn changes sign, and
// each physical point (the same pair of corners and edges) keeps its id, so its warm start
// survives the change (Box2D v3's ids: A's vertex and B's at the point's end).
TEST(Manifold, a_point_keeps_its_id_when_the_reference_face_changes_sides) {
  const Polygon box = makeBox(0.5f, 0.5f);
  int changes = 0;
  Manifold previous{};
  bool previousOnB = false;
  for (int k = -20; k <= 20; ++k) {
    const float turn = 1e-4f * static_cast<float>(k);
    const Transform2f xa = at(0, 0);
    const Transform2f xb = at(0.5f, 0.999f, turn);
    const Manifold m = collidePolygons(box, xa, box, xb);
    ASSERT_EQ(m.pointCount, 2) << k;
    const bool onB = referenceIsB(m, box, xa, box, xb);
    if (k > -20 && onB != previousOnB) {
      ++changes;
      // The points (in either order) at the same places carry the same ids.
      for (int i = 0; i < 2; ++i) {
        const ManifoldPoint& p = m.points[static_cast<std::size_t>(i)];
        const ManifoldPoint& q =
            length(p.point - previous.points[0].point) < 1e-3f ? previous.points[0] : previous.points[1];
        ASSERT_LT(length(p.point - q.point), 1e-3f) << k;
        EXPECT_EQ(p.id, q.id) << k;
      }
    }
    previous = m;
    previousOnB = onB;
  }
  EXPECT_GE(changes, 1); // the sweep did cross from one box's face to the other's
}

TEST(Manifold, tilted_box_touches_with_one_corner) {
  const Polygon ground = makeBox(5.0f, 0.5f);
  const Polygon box = makeBox(0.5f, 0.5f);
  const float half = 0.5f * std::sqrt(2.0f); // corner distance at 45 degrees
  const Manifold m = collidePolygons(ground, at(0, 0), box, at(0, 0.5f + half - 0.01f, pi<float> / 4));
  ASSERT_EQ(m.pointCount, 1);
  EXPECT_NEAR(m.points[0].separation, -0.01f, 1e-5f);
  EXPECT_NEAR(m.points[0].point.x, 0.0f, 1e-5f);
}

TEST(Manifold, polygon_and_circle_face_and_vertex_regions) {
  const Polygon box = makeBox(1.0f, 1.0f);
  const Circle ball{{0, 0}, 0.5f};
  const Manifold face = collidePolygonAndCircle(box, at(0, 0), ball, at(0.3f, 1.4f));
  ASSERT_EQ(face.pointCount, 1);
  EXPECT_NEAR(face.normal.y, 1.0f, 1e-6f);
  EXPECT_NEAR(face.points[0].separation, -0.1f, 1e-6f);
  // Off the corner: the normal points from the corner to the centre.
  const Manifold corner = collidePolygonAndCircle(box, at(0, 0), ball, at(1.3f, 1.3f));
  ASSERT_EQ(corner.pointCount, 1);
  EXPECT_NEAR(corner.normal.x, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(corner.points[0].separation, std::sqrt(0.18f) - 0.5f, 1e-6f);
}

TEST(Manifold, parallel_capsules_touch_along_a_segment) {
  const Polygon capsule = asPolygon(Capsule{{-1, 0}, {1, 0}, 0.25f});
  const Manifold m = collidePolygons(capsule, at(0, 0), capsule, at(0.5f, 0.49f));
  ASSERT_EQ(m.pointCount, 2);
  EXPECT_NEAR(std::abs(m.normal.y), 1.0f, 1e-6f);
  EXPECT_NEAR(m.points[0].separation, -0.01f, 1e-5f);
  EXPECT_NEAR(m.points[1].separation, -0.01f, 1e-5f);
}

// A reference in double precision, in world coordinates: the signed distance between two
// polygons' cores (2-vertex ones for capsules and segments) and its direction, computed apart
// from the narrowphase. Apart, the distance is the least between a vertex of one and an edge of
// the other (two segments that do not cross are closest at an end of one of them), and the
// direction is the line between those points; overlapping, it is minus the depth along the best
// separating axis: the edge normals of both and, for a segment, its direction both ways (the
// axis two segments on one line need).
struct CoreReference {
  double signedDistance = 0.0; ///< of the cores; less both radii for the shapes'
  Vec2d direction;             ///< unit, from A to B: the closest points' line, or the best axis
};

std::vector<Vec2d> worldCore(const Polygon& p, const Transform2f& xf) {
  std::vector<Vec2d> v;
  for (int i = 0; i < p.count; ++i) {
    const Vec2f l = p.vertices[static_cast<std::size_t>(i)];
    const double c = xf.q.c;
    const double s = xf.q.s;
    v.emplace_back(c * l.x - s * l.y + xf.p.x, s * l.x + c * l.y + xf.p.y);
  }
  return v;
}

CoreReference coreReference(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB) {
  const std::vector<Vec2d> va = worldCore(a, xfA);
  const std::vector<Vec2d> vb = worldCore(b, xfB);
  const auto edges = [](const std::vector<Vec2d>& v) {
    std::vector<std::array<Vec2d, 2>> e;
    for (std::size_t i = 0; i < (v.size() == 2 ? 1 : v.size()); ++i) {
      e.push_back({v[i], v[(i + 1) % v.size()]});
    }
    return e;
  };
  // The best separating axis (from A to B).
  CoreReference best{-1e300, {}};
  for (const std::vector<Vec2d>* k : {&va, &vb}) {
    for (const auto& e : edges(*k)) {
      const Vec2d d = e[1] - e[0];
      const double l = length(d);
      std::vector<Vec2d> axes{Vec2d{d.y / l, -d.x / l}, Vec2d{-d.y / l, d.x / l}};
      if (k->size() == 2) {
        axes.push_back(d * (1.0 / l));
        axes.push_back(d * (-1.0 / l));
      }
      for (const Vec2d& u : axes) {
        double maxA = -1e300;
        double minB = 1e300;
        for (const Vec2d& p : va) {
          maxA = std::max(maxA, dot(u, p));
        }
        for (const Vec2d& q : vb) {
          minB = std::min(minB, dot(u, q));
        }
        if (minB - maxA > best.signedDistance) {
          best = {minB - maxA, u};
        }
      }
    }
  }
  if (best.signedDistance <= 0.0) {
    return best;
  }
  // Apart: the closest vertex-edge pair.
  const auto closestOnSegment = [](Vec2d p, Vec2d e0, Vec2d e1) {
    const Vec2d d = e1 - e0;
    const double t = std::clamp(dot(p - e0, d) / dot(d, d), 0.0, 1.0);
    return e0 + d * t;
  };
  CoreReference apart{1e300, {}};
  const auto consider = [&](Vec2d onA, Vec2d onB) {
    const double distance = length(onB - onA);
    if (distance < apart.signedDistance) {
      apart = {distance, (onB - onA) * (1.0 / distance)};
    }
  };
  for (const auto& ea : edges(va)) {
    for (const auto& eb : edges(vb)) {
      for (const Vec2d& p : ea) {
        consider(p, closestOnSegment(p, eb[0], eb[1]));
      }
      for (const Vec2d& q : eb) {
        consider(closestOnSegment(q, ea[0], ea[1]), q);
      }
    }
  }
  return apart;
}

float deepestSeparation(const Manifold& m) {
  float d = std::numeric_limits<float>::max();
  for (int i = 0; i < m.pointCount; ++i) {
    d = std::min(d, m.points[static_cast<std::size_t>(i)].separation);
  }
  return d;
}

/// The manifold of A against B, and of B against A, against the reference: a point, the
/// deepest at the signed distance (1e-5 m), a unit normal along the reference direction
/// (1e-4), and B against A the same with the normal reversed.
void expectReferenceContact(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB) {
  const CoreReference ref = coreReference(a, xfA, b, xfB);
  const double expected = ref.signedDistance - a.radius - b.radius;
  ASSERT_LT(expected, speculativeDistance);
  const Manifold ab = collidePolygons(a, xfA, b, xfB);
  const Manifold ba = collidePolygons(b, xfB, a, xfA);
  ASSERT_GT(ab.pointCount, 0);
  ASSERT_GT(ba.pointCount, 0);
  EXPECT_NEAR(deepestSeparation(ab), expected, 1e-5);
  EXPECT_NEAR(deepestSeparation(ba), expected, 1e-5);
  EXPECT_NEAR(length(ab.normal), 1.0f, 1e-6f);
  EXPECT_NEAR(length(ba.normal), 1.0f, 1e-6f);
  EXPECT_NEAR(ab.normal.x, ref.direction.x, 1e-4);
  EXPECT_NEAR(ab.normal.y, ref.direction.y, 1e-4);
  EXPECT_NEAR(ba.normal.x, -ref.direction.x, 1e-4);
  EXPECT_NEAR(ba.normal.y, -ref.direction.y, 1e-4);
  for (const Manifold* m : {&ab, &ba}) {
    for (int i = 0; i < m->pointCount; ++i) {
      const ManifoldPoint& mp = m->points[static_cast<std::size_t>(i)];
      EXPECT_TRUE(isFinite(mp.point) && std::isfinite(mp.separation));
      EXPECT_LE(mp.separation, speculativeDistance);
    }
  }
}

// The fuzzer's finding 5 (docs/reliability.md; tests/fuzz/regressions/narrowphase/corner-*,
// clip-*): where the incident edge lay wholly beyond a side plane of the reference face the clip
// returned no point, and the corner path ran only for cores more than 0.1 linearSlop apart
// whose closest points were exactly (== on clamped parameters) two vertices.
TEST(Manifold, capsules_end_to_end_in_line_touch_along_the_line) {
  // Radius 0.25, cores 0.1 m apart on the x axis: the rounded ends overlap by 0.4 m.
  const Polygon a = asPolygon(Capsule{{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f});
  const Polygon b = asPolygon(Capsule{{0.6f, 0.0f}, {1.5f, 0.0f}, 0.25f});
  expectReferenceContact(a, at(0, 0), b, at(0, 0));
  const Manifold m = collidePolygons(a, at(0, 0), b, at(0, 0));
  ASSERT_EQ(m.pointCount, 1);
  EXPECT_NEAR(m.points[0].separation, -0.4f, 1e-6f);
  EXPECT_NEAR(m.normal.x, 1.0f, 1e-6f);
  EXPECT_NEAR(m.points[0].point.x, 0.55f, 1e-6f); // midway between the two surfaces
  // The same pair turned and moved, B's ends swapped, and nearly (1 mrad) in line.
  expectReferenceContact(a, at(3.0f, -2.0f, 0.7f), asPolygon(Capsule{{1.5f, 0.0f}, {0.6f, 0.0f}, 0.25f}),
                         at(3.0f, -2.0f, 0.7f));
  expectReferenceContact(a, at(0, 0), b, {{0.0f, 0.0f}, Rot2f::fromAngle(1e-3f)});
  // Cores touching (0.1 mm apart) and overlapping by 0.2 m end to end: still a contact.
  expectReferenceContact(a, at(0, 0), b, at(-0.0999f, 0));
  const Manifold overlapping = collidePolygons(a, at(0, 0), b, at(-0.3f, 0));
  ASSERT_GT(overlapping.pointCount, 0);
  EXPECT_LE(deepestSeparation(overlapping), -0.5f + 1e-5f);
}

TEST(Manifold, capsules_in_an_l_and_a_capsule_on_a_box_corner_touch_at_the_corner) {
  // The fuzzer's inputs: a capsule along x whose end is 0.2 mm left of and 0.3 mm above the top
  // of a capsule along -y, or the corner of a box below and right of it (cores 0.36 mm apart).
  const Polygon horizontal = asPolygon(Capsule{{-0.5f, 0.0003f}, {-0.0002f, 0.0003f}, 0.1f});
  const Polygon vertical = asPolygon(Capsule{{0.0f, 0.0f}, {0.0f, -0.4f}, 0.1f});
  const Polygon box = makeOffsetBox(0.2f, 0.2f, {0.2f, -0.2f}, 0.0f);
  expectReferenceContact(horizontal, at(0, 0), vertical, at(0, 0));
  expectReferenceContact(horizontal, at(0, 0), box, at(0, 0));
  const Manifold l = collidePolygons(horizontal, at(0, 0), vertical, at(0, 0));
  ASSERT_EQ(l.pointCount, 1);
  const double gap = std::hypot(0.0002, 0.0003);
  EXPECT_NEAR(l.points[0].separation, gap - 0.2, 1e-6);
  EXPECT_NEAR(l.normal.x, 0.0002 / gap, 1e-3); // the cores' line: 0.36 mm at float precision
  EXPECT_NEAR(l.normal.y, -0.0003 / gap, 1e-3);
  // Found by the fuzzer: a capsule along x starting 2.3 cm right of a 25.6 m box's corner, its
  // start a rounding (38 um, the side tolerance there) above the box's top: the vertex test and
  // the clip measured that distance in different roundings, and the clip moved the start along
  // the capsule onto the plane, 0.75 m out, beyond reach.
  expectReferenceContact(makeBox(12.7841587f, 12.784276f), at(1000.0f, -1000.0f),
                         asPolygon(Capsule{{12.8076162f, 12.7843142f}, {19.9999809f, 12.7839546f}, 0.5f}),
                         at(1000.0f, -1000.0f));
  // Farther apart, turned, and resting on the corner with the capsule's rounded end 2 cm deep.
  for (const Vec2f end : {Vec2f{-0.05f, 0.05f}, Vec2f{-0.03f, 0.09f}, Vec2f{-0.09f, 0.02f}}) {
    const Polygon capsule = asPolygon(Capsule{end - Vec2f{0.6f, 0.0f}, end, 0.1f});
    expectReferenceContact(capsule, at(1.0f, 2.0f, 0.3f), vertical, at(1.0f, 2.0f, 0.3f));
    expectReferenceContact(capsule, at(1.0f, 2.0f, -2.0f), box, at(1.0f, 2.0f, -2.0f));
    const Polygon tilted = asPolygon(Capsule{end, end + Vec2f{-0.5f, 0.3f}, 0.1f});
    expectReferenceContact(tilted, at(0, 0), box, at(0, 0));
    expectReferenceContact(tilted, at(0, 0), vertical, at(0, 0));
  }
}

TEST(Manifold, a_sliver_inside_a_rounded_polygon_has_a_contact) {
  // The fuzzer's input: a thin triangle (radius 0.3) whose incident edge lies below the lower
  // end of the reference face of a hexagon of radius 1, overlapping it by 1.4 m.
  const std::array<Vec2f, 6> hexagon{Vec2f{-0.988220453f, 1.015625f},    Vec2f{-0.936462104f, 0.0f},
                                     Vec2f{-0.807843149f, -0.80784297f}, Vec2f{0.0f, -0.807843149f},
                                     Vec2f{2.0f, -0.437499911f},         Vec2f{2.0f, 2.0f}};
  const std::array<Vec2f, 3> sliver{Vec2f{1.98492444f, -0.0875478685f}, Vec2f{1.98854673f, -0.608499229f},
                                    Vec2f{2.0f, 2.0f}};
  const Polygon a = makePolygon(hexagon, 1.0f);
  const Polygon b = makePolygon(sliver, 0.301960796f);
  const Transform2f xfA{{-1.20784283f, 3.99859214f}, Rot2f{0.861115217f, -0.508409858f}};
  const Transform2f xfB{{-1.47450948f, 3.73192549f}, Rot2f{0.861117184f, -0.508406579f}};
  const CoreReference ref = coreReference(a, xfA, b, xfB);
  const double expected = ref.signedDistance - a.radius - b.radius;
  EXPECT_NEAR(expected, -1.41097784, 1e-6);
  for (const bool swapped : {false, true}) {
    const Manifold m = swapped ? collidePolygons(b, xfB, a, xfA) : collidePolygons(a, xfA, b, xfB);
    ASSERT_GT(m.pointCount, 0) << swapped;
    // Both sides' best faces are within the 0.1 linearSlop hysteresis of the reference face
    // choice (the sliver's long edges are nearly parallel to the hexagon's face): A's face
    // and B's may be taken, each at its own depth.
    EXPECT_NEAR(deepestSeparation(m), expected, 0.1 * linearSlop) << swapped;
    EXPECT_GE(deepestSeparation(m), expected - 0.1 * linearSlop - 1e-5) << swapped;
    EXPECT_NEAR(length(m.normal), 1.0f, 1e-6f);
    const Vec2f towardB = swapped ? -m.normal : m.normal;
    EXPECT_GT(towardB.x * ref.direction.x + towardB.y * ref.direction.y, 0.999) << swapped;
  }
}

// Found by the fuzzer while fixing finding 5: within the 0.1 linearSlop hysteresis the
// reference face need not be the best face, and neither the closest points nor a fair clip
// come from it.
TEST(Manifold, apart_cores_within_the_face_hysteresis_touch_at_their_closest_points) {
  // A segment's end 34 um from a triangle's face, the segment's own face (separation -0.1 mm,
  // within the hysteresis of the triangle's +34 um) taken as the reference: the closest points
  // (the segment's end, the triangle's face) are not on its incident edge, whose vertex is
  // 88 um away.
  const Polygon segment = asPolygon(Segment{{0.0f, 0.0f}, {0.120781235f, -8.80821026e-05f}});
  const std::array<Vec2f, 3> corners{Vec2f{-0.0799999759f, -8.80147854e-05f}, Vec2f{-8.80807638e-05f, 0.0f},
                                     Vec2f{0.119731449f, 0.05f}};
  const Polygon triangle = makePolygon(corners, 0.0f);
  expectReferenceContact(segment, at(0, 0), triangle, at(0, 0));
  expectReferenceContact(segment, at(2.0f, 1.0f, 1.0f), triangle, at(2.0f, 1.0f, 1.0f));
  // A capsule along x whose end is 0.45 mm from a tilted capsule's core (76 degrees to it):
  // clipped on the first one's side (its separation 0, within the hysteresis of the second's
  // 0.45 mm), the contact was 1.4 mm shallow.
  const Polygon a = asPolygon(Capsule{{-0.500488281f, 0.0f}, {0.5f, 0.0f}, 0.25f});
  const Polygon b = asPolygon(Capsule{{-0.500951469f, 0.0f}, {0.0f, 2.0f}, 0.999969482f});
  expectReferenceContact(a, at(0, 0), b, at(0, 0));
  expectReferenceContact(a, at(-3.0f, 4.0f, 2.5f), b, at(-3.0f, 4.0f, 2.5f));
}

// Capsules against capsules and boxes at random, within reach: where the cores are apart, the
// deepest point is at the true signed distance (double precision) along the true direction;
// where they overlap, there is a contact no deeper than the best axis' depth (less the 0.1
// linearSlop hysteresis of the reference face).
TEST(Manifold, capsule_and_box_pairs_match_the_double_reference) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * unit(rng); };
  int apart = 0;
  int overlapping = 0;
  int vertexContacts = 0;
  double worstSeparation = 0.0;
  double worstNormal = 0.0;
  for (int trial = 0; trial < 20000; ++trial) {
    const auto capsule = [&] {
      const float half = uniform(0.05f, 1.0f);
      const float angle = uniform(-3.2f, 3.2f);
      const Vec2f axis{half * std::cos(angle), half * std::sin(angle)};
      const Vec2f center{uniform(-0.3f, 0.3f), uniform(-0.3f, 0.3f)};
      return asPolygon(Capsule{center - axis, center + axis, uniform(0.01f, 0.4f)});
    };
    const Polygon a = capsule();
    Polygon b;
    switch (trial % 3) {
    case 0:
      b = capsule();
      break;
    case 1:
      b = makeBox(uniform(0.05f, 1.0f), uniform(0.05f, 1.0f));
      break;
    default: {
      const Polygon box =
          makeOffsetBox(uniform(0.05f, 1.0f), uniform(0.05f, 1.0f), {uniform(-0.3f, 0.3f), 0.0f}, uniform(-1.0f, 1.0f));
      b = makePolygon(std::span<const Vec2f>(box.vertices.data(), 4), uniform(0.0f, 0.2f));
      break;
    }
    }
    const Transform2f xfA{{uniform(-5, 5), uniform(-5, 5)}, Rot2f::fromAngle(uniform(-3.2f, 3.2f))};
    // Now and then exactly in line with A (end to end, or at a box's face).
    const float angleB = trial % 7 == 0 ? 0.0f : uniform(-3.2f, 3.2f);
    const Transform2f xfB{transformPoint(xfA, {uniform(-2.5f, 2.5f), trial % 7 == 0 ? 0.0f : uniform(-2.5f, 2.5f)}),
                          trial % 7 == 0 ? xfA.q : Rot2f::fromAngle(angleB)};
    const CoreReference ref = coreReference(a, xfA, b, xfB);
    const double expected = ref.signedDistance - a.radius - b.radius;
    const Manifold ab = collidePolygons(a, xfA, b, xfB);
    const Manifold ba = collidePolygons(b, xfB, a, xfA);
    if (ref.signedDistance > 1e-4) {
      if (std::abs(expected - speculativeDistance) < 1e-5) {
        continue;
      }
      ASSERT_EQ(ab.pointCount > 0, expected < speculativeDistance) << trial;
      ASSERT_EQ(ba.pointCount > 0, expected < speculativeDistance) << trial;
      if (ab.pointCount == 0) {
        continue;
      }
      ++apart;
      vertexContacts += (ab.points[0].id & 0x4000) == 0 && (ab.points[0].id & 0xF) >= 10 ? 1 : 0;
      for (const Manifold* m : {&ab, &ba}) {
        const double sign = m == &ab ? 1.0 : -1.0;
        worstSeparation = std::max(worstSeparation, std::abs(deepestSeparation(*m) - expected));
        worstNormal = std::max(worstNormal,
                               std::hypot(m->normal.x - sign * ref.direction.x, m->normal.y - sign * ref.direction.y));
        EXPECT_NEAR(deepestSeparation(*m), expected, 1e-5) << trial;
        EXPECT_NEAR(m->normal.x, sign * ref.direction.x, 1e-3) << trial;
        EXPECT_NEAR(m->normal.y, sign * ref.direction.y, 1e-3) << trial;
      }
    } else if (ref.signedDistance < -1e-4) {
      ++overlapping;
      for (const Manifold* m : {&ab, &ba}) {
        ASSERT_GT(m->pointCount, 0) << trial;
        EXPECT_GE(deepestSeparation(*m), expected - 0.1 * linearSlop - 1e-5) << trial;
      }
    }
    if (HasFailure()) {
      return;
    }
  }
  std::printf("apart %d (vertex contacts %d), overlapping %d; apart: worst separation error %.3g m, normal %.3g\n",
              apart, vertexContacts, overlapping, worstSeparation, worstNormal);
  EXPECT_GT(apart, 1500);
  EXPECT_GT(vertexContacts, 300);
  EXPECT_GT(overlapping, 1500);
}

// Found by the fuzzer (regressions/narrowphase/circle-on-segment-axis-far-from-origin): a
// circle on a segment's line, 3.9 cm beyond its end, 100 m from the origin: both faces'
// separations rounded below 0 and the centre counted as over the segment (a contact at -1 mm
// where the shapes are 3.8 cm apart).
TEST(Manifold, a_circle_on_a_segments_line_beyond_its_end_is_at_the_end) {
  const Polygon segment = asPolygon(Segment{{1.99999976f, 2.0f}, {0.0f, 0.0f}});
  const Transform2f far{{100.0f, -100.0f}, Rot2f{}};
  const Circle small{{-0.0274509806f, -0.0274509806f}, 0.00100011879f};
  EXPECT_EQ(collidePolygonAndCircle(segment, far, small, far).pointCount, 0);
  // Within reach: the end's distance, along the line.
  const Circle near{{-0.01f, -0.01f}, 0.01f};
  const Manifold m = collidePolygonAndCircle(segment, far, near, far);
  ASSERT_EQ(m.pointCount, 1);
  EXPECT_NEAR(m.points[0].separation, std::sqrt(2e-4) - 0.01, 1e-5);
  EXPECT_NEAR(m.normal.x, -std::sqrt(0.5f), 1e-4f);
  EXPECT_NEAR(m.normal.y, -std::sqrt(0.5f), 1e-4f);
}

// The fuzzer's finding 7 (regressions/narrowphase/tiny-normal-circles): centres closer than
// about 1e-19 m gave a "normal" of length 0.98 (the squared distance underflows). Below 1e-9 m
// the normal is a defined one: (0, 1) for circles, the face's for a polygon's vertex.
TEST(Manifold, normals_from_nearly_coincident_points_are_unit_vectors) {
  const Circle tiny{{0.0f, 0.0f}, 0.001f};
  const Circle nearby{{2.23535131e-41f, -6.36929072e-23f}, 0.001f};
  const Manifold m = collideCircles(tiny, at(0, 2.27038377e-41f, 0.0588379f), nearby, at(0, 2.27038377e-41f));
  ASSERT_EQ(m.pointCount, 1);
  EXPECT_EQ(m.normal, (Vec2f{0.0f, 1.0f}));
  EXPECT_NEAR(m.points[0].separation, -0.002f, 1e-9f);
  for (const float d : {1e-30f, 1e-20f, 1e-12f, 1e-9f, 2e-9f, 1e-6f}) {
    const float offset = std::sqrt(2.0f) * d; // the centres' distance
    const Manifold c = collideCircles(Circle{{0, 0}, 0.5f}, at(0, 0), Circle{{0, 0}, 0.5f}, at(d, d));
    ASSERT_EQ(c.pointCount, 1);
    EXPECT_NEAR(length(c.normal), 1.0f, 1e-6f) << d;
    EXPECT_NEAR(c.points[0].separation, offset - 1.0f, 1e-6f) << d;
    // A circle centred on (or 1e-30 to 1e-6 m off) a box's corner, and on a capsule's end.
    const Polygon box = makeBox(0.5f, 0.5f);
    const Manifold corner = collidePolygonAndCircle(box, at(0, 0), Circle{{0, 0}, 0.1f}, at(0.5f + d, 0.5f + d));
    ASSERT_EQ(corner.pointCount, 1);
    EXPECT_NEAR(length(corner.normal), 1.0f, 1e-6f) << d;
    EXPECT_NEAR(corner.points[0].separation, offset - 0.1f, 1e-6f) << d;
    const Polygon capsule = asPolygon(Capsule{{-1.0f, 0.0f}, {0.0f, 0.0f}, 0.2f});
    const Manifold end = collidePolygonAndCircle(capsule, at(0, 0), Circle{{0, 0}, 0.1f}, at(d, -d));
    ASSERT_EQ(end.pointCount, 1);
    EXPECT_NEAR(length(end.normal), 1.0f, 1e-6f) << d;
    EXPECT_NEAR(end.points[0].separation, offset - 0.3f, 1e-6f) << d;
  }
}

// Swapping A and B flips the normal and keeps the separations.
TEST(Manifold, swapping_the_shapes_flips_the_normal) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int touching = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const Polygon a = makeOffsetBox(0.6f, 0.3f, {}, u(rng));
    const Polygon b = asPolygon(Capsule{{-0.4f, 0.0f}, {0.4f, 0.1f}, 0.2f});
    const Transform2f xa = at(u(rng) * 0.2f, u(rng) * 0.2f, u(rng) * 3.0f);
    const Transform2f xb = at(u(rng), u(rng), u(rng) * 3.0f);
    const Manifold ab = collidePolygons(a, xa, b, xb);
    const Manifold ba = collidePolygons(b, xb, a, xa);
    ASSERT_EQ(ab.pointCount > 0, ba.pointCount > 0) << trial;
    if (ab.pointCount == 0) {
      continue;
    }
    ++touching;
    // Deep overlaps (which the solver never lets happen) can have two near-equal faces, and
    // the reference face prefers A within 0.1 linearSlop for frame-to-frame stability: there
    // the two orders may pick different faces. Below 5 cm of overlap they must agree.
    if (std::min(ab.points[0].separation, ab.pointCount > 1 ? ab.points[1].separation : 0.0f) < -0.05f) {
      continue;
    }
    EXPECT_NEAR(dot(ab.normal, ba.normal), -1.0f, 1e-4f) << trial;
    float minAB = 1e9f, minBA = 1e9f;
    for (int i = 0; i < ab.pointCount; ++i) {
      minAB = std::min(minAB, ab.points[static_cast<std::size_t>(i)].separation);
      EXPECT_TRUE(isFinite(ab.points[static_cast<std::size_t>(i)].point));
    }
    for (int i = 0; i < ba.pointCount; ++i) {
      minBA = std::min(minBA, ba.points[static_cast<std::size_t>(i)].separation);
    }
    EXPECT_NEAR(minAB, minBA, 1e-4f) << trial;
  }
  EXPECT_GT(touching, 50);
}

// collidePolygons' shortcuts (two plain boxes; an axis-aligned rectangle against anything) must
// give the general path's manifold: the same points, features and reference face, and the same
// floats within 1e-5 of the scale. The shortcuts are built to run the same float operations
// as the general path (fewer of them), so in fact not one float may differ: counted apart.
struct ShortcutChecker {
  int checked = 0;
  std::array<int, 3> pointCounts{};
  int flipped = 0; // B's face is the reference
  int clipped = 0; // a point on a side plane of the reference face (unrounded shapes)
  int corners = 0; // cores apart: vertex against vertex (ids 10, 11)
  int inexact = 0; // some float differs (by the design, none: the same operations run)

  void check(const Polygon& a, const Transform2f& xa, const Polygon& b, const Transform2f& xb, detail::PolygonPath path,
             int trial) {
    ASSERT_EQ(detail::polygonPath(a, b), path) << trial;
    const Manifold fast = collidePolygons(a, xa, b, xb);
    const Manifold general = detail::collidePolygonsGeneral(a, xa, b, xb);
    ASSERT_EQ(fast.pointCount, general.pointCount) << trial;
    ++checked;
    bool same = fast.pointCount == 0 || fast.normal == general.normal;
    for (std::size_t i = 0; i < static_cast<std::size_t>(fast.pointCount); ++i) {
      const ManifoldPoint& f = fast.points[i];
      const ManifoldPoint& g = general.points[i];
      same = same && f.point == g.point && f.anchorA == g.anchorA && f.anchorB == g.anchorB &&
             f.separation == g.separation;
    }
    inexact += same ? 0 : 1;
    ++pointCounts[static_cast<std::size_t>(fast.pointCount)];
    if (fast.pointCount == 0) {
      return;
    }
    const float scale = std::max({1.0f, std::abs(xa.p.x), std::abs(xa.p.y), std::abs(xb.p.x), std::abs(xb.p.y)});
    const float tolerance = 1e-5f * scale;
    EXPECT_NEAR(fast.normal.x, general.normal.x, 1e-5f) << trial;
    EXPECT_NEAR(fast.normal.y, general.normal.y, 1e-5f) << trial;
    for (std::size_t i = 0; i < static_cast<std::size_t>(fast.pointCount); ++i) {
      const ManifoldPoint& f = fast.points[i];
      const ManifoldPoint& g = general.points[i];
      EXPECT_EQ(f.id, g.id) << trial;
      EXPECT_NEAR(f.separation, g.separation, tolerance) << trial;
      EXPECT_NEAR(f.point.x, g.point.x, tolerance) << trial;
      EXPECT_NEAR(f.point.y, g.point.y, tolerance) << trial;
      EXPECT_NEAR(f.anchorA.x, g.anchorA.x, tolerance) << trial;
      EXPECT_NEAR(f.anchorA.y, g.anchorA.y, tolerance) << trial;
      EXPECT_NEAR(f.anchorB.x, g.anchorB.x, tolerance) << trial;
      EXPECT_NEAR(f.anchorB.y, g.anchorB.y, tolerance) << trial;
      const bool onePointContact = (f.id & 0x4000) == 0;
      corners += onePointContact && (f.id & 0xf) >= 10 ? 1 : 0;
      if (!onePointContact && a.radius == 0.0f && b.radius == 0.0f) {
        const bool onB = referenceIsB(fast, a, xa, b, xb);
        clipped += atNoCorner(f, onB ? a : b, onB ? xa : xb, tolerance) ? 1 : 0;
      }
    }
    flipped += fast.pointCount > 0 && (fast.points[0].id & 0x4000) != 0 && referenceIsB(fast, a, xa, b, xb) ? 1 : 0;
  }
};

/// A rotation by `quarterTurns` right angles, exactly ((1, 0), (0, 1), ...; Rot2f::fromAngle is
/// off by a rounding), then by `angle` more.
Rot2f quarterTurnsAnd(int quarterTurns, float angle) {
  constexpr std::array<Rot2f, 4> exact{Rot2f{1, 0}, Rot2f{0, 1}, Rot2f{-1, 0}, Rot2f{0, -1}};
  const Rot2f q = exact[static_cast<std::size_t>(quarterTurns & 3)];
  return angle == 0.0f ? q : mul(q, Rot2f::fromAngle(angle));
}

TEST(Manifold, box_shortcut_matches_the_general_path) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * unit(rng); };
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  ShortcutChecker checker;
  for (int trial = 0; trial < 40000; ++trial) {
    // Sizes 0.05 to 5 m (log-uniform); three pairs in eight equal boxes, one of them the
    // pyramid's 0.5 m boxes.
    const int kind = pick(8);
    const bool pyramid = kind == 0;
    const float ax = pyramid ? 0.5f : std::exp(uniform(std::log(0.05f), std::log(5.0f)));
    const float ay = pyramid ? 0.5f : std::exp(uniform(std::log(0.05f), std::log(5.0f)));
    const bool equal = pyramid || kind < 3;
    const float bx = equal ? ax : std::exp(uniform(std::log(0.05f), std::log(5.0f)));
    const float by = equal ? ay : std::exp(uniform(std::log(0.05f), std::log(5.0f)));
    // A: a plain box, centred or not (makeOffsetBox at angle 0); B: makeBox.
    const Vec2f aCenter = pick(3) == 0 ? Vec2f{uniform(-1, 1), uniform(-1, 1)} : Vec2f{};
    const Polygon a = aCenter == Vec2f{} ? makeBox(ax, ay) : makeOffsetBox(ax, ay, aCenter, 0.0f);
    const Polygon b = makeBox(bx, by);
    // Relative rotation: exact right angles, right angles and a hair, or anything.
    float hair = 0.0f;
    switch (pick(4)) {
    case 0:
      break;
    case 1:
      hair = uniform(-1e-3f, 1e-3f);
      break;
    case 2:
      hair = uniform(-1e-6f, 1e-6f);
      break;
    default:
      hair = uniform(-0.8f, 0.8f);
      break;
    }
    const Rot2f relative = quarterTurnsAnd(pick(4), hair);
    // A anywhere (at exactly 0 now and then), B placed in A's frame.
    const Transform2f xa =
        pick(4) == 0 ? Transform2f{{uniform(-50, 50), uniform(-50, 50)}, Rot2f{}}
                     : Transform2f{{uniform(-50, 50), uniform(-50, 50)}, Rot2f::fromAngle(uniform(-3.2f, 3.2f))};
    // B's half-extents along A's axes (exact at right angles).
    const bool turned = (std::abs(relative.s) > std::abs(relative.c));
    const float reachX = turned ? by : bx;
    const float reachY = turned ? bx : by;
    Vec2f offset;
    const float depth = std::min({ax, ay, bx, by});
    const float gap = pick(4) == 0 ? 0.0f : uniform(-0.6f * depth, 2.0f * speculativeDistance);
    switch (pick(4)) {
    case 0: // side by side (the pyramid's rows: exactly touching when gap is 0)
      offset = {(pick(2) == 0 ? 1.0f : -1.0f) * (ax + reachX + gap),
                pyramid ? 0.0f : uniform(-(ay + reachY), ay + reachY)};
      break;
    case 1: // stacked (the pyramid: half a box to the side)
      offset = {pyramid ? (pick(2) == 0 ? 0.5f : -0.5f) : uniform(-(ax + reachX), ax + reachX),
                (pick(2) == 0 ? 1.0f : -1.0f) * (ay + reachY + gap)};
      break;
    case 2: // corner to corner
      offset = {(pick(2) == 0 ? 1.0f : -1.0f) * (ax + reachX + gap),
                (pick(2) == 0 ? 1.0f : -1.0f) * (ay + reachY + gap)};
      break;
    default: // anywhere from deep overlap to out of reach
      offset = {uniform(-1.2f, 1.2f) * (ax + reachX + 2.0f * speculativeDistance),
                uniform(-1.2f, 1.2f) * (ay + reachY + 2.0f * speculativeDistance)};
      break;
    }
    if (pick(3) == 0) { // a hair off the exact arrangement
      offset += Vec2f{uniform(-1e-4f, 1e-4f), uniform(-1e-4f, 1e-4f)};
    }
    offset += aCenter;
    const Transform2f xb{transformPoint(xa, offset), mul(xa.q, relative)};
    checker.check(a, xa, b, xb, detail::PolygonPath::boxes, trial);
    if (HasFatalFailure()) {
      return;
    }
  }
  EXPECT_EQ(checker.inexact, 0);
  // Every branch of the clip was taken, many times.
  EXPECT_GT(checker.pointCounts[0], 1000);
  EXPECT_GT(checker.pointCounts[1], 1000);
  EXPECT_GT(checker.pointCounts[2], 1000);
  EXPECT_GT(checker.flipped, 1000);
  EXPECT_GT(checker.clipped, 1000);
  EXPECT_GT(checker.corners, 10);
}

TEST(Manifold, rectangle_shortcut_matches_the_general_path) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * unit(rng); };
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  ShortcutChecker checker;
  for (int trial = 0; trial < 20000; ++trial) {
    const float ax = uniform(0.05f, 3.0f);
    const float ay = uniform(0.05f, 3.0f);
    // A: an axis-aligned rectangle, rounded now and then (not a plain box then).
    const Polygon plain = makeOffsetBox(ax, ay, {uniform(-0.5f, 0.5f), uniform(-0.5f, 0.5f)}, 0.0f);
    const Polygon a =
        pick(3) == 0 ? makePolygon(std::span<const Vec2f>(plain.vertices.data(), 4), uniform(0.0f, 0.3f)) : plain;
    // B: anything but a centred plain box: an offset or turned box, a rounded box, a convex
    // polygon of 3 to 8 points, a capsule or a segment.
    Polygon b;
    switch (pick(5)) {
    case 0:
      b = makeOffsetBox(uniform(0.05f, 3.0f), uniform(0.05f, 3.0f), {uniform(-1, 1), uniform(-1, 1)},
                        pick(2) == 0 ? 0.0f : uniform(-3, 3));
      break;
    case 1: {
      const Polygon box = makeBox(uniform(0.05f, 3.0f), uniform(0.05f, 3.0f));
      b = makePolygon(std::span<const Vec2f>(box.vertices.data(), 4), uniform(0.01f, 0.3f));
      break;
    }
    case 2: {
      // 3 to 8 points around a circle, each in its own sector: never collinear.
      std::vector<Vec2f> points(static_cast<std::size_t>(3 + pick(6)));
      const float sector = 2.0f * pi<float> / static_cast<float>(points.size());
      for (std::size_t i = 0; i < points.size(); ++i) {
        const float angle = sector * (static_cast<float>(i) + uniform(0.1f, 0.9f));
        const float r = uniform(0.5f, 2.0f);
        points[i] = {r * std::cos(angle), r * std::sin(angle)};
      }
      b = makePolygon(points, pick(2) == 0 ? 0.0f : uniform(0.0f, 0.2f));
      break;
    }
    case 3:
      b = asPolygon(Capsule{{uniform(-1, 1), uniform(-1, 1)}, {uniform(-1, 1), uniform(-1, 1)}, uniform(0.05f, 0.5f)});
      break;
    default:
      b = asPolygon(Segment{{uniform(-1, 1), uniform(-1, 1)}, {uniform(-1, 1), uniform(-1, 1)}});
      break;
    }
    const Transform2f xa{{uniform(-20, 20), uniform(-20, 20)}, Rot2f::fromAngle(uniform(-3.2f, 3.2f))};
    const Rot2f relative = quarterTurnsAnd(pick(4), pick(2) == 0 ? 0.0f : uniform(-0.8f, 0.8f));
    const Vec2f offset{uniform(-1.2f, 1.2f) * (ax + 2.0f), uniform(-1.2f, 1.2f) * (ay + 2.0f)};
    const Transform2f xb{transformPoint(xa, offset), mul(xa.q, relative)};
    checker.check(a, xa, b, xb, detail::PolygonPath::rectangle, trial);
    if (HasFatalFailure()) {
      return;
    }
  }
  EXPECT_EQ(checker.inexact, 0);
  EXPECT_GT(checker.pointCounts[1], 500);
  EXPECT_GT(checker.pointCounts[2], 500);
  EXPECT_GT(checker.flipped, 500);
  EXPECT_GT(checker.corners, 50);
}

TEST(Manifold, polygons_take_the_shortcuts_only_when_they_apply) {
  const Polygon box = makeBox(0.5f, 0.25f);
  const Polygon offset = makeOffsetBox(0.5f, 0.25f, {0.1f, 0.2f}, 0.0f);
  const Polygon turned = makeOffsetBox(0.5f, 0.25f, {}, 0.3f);
  const std::array<Vec2f, 4> corners{Vec2f{-0.5f, -0.25f}, Vec2f{0.5f, -0.25f}, Vec2f{0.5f, 0.25f},
                                     Vec2f{-0.5f, 0.25f}};
  const Polygon rounded = makePolygon(corners, 0.1f);
  const Polygon capsule = asPolygon(Capsule{{-0.5f, 0}, {0.5f, 0}, 0.1f});
  EXPECT_EQ(detail::polygonPath(box, box), detail::PolygonPath::boxes);
  EXPECT_EQ(detail::polygonPath(offset, box), detail::PolygonPath::boxes);
  EXPECT_EQ(detail::polygonPath(box, offset), detail::PolygonPath::rectangle); // B must be centred
  EXPECT_EQ(detail::polygonPath(box, rounded), detail::PolygonPath::rectangle);
  EXPECT_EQ(detail::polygonPath(rounded, box), detail::PolygonPath::rectangle);
  EXPECT_EQ(detail::polygonPath(box, capsule), detail::PolygonPath::rectangle);
  EXPECT_EQ(detail::polygonPath(turned, box), detail::PolygonPath::general);
  EXPECT_EQ(detail::polygonPath(capsule, box), detail::PolygonPath::general);
  // A hand-made polygon that only looks like a box (normals not the axes) takes no shortcut.
  Polygon skewed = box;
  skewed.normals[1] = normalize(Vec2f{1.0f, 0.01f});
  EXPECT_EQ(detail::polygonPath(skewed, box), detail::PolygonPath::general);
  EXPECT_EQ(detail::polygonPath(box, skewed), detail::PolygonPath::rectangle);
}

} // namespace
} // namespace impetus::rigid2d
