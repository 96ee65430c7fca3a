// SolverKind::bookImpulse: the book's rigid-body collision response (ch. 9 and 10), kept so its
// programs can be reproduced, with its errors fixed (../shared/spec/ch07-10.md, section 7):
//
// - One semi-implicit Euler step per frame (the book's UpdateBodyEuler), no substeps. (Joints,
//   which the book does not have, are solved as in the soft step, once per frame.)
// - One impulse per touching pair, J = -(1 + e) v_rn / (1/m1 + 1/m2 + (r1 x n)^2/I1 + (r2 x n)^2/I2)
//   (impetus::resolveImpact in the mechanics layer, the book's ch. 5 formula), applied when the
//   gap is within the contact tolerance and the pair approaches.
// Fixed: contacts come from the SAT narrowphase, not the book's corner-against-edge test (which
// missed edges, tested one direction and inverted its penetration test); pairs are resolved one
// after another with the velocities the previous impulses left (the book summed impulses from
// the same pre-contact velocities and over-responded); slow impacts (below the world's
// restitutionThreshold) do not bounce, so resting bodies do not jitter; Coulomb friction (the
// book has none) is capped so slip never reverses; and overlap beyond linearSlop is pushed
// apart after the step (the book backs up in time by halving the step, which stalls).
#include "rigid2d/joints.hpp"
#include "rigid2d/world_impl.hpp"

#include <impetus/mechanics/impact.hpp>

#include <algorithm>

namespace impetus::rigid2d::detail {
namespace {

/// The contact's single point: the deepest one, or the middle of both when they are equally
/// deep (within linearSlop: a face resting on a face), so a flat impact gives no spin.
struct ImpactPoint {
  Vec2f anchorA, anchorB; ///< relative to the body origins, world axes
  float separation = 0.0f;
};

ImpactPoint impactPoint(const Manifold& m) {
  const ManifoldPoint& p0 = m.points[0];
  if (m.pointCount == 1) {
    return {p0.anchorA, p0.anchorB, p0.separation};
  }
  const ManifoldPoint& p1 = m.points[1];
  if (std::abs(p0.separation - p1.separation) <= linearSlop) {
    return {(p0.anchorA + p1.anchorA) * 0.5f, (p0.anchorB + p1.anchorB) * 0.5f, std::min(p0.separation, p1.separation)};
  }
  const ManifoldPoint& deepest = p0.separation < p1.separation ? p0 : p1;
  return {deepest.anchorA, deepest.anchorB, deepest.separation};
}

Vec2d toDouble(const Vec2f& v) { return {static_cast<double>(v.x), static_cast<double>(v.y)}; }
Vec2f toFloat(const Vec2d& v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

} // namespace

void solveBookImpulse(WorldState& w, float dt) {
  const StepContext context = makeStepContext(w, dt, 1);
  returnJointSims(w); // the soft step's copies, if it ran before, hold the joints' data
  buildSolverBodies(w);
  integrateVelocities(w, context);
  // Joints (the book has none: they are the soft step's, solved once per frame here).
  prepareJoints(w, context);
  warmStartJoints(w);
  solveJoints(w, context, true);
  const std::uint32_t staticIndex = w.staticIndex();
  for (std::uint32_t slot = 0; slot < w.contacts.size(); ++slot) {
    Contact& contact = w.contacts[slot];
    contact.approachSpeed = 0.0f;
    if (!contact.alive || contact.sensor || contact.manifold.pointCount == 0) {
      continue;
    }
    const Body& a = w.bodies[contact.bodyA];
    const Body& b = w.bodies[contact.bodyB];
    if (!a.moving() && !b.moving()) {
      continue;
    }
    const ImpactPoint point = impactPoint(contact.manifold);
    BodyState& sa = w.states[a.moving() ? a.solverIndex : staticIndex];
    BodyState& sb = w.states[b.moving() ? b.solverIndex : staticIndex];
    const Vec2f rA = point.anchorA - (a.center - a.transform.p);
    const Vec2f rB = point.anchorB - (b.center - b.transform.p);
    const Vec2f normal = contact.manifold.normal; // from A to B
    const float approach = dot((sb.v + cross(sb.w, rB)) - (sa.v + cross(sa.w, rA)), normal);
    // The book's "colliding contact": within the contact tolerance and approaching. Its fixed
    // tolerance either lets bodies hover (too large) or tunnel (too small); here the tolerance
    // is what the pair closes this frame, so a gap that would close within dt counts.
    if (approach >= 0.0f || point.separation + approach * dt > 0.0f) {
      continue; // separating, at rest, or still apart at the end of the frame: no impulse
    }
    const float restitution = -approach < w.def.restitutionThreshold ? 0.0f : contact.restitution;
    // Body 1 is B, pushed along +n (from A to B); body 2 is A.
    const ImpactBody2D body1{b.inverseMass, b.inverseInertia, toDouble(sb.v), sb.w, toDouble(rB)};
    const ImpactBody2D body2{a.inverseMass, a.inverseInertia, toDouble(sa.v), sa.w, toDouble(rA)};
    const ImpactResult2D r = resolveImpact(body1, body2, toDouble(normal), restitution, contact.friction);
    if (b.moving()) {
      sb.v = toFloat(r.velocity1);
      sb.w = static_cast<float>(r.angularVelocity1);
    }
    if (a.moving()) {
      sa.v = toFloat(r.velocity2);
      sa.w = static_cast<float>(r.angularVelocity2);
    }
    contact.approachSpeed = -approach;
    contact.fastestPoint = 0;
    w.maybeHit[slot] = 1;
  }
  integratePositions(w, context);
  solveJoints(w, context, false);
  finishJoints(w, context);
  // Push overlap deeper than linearSlop apart along the normal, shared by inverse mass (a
  // position correction in place of the book's step halving).
  for (const Contact& contact : w.contacts) {
    if (!contact.alive || contact.sensor || contact.manifold.pointCount == 0) {
      continue;
    }
    const Body& a = w.bodies[contact.bodyA];
    const Body& b = w.bodies[contact.bodyB];
    const float mA = a.moving() ? a.inverseMass : 0.0f;
    const float mB = b.moving() ? b.inverseMass : 0.0f;
    if (mA + mB == 0.0f) {
      continue;
    }
    BodyState& sa = w.states[a.moving() ? a.solverIndex : staticIndex];
    BodyState& sb = w.states[b.moving() ? b.solverIndex : staticIndex];
    const ImpactPoint point = impactPoint(contact.manifold);
    const Vec2f normal = contact.manifold.normal;
    const float separation = point.separation + dot(sb.dp - sa.dp, normal);
    if (separation >= -linearSlop) {
      continue;
    }
    const Vec2f push = normal * ((-separation - linearSlop) / (mA + mB));
    if (a.moving()) {
      sa.dp -= push * mA;
    }
    if (b.moving()) {
      sb.dp += push * mB;
    }
  }
}

} // namespace impetus::rigid2d::detail
