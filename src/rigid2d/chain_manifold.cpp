// Manifolds of a one-sided chain segment against a convex polygon (capsules and segments as
// 2-vertex polygons, rounded polygons) and against a circle, without ghost collisions.
//
// The idea (Box2D v3's chain segments, E. Catto, "Ghost collisions", 2020): the chain near a
// segment is the segment plus its two neighbours, whose far ends are the ghost vertices. The set
// of normals that surface can produce (its Gauss map) is the segment normal n1, plus, at a convex
// corner, the arc of normals between the neighbour's normal and n1. A candidate contact normal is
//   - admitted when it lies in that set,
//   - skipped when it lies beyond a convex corner's arc (the neighbour owns that contact),
//   - snapped to n1 when it leans towards a flat seam or a concave corner, where the chain has no
//     normal but n1 (this is what removes the ghost contacts: a box sliding across the seam of two
//     collinear segments can only ever be pushed along n1).
// Everything is computed in the chain body's frame (A) and converted to world at the end.
#include <impetus/rigid2d/chain.hpp>

#include "rigid2d/manifold_internal.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace impetus::rigid2d {
namespace {

using detail::minNormalDistance;

/// A turn whose sine is below this (about 0.57 degrees) is a flat seam, not a corner: slightly
/// bent terrain stays ghost-free.
constexpr float convexTolerance = 0.01f;
/// A normal may lean this far (sine of the angle) past a convex corner's arc and still be admitted.
constexpr float arcTolerance = 0.01f;
/// Below this distance (m) the shapes count as touching and the separating-axis test decides;
/// above it the closest features do (a vertex-vertex normal where they are two corners).
constexpr float touchingDistance = 0.1f * linearSlop;
/// The segment keeps its own normal as the reference unless a polygon face separates better by
/// this much (m): the choice does not flicker, so feature ids stay stable for warm starting.
constexpr float referenceHysteresis = 0.1f * linearSlop;

Vec2f rightPerp(const Vec2f& v) { return {v.y, -v.x}; }

/// The chain segment in A's frame, with the normals and corner types of its neighbourhood.
struct ChainFrame {
  Vec2f p1;
  Vec2f p2;
  Vec2f tangent;        ///< unit, p1 -> p2
  float length = 0.0f;  ///< m
  Vec2f normal1;        ///< the segment's normal (free side)
  Vec2f normal0;        ///< the previous segment's normal (used only when convex1)
  Vec2f normal2;        ///< the next segment's normal (used only when convex2)
  bool convex1 = false; ///< p1 is a convex corner (a left turn from ghost1 -> p1 to p1 -> p2)
  bool convex2 = false; ///< p2 is a convex corner
};

std::optional<ChainFrame> describe(const ChainSegment& s) {
  ChainFrame f;
  f.p1 = s.segment.point1;
  f.p2 = s.segment.point2;
  f.length = distance(f.p1, f.p2);
  if (!(f.length > 0.0f)) {
    return std::nullopt;
  }
  f.tangent = (f.p2 - f.p1) / f.length;
  f.normal1 = rightPerp(f.tangent);
  // Ghosts that coincide with their vertex normalise to zero: the corner then reads as flat.
  const Vec2f edge0 = normalize(f.p1 - s.ghost1);
  const Vec2f edge2 = normalize(s.ghost2 - f.p2);
  f.normal0 = rightPerp(edge0);
  f.normal2 = rightPerp(edge2);
  f.convex1 = cross(edge0, f.tangent) >= convexTolerance;
  f.convex2 = cross(f.tangent, edge2) >= convexTolerance;
  return f;
}

enum class Admission { skip, admit, snap };

/// Where `normal` (unit, A to B) falls on the chain's Gauss map near this segment. A normal that
/// leans towards p1 is judged by the corner at p1, one that leans towards p2 by the corner at p2.
Admission classify(const ChainFrame& f, const Vec2f& normal) {
  if (dot(normal, f.tangent) <= 0.0f) {
    if (!f.convex1) {
      return Admission::snap;
    }
    // The arc at p1 runs from normal0 (clockwise end) to normal1.
    return cross(normal, f.normal0) > arcTolerance ? Admission::skip : Admission::admit;
  }
  if (!f.convex2) {
    return Admission::snap;
  }
  // The arc at p2 runs from normal1 to normal2 (counter-clockwise end).
  return cross(f.normal2, normal) > arcTolerance ? Admission::skip : Admission::admit;
}

/// Polygon B in A's frame.
struct LocalPolygon {
  std::array<Vec2f, maxPolygonVertices> vertices{};
  std::array<Vec2f, maxPolygonVertices> normals{};
  Vec2f centroid;
  float radius = 0.0f;
  std::size_t count = 0;

  [[nodiscard]] std::size_t next(std::size_t i) const { return i + 1 < count ? i + 1 : 0; }
  [[nodiscard]] std::size_t previous(std::size_t i) const { return i > 0 ? i - 1 : count - 1; }
};

LocalPolygon inFrameOfA(const Polygon& b, const Transform2f& xfA, const Transform2f& xfB) {
  const Transform2f relative = invMul(xfA, xfB);
  LocalPolygon out;
  out.count = static_cast<std::size_t>(b.count);
  for (std::size_t i = 0; i < out.count; ++i) {
    out.vertices[i] = transformPoint(relative, b.vertices[i]);
    out.normals[i] = rotate(relative.q, b.normals[i]);
  }
  out.centroid = transformPoint(relative, b.centroid);
  out.radius = b.radius;
  return out;
}

/// Feature ids: kind (1 segment face is the reference, 2 a polygon face is, 3 vertex against
/// vertex) in the high byte, then two 4-bit feature numbers. Side planes of a reference face (a
/// point clipped there) are 8 (at its first vertex) and 9 (at its second).
std::uint16_t featureId(int kind, std::size_t first, std::size_t second) {
  return static_cast<std::uint16_t>((kind << 8) | static_cast<int>(first << 4) | static_cast<int>(second));
}
constexpr std::size_t lowerSidePlane = 8;
constexpr std::size_t upperSidePlane = 9;

/// A contact in A's frame before the conversion to world.
struct LocalPoint {
  Vec2f point; ///< midway between the surfaces
  float separation = 0.0f;
  std::uint16_t id = 0;
};

/// The world manifold from local points: points beyond the speculative distance are dropped.
Manifold toWorld(const Vec2f& localNormal, std::span<const LocalPoint> points, const Transform2f& xfA,
                 const Transform2f& xfB) {
  Manifold m;
  for (const LocalPoint& lp : points) {
    if (lp.separation > speculativeDistance) {
      continue;
    }
    ManifoldPoint& mp = m.points[static_cast<std::size_t>(m.pointCount)];
    mp.point = transformPoint(xfA, lp.point);
    mp.anchorA = mp.point - xfA.p;
    mp.anchorB = mp.point - xfB.p;
    mp.separation = lp.separation;
    mp.id = lp.id;
    ++m.pointCount;
  }
  if (m.pointCount > 0) {
    m.normal = rotate(xfA.q, localNormal);
  }
  return m;
}

/// Two points of an incident edge and their feature numbers, clipped in turn to side planes.
struct ClipPoint {
  Vec2f p;
  std::size_t feature = 0;
};

/// Keeps the part of the edge whose coordinate along `axis` from `origin` is in [0, extent];
/// clipped ends take the side plane's feature number. False when nothing is left.
bool clipToSlab(std::array<ClipPoint, 2>& edge, const Vec2f& origin, const Vec2f& axis, float extent) {
  std::array<float, 2> t{dot(edge[0].p - origin, axis), dot(edge[1].p - origin, axis)};
  if ((t[0] < 0.0f && t[1] < 0.0f) || (t[0] > extent && t[1] > extent)) {
    return false;
  }
  for (std::size_t k = 0; k < 2; ++k) {
    const std::size_t o = 1 - k;
    if (t[k] < 0.0f) { // then t[o] >= 0: the edge crosses the plane
      edge[k].p = lerp(edge[k].p, edge[o].p, (0.0f - t[k]) / (t[o] - t[k]));
      edge[k].feature = lowerSidePlane;
      t[k] = 0.0f;
    }
  }
  for (std::size_t k = 0; k < 2; ++k) {
    const std::size_t o = 1 - k;
    if (t[k] > extent) { // then t[o] <= extent
      edge[k].p = lerp(edge[k].p, edge[o].p, (t[k] - extent) / (t[k] - t[o]));
      edge[k].feature = upperSidePlane;
      t[k] = extent;
    }
  }
  return true;
}

/// Two clipped points closer than this (m) are one contact.
constexpr float weldDistance = 0.1f * linearSlop;

/// The segment normal is the reference: B's edge `incidentEdge` is clipped to the segment's
/// extent, and the height of each clipped point above the segment's line, less B's radius, is
/// its separation.
Manifold clipOnSegment(const ChainFrame& f, const LocalPolygon& b, std::size_t incidentEdge, const Transform2f& xfA,
                       const Transform2f& xfB) {
  const std::size_t i2 = b.next(incidentEdge);
  std::array<ClipPoint, 2> edge{ClipPoint{b.vertices[incidentEdge], incidentEdge}, ClipPoint{b.vertices[i2], i2}};
  if (!clipToSlab(edge, f.p1, f.tangent, f.length)) {
    return {};
  }
  std::array<LocalPoint, 2> points{};
  std::size_t count = 0;
  for (const ClipPoint& c : edge) {
    const float core = dot(f.normal1, c.p - f.p1); // B's core point above the segment line
    const float separation = core - b.radius;
    // Midway between B's surface (c.p pulled back by its radius) and the segment (c.p dropped
    // onto the line).
    const Vec2f onB = c.p - f.normal1 * b.radius;
    const Vec2f onA = c.p - f.normal1 * core;
    points[count++] = {lerp(onA, onB, 0.5f), separation, featureId(1, 0, c.feature)};
  }
  if (distance(edge[0].p, edge[1].p) < weldDistance) {
    count = 1; // the edge touches the segment's extent at a single point
    if (points[1].separation < points[0].separation) {
      points[0] = points[1];
    }
  }
  return toWorld(f.normal1, std::span<const LocalPoint>(points.data(), count), xfA, xfB);
}

/// The incident edge of B at vertex `k` for the segment normal: of the two edges meeting there,
/// the one facing the segment most directly.
std::size_t incidentEdgeAt(const LocalPolygon& b, std::size_t k, const Vec2f& normal1) {
  const std::size_t before = b.previous(k);
  return dot(normal1, b.normals[before]) < dot(normal1, b.normals[k]) ? before : k;
}

/// B's face `face` is the reference (its outward normal m; the contact normal A to B is -m): the
/// segment is clipped to the face's extent. Empty when a neighbouring segment, not this one,
/// faces m more directly: that neighbour reports the contact, and this segment reporting it too
/// would push B against the seam (a ghost contact).
Manifold clipOnPolygonFace(const ChainFrame& f, const LocalPolygon& b, std::size_t face, const Transform2f& xfA,
                           const Transform2f& xfB) {
  const Vec2f a1 = b.vertices[face];
  const Vec2f a2 = b.vertices[b.next(face)];
  const Vec2f m = b.normals[face];
  // The segment end deepest into the face decides which neighbour could be incident instead.
  const bool p1Deeper = dot(m, f.p1 - a1) < dot(m, f.p2 - a1);
  const Vec2f neighbour = p1Deeper ? (f.convex1 ? f.normal0 : f.normal1) : (f.convex2 ? f.normal2 : f.normal1);
  if (dot(neighbour, m) < dot(f.normal1, m)) {
    return {};
  }
  const float faceLength = distance(a1, a2);
  if (!(faceLength > 0.0f)) {
    return {};
  }
  std::array<ClipPoint, 2> edge{ClipPoint{f.p1, 0}, ClipPoint{f.p2, 1}};
  if (!clipToSlab(edge, a1, (a2 - a1) / faceLength, faceLength)) {
    return {};
  }
  std::array<LocalPoint, 2> points{};
  std::size_t count = 0;
  for (const ClipPoint& c : edge) {
    const float separation = dot(m, c.p - a1) - b.radius;
    // c.p is on A's surface (the segment has no radius); B's surface is `separation` along -m.
    points[count++] = {c.p - m * (0.5f * separation), separation, featureId(2, face, c.feature)};
  }
  if (distance(edge[0].p, edge[1].p) < weldDistance) {
    count = 1;
    if (points[1].separation < points[0].separation) {
      points[0] = points[1];
    }
  }
  return toWorld(-m, std::span<const LocalPoint>(points.data(), count), xfA, xfB);
}

/// Closest features of the segment and B's core when they are apart.
struct ClosestFeatures {
  float distance = 0.0f; ///< 0 when they overlap, m
  Vec2f onSegment;
  Vec2f onPolygon;
  /// Segment feature: 0 = p1, 1 = p2, 2 = the interior.
  int segmentFeature = 2;
  /// B's feature: the vertex `polygonIndex` when polygonIsVertex, else the edge `polygonIndex`
  /// (its interior).
  std::size_t polygonIndex = 0;
  bool polygonIsVertex = true;
};

/// Parameter in [0, 1] of the point of segment a-b closest to p.
float closestParameter(const Vec2f& a, const Vec2f& b, const Vec2f& p) {
  const Vec2f ab = b - a;
  const float ab2 = dot(ab, ab);
  return ab2 > 0.0f ? std::clamp(dot(p - a, ab) / ab2, 0.0f, 1.0f) : 0.0f;
}

ClosestFeatures closestFeatures(const ChainFrame& f, const LocalPolygon& b) {
  // Separating axes of a segment and a convex polygon in the plane: the segment's two normals
  // and B's edge normals. All non-positive: they overlap.
  float axisSeparation = -std::numeric_limits<float>::max();
  float below = std::numeric_limits<float>::max();
  float above = std::numeric_limits<float>::max();
  for (std::size_t i = 0; i < b.count; ++i) {
    above = std::min(above, dot(f.normal1, b.vertices[i] - f.p1));
    below = std::min(below, -dot(f.normal1, b.vertices[i] - f.p1));
    const Vec2f& m = b.normals[i];
    axisSeparation = std::max(axisSeparation, std::min(dot(m, f.p1 - b.vertices[i]), dot(m, f.p2 - b.vertices[i])));
  }
  axisSeparation = std::max({axisSeparation, above, below});
  ClosestFeatures best;
  if (axisSeparation <= 0.0f) {
    return best; // overlapping: distance 0
  }
  // Apart: the closest pair of two disjoint convex outlines has a vertex of one of them in it,
  // so B's vertices against the segment and the segment's ends against B's edges cover it.
  float bestSquared = std::numeric_limits<float>::max();
  for (std::size_t i = 0; i < b.count; ++i) {
    const Vec2f v = b.vertices[i];
    const float s = closestParameter(f.p1, f.p2, v);
    const Vec2f onSegment = lerp(f.p1, f.p2, s);
    const float d2 = lengthSquared(v - onSegment);
    if (d2 < bestSquared) {
      bestSquared = d2;
      best.onSegment = onSegment;
      best.onPolygon = v;
      best.segmentFeature = s == 0.0f ? 0 : (s == 1.0f ? 1 : 2);
      best.polygonIndex = i;
      best.polygonIsVertex = true;
    }
  }
  for (std::size_t i = 0; i < b.count; ++i) {
    const Vec2f v1 = b.vertices[i];
    const Vec2f v2 = b.vertices[b.next(i)];
    for (int end = 0; end < 2; ++end) {
      const Vec2f p = end == 0 ? f.p1 : f.p2;
      const float t = closestParameter(v1, v2, p);
      const Vec2f onPolygon = lerp(v1, v2, t);
      const bool interior = t > 0.0f && t < 1.0f;
      if (interior && dot(b.normals[i], p - onPolygon) < 0.0f) {
        // p is behind this edge's face. For a polygon with an inside, another edge is nearer;
        // a 2-vertex polygon's two edges are one segment facing both ways, and only the edge
        // facing p is the face it touches.
        continue;
      }
      const float d2 = lengthSquared(onPolygon - p);
      if (d2 < bestSquared) {
        bestSquared = d2;
        best.onSegment = p;
        best.onPolygon = onPolygon;
        best.segmentFeature = end;
        best.polygonIsVertex = t == 0.0f || t == 1.0f;
        best.polygonIndex = t == 1.0f ? b.next(i) : i;
      }
    }
  }
  best.distance = std::sqrt(bestSquared);
  return best;
}

} // namespace

Manifold collideChainSegmentAndCircle(const ChainSegment& a, const Transform2f& xfA, const Circle& b,
                                      const Transform2f& xfB) {
  const std::optional<ChainFrame> frame = describe(a);
  if (!frame) {
    return {};
  }
  const ChainFrame& f = *frame;
  const Vec2f c = inverseTransformPoint(xfA, transformPoint(xfB, b.center)); // in A's frame
  // The plane around the segment is split into regions with half-open borders, and each region
  // is reported by exactly one segment of the chain: before p1 (v < 0), over the segment
  // (0 <= v, u < 0), beyond p2 (u >= 0). Every test that two neighbours both make about a shared
  // border is written with the same operands (unnormalised edges, differences from the same
  // vertices), so the two agree bit for bit and no circle falls between them.
  const Vec2f edge = f.p2 - f.p1;
  if (dot(rightPerp(edge), c - f.p1) < 0.0f) {
    return {}; // behind the segment's line: one-sided
  }
  const float v = dot(edge, c - f.p1);
  const float u = dot(edge, c - f.p2);
  Vec2f onA;
  Vec2f normal;
  float dist = 0.0f;
  if (v < 0.0f) {
    // Before p1. Over the previous segment, that segment reports the circle. Beyond it, at a
    // convex corner, this is the corner's region, which the previous segment reports (as its p2)
    // unless the centre is behind that segment's line (a corner sharper than a right angle),
    // where this segment alone sees it. A concave or flat corner has no region of its own in
    // front of the chain (a centre there is through the other wall): no contact. An open
    // chain's first segment has a straight-on ghost: nothing is reported before its start.
    const Vec2f previous = f.p1 - a.ghost1;
    if (!(cross(previous, edge) > 0.0f) || dot(previous, c - f.p1) < 0.0f ||
        dot(rightPerp(previous), c - a.ghost1) >= 0.0f) {
      return {};
    }
    onA = f.p1;
  } else if (u >= 0.0f) {
    // Beyond p2: the next segment reports the centre when it is over it (or over an open chain's
    // straight-on ghost); otherwise, at a convex corner, this is the corner's region, which is
    // ours. (The two neighbours compute the corner's turn with the same operands, so they agree.)
    const Vec2f next = a.ghost2 - f.p2;
    if (!(cross(edge, next) > 0.0f) || dot(next, c - f.p2) >= 0.0f) {
      return {};
    }
    onA = f.p2;
  }
  if (v < 0.0f || u >= 0.0f) {
    dist = distance(c, onA);
    // A centre on the corner (within minNormalDistance) has no direction from it: the segment's
    // normal, one end of the corner's arc of normals. (Dividing by any positive distance gave a
    // normal of length 1.0014 for a centre 1e-21 m from p2: its square underflows.)
    normal = dist > minNormalDistance ? (c - onA) / dist : f.normal1;
  } else {
    // Over the segment: its own normal, exactly (no rounding drift across a flat seam).
    const float along = dot(f.tangent, c - f.p1);
    onA = f.p1 + f.tangent * along;
    dist = std::max(0.0f, dot(f.normal1, c - f.p1));
    normal = f.normal1;
  }
  const float separation = dist - b.radius;
  const LocalPoint point{lerp(onA, c - normal * b.radius, 0.5f), separation, 0};
  return toWorld(normal, std::span<const LocalPoint>(&point, 1), xfA, xfB);
}

Manifold collideChainSegmentAndPolygon(const ChainSegment& a, const Transform2f& xfA, const Polygon& b,
                                       const Transform2f& xfB) {
  if (b.count == 1) {
    return collideChainSegmentAndCircle(a, xfA, Circle{b.vertices[0], b.radius}, xfB);
  }
  if (b.count < 1) {
    return {};
  }
  const std::optional<ChainFrame> frame = describe(a);
  if (!frame) {
    return {};
  }
  const ChainFrame& f = *frame;
  const LocalPolygon pb = inFrameOfA(b, xfA, xfB);

  // One-sided: B's centroid behind the segment's line, and behind a convex neighbour's line too
  // (where there is one: around a convex corner the neighbour's side may still see B).
  const bool behind1 = dot(f.normal1, pb.centroid - f.p1) < 0.0f;
  const bool behind0 = !f.convex1 || dot(f.normal0, pb.centroid - f.p1) < 0.0f;
  const bool behind2 = !f.convex2 || dot(f.normal2, pb.centroid - f.p2) < 0.0f;
  if (behind1 && behind0 && behind2) {
    return {};
  }

  const ClosestFeatures closest = closestFeatures(f, pb);
  if (closest.distance > pb.radius + speculativeDistance) {
    return {};
  }

  if (!behind1 && closest.distance > touchingDistance) {
    // Apart: the closest features tell the contact normal.
    if (closest.segmentFeature == 2) {
      // B's vertex over the segment's interior: the segment normal.
      return clipOnSegment(f, pb, incidentEdgeAt(pb, closest.polygonIndex, f.normal1), xfA, xfB);
    }
    if (closest.polygonIsVertex) {
      // Corner against corner: the normal runs between them, if the chain's corner has it.
      const Vec2f normal = (closest.onPolygon - closest.onSegment) / closest.distance;
      switch (classify(f, normal)) {
      case Admission::skip:
        return {};
      case Admission::admit: {
        const auto segmentVertex = static_cast<std::size_t>(closest.segmentFeature);
        const LocalPoint point{lerp(closest.onSegment, closest.onPolygon - normal * pb.radius, 0.5f),
                               closest.distance - pb.radius, featureId(3, segmentVertex, closest.polygonIndex)};
        return toWorld(normal, std::span<const LocalPoint>(&point, 1), xfA, xfB);
      }
      case Admission::snap:
        return clipOnSegment(f, pb, incidentEdgeAt(pb, closest.polygonIndex, f.normal1), xfA, xfB);
      }
    }
    // A segment end against B's edge: that face's normal, if the chain has it.
    const std::size_t face = closest.polygonIndex;
    switch (classify(f, -pb.normals[face])) {
    case Admission::skip:
      return {};
    case Admission::admit:
      return clipOnPolygonFace(f, pb, face, xfA, xfB);
    case Admission::snap:
      return clipOnSegment(f, pb, face, xfA, xfB);
    }
    return {};
  }

  // Touching, overlapping, or B's centroid behind this segment but in front of a convex
  // neighbour: the separating axis of greatest separation among those the chain admits.
  float edgeSeparation = std::numeric_limits<float>::max();
  std::size_t incidentVertex = 0;
  for (std::size_t i = 0; i < pb.count; ++i) {
    const float s = dot(f.normal1, pb.vertices[i] - f.p1);
    if (s < edgeSeparation) {
      edgeSeparation = s;
      incidentVertex = i;
    }
  }
  float best = edgeSeparation;
  bool neighbourOwns = false;
  const auto neighbourSeparation = [&](const Vec2f& normal, const Vec2f& vertex) {
    float s = std::numeric_limits<float>::max();
    for (std::size_t i = 0; i < pb.count; ++i) {
      s = std::min(s, dot(normal, pb.vertices[i] - vertex));
    }
    if (s > best) {
      best = s;
      neighbourOwns = true;
    }
  };
  if (f.convex1) {
    neighbourSeparation(f.normal0, f.p1);
  }
  if (f.convex2) {
    neighbourSeparation(f.normal2, f.p2);
  }
  float faceSeparation = -std::numeric_limits<float>::max();
  std::optional<std::size_t> referenceFace;
  for (std::size_t i = 0; i < pb.count; ++i) {
    const Vec2f& m = pb.normals[i];
    if (classify(f, -m) != Admission::admit) {
      continue;
    }
    const float s = std::min(dot(m, f.p1 - pb.vertices[i]), dot(m, f.p2 - pb.vertices[i]));
    if (s > faceSeparation) {
      faceSeparation = s;
      referenceFace = i;
    }
  }
  // Against the segment's own normal a face must win clearly (stable ids); against a
  // neighbour's, any margin decides, so one of the two segments always reports.
  const float margin = neighbourOwns ? 0.0f : referenceHysteresis;
  if (referenceFace && faceSeparation > best + margin) {
    return clipOnPolygonFace(f, pb, *referenceFace, xfA, xfB);
  }
  if (neighbourOwns) {
    return {}; // the neighbouring segment is the separating axis: it reports
  }
  return clipOnSegment(f, pb, incidentEdgeAt(pb, incidentVertex, f.normal1), xfA, xfB);
}

} // namespace impetus::rigid2d
