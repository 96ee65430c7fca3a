// Fuzzes the narrowphase (include/impetus/rigid2d/manifold.hpp, chain.hpp): a pair of shapes
// (circle, capsule, segment, polygon, box, rounded or not; a chain segment as A) at two
// transforms, built from the fuzzer's bytes with finite values at one of three scales
// (0.1, 1 or 10 m: the world's working range), through the pair dispatch of src/rigid2d/world.cpp.
//
// Checked, for every pair, against a reference computed here in double precision (the exact
// distance between the shapes' cores, or their penetration along the best separating axis):
//  - every manifold: 0 to 2 points; when it has points, a finite unit normal and finite points,
//    separations and anchors (anchorA = point - A's origin, anchorB = point - B's origin), and
//    no separation beyond speculativeDistance (such points are dropped);
//  - a circle against a circle, polygon, capsule or segment: a point exactly when the shapes are
//    within speculativeDistance, at their true signed distance;
//  - two polygons, capsules or segments overlapping by more than linearSlop: a contact (a
//    missed one lets shapes sink through each other); when both have an area, no point deeper
//    than the shapes' actual penetration (the solver would push them apart too hard); when
//    their cores are apart, a point exactly when the shapes are within speculativeDistance, and
//    the deepest at their true signed distance (in either order);
//  - symmetry: A against B and B against A give the same number of points, the same
//    separations and opposite normals. Exempt are the ties the algorithm resolves by the order
//    (both faces within the 0.1 linearSlop hysteresis of collidePolygons, two candidate faces or
//    incident edges equally good, a point at the speculative cut-off), where either answer is
//    right; there only the deepest separation must agree.
// Tolerances scale with the size of the scene (float rounding at that magnitude).
#include "fuzz_support.hpp"

#include <impetus/error.hpp>
#include <impetus/rigid2d/chain.hpp>
#include <impetus/rigid2d/manifold.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace {

using impetus::Transform2f;
using impetus::Vec2d;
using impetus::Vec2f;
using impetus::fuzz::str;
namespace r2 = impetus::rigid2d;

enum class Kind { circle, capsule, segment, polygon, chain };
const char* name(Kind k) {
  switch (k) {
  case Kind::circle:
    return "circle";
  case Kind::capsule:
    return "capsule";
  case Kind::segment:
    return "segment";
  case Kind::polygon:
    return "polygon";
  case Kind::chain:
    break;
  }
  return "chain segment";
}

/// One shape as the world keeps it: its geometry and its collision polygon.
struct Shape {
  Kind kind = Kind::circle;
  r2::Circle circle;
  r2::Polygon polygon; ///< the collision polygon (capsule and segment: 2 vertices)
  r2::ChainSegment chain;
};

std::string describe(const Shape& s, const Transform2f& xf) {
  std::string text = std::string(name(s.kind)) + " at " + str(xf.p) + " rot (" + str(xf.q.c) + ", " + str(xf.q.s) + ")";
  if (s.kind == Kind::circle) {
    return text + " center " + str(s.circle.center) + " radius " + str(s.circle.radius);
  }
  if (s.kind == Kind::chain) {
    return text + " ghost1 " + str(s.chain.ghost1) + " " + str(s.chain.segment.point1) + " -> " +
           str(s.chain.segment.point2) + " ghost2 " + str(s.chain.ghost2);
  }
  text += " radius ";
  text += str(s.polygon.radius);
  text += " vertices";
  for (int i = 0; i < s.polygon.count; ++i) {
    text += " ";
    text += str(s.polygon.vertices[static_cast<std::size_t>(i)]);
  }
  return text;
}

// The pair dispatch of src/rigid2d/world.cpp (collide, collideChain, reversed). -------------

r2::Manifold reversed(r2::Manifold m) {
  m.normal = -m.normal;
  for (auto& p : m.points) {
    std::swap(p.anchorA, p.anchorB);
  }
  return m;
}

bool isLine(const Shape& s) { return s.kind == Kind::segment || s.kind == Kind::chain; }

r2::Manifold collideChain(const Shape& chain, const Transform2f& xfChain, const Shape& other,
                          const Transform2f& xfOther) {
  if (other.kind == Kind::circle) {
    return r2::collideChainSegmentAndCircle(chain.chain, xfChain, other.circle, xfOther);
  }
  if (isLine(other)) {
    return {};
  }
  return r2::collideChainSegmentAndPolygon(chain.chain, xfChain, other.polygon, xfOther);
}

r2::Manifold collide(const Shape& a, const Transform2f& xfA, const Shape& b, const Transform2f& xfB) {
  if (a.kind == Kind::chain) {
    return collideChain(a, xfA, b, xfB);
  }
  if (b.kind == Kind::chain) {
    return reversed(collideChain(b, xfB, a, xfA));
  }
  if (a.kind == Kind::circle && b.kind == Kind::circle) {
    return r2::collideCircles(a.circle, xfA, b.circle, xfB);
  }
  if (b.kind == Kind::circle) {
    return r2::collidePolygonAndCircle(a.polygon, xfA, b.circle, xfB);
  }
  if (a.kind == Kind::circle) {
    return reversed(r2::collidePolygonAndCircle(b.polygon, xfB, a.circle, xfA));
  }
  return r2::collidePolygons(a.polygon, xfA, b.polygon, xfB);
}

// The reference, in double precision, in world coordinates. ----------------------------------

/// A shape's core (its vertices, world frame) and radius.
struct Core {
  std::vector<Vec2d> v;
  double radius = 0.0;
};

Vec2d world(const Transform2f& xf, const Vec2f& p) {
  const double c = xf.q.c;
  const double s = xf.q.s;
  return {c * p.x - s * p.y + xf.p.x, s * p.x + c * p.y + xf.p.y};
}

Core core(const Shape& s, const Transform2f& xf) {
  Core k;
  if (s.kind == Kind::circle) {
    k.v = {world(xf, s.circle.center)};
    k.radius = s.circle.radius;
  } else if (s.kind == Kind::chain) {
    k.v = {world(xf, s.chain.segment.point1), world(xf, s.chain.segment.point2)};
  } else {
    for (int i = 0; i < s.polygon.count; ++i) {
      k.v.push_back(world(xf, s.polygon.vertices[static_cast<std::size_t>(i)]));
    }
    k.radius = s.polygon.radius;
  }
  return k;
}

double pointSegment(Vec2d p, Vec2d a, Vec2d b) {
  const Vec2d ab = b - a;
  const double ab2 = dot(ab, ab);
  const double t = ab2 > 0.0 ? std::clamp(dot(p - a, ab) / ab2, 0.0, 1.0) : 0.0;
  return length(p - (a + ab * t));
}

/// The signed distance between two cores: their distance when apart; when they overlap, minus
/// the depth along the best separating axis. The axes are the edge normals of both cores, both
/// ways, and for a 2-vertex core (a segment, which has no end faces) its direction both ways: a
/// complete set, so the best axis separates exactly when the cores are apart (then the exact
/// distance is the smallest between their edges and vertices), and an axis more never separates
/// what overlaps.
double coreSignedDistance(const Core& a, const Core& b) {
  const auto edges = [](const Core& k) {
    std::vector<std::array<Vec2d, 2>> e;
    if (k.v.size() == 1) {
      e.push_back({k.v[0], k.v[0]});
    } else if (k.v.size() == 2) {
      e.push_back({k.v[0], k.v[1]});
    } else {
      for (std::size_t i = 0; i < k.v.size(); ++i) {
        e.push_back({k.v[i], k.v[(i + 1) % k.v.size()]});
      }
    }
    return e;
  };
  std::vector<Vec2d> axes;
  for (const Core* k : {&a, &b}) {
    for (const auto& e : edges(*k)) {
      const Vec2d d = e[1] - e[0];
      const double l = length(d);
      if (l > 0.0) {
        axes.push_back(Vec2d{d.y, -d.x} * (1.0 / l));
        axes.push_back(Vec2d{-d.y, d.x} * (1.0 / l));
        if (k->v.size() == 2) {
          axes.push_back(d * (1.0 / l));
          axes.push_back(d * (-1.0 / l));
        }
      }
    }
  }
  double best = -std::numeric_limits<double>::max();
  for (const Vec2d& u : axes) {
    double maxA = -std::numeric_limits<double>::max();
    double minB = std::numeric_limits<double>::max();
    for (const Vec2d& p : a.v) {
      maxA = std::max(maxA, dot(u, p));
    }
    for (const Vec2d& q : b.v) {
      minB = std::min(minB, dot(u, q));
    }
    best = std::max(best, minB - maxA);
  }
  if (!axes.empty() && best <= 0.0) {
    return best;
  }
  double distance = std::numeric_limits<double>::max();
  for (const auto& ea : edges(a)) {
    for (const auto& eb : edges(b)) {
      distance = std::min({distance, pointSegment(ea[0], eb[0], eb[1]), pointSegment(ea[1], eb[0], eb[1]),
                           pointSegment(eb[0], ea[0], ea[1]), pointSegment(eb[1], ea[0], ea[1])});
    }
  }
  return distance;
}

/// Separation of B from A's faces (the separating-axis test of collidePolygons, in double):
/// the best face, the runner-up's separation.
struct FaceSeparation {
  double best = -std::numeric_limits<double>::max();
  double second = -std::numeric_limits<double>::max();
  Vec2d normal;
};

FaceSeparation faces(const Shape& a, const Transform2f& xfA, const Core& b) {
  FaceSeparation f;
  for (int i = 0; i < a.polygon.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec2f nl = a.polygon.normals[k];
    const Vec2d n{xfA.q.c * nl.x - xfA.q.s * nl.y, xfA.q.s * nl.x + xfA.q.c * nl.y};
    const Vec2d v = world(xfA, a.polygon.vertices[k]);
    double deepest = std::numeric_limits<double>::max();
    for (const Vec2d& q : b.v) {
      deepest = std::min(deepest, dot(n, q - v));
    }
    if (deepest > f.best) {
      f.second = f.best;
      f.best = deepest;
      f.normal = n;
    } else if (deepest > f.second) {
      f.second = deepest;
    }
  }
  return f;
}

/// The two best dot products of `n` with the other polygon's normals (its incident edge is the
/// most anti-parallel one).
bool incidentTie(const Shape& s, const Transform2f& xf, Vec2d n, double tolerance) {
  double first = std::numeric_limits<double>::max();
  double second = std::numeric_limits<double>::max();
  for (int i = 0; i < s.polygon.count; ++i) {
    const Vec2f nl = s.polygon.normals[static_cast<std::size_t>(i)];
    const double d = dot(n, Vec2d{xf.q.c * nl.x - xf.q.s * nl.y, xf.q.s * nl.x + xf.q.c * nl.y});
    if (d < first) {
      second = first;
      first = d;
    } else if (d < second) {
      second = d;
    }
  }
  return second - first <= tolerance;
}

// Checks. -----------------------------------------------------------------------------------

struct Pair {
  const Shape& a;
  Transform2f xfA;
  const Shape& b;
  Transform2f xfB;
  double scale;     ///< the largest coordinate or size involved, >= 1
  double tolerance; ///< float rounding at that scale, m
  /// The pair in words, for a failure's message (built only then: it is slow).
  [[nodiscard]] std::string text() const { return std::string("A: ") + describe(a, xfA) + "; B: " + describe(b, xfB); }
};

/// A manifold's own validity. The normal is of unit length even between points closer than
/// about 1e-19 m, whose squared distance underflows (regressions/narrowphase/tiny-normal-circles,
/// tiny-normal-chain-circle: below 1e-9 m the narrowphase takes a defined normal instead).
void checkValid(const r2::Manifold& m, const Pair& p, const std::string& order) {
  const auto where = [&] { return p.text() + " (" + order + ")"; };
  FUZZ_CHECK(m.pointCount >= 0 && m.pointCount <= 2, where() + ": " + std::to_string(m.pointCount) + " points");
  if (m.pointCount == 0) {
    return;
  }
  FUZZ_CHECK(isFinite(m.normal) && std::abs(length(m.normal) - 1.0f) <= 1e-4f,
             where() + ": normal " + str(m.normal) + " is not a unit vector");
  const Transform2f& xfA = order == "A, B" ? p.xfA : p.xfB;
  const Transform2f& xfB = order == "A, B" ? p.xfB : p.xfA;
  for (int i = 0; i < m.pointCount; ++i) {
    const r2::ManifoldPoint& mp = m.points[static_cast<std::size_t>(i)];
    const auto pt = [&] {
      return where() + ": point " + std::to_string(i) + " " + str(mp.point) + " separation " + str(mp.separation) +
             " anchors " + str(mp.anchorA) + " " + str(mp.anchorB);
    };
    FUZZ_CHECK(isFinite(mp.point) && std::isfinite(mp.separation) && isFinite(mp.anchorA) && isFinite(mp.anchorB),
               pt() + ": not finite");
    FUZZ_CHECK(mp.separation <= r2::speculativeDistance + p.tolerance, pt() + ": beyond speculativeDistance");
    FUZZ_CHECK(distance(mp.anchorA, mp.point - xfA.p) <= p.tolerance &&
                   distance(mp.anchorB, mp.point - xfB.p) <= p.tolerance,
               pt() + ": anchors are not the point relative to the bodies' origins");
  }
}

double deepest(const r2::Manifold& m) {
  double d = std::numeric_limits<double>::max();
  for (int i = 0; i < m.pointCount; ++i) {
    d = std::min(d, static_cast<double>(m.points[static_cast<std::size_t>(i)].separation));
  }
  return d;
}

/// The point was made by collidePolygons' vertex contact (feature ids 10 to 12: a reference
/// face's end vertex against the incident edge's vertex or the edge between, the cores' closest
/// points apart), not by clipping a face.
bool cornerPoint(const r2::Manifold& m) { return m.pointCount == 1 && (m.points[0].id & 0xF) >= 10; }

void checkPair(const Pair& p) {
  const Core ca = core(p.a, p.xfA);
  const Core cb = core(p.b, p.xfB);
  const r2::Manifold ab = collide(p.a, p.xfA, p.b, p.xfB);
  checkValid(ab, p, "A, B");
  const bool chain = p.a.kind == Kind::chain || p.b.kind == Kind::chain;
  const r2::Manifold ba = collide(p.b, p.xfB, p.a, p.xfA);
  checkValid(ba, p, "B, A");
  const double coreDistance = coreSignedDistance(ca, cb);
  const double signedDistance = coreDistance - ca.radius - cb.radius;
  const auto where = [&] { return p.text() + ": signed distance " + str(signedDistance); };
  const double tol = p.tolerance;

  if (chain) {
    return; // one-sided: no symmetry, and a shape behind the chain gets no contact
  }

  // A circle: one point exactly within reach, at the true signed distance.
  // (regressions/narrowphase/circle-on-segment-axis*: a circle on a capsule's or segment's line,
  // beyond its end, once got a contact at any distance.)
  if (p.a.kind == Kind::circle || p.b.kind == Kind::circle) {
    const bool reach = signedDistance <= r2::speculativeDistance;
    if (std::abs(signedDistance - r2::speculativeDistance) > tol) {
      FUZZ_CHECK(ab.pointCount == (reach ? 1 : 0),
                 where() + ": " + std::to_string(ab.pointCount) + " points (one exactly within speculativeDistance)");
    }
    if (ab.pointCount == 1) {
      FUZZ_CHECK(std::abs(ab.points[0].separation - signedDistance) <= tol,
                 where() + ": the point's separation is " + str(ab.points[0].separation));
    }
  } else {
    // Two polygons (capsules, segments): an overlap deeper than the slop has a contact.
    // (regressions/narrowphase/corner-*, clip-*: the clip returned no point where the incident
    // edge lay wholly beyond a side plane of the reference face, and the corner path ran only
    // for cores more than 0.1 linearSlop apart whose closest points were exactly, by == on the
    // clamped parameters, two vertices; two capsules of radius 0.25 in line, 0.1 m apart, a
    // capsule on a box's corner, a sliver against a rounded face overlapped with no contact.)
    FUZZ_CHECK(signedDistance >= -r2::linearSlop || ab.pointCount > 0, where() + ": overlapping, but no contact");
    FUZZ_CHECK(signedDistance >= -r2::linearSlop || ba.pointCount > 0,
               where() + ": overlapping, but no contact (B, A)");
    // Cores apart: their closest points decide, so each order has a point exactly when the
    // shapes are within speculativeDistance, and its deepest point is at the true signed
    // distance: a vertex contact along the line between the closest points, or a face contact
    // whose point over the face is the incident shape's closest. Within the 0.1 linearSlop
    // hysteresis of the reference face a face contact may be clipped on the other face where
    // the two are nearly parallel (the separation along its normal is then within a factor
    // 1 + 1e-5, and the face's own at most 0.1 linearSlop less).
    if (coreDistance > tol) {
      const bool hysteresis =
          std::abs(faces(p.a, p.xfA, cb).best - faces(p.b, p.xfB, ca).best) <= 0.1 * r2::linearSlop + tol;
      const double depthTolerance = hysteresis ? 0.1 * r2::linearSlop + tol : tol;
      for (const r2::Manifold* m : {&ab, &ba}) {
        const std::string order = m == &ab ? " (A, B)" : " (B, A)";
        if (std::abs(signedDistance - r2::speculativeDistance) > depthTolerance) {
          FUZZ_CHECK((m->pointCount > 0) == (signedDistance < r2::speculativeDistance),
                     where() + ": cores apart, " + std::to_string(m->pointCount) + " points" + order +
                         " (some exactly within speculativeDistance)");
        }
        FUZZ_CHECK(m->pointCount == 0 || std::abs(deepest(*m) - signedDistance) <= depthTolerance,
                   where() + ": cores apart, the deepest point's separation is " + str(deepest(*m)) + order);
      }
    }
    // With area on both sides the separating-axis test is complete: no point deeper than the
    // penetration along the best axis, but for the 0.1 linearSlop hysteresis of the face choice.
    if (p.a.polygon.count >= 3 && p.b.polygon.count >= 3 && signedDistance < 0.0) {
      for (const r2::Manifold* m : {&ab, &ba}) {
        FUZZ_CHECK(m->pointCount == 0 || deepest(*m) >= signedDistance - 0.1 * r2::linearSlop - tol,
                   where() + ": a point at separation " + str(deepest(*m)) + " is deeper than the overlap");
      }
    }
  }

  // Symmetry. Circles against polygons are collided one way only (the dispatch reverses the
  // result), so the two orders agree by construction; circles against circles and polygons
  // against polygons are computed both ways.
  const bool circles = p.a.kind == Kind::circle && p.b.kind == Kind::circle;
  const bool polygons = p.a.kind != Kind::circle && p.b.kind != Kind::circle;
  if (!circles && !polygons) {
    return;
  }
  // Concentric (within the narrowphase's 1e-9 m, minNormalDistance): the normal is an arbitrary
  // (0, 1) either way.
  if (circles &&
      distance(transformPoint(p.xfA, p.a.circle.center), transformPoint(p.xfB, p.b.circle.center)) <= 1e-9f) {
    return;
  }
  // The ties, where the order decides and either answer is right.
  bool tie = false;
  for (const r2::Manifold* m : {&ab, &ba}) {
    for (int i = 0; i < m->pointCount; ++i) {
      tie = tie || std::abs(m->points[static_cast<std::size_t>(i)].separation - r2::speculativeDistance) <= tol;
    }
    // Two points a rounding apart (an incident vertex just over a side plane of the reference
    // face, and the edge clipped at that plane): the other order may have merged them into one,
    // its side tolerance scaling with the coordinates in its own frame.
    tie = tie || (m->pointCount == 2 && distance(m->points[0].point, m->points[1].point) <= tol);
  }
  if (polygons) {
    const FaceSeparation fa = faces(p.a, p.xfA, cb);
    const FaceSeparation fb = faces(p.b, p.xfB, ca);
    const double radius = ca.radius + cb.radius;
    tie = tie || std::abs(fa.best - fb.best) <= 0.1 * r2::linearSlop + tol;
    tie = tie || fa.best - fa.second <= tol || fb.best - fb.second <= tol;
    tie = tie || incidentTie(p.b, p.xfB, fa.normal, 1e-4) || incidentTie(p.a, p.xfA, fb.normal, 1e-4);
    tie = tie || std::abs(std::max(fa.best, fb.best) - radius - r2::speculativeDistance) <= tol;
    // A vertex contact against a clipped face near the border of their regions (the closest
    // points within the side tolerance of a side plane in one order): one point or two, the
    // same depth.
    tie = tie || cornerPoint(ab) || cornerPoint(ba);
  }
  if (ab.pointCount == 0 || ba.pointCount == 0) {
    FUZZ_CHECK(tie || ab.pointCount == ba.pointCount, where() + ": " + std::to_string(ab.pointCount) +
                                                          " points (A, B) but " + std::to_string(ba.pointCount) +
                                                          " (B, A)");
    return;
  }
  // In a tie the two answers are different faces' clips: the hysteresis allows 0.1 linearSlop
  // between the faces, and clipping at a side plane a little more; within linearSlop they agree.
  FUZZ_CHECK(std::abs(deepest(ab) - deepest(ba)) <= tol ||
                 (tie && std::abs(deepest(ab) - deepest(ba)) <= r2::linearSlop + tol),
             where() + ": deepest separation " + str(deepest(ab)) + " (A, B) but " + str(deepest(ba)) + " (B, A)");
  if (tie) {
    return;
  }
  FUZZ_CHECK(ab.pointCount == ba.pointCount, where() + ": " + std::to_string(ab.pointCount) + " points (A, B) but " +
                                                 std::to_string(ba.pointCount) + " (B, A)");
  FUZZ_CHECK(distance(ab.normal, -ba.normal) <= 1e-3f,
             where() + ": normal " + str(ab.normal) + " (A, B) but " + str(ba.normal) + " (B, A): not opposite");
  // The same points, in either order.
  std::array<double, 2> sab{};
  std::array<double, 2> sba{};
  for (std::size_t i = 0; i < static_cast<std::size_t>(ab.pointCount); ++i) {
    sab[i] = ab.points[i].separation;
    sba[i] = ba.points[i].separation;
  }
  std::sort(sab.begin(), sab.begin() + ab.pointCount);
  std::sort(sba.begin(), sba.begin() + ab.pointCount);
  for (std::size_t i = 0; i < static_cast<std::size_t>(ab.pointCount); ++i) {
    FUZZ_CHECK(std::abs(sab[i] - sba[i]) <= tol,
               where() + ": separations " + str(sab[i]) + " (A, B) but " + str(sba[i]) + " (B, A)");
  }
}

// Shapes from bytes. --------------------------------------------------------------------------

/// A shape of the kind byte `k`, sizes at scale `L`; false when the bytes give a degenerate one
/// (the world refuses those before they reach the narrowphase).
bool makeShape(impetus::fuzz::Reader& in, std::uint8_t k, float L, bool chainAllowed, Shape& s) {
  const auto longEnough = [](const Vec2f& a, const Vec2f& b) { return distance(a, b) > r2::linearSlop; };
  switch (k % (chainAllowed ? 6 : 5)) {
  case 0:
    s.kind = Kind::circle;
    s.circle.center = in.vec2(L);
    s.circle.radius = in.inRange(1e-3f * L, 2.0f * L);
    return true;
  case 1: {
    s.kind = Kind::capsule;
    r2::Capsule c{in.vec2(2.0f * L), in.vec2(2.0f * L), in.inRange(1e-3f * L, L)};
    if (!longEnough(c.center1, c.center2)) {
      return false;
    }
    s.polygon = r2::asPolygon(c);
    return true;
  }
  case 2: {
    s.kind = Kind::segment;
    const r2::Segment g{in.vec2(2.0f * L), in.vec2(2.0f * L)};
    if (!longEnough(g.point1, g.point2)) {
      return false;
    }
    s.polygon = r2::asPolygon(g);
    return true;
  }
  case 3: {
    s.kind = Kind::polygon;
    std::vector<Vec2f> points(3 + in.byte() % 6);
    for (Vec2f& p : points) {
      p = in.vec2(2.0f * L);
    }
    const std::uint8_t rounded = in.byte();
    const float radius = (rounded & 1) != 0 ? in.inRange(0.0f, L) : 0.0f;
    try {
      s.polygon = r2::makePolygon(points, radius);
    } catch (const impetus::Error&) {
      return false;
    }
    // Only valid polygons: one with a repeated vertex comes from an open finding of computeHull
    // (fuzz_polygon_hull reports it), and is no input for the narrowphase.
    for (int i = 0; i < s.polygon.count; ++i) {
      for (int j = i + 1; j < s.polygon.count; ++j) {
        if (s.polygon.vertices[static_cast<std::size_t>(i)] == s.polygon.vertices[static_cast<std::size_t>(j)]) {
          return false;
        }
      }
    }
    return true;
  }
  case 4: {
    // A box: makeBox (the narrowphase's box fast path) or makeOffsetBox; rounded or not.
    s.kind = Kind::polygon;
    const std::uint8_t form = in.byte();
    const float hx = in.inRange(1e-2f * L, 2.0f * L);
    const float hy = in.inRange(1e-2f * L, 2.0f * L);
    try {
      if ((form & 1) != 0) {
        s.polygon = r2::makeBox(hx, hy);
      } else {
        const Vec2f center = in.vec2(L);
        s.polygon = r2::makeOffsetBox(hx, hy, center, in.bounded(4.0f));
      }
    } catch (const impetus::Error&) {
      return false;
    }
    if ((form & 2) != 0) {
      s.polygon.radius = in.inRange(0.0f, L);
    }
    return true;
  }
  default: {
    s.kind = Kind::chain;
    s.chain.ghost1 = in.vec2(2.0f * L);
    s.chain.segment = {in.vec2(2.0f * L), in.vec2(2.0f * L)};
    s.chain.ghost2 = in.vec2(2.0f * L);
    if (!longEnough(s.chain.segment.point1, s.chain.segment.point2)) {
      return false;
    }
    s.polygon = r2::asPolygon(s.chain.segment);
    return true;
  }
  }
}

double extent(const Core& c) {
  double e = c.radius;
  for (const Vec2d& v : c.v) {
    e = std::max({e, std::abs(v.x), std::abs(v.y)});
  }
  return e;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  impetus::fuzz::Reader in(data, size);
  // Byte 0: the kinds of A and B; byte 1: the scale (0.1, 1 or 10 m) and whether both bodies
  // sit far from the origin (rounding at 100 times the scale).
  const std::uint8_t kinds = in.byte();
  const std::uint8_t setting = in.byte();
  const float L = std::array<float, 3>{0.1f, 1.0f, 10.0f}[setting % 3];
  const float offset = (setting & 0x10) != 0 ? 100.0f * L : 0.0f;
  Shape a;
  Shape b;
  if (!makeShape(in, kinds & 0x0F, L, true, a) || !makeShape(in, static_cast<std::uint8_t>(kinds >> 4), L, false, b)) {
    return 0;
  }
  // Transforms: A anywhere near the origin (or far off), B close to A so that they often touch.
  const Vec2f base = in.vec2(4.0f * L) + Vec2f{offset, -offset};
  const Transform2f xfA{base, impetus::Rot2f::fromAngle(in.bounded(8.0f))};
  const Transform2f xfB{base + in.vec2(4.0f * L), impetus::Rot2f::fromAngle(in.bounded(8.0f))};

  const double scale = std::max({1.0, extent(core(a, xfA)), extent(core(b, xfB))});
  // Float rounding at that scale: a few hundred units in the last place.
  const double tolerance = 256.0 * scale * std::numeric_limits<float>::epsilon();
  const Pair pair{a, xfA, b, xfB, scale, tolerance};
  checkPair(pair);
  return 0;
}
