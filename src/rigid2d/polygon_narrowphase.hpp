// The polygon narrowphase's shared steps (polygon_manifold.cpp: the general path and the
// axis-aligned rectangle shortcut; box_manifold.cpp: the two-boxes shortcut): views of a
// polygon, the separating-axis search, the closest points of cores apart, the clip of the
// incident edge and the points. Inline: each path compiles them into its own loops.
#pragma once

#include <impetus/rigid2d/manifold.hpp>

#include "rigid2d/manifold_internal.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace impetus::rigid2d::narrowphase {

/// A polygon contact point and its anchors, from the point in registers (reading the point
/// back from the manifold would wait on its two stores).
inline void setPoint(ManifoldPoint& mp, Vec2f point, float separation, std::uint16_t id, const Transform2f& xfA,
                     const Transform2f& xfB) {
  mp.point = point;
  mp.anchorA = point - xfA.p;
  mp.anchorB = point - xfB.p;
  mp.separation = separation;
  mp.id = id;
}

/// A polygon's vertices and normals without the rest of the struct: B in A's frame lives in
/// local arrays, so the narrowphase never copies (or transforms) the unused slots.
struct PolygonView {
  const Vec2f* vertices;
  const Vec2f* normals;
  int count;
};

inline PolygonView view(const Polygon& p) { return {p.vertices.data(), p.normals.data(), p.count}; }

/// The edge of `p1` along whose normal `p2` is farthest away, and that separation.
struct EdgeSeparation {
  int edge = 0;
  float separation = -std::numeric_limits<float>::max();
};

inline EdgeSeparation maxSeparation(const PolygonView& p1, const PolygonView& p2) {
  EdgeSeparation best;
  for (int i = 0; i < p1.count; ++i) {
    float deepest = std::numeric_limits<float>::max();
    for (int j = 0; j < p2.count; ++j) {
      deepest = std::min(deepest, dot(p1.normals[i], p2.vertices[j] - p1.vertices[i]));
    }
    if (deepest > best.separation) {
      best = {i, deepest};
    }
  }
  return best;
}

inline std::uint16_t featureId(int referenceEdge, int incidentVertex, bool flipped) {
  return static_cast<std::uint16_t>((flipped ? 0x8000 : 0) | (referenceEdge << 4) | incidentVertex);
}

/// A face clip's point id, Box2D v3's: A's vertex and B's vertex at the point's end of the
/// reference face and the incident edge (whichever of the two is the reference), so that a
/// point keeps its id, and its warm start, when two nearly parallel faces trade the reference
/// role. (The tag bit keeps these apart from featureId's one-point contacts.)
inline std::uint16_t clipPointId(int referenceVertex, int incidentVertex, bool flipped) {
  const int vertexA = flipped ? incidentVertex : referenceVertex;
  const int vertexB = flipped ? referenceVertex : incidentVertex;
  return static_cast<std::uint16_t>(0x4000 | (vertexA << 4) | vertexB);
}

/// The closest points of segment p1-q1 (the reference face) and segment p2-q2 (the incident
/// edge): parameters s on the first and t on the second, both in [0, 1] (Ericson, Real-Time
/// Collision Detection 5.1.9), and which feature of the second holds its point (0 p2, 1 q2,
/// 2 between them), named by the branch that clamps t, not by comparing t with 0 and 1.
struct SegmentClosest {
  float s;
  float t;
  int feature2;
};

inline SegmentClosest segmentClosest(const Vec2f& p1, const Vec2f& q1, const Vec2f& p2, const Vec2f& q2) {
  const Vec2f d1 = q1 - p1;
  const Vec2f d2 = q2 - p2;
  const Vec2f r = p1 - p2;
  const float a = dot(d1, d1);
  const float e = dot(d2, d2);
  const float f = dot(d2, r);
  constexpr float tiny = 1e-12f; // hand-made polygons only: makePolygon welds closer points
  if (e <= tiny) {
    return {a <= tiny ? 0.0f : std::clamp(dot(d1, p2 - p1) / a, 0.0f, 1.0f), 0.0f, 0};
  }
  if (a <= tiny) {
    const float t = f / e;
    return t <= 0.0f ? SegmentClosest{0.0f, 0.0f, 0}
                     : (t >= 1.0f ? SegmentClosest{0.0f, 1.0f, 1} : SegmentClosest{0.0f, t, 2});
  }
  const float c = dot(d1, r);
  const float b = dot(d1, d2);
  const float denom = a * e - b * b; // 0: parallel, any s will do
  const float s = denom > tiny ? std::clamp((b * f - c * e) / denom, 0.0f, 1.0f) : 0.0f;
  // t for that s; where it leaves [0, 1], t is the end and s the closest point to that end.
  const float tNumerator = b * s + f;
  if (tNumerator <= 0.0f) {
    return {std::clamp(-c / a, 0.0f, 1.0f), 0.0f, 0};
  }
  if (tNumerator >= e) {
    return {std::clamp((b - c) / a, 0.0f, 1.0f), 1.0f, 1};
  }
  return {s, tNumerator / e, 2};
}

/// How far an incident point may lie beyond a side plane of the reference face and still count
/// as over the face (kept by the clip, not moved onto the plane). It absorbs rounding, so that a
/// box flush with the one below keeps its face contact (its corners a rounding beyond the side
/// planes) and its vertex ids: 5 um, or 16 units in the last place of the largest coordinate in
/// play where that is more. An incident vertex that far beyond a side plane changes a face
/// contact's point and separation by at most that much.
inline float sideTolerance(const Vec2f& v1, const Vec2f& v2, const Vec2f& w1, const Vec2f& w2) {
  const float extent = std::max({std::abs(v1.x), std::abs(v1.y), std::abs(v2.x), std::abs(v2.y), std::abs(w1.x),
                                 std::abs(w1.y), std::abs(w2.x), std::abs(w2.y)});
  return std::max(1e-3f * linearSlop, 16.0f * std::numeric_limits<float>::epsilon() * extent);
}

/// A reference face and its incident edge, in A's frame: the face v1-v2 (edge `edge` of the
/// reference polygon, outward normal n) and the edge w1-w2 (vertices i1, i2) of the other
/// polygon most anti-parallel to n; `flip` when the reference polygon is B.
struct FacePair {
  Vec2f v1;
  Vec2f v2;
  Vec2f n;
  Vec2f w1;
  Vec2f w2;
  int edge;
  int edgeNext;
  int i1;
  int i2;
  float rRef;
  float rInc;
  bool flip;
};

[[gnu::always_inline]] inline FacePair facePair(const PolygonView& reference, int referenceCount, float rRef,
                                                const PolygonView& incident, int incidentCount, float rInc, int edge,
                                                bool flip) {
  const int edgeNext = edge + 1 < referenceCount ? edge + 1 : 0;
  const Vec2f n = reference.normals[edge];
  // Incident edge: the one most anti-parallel to the reference normal.
  int incidentEdge = 0;
  float minDot = std::numeric_limits<float>::max();
  for (int i = 0; i < incidentCount; ++i) {
    const float d = dot(n, incident.normals[i]);
    if (d < minDot) {
      minDot = d;
      incidentEdge = i;
    }
  }
  const int i2 = incidentEdge + 1 < incidentCount ? incidentEdge + 1 : 0;
  return {reference.vertices[edge],
          reference.vertices[edgeNext],
          n,
          incident.vertices[incidentEdge],
          incident.vertices[i2],
          edge,
          edgeNext,
          incidentEdge,
          i2,
          rRef,
          rInc,
          flip};
}

/// The closest points of a face pair's face and incident edge, and how far the incident point
/// lies beyond the face's side planes (`beyond` <= 0: over the face).
struct CoreClosest {
  Vec2f onReference;
  Vec2f onIncident;
  float distance = 0.0f;
  float beyond = 0.0f;
  int referenceVertex = 0; ///< the face's end nearer the incident point: 0 v1, 1 v2
  int incidentFeature = 0; ///< 0 w1, 1 w2, 2 between them
};

/// Over the face (`beyond` within the side tolerance) the closest points are a face contact:
/// the incident point is at its distance straight along n, and clipping finds it (and the
/// edge's other point on the face). Beyond a side plane, the face's nearest point is its end
/// vertex, exactly: the incident point is then taken again as the closest point to that vertex
/// (a vertex of the incident edge, or a point between where the incident edge is the nearer
/// feature), and the contact is along the line between them. The decision is by where the
/// incident point lies, not by comparing clamped parameters with 0 and 1: a parameter a
/// rounding off its end used to send a corner-to-corner pair to the clip, which dropped it.
inline CoreClosest coreClosest(const FacePair& f, float tolerance) {
  const SegmentClosest sc = segmentClosest(f.v1, f.v2, f.w1, f.w2);
  CoreClosest c;
  c.onReference = lerp(f.v1, f.v2, sc.s);
  c.onIncident = lerp(f.w1, f.w2, sc.t);
  c.incidentFeature = sc.feature2;
  // The face's direction: the outward normal of a counter-clockwise edge is (t.y, -t.x). The
  // distances beyond the side planes are the clip's, on the same floats: where the incident
  // point is an end of the edge, this and the clip agree on which side of the tolerance it is
  // (a steep edge an end of which the clip moved onto the plane went far out along n).
  const Vec2f tangent{-f.n.y, f.n.x};
  const float along = dot(tangent, c.onIncident);
  const float beyondLower = dot(tangent, f.v1) - along;
  const float beyondUpper = along - dot(tangent, f.v2);
  c.beyond = std::max(beyondLower, beyondUpper);
  c.referenceVertex = beyondLower > beyondUpper ? 0 : 1;
  if (c.beyond > tolerance) {
    const Vec2f vertex = c.referenceVertex == 0 ? f.v1 : f.v2;
    const SegmentClosest toVertex = segmentClosest(vertex, vertex, f.w1, f.w2);
    c.onReference = vertex;
    c.onIncident = lerp(f.w1, f.w2, toVertex.t);
    c.incidentFeature = toVertex.feature2;
  }
  c.distance = distance(c.onReference, c.onIncident);
  return c;
}

/// One contact point from the cores' closest points (the rounded corner or end of the
/// reference shape against the incident shape): its separation is their distance less the
/// radii, exactly, and the normal is along the line between them (the face normal where they
/// are too close for a direction). None beyond reach.
inline void pointContact(const CoreClosest& c, const FacePair& f, float tolerance, const Transform2f& xfA,
                         const Transform2f& xfB, Manifold& m) {
  const float separation = c.distance - f.rRef - f.rInc;
  if (separation > speculativeDistance) {
    m.separationBound = separation;
    return;
  }
  const Vec2f dir = c.distance > tolerance ? (c.onIncident - c.onReference) / c.distance : f.n; // to the incident
  m.normal = rotate(xfA.q, f.flip ? -dir : dir);
  setPoint(m.points[0], transformPoint(xfA, lerp(c.onReference + dir * f.rRef, c.onIncident - dir * f.rInc, 0.5f)),
           separation, featureId(c.referenceVertex == 0 ? f.edge : f.edgeNext, 10 + c.incidentFeature, f.flip), xfA,
           xfB);
  m.pointCount = 1;
}

/// Cores apart: the closest points, from the best face (the greater separation, without the
/// reference face's hysteresis) and its incident edge, which hold them: in the Minkowski
/// difference B - A the origin is nearest to an edge, whose separation is then the distance
/// and the greatest, or to a vertex, and the edge of greatest separation is one of the two at
/// that vertex (any other's normal is farther from the direction to the origin); either way
/// the closest points are on that edge's face and on the incident edge, whose end is the other
/// polygon's support point against the face's normal. (The reference face within the
/// hysteresis may be another face: a segment's, while the closest points were a vertex of it
/// and a polygon's face.)
struct Apart {
  FacePair best;
  float tolerance;
};

/// True when the cores' closest points are a vertex contact (beyond the best face's side
/// planes): then `m` is that contact (or none, beyond reach). Where the incident edge reaches
/// over the face (an end over it, or one beyond each side plane) and no end beyond a side plane
/// lies lower along n than the other end, the edge rises (or stays level) from the plane out,
/// and its points out there are farther from the face's end vertex than their height, which is
/// at least the height at the plane: the closest point is over the face, a face contact, found
/// without the closest points (a face resting on a face: the common case). An end that falls
/// away below the other by a slope s (height per length along the face) from a height h has
/// its closest point at most h s beyond the plane: within the side tolerance, a face contact too.
[[gnu::always_inline]] inline bool vertexContact(const Apart& apart, const Transform2f& xfA, const Transform2f& xfB,
                                                 Manifold& m) {
  const FacePair& f = apart.best;
  const float tolerance = apart.tolerance;
  // The ends' distances beyond the side planes, as the clip has them.
  const Vec2f tangent{-f.n.y, f.n.x};
  const float lower = dot(tangent, f.v1);
  const float upper = dot(tangent, f.v2);
  const float along1 = dot(tangent, f.w1);
  const float along2 = dot(tangent, f.w2);
  const bool over1 = !(lower - along1 > tolerance) && !(along1 - upper > tolerance);
  const bool over2 = !(lower - along2 > tolerance) && !(along2 - upper > tolerance);
  if (!(std::min(along1, along2) - upper > tolerance) && !(lower - std::max(along1, along2) > tolerance)) {
    const float h1 = dot(f.n, f.w1 - f.v1);
    const float h2 = dot(f.n, f.w2 - f.v1);
    const float run = std::abs(along1 - along2);
    const float highest = std::max(h1, h2);
    const auto falls = [&](float hEnd, float hOther) { return (hOther - hEnd) * highest > tolerance * run; };
    if ((over1 || !falls(h1, h2)) && (over2 || !falls(h2, h1))) {
      return false;
    }
  }
  const CoreClosest closest = coreClosest(f, tolerance);
  if (closest.beyond > tolerance) {
    pointContact(closest, f, tolerance, xfA, xfB, m);
    return true;
  }
  return false;
}

/// Apart's best face pair, from the two separating-axis searches' results.
[[gnu::always_inline]] inline Apart apartFaces(const PolygonView& a, int countA, float radiusA, const PolygonView& pb,
                                               int countB, float radiusB, const EdgeSeparation& sa,
                                               const EdgeSeparation& sb) {
  Apart apart{sb.separation > sa.separation ? facePair(pb, countB, radiusB, a, countA, radiusA, sb.edge, true)
                                            : facePair(a, countA, radiusA, pb, countB, radiusB, sa.edge, false),
              0.0f};
  apart.tolerance = sideTolerance(apart.best.v1, apart.best.v2, apart.best.w1, apart.best.w2);
  return apart;
}

/// A face clip that found the incident edge wholly beyond a side plane while the cores are
/// apart: the closest points are over the best face (the reference face within the hysteresis is
/// another one, or a rounding sent them there): the contact at them.
inline void closestPointsContact(const Apart& apart, const Transform2f& xfA, const Transform2f& xfB, Manifold& m) {
  pointContact(coreClosest(apart.best, apart.tolerance), apart.best, apart.tolerance, xfA, xfB, m);
}

/// The reference face: A's unless B's is clearly better (by 0.1 linearSlop: the hysteresis keeps
/// the choice, and so the normal, from flickering between two nearly parallel faces of equal
/// separation; the points keep their ids either way, clipPointId). With the cores apart, the
/// hysteresis' face is kept only when it is nearly parallel to the best face (normals within
/// 4.5 mrad of opposite: a face contact measured along it is then deeper by a factor 1 / cos of
/// the angle, at most 1 + 1e-5); otherwise the best face is taken: its closest points are over it
/// (a face contact), and a face at an angle to it clipped the incident edge far from them (a
/// capsule's side within the hysteresis of a segment's face, 76 degrees apart, was 1.4 mm off).
[[gnu::always_inline]] inline bool referenceIsB(const Vec2f& normalA, const Vec2f& normalB, const EdgeSeparation& sa,
                                                const EdgeSeparation& sb, const Apart* apart) {
  const bool flip = sb.separation > sa.separation + 0.1f * linearSlop;
  if (apart == nullptr || flip == apart->best.flip || dot(normalA, normalB) < -(1.0f - 1e-5f)) {
    return flip;
  }
  return apart->best.flip;
}

/// Clips the incident edge `clip` (feature ids `clipId`) to one side plane of the reference
/// face, given each end's distance beyond the plane (d0, d1; > 0 beyond). An end beyond by more
/// than `tolerance` moves onto the plane along the edge and becomes the plane's feature
/// (`planeId`), unless that lands it within the tolerance of the other end (that end is at the
/// plane, or beyond it within the tolerance): then both are the other end, one point (two there
/// would be one contact counted twice). False when both ends are beyond by more than the
/// tolerance: then the edge is left as it was, and the caller decides (a face clip would have
/// no point).
[[gnu::always_inline]] inline bool clipToPlane(std::array<Vec2f, 2>& clip, std::array<int, 2>& clipId, float d0,
                                               float d1, float tolerance, int planeId) {
  if (d0 > tolerance && d1 > tolerance) {
    return false;
  }
  const auto moveOntoPlane = [&](std::size_t moved, float dMoved, float dKept) {
    const std::size_t kept = 1 - moved;
    const Vec2f onPlane = clip[moved] + (clip[kept] - clip[moved]) * (dMoved / (dMoved - dKept));
    if (dKept > 0.0f || lengthSquared(onPlane - clip[kept]) <= tolerance * tolerance) {
      clip[moved] = clip[kept];
      clipId[moved] = clipId[kept];
    } else {
      clip[moved] = onPlane;
      clipId[moved] = planeId;
    }
  };
  if (d0 > tolerance) {
    moveOntoPlane(0, d0, d1);
  } else if (d1 > tolerance) {
    moveOntoPlane(1, d1, d0);
  }
  return true;
}

/// A contact point of the clip, before its anchors.
struct ClipPoint {
  Vec2f point; // world
  float separation;
  std::uint16_t id;
  int clipFeature; // what the clip left at it: an incident vertex, or a side plane (8, 9)
};

/// clipContact's output for two clip points: each kept unless beyond reach, in order, and the
/// second dropped when both were clipped to the same feature (after being written, as there).
/// The slots are fixed, so both points can be computed side by side. The order is Box2D v3's:
/// the end of the incident edge that lies first along the reference face's tangent (A's face:
/// the incident edge's second vertex, clip point 1; B's face: clip point 0) comes first. The
/// solver takes a manifold's points one after the other, so the order is part of the result;
/// v3's makes the two engines' piles settle alike, point for point.
[[gnu::always_inline]] inline void storePoints(const ClipPoint& p0, const ClipPoint& p1, const Transform2f& xfA,
                                               const Transform2f& xfB, Manifold& m) {
  const bool keep0 = !(p0.separation > speculativeDistance);
  const bool keep1 = !(p1.separation > speculativeDistance);
  if (keep0) {
    setPoint(m.points[0], p0.point, p0.separation, p0.id, xfA, xfB);
    if (keep1) {
      setPoint(m.points[1], p1.point, p1.separation, p1.id, xfA, xfB);
      m.pointCount = p0.clipFeature == p1.clipFeature ? 1 : 2; // both clipped to the same vertex: one
    } else {
      m.pointCount = 1;
    }
  } else if (keep1) {
    setPoint(m.points[0], p1.point, p1.separation, p1.id, xfA, xfB);
    m.pointCount = 1;
  }
}

/// The polygon narrowphase after both separating-axis searches, in A's frame (`pb` is B there):
/// the reference face, the incident edge, the clip and the points. CountA and CountB > 0 fix
/// the vertex counts at compile time (so that the loops unroll); 0 reads them.
template <int CountA, int CountB> void clipContact(const PolygonView& a, float radiusA, const PolygonView& pb,
                                                   float radiusB, const EdgeSeparation& sa, const EdgeSeparation& sb,
                                                   const Transform2f& xfA, const Transform2f& xfB, Manifold& m) {
  const int countA = CountA > 0 ? CountA : a.count;
  const int countB = CountB > 0 ? CountB : pb.count;
  // Cores apart: a positive separation on either side's best axis (the separating-axis test
  // is complete for convex polygons, 2-vertex ones included), or two segments, whose face
  // normals miss the axis along them (capsules end to end on one line have a separation of 0
  // on every face, and their ends may still be apart). Then the closest points decide; beyond
  // the side planes of the best face they are a vertex contact, one point along the line
  // between them (see Apart).
  const bool coresApart = std::max(sa.separation, sb.separation) > 0.0f || (countA == 2 && countB == 2);
  Apart apart{};
  if (coresApart) {
    apart = apartFaces(a, countA, radiusA, pb, countB, radiusB, sa, sb);
    if (vertexContact(apart, xfA, xfB, m)) {
      return;
    }
  }
  const bool flip = referenceIsB(a.normals[sa.edge], pb.normals[sb.edge], sa, sb, coresApart ? &apart : nullptr);
  const FacePair f = flip ? facePair(pb, countB, radiusB, a, countA, radiusA, sb.edge, true)
                          : facePair(a, countA, radiusA, pb, countB, radiusB, sa.edge, false);
  const float tolerance = sideTolerance(f.v1, f.v2, f.w1, f.w2);
  // Clip the incident edge to the reference face's side planes. A clipped point is a new
  // feature: the reference face's side plane (ids 8 and 9).
  std::array<Vec2f, 2> clip{f.w1, f.w2};
  std::array<int, 2> clipId{f.i1, f.i2};
  const Vec2f tangent{-f.n.y, f.n.x};
  const auto clipTo = [&](float offsetAlong, float sign) {
    // Keep the part where sign * (dot(tangent, p) - offsetAlong) <= 0.
    const float d0 = sign * (dot(tangent, clip[0]) - offsetAlong);
    const float d1 = sign * (dot(tangent, clip[1]) - offsetAlong);
    return clipToPlane(clip, clipId, d0, d1, tolerance, sign < 0.0f ? 8 : 9);
  };
  if (!clipTo(dot(tangent, f.v1), -1.0f) || !clipTo(dot(tangent, f.v2), 1.0f)) {
    // The incident edge lies wholly beyond a side plane. Apart, the closest points are over the
    // best face: take them (the reference face within the hysteresis is another one, or it is
    // a rounding away from the vertex contact). Overlapping (a sliver against a short face),
    // the edge's ends as they are, each at its depth along n: the deeper is the incident
    // shape's deepest point along n (the edge is the most anti-parallel one), so the contact
    // has the separating-axis depth (a clip that returned no point let the shapes pass
    // through each other).
    if (coresApart) {
      closestPointsContact(apart, xfA, xfB, m);
      return;
    }
    clip = {f.w1, f.w2};
    clipId = {f.i1, f.i2};
  }
  m.normal = rotate(xfA.q, flip ? -f.n : f.n);
  const auto clipPoint = [&](std::size_t k) {
    const Vec2f p = clip[k];
    const float core = dot(f.n, p - f.v1);
    // Surface points: on the incident shape (p pulled back by its radius) and on the reference
    // face (pushed out by its radius); the contact point is midway.
    const Vec2f onIncident = p - f.n * f.rInc;
    const Vec2f onReference = p - f.n * (core - f.rRef);
    return ClipPoint{transformPoint(xfA, lerp(onIncident, onReference, 0.5f)), core - f.rRef - f.rInc,
                     clipPointId(k == 0 ? f.edgeNext : f.edge, k == 0 ? f.i1 : f.i2, flip), clipId[k]};
  };
  if (flip) {
    storePoints(clipPoint(0), clipPoint(1), xfA, xfB, m);
  } else {
    storePoints(clipPoint(1), clipPoint(0), xfA, xfB, m);
  }
}

/// Whether `p` is exactly what makeBox builds (box_manifold.cpp).
[[nodiscard]] bool isPlainBox(const Polygon& p, bool centred);
/// collidePolygons for two plain boxes, B centred (box_manifold.cpp).
void collideBoxes(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB, Manifold& m);

} // namespace impetus::rigid2d::narrowphase
