// Area, centroid and polar moment of inertia of a planar polygon (2D rigid bodies, ch. 9).
#pragma once

#include <impetus/math/vec2.hpp>

#include <span>

namespace impetus {

/// Mass properties of a uniform planar lamina.
struct PolygonMass {
  double area = 0.0;    ///< m^2 (always positive)
  Vec2d centroid{};     ///< m, in the vertices' frame
  double mass = 0.0;    ///< kg = density * area
  double inertia = 0.0; ///< kg m^2, about the z axis through the centroid
};

/// Mass properties of a simple (non-self-intersecting, convex or not) polygon of uniform areal
/// density (kg/m^2), vertices in either winding order. Sums signed triangles from the first
/// vertex: each triangle (r, a, b) adds area cross(a-r, b-r)/2 and polar moment
/// area/6 (|e1|^2 + e1.e2 + |e2|^2) about r. Throws impetus::Error for fewer than 3 vertices,
/// non-finite coordinates, a non-positive density or a zero area.
[[nodiscard]] PolygonMass polygonMass(std::span<const Vec2d> vertices, double density);

} // namespace impetus
