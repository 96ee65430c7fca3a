// The manifolds of hulls against round shapes: the closest points of the cores by GJK, or, where
// the core is inside the hull, the face it is least deep behind; a capsule lying along a face
// touches it at two points, its segment clipped to the face.
#include <impetus/rigid3d/constants.hpp>
#include <impetus/rigid3d/distance.hpp>
#include <impetus/rigid3d/manifold.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace impetus::rigid3d {

Manifold collideHullAndSphere(const Hull& a, const Transform3f& xfA, const Sphere& b, const Transform3f& xfB) {
  Manifold m;
  // In A's frame: the hull's points as they are.
  const Vec3f center = inverseTransformPoint(xfA, transformPoint(xfB, b.center));
  const DistanceOutput d = coreDistance({a.points, 0.0f}, {std::span<const Vec3f>(&center, 1), b.radius});
  Vec3f normal;
  Vec3f onHull;
  float separation = 0.0f;
  if (!d.overlap && d.distance > 0.0f) {
    separation = d.distance - b.radius;
    normal = (center - d.pointA) * (1.0f / d.distance);
    onHull = d.pointA;
  } else {
    // The centre is inside: push out through the face it is least deep behind.
    float least = -3.4e38f;
    for (const HullPlane& plane : a.planes) {
      if (const float s = dot(plane.normal, center) - plane.offset; s > least) {
        least = s;
        normal = plane.normal;
      }
    }
    separation = least - b.radius;
    onHull = center - normal * least;
  }
  if (separation > speculativeDistance) {
    m.separationBound = separation;
    return m;
  }
  m.normal = rotate(xfA.q, normal);
  ManifoldPoint& mp = m.points[0];
  mp.point = transformPoint(xfA, (onHull + (center - normal * b.radius)) * 0.5f);
  mp.separation = separation;
  mp.anchorA = mp.point - xfA.p;
  mp.anchorB = mp.point - xfB.p;
  m.pointCount = 1;
  return m;
}

namespace {

/// A capsule whose axis is within this angle of a face's plane (its sine) lies along the face:
/// two points, the segment clipped to the face, so that it rests without rocking.
constexpr float alongFaceSine = 0.05f; // about 3 degrees

/// The face of the hull whose normal is nearest `direction`.
std::size_t faceToward(const Hull& hull, const Vec3f& direction) {
  std::size_t best = 0;
  for (std::size_t f = 1; f < hull.planes.size(); ++f) {
    if (dot(hull.planes[f].normal, direction) > dot(hull.planes[best].normal, direction)) {
      best = f;
    }
  }
  return best;
}

/// Clips segment [p, q] to the prism over face f (its side planes: through each edge, facing
/// out of the face); false if nothing is left.
bool clipToFace(const Hull& hull, std::size_t f, Vec3f& p, Vec3f& q) {
  const Vec3f n = hull.planes[f].normal;
  const std::uint16_t first = hull.faceEdges[f];
  std::uint16_t e = first;
  do {
    const Vec3f& from = hull.points[hull.edges[e].origin];
    const Vec3f& to = hull.points[hull.edges[hull.edges[e].next].origin];
    const Vec3f side = normalize(cross(to - from, n)); // out of the face, in its plane
    const float dp = dot(side, p - from);
    const float dq = dot(side, q - from);
    if (dp > 0.0f && dq > 0.0f) {
      return false;
    }
    if (dp > 0.0f) {
      p = p + (q - p) * (dp / (dp - dq));
    } else if (dq > 0.0f) {
      q = q + (p - q) * (dq / (dq - dp));
    }
    e = hull.edges[e].next;
  } while (e != first);
  return true;
}

} // namespace

Manifold collideHullAndCapsule(const Hull& a, const Transform3f& xfA, const Capsule& b, const Transform3f& xfB) {
  Manifold m;
  const std::array<Vec3f, 2> segment{inverseTransformPoint(xfA, transformPoint(xfB, b.center1)),
                                     inverseTransformPoint(xfA, transformPoint(xfB, b.center2))};
  const DistanceOutput d = coreDistance({a.points, 0.0f}, {segment, b.radius});
  const Vec3f axis = normalize(segment[1] - segment[0]);
  Vec3f normal;
  std::size_t face = 0;
  if (!d.overlap && d.distance > 0.0f) {
    normal = (d.pointB - d.pointA) * (1.0f / d.distance);
    face = faceToward(a, normal);
    if (const float s = d.distance - b.radius; s > speculativeDistance) {
      m.separationBound = s;
      return m;
    }
  } else {
    // The segment is inside: the face whose plane it is least deep behind at its deeper end.
    float least = -3.4e38f;
    for (std::size_t f = 0; f < a.planes.size(); ++f) {
      const HullPlane& plane = a.planes[f];
      if (const float s = std::min(dot(plane.normal, segment[0]), dot(plane.normal, segment[1])) - plane.offset;
          s > least) {
        least = s;
        face = f;
      }
    }
    normal = a.planes[face].normal;
  }
  const HullPlane& plane = a.planes[face];
  Vec3f p = segment[0];
  Vec3f q = segment[1];
  const bool alongFace = std::abs(dot(axis, plane.normal)) < alongFaceSine && dot(normal, plane.normal) > 0.0f;
  const auto addPoint = [&](const Vec3f& onHull, const Vec3f& core, const Vec3f& n, float separation,
                            std::uint32_t id) {
    ManifoldPoint& mp = m.points[static_cast<std::size_t>(m.pointCount++)];
    mp.point = transformPoint(xfA, (onHull + (core - n * b.radius)) * 0.5f);
    mp.separation = separation;
    mp.id = id;
    mp.anchorA = mp.point - xfA.p;
    mp.anchorB = mp.point - xfB.p;
  };
  if (alongFace && clipToFace(a, face, p, q)) {
    for (const auto& [core, id] : {std::pair{p, 1U}, std::pair{q, 2U}}) {
      const float height = dot(plane.normal, core) - plane.offset;
      if (height - b.radius <= speculativeDistance) {
        addPoint(core - plane.normal * height, core, plane.normal, height - b.radius, id);
      }
    }
    if (m.pointCount > 0) {
      m.normal = rotate(xfA.q, plane.normal);
      return m;
    }
  }
  if (!d.overlap && d.distance > 0.0f) {
    addPoint(d.pointA, d.pointB, normal, d.distance - b.radius, 0U);
  } else {
    // The segment's deeper end, pushed out through the face.
    const float h0 = dot(plane.normal, segment[0]) - plane.offset;
    const float h1 = dot(plane.normal, segment[1]) - plane.offset;
    const Vec3f core = h0 < h1 ? segment[0] : segment[1];
    const float height = std::min(h0, h1);
    addPoint(core - plane.normal * height, core, plane.normal, height - b.radius, 0U);
  }
  m.normal = rotate(xfA.q, normal);
  return m;
}

} // namespace impetus::rigid3d
