// The face contact of two hulls: the incident face's polygon clipped to the reference face's side
// planes (Sutherland-Hodgman), the points within reach of the reference plane, reduced to the
// four that span the most area. In A's frame, on fixed-size buffers.
#include <impetus/rigid3d/constants.hpp>

#include "rigid3d/hull_clip.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace impetus::rigid3d::hullclip {
namespace {

/// The most vertices a clip holds: a convex polygon of n vertices cut by one plane gains at most
/// one (the cut replaces a chain of vertices by two), so the incident face (at most
/// maxHullVertices vertices) cut by the reference face's side planes (at most maxHullVertices)
/// has at most twice maxHullVertices. A face of more vertices (makeHullFromFaces does not cap
/// them, computeHull does) is read up to the cap, and the clip stops adding beyond it.
constexpr int maxClipVertices = 2 * maxHullVertices;

/// A vertex of the polygon being clipped, its feature id, and what the polygon's edge from it to
/// the next vertex lies on: an edge of the incident face (its lower half-edge index) or a side
/// plane of the reference face (its half-edge), so that a cut through that edge names its point.
struct ClipVertex {
  Vec3f point;
  std::uint32_t id = 0;
  std::uint16_t edge = 0;
  bool alongSide = false;
};

struct ClipPolygon {
  std::array<ClipVertex, maxClipVertices> vertices;
  int count = 0;

  void push(const ClipVertex& v) {
    if (count < maxClipVertices) {
      vertices[static_cast<std::size_t>(count++)] = v;
    }
  }
};

/// How far from a side plane of the reference face an incident point counts as on it: kept as it
/// is, not cut (beyond the plane) nor joined by a cut (inside it). It absorbs rounding, so that a
/// box flush with the one under it keeps its corners' points and their ids instead of cuts a
/// rounding away from them. 5 um, or 16 units in the last place of the largest coordinate in play
/// where that is more (the 2D engine's choice); a point kept that far beyond moves a contact by at
/// most that much.
float sideTolerance(const ClipPolygon& polygon) {
  float extent = 0.0f;
  for (int k = 0; k < polygon.count; ++k) {
    const Vec3f& p = polygon.vertices[static_cast<std::size_t>(k)].point;
    extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  return std::max(1e-3f * linearSlop, 16.0f * std::numeric_limits<float>::epsilon() * extent);
}

/// Cuts `in` by the side plane side . x = offset (keeping what is behind it, and what is beyond
/// it by at most `tolerance`) into `out` (Sutherland-Hodgman). Where the polygon crosses the
/// plane, the cut is on the plane, named by the edge it cuts: an incident edge and this side
/// (incidentEdgeSide), or another side plane and this one (referenceCorner); where the vertex
/// inside is within the tolerance of the plane, that vertex is the crossing and no cut is added.
void clipToSide(const ClipPolygon& in, ClipPolygon& out, const Vec3f& side, float offset, float tolerance,
                std::uint16_t sideEdge, bool referenceIsB, std::uint32_t face) {
  out.count = 0;
  if (in.count == 0) {
    return;
  }
  const auto runAlongSide = [&](ClipVertex& v) {
    v.edge = sideEdge;
    v.alongSide = true;
  };
  bool lastRunsAlongSide = false; // the polygon leaves at its last vertex, pushed at the end
  const ClipVertex* previous = &in.vertices[static_cast<std::size_t>(in.count - 1)];
  float dPrevious = dot(side, previous->point) - offset;
  for (int k = 0; k < in.count; ++k) {
    const ClipVertex& current = in.vertices[static_cast<std::size_t>(k)];
    const float dCurrent = dot(side, current.point) - offset;
    const bool previousIn = dPrevious <= tolerance;
    const bool currentIn = dCurrent <= tolerance;
    const auto cut = [&] {
      ClipVertex v;
      v.point = previous->point + (current.point - previous->point) * (dPrevious / (dPrevious - dCurrent));
      v.id = previous->alongSide
                 ? featureId(FeatureKind::referenceCorner, referenceIsB, face, std::min(previous->edge, sideEdge),
                             std::max(previous->edge, sideEdge))
                 : featureId(FeatureKind::incidentEdgeSide, referenceIsB, face, previous->edge, sideEdge);
      return v;
    };
    if (previousIn && !currentIn) {
      // Leaving: from here the polygon runs along the side plane.
      if (dPrevious < -tolerance) {
        ClipVertex v = cut();
        runAlongSide(v);
        out.push(v);
      } else if (k == 0) {
        lastRunsAlongSide = true;
      } else if (out.count > 0) {
        runAlongSide(out.vertices[static_cast<std::size_t>(out.count - 1)]); // previous, just pushed
      }
    } else if (!previousIn && currentIn && dCurrent < -tolerance) {
      // Entering: along the cut edge on to the current vertex.
      ClipVertex v = cut();
      v.edge = previous->edge;
      v.alongSide = previous->alongSide;
      out.push(v);
    }
    if (currentIn) {
      out.push(current);
    }
    previous = &current;
    dPrevious = dCurrent;
  }
  if (lastRunsAlongSide && out.count > 0) {
    runAlongSide(out.vertices[static_cast<std::size_t>(out.count - 1)]);
  }
}

/// The reference face's plane in A's frame: n . x = offset.
struct ReferencePlane {
  Vec3f normal;
  float offset = 0.0f;
};

ReferencePlane referencePlane(const Hull& reference, int face, const Transform3f& referenceToA) {
  const HullPlane& plane = reference.planes[static_cast<std::size_t>(face)];
  const Vec3f normal = rotate(referenceToA.q, plane.normal);
  return {normal, plane.offset + dot(normal, referenceToA.p)};
}

/// The point midway between the incident point x and its projection on the plane, at height h.
LocalPoint pointOver(const ReferencePlane& plane, const Vec3f& x, std::uint32_t id) {
  const float height = dot(plane.normal, x) - plane.offset;
  return {x - plane.normal * (0.5f * height), height, id};
}

/// The twice-area of triangle (p, q, r) seen along n: positive counter-clockwise about n.
float twiceArea(const Vec3f& n, const Vec3f& p, const Vec3f& q, const Vec3f& r) { return dot(n, cross(q - p, r - p)); }

/// At most four of the candidates, spanning the most area: the deepest point (the contact's
/// depth is kept exactly), the point farthest from it, the point making the largest triangle
/// with those two, then the point that adds the most area to that triangle, outside one of its
/// edges (for the clip of a face, a convex polygon, most often across the diagonal from the
/// third point: the largest-area quad among them). Points within `tolerance` (m) of the line or
/// the point already chosen add nothing and are left out. In convex order.
void reduceToFour(const std::array<LocalPoint, maxClipVertices>& candidates, int count, const Vec3f& n, float tolerance,
                  LocalContact& out) {
  out.count = 0;
  if (count <= 4) {
    for (int k = 0; k < count; ++k) {
      out.points[static_cast<std::size_t>(out.count++)] = candidates[static_cast<std::size_t>(k)];
    }
    return;
  }
  const auto at = [&](int k) -> const LocalPoint& { return candidates[static_cast<std::size_t>(k)]; };
  int i0 = 0;
  for (int k = 1; k < count; ++k) {
    if (at(k).separation < at(i0).separation) {
      i0 = k;
    }
  }
  const Vec3f p0 = at(i0).point;
  int i1 = i0;
  float farthest = 0.0f;
  for (int k = 0; k < count; ++k) {
    if (const float d = lengthSquared(at(k).point - p0); d > farthest) {
      farthest = d;
      i1 = k;
    }
  }
  out.points[0] = at(i0);
  out.count = 1;
  if (farthest <= tolerance * tolerance) {
    return;
  }
  out.points[1] = at(i1);
  out.count = 2;
  const Vec3f p1 = at(i1).point;
  int i2 = i0;
  float area2 = 0.0f;
  for (int k = 0; k < count; ++k) {
    if (const float a = twiceArea(n, p0, p1, at(k).point); std::abs(a) > std::abs(area2)) {
      area2 = a;
      i2 = k;
    }
  }
  if (std::abs(area2) <= tolerance * std::sqrt(farthest)) {
    return;
  }
  // The triangle p0, p1, p2 turns about n with the sign of area2; a point outside its edge u-v
  // adds the triangle (u, q, v) to it, twice-area -sign * twiceArea(n, u, v, q).
  const float sign = area2 > 0.0f ? 1.0f : -1.0f;
  const std::array<int, 3> triangle{i0, i1, i2};
  int i3 = -1;
  int after = 0; // the edge (triangle[after], triangle[after + 1]) it is outside of
  float added = 0.0f;
  for (int k = 0; k < count; ++k) {
    for (int e = 0; e < 3; ++e) {
      const Vec3f& u = at(triangle[static_cast<std::size_t>(e)]).point;
      const Vec3f& v = at(triangle[static_cast<std::size_t>((e + 1) % 3)]).point;
      if (const float a = -sign * twiceArea(n, u, v, at(k).point); a > added && a > tolerance * length(v - u)) {
        added = a;
        i3 = k;
        after = e;
      }
    }
  }
  out.count = 0;
  for (int e = 0; e < 3; ++e) {
    out.points[static_cast<std::size_t>(out.count++)] = at(triangle[static_cast<std::size_t>(e)]);
    if (i3 >= 0 && e == after) {
      out.points[static_cast<std::size_t>(out.count++)] = at(i3);
    }
  }
}

/// The incident hull's support point against `normal` (in its frame): its deepest vertex under
/// the reference face.
std::size_t deepestVertex(const Hull& incident, const Vec3f& normal) {
  std::size_t deepest = 0;
  for (std::size_t k = 1; k < incident.points.size(); ++k) {
    if (dot(normal, incident.points[k]) < dot(normal, incident.points[deepest])) {
      deepest = k;
    }
  }
  return deepest;
}

/// The incident face: of the faces around the deepest vertex, the one whose normal is the most
/// anti-parallel to the reference normal (`normal`, in the incident hull's frame). For a box it is
/// the most anti-parallel face of the hull; for a hull of faces in many directions that face may
/// lie far from the contact, while a face around the deepest vertex holds the deepest point.
std::size_t incidentFaceOf(const Hull& incident, const Vec3f& normal) {
  const auto vertex = static_cast<std::uint16_t>(deepestVertex(incident, normal));
  std::size_t start = 0;
  while (start < incident.edges.size() && incident.edges[start].origin != vertex) {
    ++start;
  }
  std::size_t best = 0;
  if (start == incident.edges.size()) {
    // A point on no face (makeHullFromFaces allows one inside): the most anti-parallel face.
    for (std::size_t f = 1; f < incident.planes.size(); ++f) {
      if (dot(incident.planes[f].normal, normal) < dot(incident.planes[best].normal, normal)) {
        best = f;
      }
    }
    return best;
  }
  // Around the vertex: the twin of a half-edge leaving it comes back to it, and the twin's next
  // leaves it again, on the next face (at most as many steps as half-edges, on any input).
  best = incident.edges[start].face;
  std::size_t e = start;
  for (std::size_t steps = 0; steps < incident.edges.size(); ++steps) {
    const std::size_t f = incident.edges[e].face;
    if (dot(incident.planes[f].normal, normal) < dot(incident.planes[best].normal, normal)) {
      best = f;
    }
    e = incident.edges[incident.edges[e].twin].next;
    if (e == start) {
      break;
    }
  }
  return best;
}

} // namespace

LocalContact faceContact(const Hull& reference, int face, const Transform3f& referenceToA, const Hull& incident,
                         const Transform3f& incidentToA, bool referenceIsB) {
  const ReferencePlane plane = referencePlane(reference, face, referenceToA);
  const auto faceBits = static_cast<std::uint32_t>(face);
  const std::size_t incidentFace = incidentFaceOf(incident, inverseRotate(incidentToA.q, plane.normal));
  std::array<ClipPolygon, 2> buffers;
  ClipPolygon* polygon = &buffers[0];
  ClipPolygon* scratch = &buffers[1];
  {
    const std::uint16_t first = incident.faceEdges[incidentFace];
    std::uint16_t e = first;
    do {
      const HullHalfEdge& edge = incident.edges[e];
      polygon->push({transformPoint(incidentToA, incident.points[edge.origin]),
                     featureId(FeatureKind::incidentVertex, referenceIsB, faceBits, edge.origin, 0),
                     std::min(e, edge.twin), false});
      e = edge.next;
    } while (e != first && polygon->count < maxHullVertices);
  }
  const float tolerance = sideTolerance(*polygon);
  {
    const std::uint16_t first = reference.faceEdges[static_cast<std::size_t>(face)];
    std::uint16_t e = first;
    int sides = 0;
    do {
      const HullHalfEdge& edge = reference.edges[e];
      const Vec3f from = transformPoint(referenceToA, reference.points[edge.origin]);
      const Vec3f to = transformPoint(referenceToA, reference.points[reference.edges[edge.next].origin]);
      const Vec3f side = normalize(cross(to - from, plane.normal)); // out of the face, in its plane
      clipToSide(*polygon, *scratch, side, dot(side, from), tolerance, e, referenceIsB, faceBits);
      std::swap(polygon, scratch);
      e = edge.next;
    } while (e != first && ++sides < maxHullVertices && polygon->count > 0);
  }
  std::array<LocalPoint, maxClipVertices> candidates;
  int count = 0;
  for (int k = 0; k < polygon->count; ++k) {
    const ClipVertex& v = polygon->vertices[static_cast<std::size_t>(k)];
    if (const LocalPoint p = pointOver(plane, v.point, v.id); p.separation <= speculativeDistance) {
      candidates[static_cast<std::size_t>(count++)] = p;
    }
  }
  LocalContact contact;
  reduceToFour(candidates, count, plane.normal, tolerance, contact);
  contact.normal = referenceIsB ? -plane.normal : plane.normal;
  return contact;
}

LocalContact deepestVertexContact(const Hull& reference, int face, const Transform3f& referenceToA,
                                  const Hull& incident, const Transform3f& incidentToA, bool referenceIsB) {
  const ReferencePlane plane = referencePlane(reference, face, referenceToA);
  const std::size_t deepest = deepestVertex(incident, inverseRotate(incidentToA.q, plane.normal));
  LocalContact contact;
  contact.points[0] = pointOver(plane, transformPoint(incidentToA, incident.points[deepest]),
                                featureId(FeatureKind::incidentVertex, referenceIsB, static_cast<std::uint32_t>(face),
                                          static_cast<std::uint32_t>(deepest), 0));
  contact.count = 1;
  contact.normal = referenceIsB ? -plane.normal : plane.normal;
  return contact;
}

} // namespace impetus::rigid3d::hullclip
