// The narrowphase of circles, and the shapes as the narrowphase sees them (asPolygon): a circle
// against a circle, and against a polygon, capsule or segment. Polygon pairs (capsules and
// segments as 2-vertex polygons) are in polygon_manifold.cpp.
#include <impetus/rigid2d/manifold.hpp>

#include "rigid2d/manifold_internal.hpp"

#include <limits>

namespace impetus::rigid2d {
namespace {

using detail::minNormalDistance;

void finishPoint(ManifoldPoint& mp, const Transform2f& xfA, const Transform2f& xfB) {
  mp.anchorA = mp.point - xfA.p;
  mp.anchorB = mp.point - xfB.p;
}

} // namespace

Polygon asPolygon(const Circle& circle) {
  Polygon p;
  p.count = 1;
  p.vertices[0] = circle.center;
  p.centroid = circle.center;
  p.radius = circle.radius;
  return p;
}

Polygon asPolygon(const Capsule& capsule) {
  Polygon p;
  p.count = 2;
  p.vertices[0] = capsule.center1;
  p.vertices[1] = capsule.center2;
  const Vec2f axis = normalize(capsule.center2 - capsule.center1);
  p.normals[0] = {axis.y, -axis.x};
  p.normals[1] = -p.normals[0];
  p.centroid = (capsule.center1 + capsule.center2) * 0.5f;
  p.radius = capsule.radius;
  return p;
}

Polygon asPolygon(const Segment& segment) { return asPolygon(Capsule{segment.point1, segment.point2, 0.0f}); }

Manifold collideCircles(const Circle& a, const Transform2f& xfA, const Circle& b, const Transform2f& xfB) {
  Manifold m;
  const Vec2f pa = transformPoint(xfA, a.center);
  const Vec2f pb = transformPoint(xfB, b.center);
  const float dist = distance(pa, pb);
  const float separation = dist - a.radius - b.radius;
  if (separation > speculativeDistance) {
    m.separationBound = separation;
    return m;
  }
  // Centres closer than minNormalDistance have no direction between them (any normal is right
  // for concentric circles): up.
  m.normal = dist > minNormalDistance ? (pb - pa) / dist : Vec2f{0.0f, 1.0f};
  ManifoldPoint& mp = m.points[0];
  // Midway between the two surfaces along the normal.
  mp.point = lerp(pa + m.normal * a.radius, pb - m.normal * b.radius, 0.5f);
  mp.separation = separation;
  finishPoint(mp, xfA, xfB);
  m.pointCount = 1;
  return m;
}

Manifold collidePolygonAndCircle(const Polygon& a, const Transform2f& xfA, const Circle& b, const Transform2f& xfB) {
  Manifold m;
  const Vec2f c = inverseTransformPoint(xfA, transformPoint(xfB, b.center)); // in A's frame
  const float radius = a.radius + b.radius;
  Vec2f normal;
  float separation = 0.0f;
  if (a.count == 1) {
    const Vec2f d = c - a.vertices[0];
    const float len = length(d);
    normal = len > minNormalDistance ? d / len : Vec2f{0.0f, 1.0f};
    separation = len - radius;
  } else {
    // The face of greatest separation; then, if the centre is beyond that face's ends, the
    // nearest vertex decides (its Voronoi region).
    int face = 0;
    float faceSeparation = -std::numeric_limits<float>::max();
    for (int i = 0; i < a.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const float s = dot(a.normals[k], c - a.vertices[k]);
      if (s > faceSeparation) {
        faceSeparation = s;
        face = i;
      }
    }
    const Vec2f v1 = a.vertices[static_cast<std::size_t>(face)];
    const Vec2f v2 = a.vertices[static_cast<std::size_t>((face + 1) % a.count)];
    const Vec2f edge = v2 - v1;
    const float u = dot(c - v1, edge);
    // On or outside the face's plane and beyond one of its ends: the end vertex is the closest
    // feature. (">= 0", not "> 0": a centre on a segment's or capsule core's line, beyond its
    // end, has a face separation of exactly 0 and got a phantom contact at any distance.) A
    // segment (2 vertices) has no inside: beyond an end, that end is the closest point whatever
    // the sign (on its line far from the origin both faces' separations can round below 0).
    if ((faceSeparation >= 0.0f || a.count == 2) && (u < 0.0f || u > dot(edge, edge))) {
      const Vec2f vertex = u < 0.0f ? v1 : v2;
      const Vec2f d = c - vertex;
      const float len = length(d);
      // A centre on the vertex (within minNormalDistance): the face's normal, one of the
      // directions of the vertex's region.
      normal = len > minNormalDistance ? d / len : a.normals[static_cast<std::size_t>(face)];
      separation = len - radius;
    } else {
      normal = a.normals[static_cast<std::size_t>(face)];
      separation = faceSeparation - radius;
    }
  }
  if (separation > speculativeDistance) {
    // The centre's distance from the face's line (or its vertex), less the radii: at most its
    // distance from the polygon.
    m.separationBound = separation;
    return m;
  }
  m.normal = rotate(xfA.q, normal);
  const Vec2f cWorld = transformPoint(xfB, b.center);
  ManifoldPoint& mp = m.points[0];
  // Circle surface point and A's surface point, midway.
  const Vec2f onB = cWorld - m.normal * b.radius;
  const Vec2f onA = onB - m.normal * separation;
  mp.point = lerp(onA, onB, 0.5f);
  mp.separation = separation;
  finishPoint(mp, xfA, xfB);
  m.pointCount = 1;
  return m;
}

} // namespace impetus::rigid2d
