// Tolerances of the 3D world, in metres: tuned, as the 2D world's, for moving objects between
// about 0.1 m and 10 m.
#pragma once

namespace impetus::rigid3d {

/// Collision and constraint tolerance: overlaps this small are allowed and not corrected, so
/// resting contacts do not jitter; shapes smaller than it are refused. m.
inline constexpr float linearSlop = 0.005f;

/// Contact points are kept while the shapes are closer than this, before they touch, so the
/// solver stops an approach before it becomes an overlap (speculative contacts). m.
inline constexpr float speculativeDistance = 4.0f * linearSlop;

} // namespace impetus::rigid3d
