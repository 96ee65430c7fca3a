// The wide contact kernels, written once over FloatW (simd.hpp) and compiled once per
// instruction set: contact_wide_sse2.cpp and contact_wide_avx2.cpp include this file, each into
// its own translation unit with its own lane width. Everything here has internal linkage, so
// the two builds never share (or swap) a function; each TU exports one table (WideKernels).
//
// Layout: a batch holds `simdWidth` contacts, field by field (structure of arrays), so a pass
// loads each field once for all lanes. Bodies are gathered from their BodyState rows and
// transposed into columns, and scattered back (never into the static state).
#pragma once

#include "rigid2d/contact_constraint.hpp"
#include "solver/simd.hpp"

namespace impetus::rigid2d::detail {
using namespace solver; // the lanes (FloatW) and their operations
namespace {

/// `simdWidth` contacts in SIMD lanes. Unused lanes point at the static state with zero masses, so
/// they compute zero impulses; a one-point manifold's second point has zero mass likewise.
struct ContactConstraintWide {
  std::array<std::uint32_t, simdWidth> indexA{}, indexB{};
  FloatW invMassA, invMassB, invIA, invIB;
  FloatW normalX, normalY;
  FloatW friction, restitution, rollingResistance, rollingMass, rollingImpulse, tangentSpeed;
  FloatW biasRate, massScale, impulseScale;
  struct Point {
    FloatW rAx, rAy, rBx, rBy;
    FloatW adjustedSeparation;
    FloatW normalImpulse, tangentImpulse, maxNormalImpulse;
    FloatW normalMass, tangentMass;
    FloatW normalBound; ///< contactImpulseBound
    FloatW impactSpeed;
  };
  std::array<Point, 2> points;
};

float& lane(FloatW& w, int i) { return reinterpret_cast<float*>(&w)[i]; }
float lane(const FloatW& w, int i) { return reinterpret_cast<const float*>(&w)[i]; }

/// Velocities (and, for the solve, position deltas) of four bodies, as columns.
struct BodiesW {
  FloatW vx, vy, w, dpx, dpy, dqc, dqs;
};

[[gnu::always_inline]] inline BodiesW gather(const BodyState* states,
                                             const std::array<std::uint32_t, simdWidth>& index) {
  const float* rows[simdWidth];
  for (std::size_t i = 0; i < simdWidth; ++i) {
    rows[i] = &states[index[i]].v.x;
  }
  FloatW columns[8];
  loadRowsW(rows, columns);
  return {columns[0], columns[1], columns[2], columns[4], columns[5], columns[6], columns[7]};
}

/// Velocities only (warm start and restitution need no position deltas).
[[gnu::always_inline]] inline BodiesW gatherVelocities(const BodyState* states,
                                                       const std::array<std::uint32_t, simdWidth>& index) {
  const float* rows[simdWidth];
  for (std::size_t i = 0; i < simdWidth; ++i) {
    rows[i] = &states[index[i]].v.x;
  }
  BodiesW b;
  FloatW unused;
  loadRowHeadsW(rows, b.vx, b.vy, b.w, unused);
  return b;
}

/// Writes the velocities back; static lanes write to the sink state after the static one
/// (never read), which keeps the stores free of branches.
[[gnu::always_inline]] inline void scatter(BodyState* states, const std::array<std::uint32_t, simdWidth>& index,
                                           std::uint32_t staticIndex, const BodiesW& b) {
  float* rows[simdWidth];
  for (std::size_t i = 0; i < simdWidth; ++i) {
    rows[i] = &states[index[i] == staticIndex ? staticIndex + 1 : index[i]].v.x;
  }
  storeRowHeadsW(rows, b.vx, b.vy, b.w, zeroW());
}

/// Lane i of a wide constraint from contact `slot`, as makeContactConstraint reads it: the
/// bodies, the material, the anchors relative to the centres of mass, the raw separations and the
/// impulses to warm start from. What follows from these (the effective masses, the separations
/// at the anchors, the approach speeds) is computed for all lanes at once (deriveLanes). Returns
/// the manifold's point count.
[[gnu::always_inline]] inline int gatherLane(ContactConstraintWide& wc, int i, WorldState& w, std::uint32_t slot,
                                             const Softness& soft, const Softness& staticSoft) {
  Contact& contact = w.contacts[slot];
  const SolverBodyInfo& a = w.bodyInfo[contact.bodyA];
  const SolverBodyInfo& b = w.bodyInfo[contact.bodyB];
  const Manifold& m = contact.manifold;
  const bool warm = w.def.enableWarmStarting;
  const auto li = static_cast<std::size_t>(i);
  wc.indexA[li] = w.solverIndexOf(a);
  wc.indexB[li] = w.solverIndexOf(b);
  lane(wc.invMassA, i) = a.inverseMass;
  lane(wc.invMassB, i) = b.inverseMass;
  lane(wc.invIA, i) = a.inverseInertia;
  lane(wc.invIB, i) = b.inverseInertia;
  lane(wc.normalX, i) = m.normal.x;
  lane(wc.normalY, i) = m.normal.y;
  lane(wc.friction, i) = contact.friction;
  lane(wc.restitution, i) = contact.restitution;
  lane(wc.rollingResistance, i) = contact.rollingResistance;
  lane(wc.rollingImpulse, i) = rollingImpulseToWarmStart(contact, warm);
  lane(wc.tangentSpeed, i) = contact.tangentSpeed;
  const Softness& s = (a.inverseMass == 0.0f || b.inverseMass == 0.0f) ? staticSoft : soft;
  lane(wc.biasRate, i) = s.biasRate;
  lane(wc.massScale, i) = s.massScale;
  lane(wc.impulseScale, i) = s.impulseScale;
  for (int k = 0; k < 2; ++k) {
    ContactConstraintWide::Point& wp = wc.points[static_cast<std::size_t>(k)];
    if (k >= m.pointCount) {
      lane(wp.rAx, i) = lane(wp.rAy, i) = lane(wp.rBx, i) = lane(wp.rBy, i) = 0.0f;
      lane(wp.adjustedSeparation, i) = lane(wp.normalImpulse, i) = lane(wp.tangentImpulse, i) = 0.0f;
      continue;
    }
    const ManifoldPoint& mp = m.points[static_cast<std::size_t>(k)];
    lane(wp.rAx, i) = mp.anchorA.x - a.centerOffset.x;
    lane(wp.rAy, i) = mp.anchorA.y - a.centerOffset.y;
    lane(wp.rBx, i) = mp.anchorB.x - b.centerOffset.x;
    lane(wp.rBy, i) = mp.anchorB.y - b.centerOffset.y;
    lane(wp.adjustedSeparation, i) = mp.separation; // made relative to the anchors in deriveLanes
    lane(wp.normalImpulse, i) = warm ? mp.normalImpulse : 0.0f;
    lane(wp.tangentImpulse, i) = warm ? mp.tangentImpulse : 0.0f;
  }
  return m.pointCount;
}

/// An unused lane i: the static state, no mass, no point (as ContactConstraint{}).
[[gnu::always_inline]] inline void clearLane(ContactConstraintWide& wc, int i, std::uint32_t staticIndex) {
  const auto li = static_cast<std::size_t>(i);
  wc.indexA[li] = wc.indexB[li] = staticIndex;
  for (FloatW* f : {&wc.invMassA, &wc.invMassB, &wc.invIA, &wc.invIB, &wc.normalX, &wc.normalY, &wc.friction,
                    &wc.restitution, &wc.rollingResistance, &wc.rollingImpulse, &wc.tangentSpeed}) {
    lane(*f, i) = 0.0f;
  }
  const Softness none;
  lane(wc.biasRate, i) = none.biasRate;
  lane(wc.massScale, i) = none.massScale;
  lane(wc.impulseScale, i) = none.impulseScale;
  for (ContactConstraintWide::Point& wp : wc.points) {
    lane(wp.rAx, i) = lane(wp.rAy, i) = lane(wp.rBx, i) = lane(wp.rBy, i) = 0.0f;
    lane(wp.adjustedSeparation, i) = lane(wp.normalImpulse, i) = lane(wp.tangentImpulse, i) = 0.0f;
  }
}

/// Cross product of a scalar angular velocity and a vector, per lane: w x r = (-w ry, w rx).
void addAngular(FloatW& vx, FloatW& vy, FloatW w, FloatW rx, FloatW ry) {
  vx = vx - w * ry;
  vy = vy + w * rx;
}

/// What makeContactConstraint computes from the gathered lanes, for all lanes at once and with
/// the same operations in the same order (a lane's results are the scalar constraint's, bit for
/// bit): effective masses, separations relative to the anchors, and each point's approach speed
/// before the step (positive approaching). Lanes without a point k (pointCount <= k) get zeros.
[[gnu::always_inline]] inline void deriveLanes(ContactConstraintWide& wc, FloatW pointCount, const BodyState* states,
                                               const ContactSpeedCaps& caps) {
  const FloatW zero = zeroW();
  const FloatW one = splatW(1.0f);
  // 1/k where the mask holds, else 0 (and no division by zero in the other lanes).
  const auto inverseWhere = [&](FloatW mask, FloatW k) { return selectW(mask, one / selectW(mask, k, one), zero); };
  const FloatW kRolling = wc.invIA + wc.invIB;
  wc.rollingMass = inverseWhere(andW(greaterW(wc.rollingResistance, zero), greaterW(kRolling, zero)), kRolling);
  const BodiesW a = gatherVelocities(states, wc.indexA);
  const BodiesW b = gatherVelocities(states, wc.indexB);
  const FloatW nx = wc.normalX;
  const FloatW ny = wc.normalY;
  const FloatW tx = ny; // the tangent (n.y, -n.x)
  const FloatW ty = negateW(nx);
  for (std::size_t k = 0; k < 2; ++k) {
    ContactConstraintWide::Point& p = wc.points[k];
    const FloatW has = greaterW(pointCount, splatW(static_cast<float>(k)));
    const FloatW rnA = p.rAx * ny - p.rAy * nx;
    const FloatW rnB = p.rBx * ny - p.rBy * nx;
    const FloatW kNormal = wc.invMassA + wc.invMassB + wc.invIA * rnA * rnA + wc.invIB * rnB * rnB;
    p.normalMass = inverseWhere(andW(has, greaterW(kNormal, zero)), kNormal);
    p.normalBound = contactImpulseBound(p.normalMass, maxW(rnA, -rnA) + maxW(rnB, -rnB), splatW(caps.twoMaxSpeed),
                                        splatW(caps.maxSpin));
    const FloatW rtA = p.rAx * ty - p.rAy * tx;
    const FloatW rtB = p.rBx * ty - p.rBy * tx;
    const FloatW kTangent = wc.invMassA + wc.invMassB + wc.invIA * rtA * rtA + wc.invIB * rtB * rtB;
    p.tangentMass = inverseWhere(andW(has, greaterW(kTangent, zero)), kTangent);
    const FloatW dx = p.rBx - p.rAx;
    const FloatW dy = p.rBy - p.rAy;
    p.adjustedSeparation = selectW(has, p.adjustedSeparation - (dx * nx + dy * ny), zero);
    FloatW vAx = a.vx;
    FloatW vAy = a.vy;
    addAngular(vAx, vAy, a.w, p.rAx, p.rAy);
    FloatW vBx = b.vx;
    FloatW vBy = b.vy;
    addAngular(vBx, vBy, b.w, p.rBx, p.rBy);
    p.impactSpeed = selectW(has, negateW((vBx - vAx) * nx + (vBy - vAy) * ny), zero);
    p.maxNormalImpulse = zero;
  }
}

/// Relative normal or tangential velocity of point p along (dx, dy).
FloatW relativeVelocity(const BodiesW& a, const BodiesW& b, const ContactConstraintWide::Point& p, FloatW dx,
                        FloatW dy) {
  FloatW vax = a.vx, vay = a.vy, vbx = b.vx, vby = b.vy;
  addAngular(vax, vay, a.w, p.rAx, p.rAy);
  addAngular(vbx, vby, b.w, p.rBx, p.rBy);
  return (vbx - vax) * dx + (vby - vay) * dy;
}

/// Applies impulse P = applied (dx, dy) at point p: -P to A, +P to B.
void applyW(BodiesW& a, BodiesW& b, const ContactConstraintWide& c, const ContactConstraintWide::Point& p, FloatW px,
            FloatW py) {
  a.vx = a.vx - c.invMassA * px;
  a.vy = a.vy - c.invMassA * py;
  a.w = a.w - c.invIA * (p.rAx * py - p.rAy * px);
  b.vx = b.vx + c.invMassB * px;
  b.vy = b.vy + c.invMassB * py;
  b.w = b.w + c.invIB * (p.rBx * py - p.rBy * px);
}

/// bounceOne (contact_solver.cpp), lane by lane: the impact of the batch's bouncing points, by
/// Newton's law with Coulomb friction on the impact's impulse, a two-point manifold's as a block.
void bounceWide(ContactConstraintWide& c, BodiesW& a, BodiesW& b, const std::array<FloatW, 2>& separation,
                const ContactSolveParams& params) {
  const FloatW zero = zeroW();
  const FloatW one = splatW(1.0f);
  const FloatW invH = splatW(params.inverseH);
  const FloatW minusThreshold = splatW(-params.restitutionThreshold);
  const FloatW hasRestitution = greaterW(c.restitution, zero);
  std::array<FloatW, 2> approach{};
  std::array<FloatW, 2> bounces{};
  for (std::size_t k = 0; k < 2; ++k) {
    const ContactConstraintWide::Point& p = c.points[k];
    approach[k] = relativeVelocity(a, b, p, c.normalX, c.normalY);
    const FloatW closes = greaterW(zero, approach[k] + maxW(separation[k], zero) * invH);
    bounces[k] = andW(hasRestitution, andW(greaterW(minusThreshold, approach[k]), closes));
  }
  if (!anyNonZeroW(orW(bounces[0], bounces[1]))) {
    return;
  }
  const auto target = [&](std::size_t k) { return -(c.restitution * approach[k]); };
  ContactConstraintWide::Point& p1 = c.points[0];
  ContactConstraintWide::Point& p2 = c.points[1];
  const FloatW rnA1 = p1.rAx * c.normalY - p1.rAy * c.normalX;
  const FloatW rnA2 = p2.rAx * c.normalY - p2.rAy * c.normalX;
  const FloatW rnB1 = p1.rBx * c.normalY - p1.rBy * c.normalX;
  const FloatW rnB2 = p2.rBx * c.normalY - p2.rBy * c.normalX;
  const FloatW k11 = normalCoupling(c.invMassA, c.invMassB, c.invIA, c.invIB, rnA1, rnA1, rnB1, rnB1);
  const FloatW k12 = normalCoupling(c.invMassA, c.invMassB, c.invIA, c.invIB, rnA1, rnA2, rnB1, rnB2);
  const FloatW k22 = normalCoupling(c.invMassA, c.invMassB, c.invIA, c.invIB, rnA2, rnA2, rnB2, rnB2);
  const FloatW block = andW(andW(bounces[0], bounces[1]),
                            greaterW(splatW(maxBlockConditionNumber) * (k11 * k22 - k12 * k12), k11 * k11));
  std::array<FloatW, 2> impulse{zero, zero};
  if (anyNonZeroW(block)) {
    // Lanes outside the block solve the identity, and discard it.
    FloatW x1 = zero;
    FloatW x2 = zero;
    solveNormalBlock(selectW(block, k11, one), selectW(block, k12, zero), selectW(block, k22, one), approach[0],
                     approach[1], target(0), target(1), zero, x1, x2);
    impulse[0] = selectW(block, x1, zero);
    impulse[1] = selectW(block, x2, zero);
    applyW(a, b, c, p1, impulse[0] * c.normalX, impulse[0] * c.normalY);
    applyW(a, b, c, p2, impulse[1] * c.normalX, impulse[1] * c.normalY);
  }
  for (std::size_t k = 0; k < 2; ++k) {
    // The points of the lanes the block did not take, one after the other.
    const ContactConstraintWide::Point& p = c.points[k];
    const FloatW alone = selectW(block, zero, bounces[k]);
    const FloatW vn = relativeVelocity(a, b, p, c.normalX, c.normalY);
    const FloatW applied = selectW(alone, maxW(-(p.normalMass * (vn - target(k))), zero), zero);
    impulse[k] = impulse[k] + applied;
    applyW(a, b, c, p, applied * c.normalX, applied * c.normalY);
  }
  const FloatW tx = c.normalY;
  const FloatW ty = -c.normalX;
  for (std::size_t k = 0; k < 2; ++k) {
    ContactConstraintWide::Point& p = c.points[k];
    const FloatW vt = relativeVelocity(a, b, p, tx, ty) - c.tangentSpeed;
    const FloatW limit = c.friction * impulse[k];
    const FloatW applied = selectW(bounces[k], maxW(minW(-(p.tangentMass * vt), limit), -limit), zero);
    applyW(a, b, c, p, applied * tx, applied * ty);
    p.maxNormalImpulse = maxW(p.maxNormalImpulse, impulse[k]);
    p.impactSpeed = selectW(bounces[k], maxW(p.impactSpeed, -approach[k]), p.impactSpeed);
  }
}

[[gnu::always_inline]] inline void solveWide(ContactConstraintWide& c, BodyState* states, std::uint32_t staticIndex,
                                             const ContactSolveParams& params) {
  BodiesW a = gather(states, c.indexA);
  BodiesW b = gather(states, c.indexB);
  const FloatW zero = zeroW();
  const FloatW one = splatW(1.0f);
  const FloatW invH = splatW(params.inverseH);
  const FloatW minBias = splatW(-params.pushSpeed);
  const FloatW dpx = b.dpx - a.dpx;
  const FloatW dpy = b.dpy - a.dpy;
  std::array<FloatW, 2> separation{};
  for (std::size_t k = 0; k < 2; ++k) {
    const ContactConstraintWide::Point& p = c.points[k];
    // Separation now: the anchors turned by each body's rotation delta.
    const FloatW prBx = b.dqc * p.rBx - b.dqs * p.rBy;
    const FloatW prBy = b.dqs * p.rBx + b.dqc * p.rBy;
    const FloatW prAx = a.dqc * p.rAx - a.dqs * p.rAy;
    const FloatW prAy = a.dqs * p.rAx + a.dqc * p.rAy;
    separation[k] = (dpx + prBx - prAx) * c.normalX + (dpy + prBy - prAy) * c.normalY + p.adjustedSeparation;
  }
  if (anyNonZeroW(c.restitution)) {
    bounceWide(c, a, b, separation, params);
  }
  FloatW totalNormal = zero;
  for (std::size_t k = 0; k < 2; ++k) {
    ContactConstraintWide::Point& p = c.points[k];
    const FloatW s = separation[k];
    const FloatW speculative = greaterW(s, zero);
    FloatW bias = s * invH;
    FloatW massScale = one;
    FloatW impulseScale = zero;
    const FloatW vn = relativeVelocity(a, b, p, c.normalX, c.normalY);
    if (params.useBias) {
      bias = selectW(speculative, bias, maxW(c.biasRate * s, minBias));
      massScale = selectW(speculative, one, c.massScale);
      impulseScale = selectW(speculative, zero, c.impulseScale);
    } else {
      bias = selectW(speculative, bias, zero);
    }
    const FloatW impulse = -(p.normalMass * massScale * (vn + bias)) - impulseScale * p.normalImpulse;
    const FloatW total = minW(maxW(p.normalImpulse + impulse, zero), p.normalBound);
    const FloatW applied = total - p.normalImpulse;
    p.normalImpulse = total;
    p.maxNormalImpulse = maxW(p.maxNormalImpulse, applied);
    totalNormal = totalNormal + total;
    applyW(a, b, c, p, applied * c.normalX, applied * c.normalY);
  }
  // Friction and rolling resistance act on the velocities alone: they are solved in the relax
  // pass only (see ContactSolveParams::useBias).
  if (!params.useBias) {
    if (anyNonZeroW(c.rollingMass)) {
      // Rolling resistance (zero rolling mass in lanes without).
      const FloatW limit = c.rollingResistance * totalNormal;
      const FloatW total = maxW(minW(c.rollingImpulse - c.rollingMass * (b.w - a.w), limit), -limit);
      const FloatW applied = total - c.rollingImpulse;
      c.rollingImpulse = total;
      a.w = a.w - c.invIA * applied;
      b.w = b.w + c.invIB * applied;
    }
    const FloatW tx = c.normalY;
    const FloatW ty = -c.normalX;
    for (ContactConstraintWide::Point& p : c.points) {
      const FloatW vt = relativeVelocity(a, b, p, tx, ty) - c.tangentSpeed;
      const FloatW limit = c.friction * p.normalImpulse;
      const FloatW total = maxW(minW(p.tangentImpulse - p.tangentMass * vt, limit), -limit);
      const FloatW applied = total - p.tangentImpulse;
      p.tangentImpulse = total;
      applyW(a, b, c, p, applied * tx, applied * ty);
    }
  }
  scatter(states, c.indexA, staticIndex, a);
  scatter(states, c.indexB, staticIndex, b);
}

[[gnu::always_inline]] inline void warmStartWide(ContactConstraintWide& c, BodyState* states,
                                                 std::uint32_t staticIndex) {
  BodiesW a = gatherVelocities(states, c.indexA);
  BodiesW b = gatherVelocities(states, c.indexB);
  const FloatW tx = c.normalY;
  const FloatW ty = -c.normalX;
  for (const ContactConstraintWide::Point& p : c.points) {
    const FloatW px = p.normalImpulse * c.normalX + p.tangentImpulse * tx;
    const FloatW py = p.normalImpulse * c.normalY + p.tangentImpulse * ty;
    applyW(a, b, c, p, px, py);
  }
  a.w = a.w - c.invIA * c.rollingImpulse;
  b.w = b.w + c.invIB * c.rollingImpulse;
  scatter(states, c.indexA, staticIndex, a);
  scatter(states, c.indexB, staticIndex, b);
}

// The table's entries: loops over batches, so the call through the table costs once per range.

ContactConstraintWide* batchesOf(void* batches) { return static_cast<ContactConstraintWide*>(batches); }

void prepareBatch(void* batches, std::uint32_t batch, WorldState& w, const std::uint32_t* slots, int count,
                  const Softness& soft, const Softness& staticSoft, const ContactSpeedCaps& caps) {
  ContactConstraintWide& wc = batchesOf(batches)[batch];
  FloatW pointCount = zeroW();
  for (int i = 0; i < simdWidth; ++i) {
    if (i < count) {
      lane(pointCount, i) = static_cast<float>(gatherLane(wc, i, w, slots[i], soft, staticSoft));
    } else {
      clearLane(wc, i, w.staticIndex());
    }
  }
  deriveLanes(wc, pointCount, w.states.data(), caps);
}

void warmStartBatches(void* batches, std::uint32_t begin, std::uint32_t end, BodyState* states,
                      std::uint32_t staticIndex) {
  for (std::uint32_t i = begin; i < end; ++i) {
    warmStartWide(batchesOf(batches)[i], states, staticIndex);
  }
}

void solveBatches(void* batches, std::uint32_t begin, std::uint32_t end, BodyState* states, std::uint32_t staticIndex,
                  const ContactSolveParams& params) {
  for (std::uint32_t i = begin; i < end; ++i) {
    solveWide(batchesOf(batches)[i], states, staticIndex, params);
  }
}

/// Whether any lane's point may raise a hit event: storeContact's test (approachMayHit of the
/// fastest point that pushed), for the whole batch at once.
[[gnu::always_inline]] inline bool anyMayHit(const ContactConstraintWide& wc, float hitThreshold) {
  const FloatW zero = zeroW();
  const FloatW resting = splatW(restingApproachSpeed);
  const FloatW threshold = splatW(hitThreshold);
  FloatW any = zero;
  for (const ContactConstraintWide::Point& p : wc.points) {
    const FloatW reached = orW(greaterW(p.impactSpeed, threshold), equalW(p.impactSpeed, threshold));
    any = orW(any, andW(andW(greaterW(p.maxNormalImpulse, zero), greaterW(p.impactSpeed, resting)), reached));
  }
  return anyNonZeroW(any);
}

void storeBatch(const void* batches, std::uint32_t batch, WorldState& w, const std::uint32_t* slots,
                float hitThreshold) {
  const ContactConstraintWide& wc = static_cast<const ContactConstraintWide*>(batches)[batch];
  const bool warm = w.def.enableWarmStarting;
  if (!anyMayHit(wc, hitThreshold)) {
    // As a rule no lane can: only the impulses (the step cleared maybeHit).
    for (int i = 0; i < simdWidth; ++i) {
      const std::uint32_t slot = slots[i];
      if (slot == noContact) {
        continue;
      }
      const std::array<SolvedPoint, 2> points{
          SolvedPoint{lane(wc.points[0].normalImpulse, i), lane(wc.points[0].tangentImpulse, i)},
          SolvedPoint{lane(wc.points[1].normalImpulse, i), lane(wc.points[1].tangentImpulse, i)}};
      storeContactImpulses(w.contacts[slot], points, lane(wc.rollingImpulse, i),
                           lane(wc.rollingMass, i) != 0.0f || !warm);
    }
    return;
  }
  for (int i = 0; i < simdWidth; ++i) {
    const std::uint32_t slot = slots[i];
    if (slot == noContact) {
      continue;
    }
    std::array<SolvedPoint, 2> points;
    for (std::size_t k = 0; k < 2; ++k) {
      const ContactConstraintWide::Point& p = wc.points[k];
      points[k] = {lane(p.normalImpulse, i), lane(p.tangentImpulse, i), lane(p.maxNormalImpulse, i),
                   lane(p.impactSpeed, i)};
    }
    const bool rollingSolved = lane(wc.rollingMass, i) != 0.0f || !warm;
    w.maybeHit[slot] =
        storeContact(w.contacts[slot], points, lane(wc.rollingImpulse, i), rollingSolved, hitThreshold) ? 1 : 0;
  }
}

static_assert(simdWidth <= maxWideLanes);
static_assert(alignof(ContactConstraintWide) <= wideAlignment);
static_assert(sizeof(ContactConstraintWide) % alignof(ContactConstraintWide) == 0);

constexpr WideKernels wideKernels{
    simdName, simdWidth, sizeof(ContactConstraintWide), &prepareBatch, &warmStartBatches, &solveBatches, &storeBatch};

} // namespace
} // namespace impetus::rigid2d::detail
