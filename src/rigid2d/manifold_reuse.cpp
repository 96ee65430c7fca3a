// Manifold reuse, after Jolt Physics' body-pair cache: most touching pairs in a game (a stack, a
// pile, a car on a road) barely move relative to each other from one step to the next, and their
// manifolds would come out the same again. So each manifold is noted in its two bodies' frames
// when it is computed, and while the bodies' surfaces at its points have moved less than a small
// distance (and the bodies turned less than a small angle) relative to each other since then,
// the points are carried along with the bodies instead: each point's separation and position
// follow exactly from the bodies' current transforms; only the choice of features and the
// clipping of the points are kept, and those cannot change while nothing moves by more than the
// tolerance. The tolerance is against the manifold as computed, not the last step, so slow drift
// cannot add up past it.
#include "rigid2d/world_impl.hpp"

#include <cmath>
#include <type_traits>

namespace impetus::rigid2d::detail {

static_assert(std::is_standard_layout_v<Contact>);

void recordManifoldFrame(Contact& contact, const Transform2f& xfA, const Transform2f& xfB) {
  const Manifold& m = contact.manifold;
  ManifoldFrame& f = contact.frame;
  for (int k = 0; k < m.pointCount; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    const ManifoldPoint& mp = m.points[kk];
    // The point lies midway between the surfaces, which are `separation` apart along the normal.
    const Vec2f half = m.normal * (0.5f * mp.separation);
    f.localA[kk] = inverseTransformPoint(xfA, mp.point - half);
    f.localB[kk] = inverseTransformPoint(xfB, mp.point + half);
    f.separation[kk] = mp.separation;
  }
  f.localNormal = inverseRotate(xfA.q, m.normal);
  f.relativeRotation = invMul(xfA.q, xfB.q);
}

bool carryManifold(Contact& contact, const Transform2f& xfA, const Transform2f& xfB, float maxDistance,
                   float maxTurnSine) {
  const ManifoldFrame& f = contact.frame;
  Manifold& m = contact.manifold;
  // The turn of B relative to A since the manifold was computed.
  const Rot2f turn = invMul(f.relativeRotation, invMul(xfA.q, xfB.q));
  if (turn.c <= 0.0f || std::abs(turn.s) > maxTurnSine) {
    return false;
  }
  std::array<Vec2f, 2> surfaceA{}, surfaceB{};
  for (int k = 0; k < m.pointCount; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    surfaceA[kk] = transformPoint(xfA, f.localA[kk]);
    surfaceB[kk] = transformPoint(xfB, f.localB[kk]);
    // B's surface point relative to A's then and now, in A's frame.
    const Vec2f moved = inverseRotate(xfA.q, surfaceB[kk] - surfaceA[kk]) - f.localNormal * f.separation[kk];
    if (!(dot(moved, moved) <= maxDistance * maxDistance)) {
      return false;
    }
  }
  m.normal = rotate(xfA.q, f.localNormal);
  for (int k = 0; k < m.pointCount; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    ManifoldPoint& mp = m.points[kk];
    mp.separation = dot(surfaceB[kk] - surfaceA[kk], m.normal);
    mp.point = (surfaceA[kk] + surfaceB[kk]) * 0.5f;
    mp.anchorA = mp.point - xfA.p;
    mp.anchorB = mp.point - xfB.p;
  }
  return true;
}

} // namespace impetus::rigid2d::detail
