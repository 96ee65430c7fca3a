// The face contact of two hulls (hull_clip.cpp) for collideHulls (hull_hull_manifold.cpp): the
// incident face clipped to the reference face, reduced to four points, in A's frame; and the
// feature ids of every hull-hull contact point.
#pragma once

#include <impetus/math/transform3.hpp>
#include <impetus/rigid3d/hull.hpp>

#include <array>
#include <cstdint>

namespace impetus::rigid3d::hullclip {

/// A contact point in A's frame: midway between the two surfaces, m.
struct LocalPoint {
  Vec3f point;
  float separation = 0.0f; ///< m, negative overlapping
  std::uint32_t id = 0;
};

/// Up to four points and the normal from A to B, in A's frame.
struct LocalContact {
  std::array<LocalPoint, 4> points{};
  Vec3f normal;
  int count = 0;
};

/// Feature ids, 32 bits: bit 31 set when B's face is the reference; bits 29-30 the kind; bits
/// 22-28 the reference face's index (mod 128; 0 for an edge pair); bits 11-21 and 0-10 two
/// feature indices (mod 2048), by kind:
/// - incidentVertex: a vertex of the incident face left by the clip (its index in its hull; 0);
/// - incidentEdgeSide: where an edge of the incident face crosses a side plane of the reference
///   face (the edge: its half-edge of the lower index; the side: the reference face's half-edge);
/// - referenceCorner: where two side planes meet over the incident face (a corner of the
///   reference face: its two half-edges, the lower first);
/// - edgePair: the edge contact (A's edge, B's edge: each its half-edge of the lower index); all
///   bits of both fields and of the face set: the closest points by GJK.
/// A vertex or edge keeps its index whichever face of its hull is the incident one, so a point
/// keeps its id (and its warm start) while the same features touch.
enum class FeatureKind : std::uint32_t { incidentVertex = 0, incidentEdgeSide = 1, referenceCorner = 2, edgePair = 3 };

inline constexpr std::uint32_t featureFieldMask = 0x7FF; // 11 bits
inline constexpr std::uint32_t featureFaceMask = 0x7F;   // 7 bits

[[nodiscard]] constexpr std::uint32_t featureId(FeatureKind kind, bool referenceIsB, std::uint32_t face,
                                                std::uint32_t first, std::uint32_t second) {
  return (referenceIsB ? 0x80000000U : 0U) | (static_cast<std::uint32_t>(kind) << 29) |
         ((face & featureFaceMask) << 22) | ((second & featureFieldMask) << 11) | (first & featureFieldMask);
}

[[nodiscard]] constexpr std::uint32_t edgePairId(std::uint32_t edgeA, std::uint32_t edgeB) {
  return featureId(FeatureKind::edgePair, false, 0, edgeA, edgeB);
}

inline constexpr std::uint32_t closestPointsId =
    featureId(FeatureKind::edgePair, false, featureFaceMask, featureFieldMask, featureFieldMask);

/// The face contact on face `face` of `reference`: the incident face of `incident` (its normal
/// the most anti-parallel to the reference normal) clipped to the reference face's side planes,
/// the points at most speculativeDistance over the reference plane, each midway between the
/// incident point and its projection on the plane, at most four kept. Each hull's points map into
/// A's frame by its transform (the identity for A). No points where nothing of the incident face
/// is over the reference face within reach.
[[nodiscard]] LocalContact faceContact(const Hull& reference, int face, const Transform3f& referenceToA,
                                       const Hull& incident, const Transform3f& incidentToA, bool referenceIsB);

/// One point at the incident hull's deepest vertex under the reference face's plane (its support
/// point against the normal), midway between it and its projection on the plane.
[[nodiscard]] LocalContact deepestVertexContact(const Hull& reference, int face, const Transform3f& referenceToA,
                                                const Hull& incident, const Transform3f& incidentToA,
                                                bool referenceIsB);

} // namespace impetus::rigid3d::hullclip
