// The 2D collision shapes, in their body's local frame: circle, capsule, convex polygon (up to
// 8 vertices, optionally rounded) and segment; their mass properties, bounding boxes and ray
// casts. Convex polygons are built from points through a convex hull.
#pragma once

#include <impetus/math/transform2.hpp>
#include <impetus/rigid2d/aabb.hpp>
#include <impetus/rigid2d/constants.hpp>

#include <array>
#include <span>

namespace impetus::rigid2d {

struct Circle {
  Vec2f center; ///< m, local
  float radius = 0.5f;
};

/// A segment with a radius: a stadium. centers are the two ends of its core segment.
struct Capsule {
  Vec2f center1;
  Vec2f center2;
  float radius = 0.25f;
};

struct Segment {
  Vec2f point1;
  Vec2f point2;
};

/// A convex polygon, counter-clockwise, with an optional rounding radius (a polygon inflated by
/// `radius`, as Box2D's rounded polygons). Built only by the functions below, which guarantee
/// convexity, winding and no collinear or repeated vertices.
struct Polygon {
  std::array<Vec2f, maxPolygonVertices> vertices{};
  std::array<Vec2f, maxPolygonVertices> normals{}; ///< outward unit normal of edge i -> i+1
  Vec2f centroid;
  float radius = 0.0f;
  int count = 0;
};

/// Bound on polygon vertex coordinates (in the body's frame) and rounding radii, m. Within it
/// the mass data stay finite in float (inertia at density 1 below 1e26 kg m^2 at the bound, the
/// float limit 3e38) and the hull's double-precision tests round by less than 1e-9 m. Beyond
/// about 3e4 m float spacing exceeds linearSlop, so such vertices are only as precise as float.
inline constexpr float maxPolygonCoordinate = 1.0e6f;

/// The convex hull of 3 to 8 points: counter-clockwise and convex, starting at the lowest x
/// (then lowest y); its vertices are input points, none closer than linearSlop to another
/// (closer points are welded) and none within linearSlop of the line through its neighbours
/// (removed one at a time, the flattest first), so every input point lies inside the hull or
/// within a few linearSlop of it. Throws impetus::Error naming `points.size` for fewer than 3 or
/// more than 8 points, `points[i].x`/`.y` for a coordinate that is not finite or beyond
/// maxPolygonCoordinate, and `points` when the hull has no area (collinear or welded points).
[[nodiscard]] std::span<const Vec2f> computeHull(std::span<const Vec2f> points, std::array<Vec2f, 8>& storage);

/// A polygon from arbitrary points (their hull) and a rounding radius in [0, maxPolygonCoordinate].
[[nodiscard]] Polygon makePolygon(std::span<const Vec2f> points, float radius = 0.0f);
/// A box of half-widths hx, hy centred on the origin.
[[nodiscard]] Polygon makeBox(float halfWidth, float halfHeight);
/// A box of half-widths hx, hy centred at `center`, rotated by `angle` radians. Each half-width
/// must lie in [linearSlop, maxPolygonCoordinate] (a thinner box would weld corners or lose one as
/// collinear and come out a triangle), as must |center| and the corners' coordinates
/// (`corners[i]`, in the order (-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)). A box whose corners
/// float rounding far from the origin welds is refused naming its thinner half-width.
[[nodiscard]] Polygon makeOffsetBox(float halfWidth, float halfHeight, const Vec2f& center, float angle);

/// Checks a shape filled in by hand (the structs are plain; World::createShape calls these) and
/// throws impetus::Error naming the field and its value where it is not a shape the makers would
/// build. Every point finite and within maxPolygonCoordinate of the body origin (`center.x`,
/// `point2.y`, `polygon.vertices[i].x`, ...); a circle's or capsule's `radius` finite, positive
/// and at most maxPolygonCoordinate, a polygon's (`polygon.radius`) the same or 0; a capsule's or
/// segment's ends more than linearSlop apart (`center2`, `point2`). A polygon as makePolygon
/// returns it: 3 to 8 vertices (`polygon.count`), each at least linearSlop from the one before
/// it and more than linearSlop outside the line through its neighbours (convex, counter-clockwise:
/// `polygon.vertices[i]`), turning once round (`polygon.vertices`); `polygon.normals[i]` the
/// outward unit normal of edge i -> i+1 to 1e-3; `polygon.centroid` finite and inside (within
/// linearSlop and its rounding). Every polygon from makePolygon, makeBox or makeOffsetBox passes.
void validateShape(const Circle& shape);
void validateShape(const Capsule& shape);
void validateShape(const Polygon& shape);
void validateShape(const Segment& shape);

/// Mass, centre of mass (local) and rotational inertia about the centre of mass.
struct MassData {
  float mass = 0.0f;              ///< kg
  Vec2f center;                   ///< m, local
  float rotationalInertia = 0.0f; ///< kg m^2, about `center`
};

/// Mass properties at an areal density (kg/m^2, > 0). A segment has none. Throws impetus::Error
/// naming `density` where the mass or the rotational inertia would not be a finite, normal float
/// (above 3.4e38 or below 1.2e-38: a body needs their inverses). A square of side s has inertia
/// density s^4 / 6: the largest, 2e6 m across, is refused above about 1.3e14 kg/m^2.
[[nodiscard]] MassData computeMass(const Circle& shape, float density);
[[nodiscard]] MassData computeMass(const Capsule& shape, float density);
[[nodiscard]] MassData computeMass(const Polygon& shape, float density);

/// World bounding boxes.
[[nodiscard]] AABB computeAABB(const Circle& shape, const Transform2f& xf);
[[nodiscard]] AABB computeAABB(const Capsule& shape, const Transform2f& xf);
[[nodiscard]] AABB computeAABB(const Polygon& shape, const Transform2f& xf);
[[nodiscard]] AABB computeAABB(const Segment& shape, const Transform2f& xf);

/// A ray (segment) p1 -> p2 in the shape's frame and the result of casting it.
struct RayCastInput {
  Vec2f origin;
  Vec2f translation; ///< the ray is origin + t translation, t in [0, maxFraction]
  float maxFraction = 1.0f;
};
struct CastOutput {
  Vec2f normal; ///< surface normal at the hit
  Vec2f point;  ///< hit point
  float fraction = 0.0f;
  bool hit = false;
};

/// First hit of the ray on the shape's boundary from outside (a ray starting inside does not hit).
[[nodiscard]] CastOutput rayCast(const Circle& shape, const RayCastInput& ray);
[[nodiscard]] CastOutput rayCast(const Capsule& shape, const RayCastInput& ray);
[[nodiscard]] CastOutput rayCast(const Polygon& shape, const RayCastInput& ray);
[[nodiscard]] CastOutput rayCast(const Segment& shape, const RayCastInput& ray);

/// Whether a local point is inside the shape.
[[nodiscard]] bool containsPoint(const Circle& shape, const Vec2f& p);
[[nodiscard]] bool containsPoint(const Capsule& shape, const Vec2f& p);
[[nodiscard]] bool containsPoint(const Polygon& shape, const Vec2f& p);

} // namespace impetus::rigid2d
