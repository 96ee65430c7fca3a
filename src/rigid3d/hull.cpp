// Hulls from faces, and the box.
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/rigid3d/constants.hpp>
#include <impetus/rigid3d/hull.hpp>

#include <cstddef>
#include <map>
#include <string>
#include <utility>

namespace impetus::rigid3d {

Hull makeHullFromFaces(std::vector<Vec3f> points, const std::vector<std::vector<std::uint16_t>>& faces) {
  Hull hull;
  hull.points = std::move(points);
  for (std::size_t i = 0; i < hull.points.size(); ++i) {
    requireFinite(hull.points[i], "points[" + std::to_string(i) + "]");
  }
  // Each directed edge (a, b) of a face's loop, and where it is in the half-edge array.
  std::map<std::pair<std::uint16_t, std::uint16_t>, std::uint16_t> directed;
  std::vector<std::uint16_t> loopEdges;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::vector<std::uint16_t>& loop = faces[f];
    if (loop.size() < 3) {
      throwInvalid("faces[" + std::to_string(f) + "] size", static_cast<double>(loop.size()),
                   "a face has at least three points");
    }
    const auto first = static_cast<std::uint16_t>(hull.edges.size());
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const std::uint16_t a = loop[k];
      const std::uint16_t b = loop[(k + 1) % loop.size()];
      if (a >= hull.points.size() || b >= hull.points.size()) {
        throwInvalid("faces[" + std::to_string(f) + "] index", a >= hull.points.size() ? a : b,
                     "must name one of the points");
      }
      HullHalfEdge e;
      e.origin = a;
      e.face = static_cast<std::uint16_t>(f);
      e.next = static_cast<std::uint16_t>(first + (k + 1) % loop.size());
      if (!directed.emplace(std::pair{a, b}, static_cast<std::uint16_t>(hull.edges.size())).second) {
        throwInvalid("faces[" + std::to_string(f) + "] edge from", a, "is in two faces the same way (not closed)");
      }
      hull.edges.push_back(e);
    }
    hull.faceEdges.push_back(first);
    // The plane: Newell's normal of the loop (robust for any convex polygon), through its centroid.
    Vec3f normal;
    Vec3f centroid;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Vec3f& p = hull.points[loop[k]];
      const Vec3f& q = hull.points[loop[(k + 1) % loop.size()]];
      normal += cross(p, q);
      centroid += p;
    }
    centroid = centroid * (1.0f / static_cast<float>(loop.size()));
    normal = normalize(normal);
    hull.planes.push_back({normal, dot(normal, centroid)});
  }
  for (HullHalfEdge& e : hull.edges) {
    const std::uint16_t b = hull.edges[e.next].origin;
    const auto twin = directed.find({b, e.origin});
    if (twin == directed.end()) {
      throwInvalid("edge from", e.origin, "has no twin: the faces do not close the hull");
    }
    e.twin = twin->second;
  }
  return hull;
}

Hull makeBoxHull(const Vec3f& halfExtents, const Vec3f& center, const Quatf& rotation) {
  for (int i = 0; i < 3; ++i) {
    if (!(std::isfinite(halfExtents[i]) && halfExtents[i] >= linearSlop)) {
      throwInvalid(std::string("halfExtents.") + "xyz"[i], halfExtents[i],
                   "must be finite and at least linearSlop (0.005 m)");
    }
  }
  requireFinite(center, "center");
  const Quatf q = normalize(rotation);
  std::vector<Vec3f> points;
  for (int k = 0; k < 8; ++k) {
    const Vec3f corner{(k & 1) != 0 ? halfExtents.x : -halfExtents.x, (k & 2) != 0 ? halfExtents.y : -halfExtents.y,
                       (k & 4) != 0 ? halfExtents.z : -halfExtents.z};
    points.push_back(center + rotate(q, corner));
  }
  // Corner k has bit 0 for +x, bit 1 for +y, bit 2 for +z; each face's loop counter-clockwise
  // seen from outside.
  const std::vector<std::vector<std::uint16_t>> faces = {
      {1, 3, 7, 5}, // +x
      {0, 4, 6, 2}, // -x
      {2, 6, 7, 3}, // +y
      {0, 1, 5, 4}, // -y
      {4, 5, 7, 6}, // +z
      {0, 2, 3, 1}, // -z
  };
  return makeHullFromFaces(std::move(points), faces);
}

} // namespace impetus::rigid3d
