// The 3D world's shapes, in their body's frame, and their mass properties: spheres, capsules and
// convex hulls (boxes: makeBoxHull) so far; hulls from points, meshes, heightfields and
// compounds come with collision.
#pragma once

#include <impetus/core/mass_properties.hpp>
#include <impetus/math/vec3.hpp>
#include <impetus/rigid3d/hull.hpp>

#include <variant>

namespace impetus::rigid3d {

/// A solid ball.
struct Sphere {
  Vec3f center;        ///< m, body frame
  float radius = 0.0f; ///< m
};

/// A solid capsule: the points within `radius` of the segment from center1 to center2 (a
/// cylinder with hemispherical caps).
struct Capsule {
  Vec3f center1; ///< m, body frame
  Vec3f center2;
  float radius = 0.0f; ///< m
};

using ShapeGeometry = std::variant<Sphere, Capsule, Hull>;

/// Throws impetus::Error, naming the field, unless the geometry is a solid a world can hold:
/// finite, a radius of at least linearSlop, a capsule's centres at least linearSlop apart (closer,
/// it is a sphere), a hull of at least four points and faces, closed, with every point on or
/// behind every face's plane (convex).
void requireValidGeometry(const ShapeGeometry& geometry);

/// The mass properties of a shape of uniform density (kg/m^3): its mass, its centroid in the body
/// frame and its inertia tensor about the centroid in the body axes.
[[nodiscard]] MassProperties3 massProperties(const ShapeGeometry& geometry, double density);

} // namespace impetus::rigid3d
