// Manifold reuse, after Jolt Physics' body-pair cache: most touching pairs in a game (a stack, a
// pile, a car on a road) barely move relative to each other from one step to the next, and their
// manifolds would come out the same again. So each manifold is noted in its two bodies' frames
// when it is computed, and while the bodies' cores at its points have moved less than a small
// distance (and the bodies turned less than a small angle) relative to each other since then,
// the points are carried along with the bodies instead: each point's separation and position
// follow exactly from the bodies' current transforms; only the choice of features and the
// clipping of the points are kept, and those cannot change while nothing moves by more than the
// tolerance. The tolerance is against the manifold as computed, not the last step, so slow drift
// cannot add up past it.
//
// A round shape (a circle, a capsule, a rounded polygon) is carried by its core, the surface
// point moved in by its radius along the normal: a material point of the body (a ball's centre),
// where the surface point is not (it stays under a turning ball). The surface is then put back a
// radius out along the normal, so a resting ball's contact stays under its centre however it
// turns, and a ball rolling or sliding across moves its centre past the tolerance.
#include "rigid2d/world_impl.hpp"

#include <cmath>
#include <type_traits>

namespace impetus::rigid2d::detail {

static_assert(std::is_standard_layout_v<Contact>);

namespace {

/// Where a carried point lies, midway between the surfaces along the normal, and across it: on
/// the normal through the core of the one round shape, if one is (a round body's contact force
/// passes through its core, a ball's through its centre, and a point off that line would turn a
/// resting ball on: a carried flat face's point stays where it was on the face, while the ball
/// above moves up to the tolerance); midway between the two surfaces otherwise.
Vec2f carriedPoint(const ManifoldFrame& f, const Vec2f& surfaceA, const Vec2f& surfaceB, const Vec2f& normal,
                   float separation) {
  if (f.radiusB > 0.0f && f.radiusA == 0.0f) {
    return surfaceB - normal * (0.5f * separation);
  }
  if (f.radiusA > 0.0f && f.radiusB == 0.0f) {
    return surfaceA + normal * (0.5f * separation);
  }
  return (surfaceA + surfaceB) * 0.5f;
}

} // namespace

void recordManifoldFrame(Contact& contact, const Transform2f& xfA, const Transform2f& xfB) {
  const Manifold& m = contact.manifold;
  ManifoldFrame& f = contact.frame;
  for (int k = 0; k < m.pointCount; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    const ManifoldPoint& mp = m.points[kk];
    // The point lies midway between the surfaces, which are `separation` apart along the normal;
    // the cores lie a radius further in on each side.
    const Vec2f half = m.normal * (0.5f * mp.separation);
    f.localA[kk] = inverseTransformPoint(xfA, mp.point - half - m.normal * f.radiusA);
    f.localB[kk] = inverseTransformPoint(xfB, mp.point + half + m.normal * f.radiusB);
    f.coreSeparation[kk] = mp.separation + f.radiusA + f.radiusB;
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
  std::array<Vec2f, 2> coreA{}, coreB{};
  for (int k = 0; k < m.pointCount; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    coreA[kk] = transformPoint(xfA, f.localA[kk]);
    coreB[kk] = transformPoint(xfB, f.localB[kk]);
    // B's core point relative to A's then and now, in A's frame (for a ball, how far its centre
    // moved across the normal fixed in A: the ball's turning does not move it).
    const Vec2f moved = inverseRotate(xfA.q, coreB[kk] - coreA[kk]) - f.localNormal * f.coreSeparation[kk];
    if (!(dot(moved, moved) <= maxDistance * maxDistance)) {
      return false;
    }
  }
  m.normal = rotate(xfA.q, f.localNormal);
  for (int k = 0; k < m.pointCount; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    ManifoldPoint& mp = m.points[kk];
    // The surfaces a radius out from the cores, along the normal (not turning with a round body).
    const Vec2f surfaceA = coreA[kk] + m.normal * f.radiusA;
    const Vec2f surfaceB = coreB[kk] - m.normal * f.radiusB;
    mp.separation = dot(surfaceB - surfaceA, m.normal);
    mp.point = carriedPoint(f, surfaceA, surfaceB, m.normal, mp.separation);
    mp.anchorA = mp.point - xfA.p;
    mp.anchorB = mp.point - xfB.p;
  }
  return true;
}

void recordSeparation(Contact& contact, const Transform2f& xfA, const Transform2f& xfB) {
  ManifoldFrame& f = contact.frame;
  const Transform2f relative = invMul(xfA, xfB);
  f.relativePosition = relative.p;
  f.relativeRotation = relative.q;
  f.separationBound = contact.manifold.separationBound;
}

bool staysApart(const Contact& contact, const Transform2f& xfA, const Transform2f& xfB) {
  const ManifoldFrame& f = contact.frame;
  if (!(f.separationBound > speculativeDistance)) {
    return false;
  }
  // Conservative advancement: no point of B's shape moved farther in A's frame than B's origin
  // did plus its reach times the chord of the turn (|(Q - I) p| = |p| |(cos t - 1, sin t)|).
  const Transform2f relative = invMul(xfA, xfB);
  const Rot2f turn = invMul(f.relativeRotation, relative.q);
  const float moved = distance(relative.p, f.relativePosition) + f.reachB * length(Vec2f{turn.c - 1.0f, turn.s});
  return f.separationBound - moved > speculativeDistance;
}

} // namespace impetus::rigid2d::detail
