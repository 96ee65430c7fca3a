// Ray casts against the 3D world's shapes: the first point where a ray (a segment, origin +
// t translation for t in [0, maxFraction]) enters a sphere, a capsule or a hull, with the
// surface normal there. The shapes are solid and closed: a ray touching the surface (tangent to
// a sphere, along a face) hits it; a ray whose origin is inside a shape or on its surface does
// not (it sees out of the shape, as the 2D world's casts and Box2D v3's do).
#pragma once

#include <impetus/math/transform3.hpp>
#include <impetus/rigid3d/geometry.hpp>

namespace impetus::rigid3d {

/// A ray in the frame the cast's transform maps into (the world, for a body's transform).
struct RayCastInput {
  Vec3f origin;             ///< m
  Vec3f translation;        ///< the ray is origin + t translation, t in [0, maxFraction]; m
  float maxFraction = 1.0f; ///< of translation, dimensionless
};

/// Where a ray first meets a shape, in the same frame as the ray.
struct CastOutput {
  Vec3f normal;          ///< unit, out of the shape at the hit
  Vec3f point;           ///< origin + fraction translation, on the surface, m
  float fraction = 0.0f; ///< of translation, in [0, maxFraction]
  bool hit = false;      ///< false: no hit, and the other fields are zero
};

/// The first hit of `ray` (world coordinates) on a shape given in its body's frame, the body at
/// `xf`. No hit for a ray starting inside the shape or on its surface, a zero translation, or a
/// shape beyond maxFraction. Throws impetus::Error naming the field for a non-finite origin or
/// translation ("origin.x") or a maxFraction that is negative or not finite ("maxFraction").
[[nodiscard]] CastOutput rayCast(const Sphere& shape, const Transform3f& xf, const RayCastInput& ray);
/// A capsule's hit is the first of its cylinder's side (between the two centres' planes across
/// the axis) and its two end spheres.
[[nodiscard]] CastOutput rayCast(const Capsule& shape, const Transform3f& xf, const RayCastInput& ray);
/// A hull's hit clips the ray against each face's plane (Cyrus-Beck: Ericson, Real-Time
/// Collision Detection 5.3.8): the last plane it enters before leaving any is the face hit.
[[nodiscard]] CastOutput rayCast(const Hull& shape, const Transform3f& xf, const RayCastInput& ray);
[[nodiscard]] CastOutput rayCast(const ShapeGeometry& shape, const Transform3f& xf, const RayCastInput& ray);

} // namespace impetus::rigid3d
