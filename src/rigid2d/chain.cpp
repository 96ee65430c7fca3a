// Chain segments: building a chain's segments with their ghost vertices, their bounding boxes
// and their one-sided ray casts. The manifolds are in chain_manifold.cpp.
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/rigid2d/chain.hpp>

#include <cmath>
#include <string>

namespace impetus::rigid2d {

std::vector<ChainSegment> makeChainSegments(std::span<const Vec2f> points, bool isLoop) {
  const std::size_t n = points.size();
  const std::size_t minimum = isLoop ? 3 : 2;
  if (n < minimum) {
    throwInvalid("points.size", static_cast<double>(n),
                 isLoop ? "a chain loop needs at least 3 points" : "an open chain needs at least 2 points");
  }
  for (std::size_t i = 0; i < n; ++i) {
    requireFinite(points[i], "points[" + std::to_string(i) + "]");
  }
  // A segment shorter than the linear slop has no trustworthy direction, so neither its normal
  // nor the convexity test at its ends would be. For a loop the closing pair counts too.
  const std::size_t pairs = isLoop ? n : n - 1;
  for (std::size_t k = 1; k <= pairs; ++k) {
    const std::size_t i = k % n;
    const float gap = distance(points[k - 1], points[i]);
    if (!(gap >= linearSlop)) {
      throwInvalid("points[" + std::to_string(i) + "]", static_cast<double>(gap),
                   "distance to points[" + std::to_string(k - 1) +
                       "] must be at least linearSlop (0.005 m): consecutive points may not coincide");
    }
  }

  std::vector<ChainSegment> segments;
  if (isLoop) {
    segments.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      segments.push_back({points[(i + n - 1) % n], {points[i], points[(i + 1) % n]}, points[(i + 2) % n]});
    }
    return segments;
  }
  segments.reserve(n - 1);
  // The end ghosts continue the end segments straight on: the end vertices are flat seams.
  const Vec2f before = points[0] * 2.0f - points[1];
  const Vec2f after = points[n - 1] * 2.0f - points[n - 2];
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Vec2f ghost1 = i == 0 ? before : points[i - 1];
    const Vec2f ghost2 = i + 2 < n ? points[i + 2] : after;
    segments.push_back({ghost1, {points[i], points[i + 1]}, ghost2});
  }
  return segments;
}

std::vector<ChainSegment> makeChainSegments(const ChainDef& def) { return makeChainSegments(def.points, def.isLoop); }

AABB computeAABB(const ChainSegment& shape, const Transform2f& xf) { return computeAABB(shape.segment, xf); }

CastOutput rayCast(const ChainSegment& shape, const RayCastInput& ray) {
  requireFinite(ray.origin, "origin");
  requireFinite(ray.translation, "translation");
  if (!(ray.maxFraction >= 0.0f) || !std::isfinite(ray.maxFraction)) {
    throwInvalid("maxFraction", ray.maxFraction, "must be finite and non-negative");
  }
  const Vec2f p1 = shape.segment.point1;
  const Vec2f p2 = shape.segment.point2;
  const Vec2f edge = p2 - p1;
  const Vec2f n = normalize(Vec2f{edge.y, -edge.x}); // right-hand normal: the free side
  if (lengthSquared(n) == 0.0f) {
    return {}; // a point has no front side
  }
  // Height of the origin above the line and the rate the ray descends towards it: the ray must
  // start on the free side (height >= 0) and move against the normal (rate < 0).
  const float height = dot(n, ray.origin - p1);
  const float rate = dot(n, ray.translation);
  if (height < 0.0f || rate >= 0.0f) {
    return {};
  }
  const float t = height / -rate;
  if (t > ray.maxFraction) {
    return {};
  }
  const Vec2f point = ray.origin + ray.translation * t;
  const float along = dot(point - p1, edge);
  if (along < 0.0f || along > dot(edge, edge)) {
    return {};
  }
  return {n, point, t, true};
}

} // namespace impetus::rigid2d
