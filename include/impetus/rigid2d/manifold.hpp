// Contact manifolds: where two shapes touch or are about to (up to two points), with the
// separation at each point, the normal from shape A to shape B, and feature ids that stay the
// same while the same vertex and edge are in contact (the solver carries impulses across steps
// by them: warm starting). Points are kept while the separation is below speculativeDistance,
// so a contact acts before the shapes overlap.
#pragma once

#include <impetus/rigid2d/geometry.hpp>

#include <array>
#include <cstdint>

namespace impetus::rigid2d {

struct ManifoldPoint {
  Vec2f point;                 ///< world point midway between the two surfaces, m
  Vec2f anchorA;               ///< point relative to A's frame origin, world axes, m
  Vec2f anchorB;               ///< point relative to B's frame origin, world axes, m
  float separation = 0.0f;     ///< negative when overlapping, m
  float normalImpulse = 0.0f;  ///< solver state, N s (carried by id)
  float tangentImpulse = 0.0f; ///< solver state, N s
  std::uint16_t id = 0;        ///< feature id: same features, same id
};

struct Manifold {
  std::array<ManifoldPoint, 2> points{};
  Vec2f normal; ///< unit, world, from A to B
  int pointCount = 0;
  /// With no points: a lower bound on the distance between the two shapes' surfaces, m (how far
  /// apart the separating axis that ended the search found them), or 0 where none was found.
  /// A pair that moves less than this less speculativeDistance relative to itself cannot
  /// touch: the world collides it again only then.
  float separationBound = 0.0f;
};

/// A shape as the narrowphase sees it: a convex polygon of 1 to 8 vertices with a radius.
/// Circles (1 vertex), capsules and segments (2 vertices) and polygons all reduce to it.
[[nodiscard]] Polygon asPolygon(const Circle& circle);
[[nodiscard]] Polygon asPolygon(const Capsule& capsule);
[[nodiscard]] Polygon asPolygon(const Segment& segment);

[[nodiscard]] Manifold collideCircles(const Circle& a, const Transform2f& xfA, const Circle& b, const Transform2f& xfB);
/// Polygon (or capsule/segment as a 2-vertex polygon) against a circle.
[[nodiscard]] Manifold collidePolygonAndCircle(const Polygon& a, const Transform2f& xfA, const Circle& b,
                                               const Transform2f& xfB);
/// Polygon against polygon by the separating-axis test and reference-face clipping; either may
/// be a 2-vertex polygon (capsule or segment), and both may be rounded.
[[nodiscard]] Manifold collidePolygons(const Polygon& a, const Transform2f& xfA, const Polygon& b,
                                       const Transform2f& xfB);

} // namespace impetus::rigid2d
