// Chain shapes: polylines of one-sided segments for terrain and level walls, without ghost
// collisions. Each segment of a chain knows its neighbours' far vertices (ghost vertices), so the
// narrowphase can tell a real corner from an internal seam of a flat run: a box sliding along a
// straight chain never catches on the vertex between two segments (Box2D v3's chain segments; see
// Erin Catto, "Ghost collisions", box2d.org/posts/2020/06/ghost-collisions).
//
// Sides. A chain segment collides only with shapes on the RIGHT of point1 -> point2: its normal
// is rightPerp(point2 - point1) = (dy, -dx), the free side, and the left side is the solid (Box2D
// v3's convention). Walk the chain with free space on your right hand and the solid on your left:
//
//      free space (shapes rest here)          a ground line is listed RIGHT TO LEFT:
//                 ^ n = (0, 1)                  points = {(3,0), (1,0), (-1,0), (-3,0)}
//   p3 <----- p2 <----- p1 <----- p0
//   ////////////// solid ////////////
//
// So a COUNTER-CLOCKWISE loop keeps shapes OUTSIDE (its right-hand normals point outwards, as a
// polygon's do: an island, a floating platform) and a CLOCKWISE loop keeps shapes INSIDE (a
// container, a cave):
//
//     counter-clockwise: solid inside        clockwise: free inside
//        p3 <------ p2                          p1 ------> p2
//        |  solid   ^                           ^   free    |
//        v          |                           |           v
//        p0 ------> p1                          p0 <------ p3
//
// A shape whose centroid is behind a segment (on its solid side) gets no contact from it: shapes
// pass through a chain from behind, which is what one-sided platforms want too.
#pragma once

#include <impetus/rigid2d/manifold.hpp>

#include <span>
#include <vector>

namespace impetus::rigid2d {

/// One segment of a chain, in its body's local frame, m. `ghost1` is the vertex before
/// segment.point1 and `ghost2` the vertex after segment.point2: they are not collided with; they
/// only decide whether the vertices point1 and point2 are convex corners (where a vertex normal
/// is admissible), concave corners or flat seams (where only the segment's own normal is).
struct ChainSegment {
  Vec2f ghost1;
  Segment segment;
  Vec2f ghost2;
};

/// A chain as the user describes it: its points in the body's local frame (m) and whether the
/// last point connects back to the first. Materials (friction, restitution) are the world's.
struct ChainDef {
  std::vector<Vec2f> points;
  bool isLoop = false;
};

/// The segments of a chain through `points`, each with its ghost vertices.
///
/// Open chain (isLoop false): n points give n - 1 segments, point i -> point i + 1. The end
/// ghosts extrapolate the end segments straight on (ghost1 of the first segment is
/// 2 points[0] - points[1], ghost2 of the last is 2 points[n-1] - points[n-2]), so the two end
/// vertices behave as flat seams: a shape resting near an end gets the end segment's normal, and
/// a circle whose centre has moved past an end gets no contact from that end's vertex.
///
/// Loop (isLoop true): n points give n segments, the last one points[n-1] -> points[0], and the
/// ghosts wrap around (segment i's ghost1 is points[i-1], its ghost2 points[i+2], modulo n).
///
/// Throws impetus::Error naming `points.size` for an open chain of fewer than 2 points or a loop
/// of fewer than 3 (the smallest closed outline with an inside: a 2-point "loop" would be one
/// segment twice with opposite normals, so each side would push shapes through the other),
/// `points[i].x`/`.y` for a coordinate that is not finite, and `points[i]` when points[i] is
/// closer than linearSlop to points[i-1] (for a loop also points[0] to points[n-1]: do not repeat
/// the first point at the end): such a segment has no reliable direction or normal.
[[nodiscard]] std::vector<ChainSegment> makeChainSegments(std::span<const Vec2f> points, bool isLoop);
/// makeChainSegments(def.points, def.isLoop).
[[nodiscard]] std::vector<ChainSegment> makeChainSegments(const ChainDef& def);

/// World bounding box of the segment (point1 and point2; the ghosts are not part of the shape).
[[nodiscard]] AABB computeAABB(const ChainSegment& shape, const Transform2f& xf);

/// One-sided ray cast in the shape's local frame: the ray hits only the front (free) side, so it
/// must start in front of the segment's line and travel against the normal; a ray from behind,
/// or parallel to the segment, misses (Box2D v3 casts chain segments one-sided the same way).
/// The hit's normal is the segment's normal. Throws impetus::Error naming `origin`,
/// `translation` or `maxFraction` for non-finite input or a negative maxFraction.
[[nodiscard]] CastOutput rayCast(const ChainSegment& shape, const RayCastInput& ray);

/// Contact manifold between chain segment A and convex polygon B (a capsule or a segment as a
/// 2-vertex polygon from asPolygon, a rounded polygon, a circle as a 1-vertex polygon): up to two
/// points, the normal from A to B, separations, anchors and feature ids as collidePolygons.
///
/// One-sided: empty when B's centroid is behind the segment (and, at a convex corner, behind the
/// neighbouring segment too). Ghost-free: the normal is the segment normal, a polygon face normal,
/// or a normal between two vertices only where the chain's Gauss map allows it: within the arc of
/// normals at a convex corner, never pointing into a flat seam or a concave corner (those snap to
/// the segment normal). So a box sliding along a straight chain always gets the surface normal,
/// including exactly over the vertex between two segments.
///
/// Near a convex corner both segments that share it may report the same vertex contact (as in
/// Box2D); elsewhere the segment that owns the separating axis reports and the other is empty.
[[nodiscard]] Manifold collideChainSegmentAndPolygon(const ChainSegment& a, const Transform2f& xfA, const Polygon& b,
                                                     const Transform2f& xfB);

/// Contact manifold between chain segment A and circle B: at most one point, normal from A to B.
/// The segment normal when the centre is over the segment; the direction from the corner to the
/// centre when it is beyond the end of the segment and of its neighbour (a convex corner's
/// region). Empty when the centre is behind the segment's line, over a neighbouring segment, or
/// beyond an open chain's end. Each point of the plane is reported by exactly one segment of a
/// chain (the borders between regions are half-open and both neighbours test them with the same
/// arithmetic): a circle on a corner gets one contact, not two, and a circle over a flat seam
/// gets the surface normal from one of the two segments.
[[nodiscard]] Manifold collideChainSegmentAndCircle(const ChainSegment& a, const Transform2f& xfA, const Circle& b,
                                                    const Transform2f& xfB);

} // namespace impetus::rigid2d
