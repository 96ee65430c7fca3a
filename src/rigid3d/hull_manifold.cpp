// The manifolds of hulls against round shapes: the closest points of the cores by GJK, or, where
// a sphere's centre is inside the hull, the face it is least deep behind.
#include <impetus/rigid3d/constants.hpp>
#include <impetus/rigid3d/distance.hpp>
#include <impetus/rigid3d/manifold.hpp>

#include <cstddef>

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

} // namespace impetus::rigid3d
