// Distance between convex shapes by GJK (Gilbert, Johnson and Keerthi): the closest points of
// two convex point sets (a sphere's centre, a capsule's segment, a hull's vertices), on which the
// round shapes' radii sit. The narrowphase of round shapes against hulls is built on it.
#pragma once

#include <impetus/math/transform3.hpp>

#include <span>

namespace impetus::rigid3d {

/// A convex point set and a radius around it, in world coordinates: the hull of the points, grown.
struct DistanceProxy {
  std::span<const Vec3f> points;
  float radius = 0.0f;
};

struct DistanceOutput {
  Vec3f pointA;          ///< on A's core (its points' hull), world, m
  Vec3f pointB;          ///< on B's core
  float distance = 0.0f; ///< between the cores, m; 0 when they overlap
  int iterations = 0;
  bool overlap = false; ///< the cores overlap (pointA and pointB are then not meaningful)
};

/// The closest points of the two proxies' cores (their radii not counted). Deterministic; at
/// most maxGjkIterations iterations.
[[nodiscard]] DistanceOutput coreDistance(const DistanceProxy& a, const DistanceProxy& b);

/// The most iterations coreDistance makes: GJK converges in a few on the shapes of a game, and
/// this bounds a degenerate input's.
inline constexpr int maxGjkIterations = 32;

} // namespace impetus::rigid3d
