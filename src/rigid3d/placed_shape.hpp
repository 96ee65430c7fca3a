// A shape's core points placed in the world, as GJK reads them: what continuous collision and
// the overlap queries measure distances between.
#pragma once

#include <impetus/math/transform3.hpp>
#include <impetus/rigid3d/distance.hpp>
#include <impetus/rigid3d/geometry.hpp>

#include <algorithm>
#include <array>
#include <span>
#include <variant>

namespace impetus::rigid3d::detail {

/// A shape's core points (a sphere's centre, a capsule's two centres, a hull's vertices) placed
/// by a transform, and its radius: what GJK reads.
struct PlacedShape {
  std::array<Vec3f, maxHullVertices> points{};
  int count = 0;
  float radius = 0.0f;

  void place(const ShapeGeometry& geometry, const Transform3f& xf) {
    count = 0;
    std::visit(
        [&](const auto& g) {
          using G = std::decay_t<decltype(g)>;
          if constexpr (std::is_same_v<G, Sphere>) {
            points[0] = transformPoint(xf, g.center);
            count = 1;
            radius = g.radius;
          } else if constexpr (std::is_same_v<G, Capsule>) {
            points[0] = transformPoint(xf, g.center1);
            points[1] = transformPoint(xf, g.center2);
            count = 2;
            radius = g.radius;
          } else {
            // A hull has at most maxHullVertices points when made from a cloud; one made from
            // faces with more is read up to that many (its GJK distance then a bound from below
            // of the rest's: the sweep still stops short of the face).
            count = static_cast<int>(std::min<std::size_t>(g.points.size(), points.size()));
            for (int i = 0; i < count; ++i) {
              points[static_cast<std::size_t>(i)] = transformPoint(xf, g.points[static_cast<std::size_t>(i)]);
            }
            radius = 0.0f;
          }
        },
        geometry);
  }
  [[nodiscard]] DistanceProxy proxy() const {
    return {std::span<const Vec3f>(points.data(), static_cast<std::size_t>(count)), radius};
  }
};

/// The distance between two placed shapes' surfaces, m; where their cores overlap, minus the
/// sum of their radii (a bound: the overlap is at least that deep).
inline float surfaceDistance(const PlacedShape& a, const PlacedShape& b) {
  const DistanceOutput d = coreDistance(a.proxy(), b.proxy());
  return d.overlap ? -(a.radius + b.radius) : d.distance - a.radius - b.radius;
}

} // namespace impetus::rigid3d::detail
