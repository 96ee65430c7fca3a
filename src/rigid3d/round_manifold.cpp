// The manifolds of the round shapes (spheres and capsules): the closest points of their cores (a
// sphere's centre, a capsule's segment), the surfaces a radius out from them.
#include <impetus/rigid3d/constants.hpp>
#include <impetus/rigid3d/manifold.hpp>

#include "rigid3d/segment_closest.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace impetus::rigid3d {

namespace {

/// Cores closer than this have no direction between them (any normal is right for concentric
/// spheres): the world's up is used. m.
constexpr float minNormalDistance = 1.0e-9f;

/// Capsules whose axes are within this angle of parallel (its sine), and whose spans overlap
/// along A's axis, touch along a line: two points at the overlap's ends, so that the pair
/// rests without rocking (one point at the closest pair would be anywhere along the line).
constexpr float parallelCapsuleSine = 0.05f; // about 3 degrees

constexpr Vec3f up{0.0f, 1.0f, 0.0f};

void finishPoint(ManifoldPoint& mp, const Transform3f& xfA, const Transform3f& xfB) {
  mp.anchorA = mp.point - xfA.p;
  mp.anchorB = mp.point - xfB.p;
}

/// One point between cores pa (on A) and pb (on B) of radii ra and rb, or none beyond the
/// speculative distance (the separation noted as the pair's bound).
Manifold pointBetweenCores(const Vec3f& pa, float ra, const Vec3f& pb, float rb, const Transform3f& xfA,
                           const Transform3f& xfB, const Vec3f& fallbackNormal) {
  Manifold m;
  const float dist = length(pb - pa);
  const float separation = dist - ra - rb;
  if (separation > speculativeDistance) {
    m.separationBound = separation;
    return m;
  }
  m.normal = dist > minNormalDistance ? (pb - pa) * (1.0f / dist) : fallbackNormal;
  ManifoldPoint& mp = m.points[0];
  // Midway between the two surfaces along the normal.
  mp.point = ((pa + m.normal * ra) + (pb - m.normal * rb)) * 0.5f;
  mp.separation = separation;
  finishPoint(mp, xfA, xfB);
  m.pointCount = 1;
  return m;
}

/// A unit direction perpendicular to both axes where they cross, else to the first alone: the
/// normal of two segments whose closest points coincide.
Vec3f perpendicularTo(const Vec3f& d1, const Vec3f& d2) {
  if (const Vec3f c = cross(d1, d2); lengthSquared(c) > minNormalDistance * minNormalDistance) {
    return normalize(c);
  }
  // Crossed with the world axis it is least along.
  const Vec3f a{std::abs(d1.x), std::abs(d1.y), std::abs(d1.z)};
  const Vec3f axis = a.x <= a.y && a.x <= a.z ? Vec3f{1.0f, 0.0f, 0.0f}
                     : a.y <= a.z             ? Vec3f{0.0f, 1.0f, 0.0f}
                                              : Vec3f{0.0f, 0.0f, 1.0f};
  return normalize(cross(d1, axis));
}

/// The point of segment [p, q] closest to x.
Vec3f closestOnSegment(const Vec3f& p, const Vec3f& q, const Vec3f& x) {
  const Vec3f d = q - p;
  const float dd = dot(d, d);
  const float t = dd > 0.0f ? std::clamp(dot(x - p, d) / dd, 0.0f, 1.0f) : 0.0f;
  return p + d * t;
}

} // namespace

Manifold collideSpheres(const Sphere& a, const Transform3f& xfA, const Sphere& b, const Transform3f& xfB) {
  return pointBetweenCores(transformPoint(xfA, a.center), a.radius, transformPoint(xfB, b.center), b.radius, xfA, xfB,
                           up);
}

Manifold collideCapsuleAndSphere(const Capsule& a, const Transform3f& xfA, const Sphere& b, const Transform3f& xfB) {
  const Vec3f p = transformPoint(xfA, a.center1);
  const Vec3f q = transformPoint(xfA, a.center2);
  const Vec3f c = transformPoint(xfB, b.center);
  return pointBetweenCores(closestOnSegment(p, q, c), a.radius, c, b.radius, xfA, xfB, up);
}

Manifold collideCapsules(const Capsule& a, const Transform3f& xfA, const Capsule& b, const Transform3f& xfB) {
  const Vec3f p1 = transformPoint(xfA, a.center1);
  const Vec3f q1 = transformPoint(xfA, a.center2);
  const Vec3f p2 = transformPoint(xfB, b.center1);
  const Vec3f q2 = transformPoint(xfB, b.center2);
  float s = 0.0f;
  float t = 0.0f;
  closestBetweenSegments(p1, q1, p2, q2, s, t);
  const Vec3f d1 = q1 - p1;
  const Vec3f d2 = q2 - p2;
  const Vec3f closestA = p1 + d1 * s;
  const Vec3f closestB = p2 + d2 * t;
  Manifold m = pointBetweenCores(closestA, a.radius, closestB, b.radius, xfA, xfB, perpendicularTo(d1, d2));
  if (m.pointCount == 0) {
    return m;
  }
  const float lengthA = length(d1);
  const float lengthB = length(d2);
  const Vec3f axisA = d1 * (1.0f / lengthA);
  const Vec3f axisB = d2 * (1.0f / lengthB);
  if (length(cross(axisA, axisB)) > parallelCapsuleSine) {
    return m;
  }
  // Side by side: B's span along A's axis, clipped to A's; a point at each end of the overlap,
  // on the normal of the closest pair (the line between the axes).
  const float along2 = dot(p2 - p1, axisA);
  const float alongQ2 = dot(q2 - p1, axisA);
  const float lower = std::max(0.0f, std::min(along2, alongQ2));
  const float upper = std::min(lengthA, std::max(along2, alongQ2));
  if (upper - lower < linearSlop) {
    return m; // end to end, or barely overlapping: the one point
  }
  const Manifold single = m;
  const Vec3f normal = m.normal;
  m.pointCount = 0;
  for (const float along : {lower, upper}) {
    const Vec3f onA = p1 + axisA * along;
    const Vec3f onB = closestOnSegment(p2, q2, onA);
    const float separation = dot(onB - onA, normal) - a.radius - b.radius;
    if (separation > speculativeDistance) {
      continue;
    }
    ManifoldPoint& mp = m.points[static_cast<std::size_t>(m.pointCount)];
    mp.point = ((onA + normal * a.radius) + (onB - normal * b.radius)) * 0.5f;
    mp.separation = separation;
    mp.id = along == lower ? 1U : 2U;
    finishPoint(mp, xfA, xfB);
    ++m.pointCount;
  }
  return m.pointCount > 0 ? m : single;
}

} // namespace impetus::rigid3d
