#include <impetus/core/mesh_mass.hpp>
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace impetus {
namespace {

/// Every directed edge must meet its reverse exactly once: then the surface is closed and
/// consistently wound.
void requireClosed(std::span<const TriangleIndices> triangles) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(triangles.size() * 3);
  for (const TriangleIndices& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      edges.emplace_back(t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]);
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto [a, b] = edges[i];
    const bool duplicated = i + 1 < edges.size() && edges[i + 1] == edges[i];
    const bool hasReverse = std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a));
    if (duplicated || !hasReverse || a == b) {
      throwInvalid("triangles edge " + std::to_string(a) + "->" + std::to_string(b), static_cast<double>(a),
                   "mesh is not a closed, consistently wound surface");
    }
  }
}

} // namespace

MassProperties3 meshMassProperties(std::span<const Vec3d> vertices, std::span<const TriangleIndices> triangles,
                                   double density) {
  requirePositive(density, "density");
  if (triangles.size() < 4) {
    throwInvalid("triangles.size", static_cast<double>(triangles.size()), "a closed mesh needs at least 4 triangles");
  }
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    requireFinite(vertices[i], "vertices[" + std::to_string(i) + "]");
  }
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    for (std::uint32_t index : triangles[i]) {
      if (index >= vertices.size()) {
        throwInvalid("triangles[" + std::to_string(i) + "] index", static_cast<double>(index),
                     "vertex index out of range");
      }
    }
  }
  requireClosed(triangles);
  // Tetrahedra from the average of the triangles' corners keep the sums well conditioned far
  // from the origin (vertices no triangle uses play no part).
  Vec3d reference{};
  for (const TriangleIndices& t : triangles) {
    reference += vertices[t[0]] + vertices[t[1]] + vertices[t[2]];
  }
  reference /= static_cast<double>(3 * triangles.size());

  double sixVolume = 0.0; // sum of det = 6 V
  Vec3d firstMoment24{};  // sum of det (a + b + c) = 24 V c
  Mat33d covariance120{}; // sum of det (...) = 120 C
  for (const TriangleIndices& t : triangles) {
    const Vec3d a = vertices[t[0]] - reference;
    const Vec3d b = vertices[t[1]] - reference;
    const Vec3d c = vertices[t[2]] - reference;
    const double det = tripleScalarProduct(a, b, c);
    const Vec3d s = a + b + c;
    sixVolume += det;
    firstMoment24 += s * det;
    covariance120 += (outer(a, a) + outer(b, b) + outer(c, c) + outer(s, s)) * det;
  }
  const double volume = sixVolume / 6.0;
  if (!(volume > 0.0)) {
    throwInvalid("volume", volume, "mesh encloses no volume or its triangles are wound inward");
  }
  const Vec3d centroid = firstMoment24 / (4.0 * sixVolume);
  // Second moment about the centroid: C_c = C - V c c^T; inertia = density (tr(C) E - C).
  const Mat33d covariance = covariance120 / 120.0 - outer(centroid, centroid) * volume;
  MassProperties3 result;
  result.mass = density * volume;
  result.centerOfMass = reference + centroid;
  result.inertia = (Mat33d::identity() * trace(covariance) - covariance) * density;
  return result;
}

} // namespace impetus
