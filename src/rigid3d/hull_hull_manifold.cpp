// The manifold of two hulls, in A's frame: the separating-axis test over both hulls' face normals
// and the edge pairs that form faces of their Minkowski difference (Gregorius, "The Separating
// Axis Test between Convex Polyhedra", GDC 2013), then a face contact (the incident face clipped
// to the reference face, hull_clip.cpp) or an edge contact (one point between the two edges'
// closest points); where the hulls are apart and neither finds the closest features, GJK's
// closest points.
#include <impetus/rigid3d/constants.hpp>
#include <impetus/rigid3d/distance.hpp>
#include <impetus/rigid3d/manifold.hpp>

#include "rigid3d/hull_clip.hpp"
#include "rigid3d/segment_closest.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

namespace impetus::rigid3d {
namespace {

using namespace hullclip;

/// Two edges within this angle of parallel (its sine) give no axis: the direction of their cross
/// product is then mostly rounding (a relative error of about float epsilon over the sine), and
/// exactly parallel edges form no face of the Minkowski difference (the two edges' arcs on the
/// Gauss map lie on one great circle), so the face normals beside them bound the separation. A
/// box resting on a box has all its edges parallel to the other's or crossing them squarely.
constexpr float parallelEdgeSine = 0.005f; // about 0.3 degrees

/// An edge axis is taken over the best face axis only when it separates the hulls by more than
/// this fraction of the face separation's magnitude plus edgeAbsoluteTolerance: the face contact
/// gives up to four points and a stable rest, and near the turn from one to the other (a box
/// tipping over an edge) the two separations are nearly equal, where choosing by the larger
/// alone would switch between one point and four from frame to frame.
constexpr float edgeRelativeTolerance = 0.1f;
constexpr float edgeAbsoluteTolerance = 0.5f * linearSlop; // m

/// B's face is the reference only when it separates the hulls by more than this fraction of A's
/// face separation's magnitude plus faceAbsoluteTolerance: two nearly parallel faces of equal
/// separation (a box resting on a box) would otherwise trade the reference role, and with it the
/// normal and the ids, with each rounding.
constexpr float faceRelativeTolerance = 0.02f;
constexpr float faceAbsoluteTolerance = 0.1f * linearSlop; // m

constexpr float lowest = -std::numeric_limits<float>::max();

/// The face of `hull` along whose normal the other hull (its points mapped into the hull's frame
/// by `other`) is farthest out, and that distance (negative: overlapping along it).
struct FaceQuery {
  int face = -1;
  float separation = lowest;
};

FaceQuery queryFaces(const Hull& hull, const Hull& otherHull, const Transform3f& other) {
  FaceQuery best;
  for (std::size_t f = 0; f < hull.planes.size(); ++f) {
    const HullPlane& plane = hull.planes[f];
    // The other hull's support point against the normal, its points left in their own frame.
    const Vec3f direction = inverseRotate(other.q, plane.normal);
    float deepest = std::numeric_limits<float>::max();
    for (const Vec3f& p : otherHull.points) {
      deepest = std::min(deepest, dot(direction, p));
    }
    if (const float separation = deepest + dot(plane.normal, other.p) - plane.offset; separation > best.separation) {
      best = {static_cast<int>(f), separation};
    }
  }
  return best;
}

/// Whether the arcs a-b and c-d on the unit sphere (the Gauss map of an edge of A, its two faces'
/// normals, and of an edge of B, its faces' normals negated) cross: then the two edges form a face
/// of the Minkowski difference A - B, whose normal is a candidate axis. c and d on opposite sides
/// of the plane of a-b, a and b on opposite sides of that of c-d, and the arcs on one hemisphere
/// (not crossing at the antipodes).
bool isMinkowskiFace(const Vec3f& a, const Vec3f& b, const Vec3f& c, const Vec3f& d) {
  const Vec3f bxa = cross(b, a);
  const Vec3f dxc = cross(d, c);
  const float cba = dot(c, bxa);
  const float dba = dot(d, bxa);
  const float adc = dot(a, dxc);
  const float bdc = dot(b, dxc);
  return cba * dba < 0.0f && adc * bdc < 0.0f && cba * bdc > 0.0f;
}

/// The edge pair (canonical half-edges of A and B) whose axis separates the hulls most, the axis
/// in A's frame pointing from A to B, and that separation.
struct EdgeQuery {
  int edgeA = -1;
  int edgeB = -1;
  Vec3f axis;
  float separation = lowest;
};

EdgeQuery queryEdges(const Hull& a, const Hull& b, const Transform3f& relative) {
  // A point inside A (its vertices' mean), to orient each axis away from A.
  Vec3f centroid;
  for (const Vec3f& p : a.points) {
    centroid += p;
  }
  centroid = centroid * (1.0f / static_cast<float>(a.points.size()));
  EdgeQuery best;
  for (std::size_t j = 0; j < b.edges.size(); ++j) {
    const HullHalfEdge& eb = b.edges[j];
    if (eb.twin < j) {
      continue; // each edge once
    }
    const Vec3f p2 = transformPoint(relative, b.points[eb.origin]);
    const Vec3f e2 = transformPoint(relative, b.points[b.edges[eb.next].origin]) - p2;
    const Vec3f c = -rotate(relative.q, b.planes[eb.face].normal);
    const Vec3f d = -rotate(relative.q, b.planes[b.edges[eb.twin].face].normal);
    for (std::size_t i = 0; i < a.edges.size(); ++i) {
      const HullHalfEdge& ea = a.edges[i];
      if (ea.twin < i || !isMinkowskiFace(a.planes[ea.face].normal, a.planes[a.edges[ea.twin].face].normal, c, d)) {
        continue;
      }
      const Vec3f& p1 = a.points[ea.origin];
      const Vec3f e1 = a.points[a.edges[ea.next].origin] - p1;
      Vec3f axis = cross(e1, e2);
      const float axisLength = length(axis);
      if (axisLength < parallelEdgeSine * std::sqrt(lengthSquared(e1) * lengthSquared(e2))) {
        continue;
      }
      axis = axis * (1.0f / axisLength);
      if (dot(axis, p1 - centroid) < 0.0f) {
        axis = -axis;
      }
      if (const float separation = dot(axis, p2 - p1); separation > best.separation) {
        best = {static_cast<int>(i), static_cast<int>(j), axis, separation};
      }
    }
  }
  return best;
}

/// Whether `candidate` beats `incumbent` by the given tolerances (separations, m).
bool clearlyBetter(float candidate, float incumbent, float relative, float absolute) {
  return candidate > incumbent + relative * std::abs(incumbent) + absolute;
}

/// The two edges' contact: one point midway between their closest points, at the axis's
/// separation. `interior` is false where a closest point is an end of its edge: the edges' lines
/// pass each other beyond the segments, and with the hulls apart the axis' separation is then
/// short of their distance.
struct EdgeContact {
  LocalContact contact;
  bool interior = false;
};

EdgeContact edgeContact(const Hull& a, const Hull& b, const Transform3f& relative, const EdgeQuery& query) {
  const HullHalfEdge& ea = a.edges[static_cast<std::size_t>(query.edgeA)];
  const HullHalfEdge& eb = b.edges[static_cast<std::size_t>(query.edgeB)];
  const Vec3f& p1 = a.points[ea.origin];
  const Vec3f& q1 = a.points[a.edges[ea.next].origin];
  const Vec3f p2 = transformPoint(relative, b.points[eb.origin]);
  const Vec3f q2 = transformPoint(relative, b.points[b.edges[eb.next].origin]);
  float s = 0.0f;
  float t = 0.0f;
  closestBetweenSegments(p1, q1, p2, q2, s, t);
  EdgeContact result;
  result.interior = s > 0.0f && s < 1.0f && t > 0.0f && t < 1.0f;
  LocalContact& c = result.contact;
  c.normal = query.axis;
  c.points[0] = {(lerp(p1, q1, s) + lerp(p2, q2, t)) * 0.5f, query.separation,
                 edgePairId(static_cast<std::uint32_t>(query.edgeA), static_cast<std::uint32_t>(query.edgeB))};
  c.count = 1;
  return result;
}

/// One point at the closest points of the two hulls (GJK), their distance its separation, for
/// hulls apart whose face or edge contact missed them; false where GJK cannot stand in (B has
/// more points than the buffer holds, or the cores count as overlapping after all).
bool closestPointsContact(const Hull& a, const Hull& b, const Transform3f& relative, LocalContact& c,
                          float& separationBound) {
  if (b.points.size() > static_cast<std::size_t>(maxHullVertices)) {
    return false;
  }
  std::array<Vec3f, maxHullVertices> pointsB;
  for (std::size_t k = 0; k < b.points.size(); ++k) {
    pointsB[k] = transformPoint(relative, b.points[k]);
  }
  const DistanceOutput d =
      coreDistance({a.points, 0.0f}, {std::span<const Vec3f>(pointsB.data(), b.points.size()), 0.0f});
  if (d.overlap || !(d.distance > 0.0f)) {
    return false;
  }
  c.count = 0;
  if (d.distance > speculativeDistance) {
    separationBound = d.distance;
    return true;
  }
  c.normal = (d.pointB - d.pointA) * (1.0f / d.distance);
  c.points[0] = {(d.pointA + d.pointB) * 0.5f, d.distance, closestPointsId};
  c.count = 1;
  return true;
}

} // namespace

Manifold collideHulls(const Hull& a, const Transform3f& xfA, const Hull& b, const Transform3f& xfB) {
  Manifold m;
  const Transform3f relative = invMul(xfA, xfB); // B in A's frame
  const FaceQuery faceA = queryFaces(a, b, relative);
  if (faceA.separation > speculativeDistance) {
    m.separationBound = faceA.separation;
    return m;
  }
  const FaceQuery faceB = queryFaces(b, a, invMul(xfB, xfA));
  if (faceB.separation > speculativeDistance) {
    m.separationBound = faceB.separation;
    return m;
  }
  const EdgeQuery edges = queryEdges(a, b, relative);
  if (edges.separation > speculativeDistance) {
    m.separationBound = edges.separation;
    return m;
  }
  const float faceSeparation = std::max(faceA.separation, faceB.separation);
  const bool apart = std::max(faceSeparation, edges.separation) > 0.0f;
  const bool referenceB =
      clearlyBetter(faceB.separation, faceA.separation, faceRelativeTolerance, faceAbsoluteTolerance);
  const auto onReferenceFace = [&](auto contactOf) {
    return referenceB ? contactOf(b, faceB.face, relative, a, Transform3f::identity(), true)
                      : contactOf(a, faceA.face, Transform3f::identity(), b, relative, false);
  };
  LocalContact c;
  bool missed = false; // the contact did not find the closest features of hulls apart
  if (edges.edgeA >= 0 &&
      clearlyBetter(edges.separation, faceSeparation, edgeRelativeTolerance, edgeAbsoluteTolerance)) {
    const EdgeContact edge = edgeContact(a, b, relative, edges);
    c = edge.contact;
    missed = apart && !edge.interior;
  } else {
    c = onReferenceFace([](auto&&... args) { return faceContact(args...); });
    if (c.count == 0 && !apart && edges.edgeA >= 0 && edges.separation >= faceSeparation) {
      // Overlapping, yet no point of the incident face lies over the reference face (its part
      // under the reference plane is beside the face): the edge pair, an axis as good, where the
      // edges meet.
      if (const EdgeContact edge = edgeContact(a, b, relative, edges); edge.interior) {
        c = edge.contact;
      }
    }
    missed = c.count == 0;
  }
  if (missed) {
    LocalContact closest;
    float separationBound = 0.0f;
    if (apart && closestPointsContact(a, b, relative, closest, separationBound)) {
      if (closest.count == 0) {
        m.separationBound = separationBound;
        return m;
      }
      c = closest;
    } else if (c.count == 0) {
      // Overlapping, and neither the face nor the edges meet over each other: the incident hull's
      // deepest vertex.
      c = onReferenceFace([](auto&&... args) { return deepestVertexContact(args...); });
    }
  }
  m.normal = rotate(xfA.q, c.normal);
  for (int k = 0; k < c.count; ++k) {
    const LocalPoint& p = c.points[static_cast<std::size_t>(k)];
    ManifoldPoint& mp = m.points[static_cast<std::size_t>(k)];
    mp.point = transformPoint(xfA, p.point);
    mp.anchorA = mp.point - xfA.p;
    mp.anchorB = mp.point - xfB.p;
    mp.separation = p.separation;
    mp.id = p.id;
  }
  m.pointCount = c.count;
  return m;
}

} // namespace impetus::rigid3d
