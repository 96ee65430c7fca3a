// Internals of the narrowphase shared by its sources, its tests and its micro-benchmark.
//
// The polygon narrowphase's paths: collidePolygons takes a shortcut for two plain boxes (makeBox)
// and another when shape A is an axis-aligned rectangle; both must give exactly the general
// separating-axis path's manifold.
#pragma once

#include <impetus/rigid2d/manifold.hpp>

namespace impetus::rigid2d::detail {

/// Below this distance two points give no direction: a normal taken along the line between
/// them is replaced by a defined one. 1e-9 m is under the spacing of floats at 1 cm (9.3e-10 m),
/// so such points coincide within rounding at any coordinate the world resolves, and no
/// direction is lost; and it is far above the distances whose squares underflow (about 1e-19 m,
/// where the "normal" of a positive but inexact length was 2% off unit length). Used by every
/// narrowphase that divides by a distance (manifold.cpp, chain_manifold.cpp).
inline constexpr float minNormalDistance = 1e-9f;

/// collidePolygons without the shortcuts: the reference they must match.
[[nodiscard]] Manifold collidePolygonsGeneral(const Polygon& a, const Transform2f& xfA, const Polygon& b,
                                              const Transform2f& xfB);

/// The ways collidePolygons can go: two plain boxes (A from makeBox or makeOffsetBox at angle
/// 0, B from makeBox), A an axis-aligned rectangle and B anything, or the general path.
enum class PolygonPath { boxes, rectangle, general };
[[nodiscard]] PolygonPath polygonPath(const Polygon& a, const Polygon& b);

} // namespace impetus::rigid2d::detail
