// Contact manifolds of the 3D world: where two shapes touch or are about to (up to four points),
// the separation at each, the normal from shape A to shape B, and feature ids that stay the same
// while the same features touch (warm starting carries impulses by them). Points are kept while
// the separation is below speculativeDistance, so a contact acts before the shapes overlap. The
// round shapes' pairs, a hull against a round shape, and two hulls (the separating-axis test and
// clipping).
#pragma once

#include <impetus/math/transform3.hpp>
#include <impetus/rigid3d/geometry.hpp>

#include <array>
#include <cstdint>

namespace impetus::rigid3d {

struct ManifoldPoint {
  Vec3f point;             ///< world point midway between the two surfaces, m
  Vec3f anchorA;           ///< point relative to A's frame origin, world axes, m
  Vec3f anchorB;           ///< point relative to B's frame origin, world axes, m
  float separation = 0.0f; ///< negative when overlapping, m
  std::uint32_t id = 0;    ///< feature id: same features, same id
};

struct Manifold {
  std::array<ManifoldPoint, 4> points{};
  Vec3f normal; ///< unit, world, from A to B
  int pointCount = 0;
  /// With no points: the distance between the two shapes' surfaces, m (a lower bound where not
  /// computed exactly), or 0 where none was found.
  float separationBound = 0.0f;
};

[[nodiscard]] Manifold collideSpheres(const Sphere& a, const Transform3f& xfA, const Sphere& b, const Transform3f& xfB);
[[nodiscard]] Manifold collideCapsuleAndSphere(const Capsule& a, const Transform3f& xfA, const Sphere& b,
                                               const Transform3f& xfB);
/// A hull against a sphere: the closest points of the hull and the sphere's centre (GJK), or,
/// with the centre inside the hull, the face it is least deep behind.
[[nodiscard]] Manifold collideHullAndSphere(const Hull& a, const Transform3f& xfA, const Sphere& b,
                                            const Transform3f& xfB);
/// A hull against a capsule: two points where the capsule lies along a face (its axis within
/// about 3 degrees of the face's plane: the segment clipped to the face), else one at the closest
/// points of the hull and the segment, or, with the segment inside, at its deeper end behind the
/// face it is least deep behind.
[[nodiscard]] Manifold collideHullAndCapsule(const Hull& a, const Transform3f& xfA, const Capsule& b,
                                             const Transform3f& xfB);
/// Two hulls, by the separating-axis test (Gregorius, GDC 2013) in A's frame: the face normals of
/// both and the edge pairs whose arcs cross on the Gauss map (faces of the Minkowski difference).
/// A face axis is preferred to an edge axis unless the edge separates by 10% of the face
/// separation's magnitude plus half linearSlop more, A's face to B's unless B's separates by 2%
/// plus 0.1 linearSlop more, so that the choice holds from frame to frame. A face contact clips
/// the incident face (around the other hull's deepest vertex, the face most anti-parallel to the
/// reference face) to the reference face's side planes and keeps the points within
/// speculativeDistance of the reference plane, each midway between the incident point and its
/// projection, its separation its height; of more than four, the deepest, the farthest from it,
/// the largest triangle and the point adding the most area. An edge contact is one point midway
/// between the edges' closest points. Hulls apart whose contact misses their closest features
/// (edges closest at an end, a clip left empty) get one point at their GJK closest points;
/// overlapping ones whose clip is empty, the edge contact where its axis is as good, else the
/// incident hull's deepest vertex. Feature ids name the reference face and, per point, the
/// incident vertex, the incident edge and side plane that cut it, the reference corner, or the
/// edge pair (src/rigid3d/hull_clip.hpp). Beyond reach: no points, and separationBound a
/// separating axis' gap or the GJK distance (a lower bound on the distance, or the distance).
[[nodiscard]] Manifold collideHulls(const Hull& a, const Transform3f& xfA, const Hull& b, const Transform3f& xfB);
/// Two points where the capsules lie side by side (their axes within parallelCapsuleAngle and
/// their spans overlapping), one at the closest points of their segments otherwise.
[[nodiscard]] Manifold collideCapsules(const Capsule& a, const Transform3f& xfA, const Capsule& b,
                                       const Transform3f& xfB);

} // namespace impetus::rigid3d
