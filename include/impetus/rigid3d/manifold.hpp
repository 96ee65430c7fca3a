// Contact manifolds of the 3D world: where two shapes touch or are about to (up to four points),
// the separation at each, the normal from shape A to shape B, and feature ids that stay the same
// while the same features touch (warm starting carries impulses by them). Points are kept while
// the separation is below speculativeDistance, so a contact acts before the shapes overlap. The
// round shapes' pairs and a hull against a sphere so far; hull pairs come with the separating-
// axis test.
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
/// Two points where the capsules lie side by side (their axes within parallelCapsuleAngle and
/// their spans overlapping), one at the closest points of their segments otherwise.
[[nodiscard]] Manifold collideCapsules(const Capsule& a, const Transform3f& xfA, const Capsule& b,
                                       const Transform3f& xfB);

} // namespace impetus::rigid3d
