// Distance between convex shapes (GJK), shape casts (one shape translated against another) and
// time of impact (two shapes moving and turning over a step), after Box2D v3's distance.c.
//
// Every shape reduces to a ShapeProxy: the convex hull of 1 to 8 points inflated by a radius
// (a circle is one point, a capsule two, a rounded polygon its vertices). GJK works on the hull
// of the points (the core) and the radii are applied afterwards, so rounded shapes cost nothing
// extra. Lengths are metres; times are fractions of the sweep in [0, 1].
#pragma once

#include <impetus/rigid2d/geometry.hpp>

#include <array>
#include <cstdint>
#include <span>

namespace impetus::rigid2d {

/// A convex shape as GJK sees it: the hull of `count` points in the shape's local frame, inflated
/// by `radius`. The points need not be in any order, nor be a hull's vertices exactly.
struct ShapeProxy {
  std::array<Vec2f, maxPolygonVertices> points{}; ///< m, local
  int count = 0;                                  ///< 1..maxPolygonVertices
  float radius = 0.0f;                            ///< m, >= 0
};

/// A proxy of 1 to 8 finite points and a finite radius >= 0. Throws impetus::Error naming
/// `points` (count out of range, a point not finite) or `radius`.
[[nodiscard]] ShapeProxy makeProxy(std::span<const Vec2f> points, float radius);
/// The proxy of a polygon: its vertices and rounding radius.
[[nodiscard]] ShapeProxy makeProxy(const Polygon& polygon);
/// The proxy of a circle: its centre and radius.
[[nodiscard]] ShapeProxy makeProxy(const Circle& circle);
/// The proxy of a capsule: its two core centres and radius.
[[nodiscard]] ShapeProxy makeProxy(const Capsule& capsule);
/// The proxy of a segment: its two end points, no radius.
[[nodiscard]] ShapeProxy makeProxy(const Segment& segment);

/// The support-point indices of the last GJK simplex, kept between calls on the same pair of
/// proxies so that the next call starts from the previous answer (warm start: coherent motion
/// then takes one or two iterations). Zero-initialise it before the first call. A cache whose
/// indices do not fit the proxies is ignored, never trusted.
struct SimplexCache {
  int count = 0; ///< 0 (empty) to 3
  std::array<std::uint8_t, 3> indexA{};
  std::array<std::uint8_t, 3> indexB{};
};

/// The closest points of two shapes.
struct DistanceOutput {
  Vec2f pointA;          ///< world witness point on A (on its surface when radii are used), m
  Vec2f pointB;          ///< world witness point on B, m
  Vec2f normal;          ///< unit, world, from A to B; zero when the cores overlap (no direction)
  float distance = 0.0f; ///< m, >= 0; 0 when the shapes overlap
  int iterations = 0;    ///< GJK iterations (support points added)
  int simplexCount = 0;  ///< vertices of the final simplex: 1 vertex-vertex, 2 vertex-edge, 3 overlap
};

/// The distance between two convex shapes placed by xfA and xfB, by GJK (computed in A's frame to
/// keep round-off small far from the origin). With `useRadii` the proxies' radii are subtracted
/// and the witness points moved onto the rounded surfaces (when the surfaces overlap but the cores
/// do not, distance is 0 and the points stay on the surfaces, so they move smoothly); without it
/// this is the distance between the cores. When the cores overlap, distance is 0, both points
/// are the same point inside the overlap and the normal is zero. `cache`, when given, seeds the
/// search and receives the final simplex. Throws impetus::Error naming the field when a proxy's
/// count is not 1..8, a radius is negative or not finite, or a transform is not finite.
[[nodiscard]] DistanceOutput shapeDistance(const ShapeProxy& a, const Transform2f& xfA, const ShapeProxy& b,
                                           const Transform2f& xfB, bool useRadii = true, SimplexCache* cache = nullptr);

/// Shape B, placed by xfB, translated by translationB * fraction for fraction in [0, maxFraction],
/// against shape A fixed at xfA.
struct ShapeCastInput {
  ShapeProxy a;
  Transform2f xfA;
  ShapeProxy b;
  Transform2f xfB;
  Vec2f translationB; ///< m, world
  float maxFraction = 1.0f;
};

/// The first fraction at which B, moving by translationB, touches A: conservative advancement on
/// the GJK distance between the cores until it is within linearSlop / 4 of
/// max(linearSlop, rA + rB - linearSlop) (rounded shapes stop just into the slop, as contacts allow;
/// sharp polygons stop linearSlop apart, since GJK needs a gap to give a normal). On a hit,
/// `point` is on A's surface, `normal` is A's outward unit normal there (world, A to B) and
/// `fraction` is the fraction of the translation. Shapes already within that target at the start
/// hit at fraction 0 (point between them; normal zero when the cores overlap). A miss (moving
/// apart, or not reaching A within maxFraction) has hit = false. Throws impetus::Error naming the
/// field for invalid proxies or transforms, a non-finite translation, or maxFraction not in [0, 1].
[[nodiscard]] CastOutput shapeCast(const ShapeCastInput& input);

/// The motion of a body over a step: its centre of mass goes linearly from c1 to c2 and its
/// rotation from q1 to q2 (normalized linear interpolation, so the turn must be less than half a
/// revolution per sweep). localCenter is the centre of mass in the body frame, so the body origin
/// is c - rotate(q, localCenter).
struct Sweep {
  Vec2f localCenter; ///< centre of mass, body frame, m
  Vec2f c1;          ///< world centre of mass at the start, m
  Vec2f c2;          ///< world centre of mass at the end, m
  Rot2f q1;          ///< rotation at the start
  Rot2f q2;          ///< rotation at the end
};

/// The body transform at fraction t of the sweep (t in [0, 1]; extrapolates outside).
[[nodiscard]] Transform2f sweepTransform(const Sweep& sweep, float t);

/// The result of timeOfImpact.
struct TOIOutput {
  enum class State {
    unknown,    ///< not computed
    failed,     ///< the root finder did not converge; fraction is the last safe time
    overlapped, ///< the cores overlap at the start: no time of impact
    hit,        ///< the shapes reach the target separation at `fraction`
    separated,  ///< the shapes stay apart up to maxFraction
  };
  State state = State::unknown;
  float fraction = 0.0f; ///< of the sweeps, in [0, maxFraction]
};

/// The first fraction of the sweeps at which shapes A and B come within
/// max(linearSlop, rA + rB - linearSlop) of each other (core distance), so that they end up just
/// touching and not overlapping: conservative advancement on GJK separating axes with a mixed
/// secant / bisection root finder (Box2D's b2TimeOfImpact). Catches fast thin shapes that a
/// discrete step would tunnel through. At a hit the core distance is within linearSlop / 4 of that
/// target. For translations the answer is exact (the separation along a fixed axis is then concave
/// in time, so a sweep whose end is clear along the axis is clear throughout). Rotation is assumed
/// small per sweep, as in a physics step: a corner swinging through a large angle can graze or cut
/// across the other shape between the checked times unseen (in random tests, the misses with up
/// to 0.3 rad per sweep were grazes about linearSlop past the target). Throws impetus::Error naming the field for
/// invalid proxies, non-finite sweeps, or maxFraction not in [0, 1].
[[nodiscard]] TOIOutput timeOfImpact(const ShapeProxy& a, const Sweep& sweepA, const ShapeProxy& b, const Sweep& sweepB,
                                     float maxFraction = 1.0f);

} // namespace impetus::rigid2d
