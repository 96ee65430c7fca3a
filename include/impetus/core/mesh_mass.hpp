// Volume, centre of mass and inertia tensor of a closed triangle mesh (a convex hull or any
// closed, outward-wound surface) of uniform density.
#pragma once

#include <impetus/core/mass_properties.hpp>

#include <array>
#include <cstdint>
#include <span>

namespace impetus {

using TriangleIndices = std::array<std::uint32_t, 3>;

/// Mass properties of the solid bounded by a closed triangle mesh whose triangles are wound
/// counter-clockwise seen from outside. Each triangle and a reference point form a signed
/// tetrahedron; their volumes, first moments and covariances (det/120 (aa^T + bb^T + cc^T +
/// (a+b+c)(a+b+c)^T)) add up to the solid's, exactly for any closed mesh.
///
/// Throws impetus::Error for a non-positive density, non-finite vertices, an index out of
/// range, a mesh that is not closed (an edge not shared by exactly two triangles in opposite
/// directions) or a non-positive volume (triangles wound inward).
[[nodiscard]] MassProperties3 meshMassProperties(std::span<const Vec3d> vertices,
                                                 std::span<const TriangleIndices> triangles, double density);

} // namespace impetus
