// The polygon narrowphase's paths, for its tests and micro-benchmark. collidePolygons takes a
// shortcut for two plain boxes (makeBox) and another when shape A is an axis-aligned rectangle;
// both must give exactly the general separating-axis path's manifold.
#pragma once

#include <impetus/rigid2d/manifold.hpp>

namespace impetus::rigid2d::detail {

/// collidePolygons without the shortcuts: the reference they must match.
[[nodiscard]] Manifold collidePolygonsGeneral(const Polygon& a, const Transform2f& xfA, const Polygon& b,
                                              const Transform2f& xfB);

/// The ways collidePolygons can go: two plain boxes (A from makeBox or makeOffsetBox at angle
/// 0, B from makeBox), A an axis-aligned rectangle and B anything, or the general path.
enum class PolygonPath { boxes, rectangle, general };
[[nodiscard]] PolygonPath polygonPath(const Polygon& a, const Polygon& b);

} // namespace impetus::rigid2d::detail
