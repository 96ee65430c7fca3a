// Tolerances of the 2D world, in metres: the world is tuned for moving objects between about
// 0.1 m and 10 m (as Box2D); these keep collision and the solver robust at that scale.
#pragma once

namespace impetus::rigid2d {

/// Collision and constraint tolerance: overlaps this small are allowed and not corrected, so
/// resting contacts do not jitter. m.
inline constexpr float linearSlop = 0.005f;

/// Contact points are kept while the shapes are closer than this, before they touch, so the
/// solver stops an approach before it becomes an overlap (speculative contacts). m.
inline constexpr float speculativeDistance = 4.0f * linearSlop;

/// Fat AABB margin: a moving shape is re-inserted in the broadphase only when it leaves its
/// box enlarged by this much, m (at most; smaller shapes: aabbMarginFraction).
inline constexpr float aabbMargin = 0.05f;

/// A shape's fat-box margin is at most this fraction of its extent (the farthest its outline
/// reaches from its centre): a small shape's fat box reaching 5 cm past it would overlap the
/// boxes of neighbours it cannot touch for several steps, and each overlap is a pair the
/// narrowphase tests every step (Box2D v3's B2_AABB_MARGIN_FRACTION). Dimensionless.
inline constexpr float aabbMarginFraction = 0.125f;

/// Polygons have at most this many vertices (a convex hull of more points is an error).
inline constexpr int maxPolygonVertices = 8;

/// Bodies are placed within this distance of the world's origin on each axis, m: at 1e6 m a
/// float's spacing is 6 cm, already twelve times linearSlop; beyond, contacts, joints and
/// sleeping lose their meaning (a body at 1e30 m cannot move at all).
inline constexpr float maxWorldCoordinate = 1.0e6f;

/// The strongest gravity a world takes, m/s^2 (1000 g): stronger, a body gains more than a
/// substep's worth of the speed cap from gravity alone in a 60 Hz step.
inline constexpr float maxGravity = 1.0e4f;

} // namespace impetus::rigid2d
