// A convex polyhedron for the 3D world's shapes (a box is one), as half-edges: each face a loop
// of half-edges counter-clockwise seen from outside, each half-edge with its twin on the
// neighbouring face, which is what the separating-axis test and clipping walk.
#pragma once

#include <impetus/math/quat.hpp>
#include <impetus/math/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace impetus::rigid3d {

/// One side of an edge: from `origin` to the origin of `next`, bounding `face`.
struct HullHalfEdge {
  std::uint16_t next = 0;   ///< the next half-edge of the face's loop
  std::uint16_t twin = 0;   ///< the other side of the edge
  std::uint16_t origin = 0; ///< vertex index
  std::uint16_t face = 0;
};

/// A plane n . x = offset, n a unit normal pointing out of the hull.
struct HullPlane {
  Vec3f normal;
  float offset = 0.0f; ///< m
};

struct Hull {
  std::vector<Vec3f> points;            ///< m, body frame
  std::vector<HullHalfEdge> edges;      ///< each face's loop in turn
  std::vector<std::uint16_t> faceEdges; ///< a half-edge of each face
  std::vector<HullPlane> planes;        ///< each face's plane
};

/// The most vertices a hull made from points keeps (computeHull): a rounded shape of more is
/// better a sphere or capsule, and the collision's cost grows with the count.
inline constexpr int maxHullVertices = 64;

/// The convex hull of a cloud of points (quickhull), its coplanar triangles merged into faces.
/// At most `maxVertices` (4 to maxHullVertices) of the points become vertices, the most extreme
/// first: beyond the cap the hull is that of those, and the other points may lie a little
/// outside it. Points within a few float epsilons of the cloud's extent of a face count as on it
/// (not vertices). Throws impetus::Error for fewer than four points, non-finite ones, or a cloud
/// without volume (all at one place, on a line or in a plane), naming which.
[[nodiscard]] Hull computeHull(std::span<const Vec3f> points, int maxVertices = maxHullVertices);

/// A box of the given half extents (each at least linearSlop; otherwise impetus::Error naming
/// `halfExtents`), centred at `center` and turned by `rotation` in the body frame.
[[nodiscard]] Hull makeBoxHull(const Vec3f& halfExtents, const Vec3f& center = {},
                               const Quatf& rotation = Quatf::identity());

/// A hull from its points and its faces, each a loop of point indices counter-clockwise seen
/// from outside (a closed convex polyhedron: every edge shared by two faces in opposite
/// directions); the half-edges and planes are built from them. Throws impetus::Error for a face
/// of fewer than three points, an index out of range or an edge not shared by exactly two faces.
[[nodiscard]] Hull makeHullFromFaces(std::vector<Vec3f> points, const std::vector<std::vector<std::uint16_t>>& faces);

} // namespace impetus::rigid3d
