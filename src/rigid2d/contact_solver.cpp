// The contact constraints of the soft-step solver (after Erin Catto's Solver2D "soft step" and
// Box2D v3): soft contacts with a stiffness in hertz, warm starting, a relax pass, restitution,
// Coulomb friction and rolling resistance.
//
// Layout: the touching contacts are coloured each step so that no two contacts of a colour share
// a moving body (static bodies do not count: nothing writes them). A colour's contacts are then
// independent: they are solved four at a time in SIMD lanes (ContactConstraintWide) and their
// batches may run on several threads, with results that do not depend on either. Contacts that
// find no free colour (a body touching very many others) go to a small overflow list solved one
// by one first. Within a colour, contacts keep their pool order, so the whole solve has a fixed
// order and is bit-identical run after run.
#include "rigid2d/joints.hpp"
#include "rigid2d/simd.hpp"
#include "rigid2d/world_impl.hpp"

#include <impetus/math/scalar.hpp>

#include <algorithm>
#include <array>

namespace impetus::rigid2d::detail {
namespace {

constexpr int colourCount = 24;
/// Contacts between two moving bodies use colours [0, dynamicColourCount); contacts with a static
/// body, which take up one body only, may use any colour, so the last ones stay free for them.
/// (Box2D v3 keeps static contacts out of colour 0; here that delayed the ground's support of a
/// stack by a colour each substep and let a 10-box stack sway 2 cm, against 0.5 cm.)
constexpr int dynamicColourCount = colourCount - 4;

struct ConstraintPoint {
  Vec2f rA, rB; ///< anchors relative to the centres of mass, world axes, m
  float adjustedSeparation = 0.0f;
  float normalImpulse = 0.0f;
  float tangentImpulse = 0.0f;
  float maxNormalImpulse = 0.0f;
  float normalMass = 0.0f;
  float tangentMass = 0.0f;
  float relativeVelocity = 0.0f; ///< normal approach speed, for restitution and hit events
};

/// One contact, solved alone (the overflow).
struct ContactConstraint {
  std::uint32_t indexA = 0, indexB = 0; ///< solver indices
  std::uint32_t contact = 0;            ///< contact slot
  float mA = 0.0f, iA = 0.0f, mB = 0.0f, iB = 0.0f;
  Vec2f normal;
  float friction = 0.0f;
  float restitution = 0.0f;
  float rollingResistance = 0.0f;
  float rollingMass = 0.0f;
  float rollingImpulse = 0.0f;
  Softness softness;
  int pointCount = 0;
  std::array<ConstraintPoint, 2> points{};
};

/// Four contacts in SIMD lanes. Unused lanes point at the static state with zero masses, so
/// they compute zero impulses; a one-point manifold's second point has zero mass likewise.
struct ContactConstraintWide {
  std::array<std::uint32_t, simdWidth> indexA{}, indexB{};
  FloatW invMassA, invMassB, invIA, invIB;
  FloatW normalX, normalY;
  FloatW friction, restitution, rollingResistance, rollingMass, rollingImpulse;
  FloatW biasRate, massScale, impulseScale;
  struct Point {
    FloatW rAx, rAy, rBx, rBy;
    FloatW adjustedSeparation;
    FloatW normalImpulse, tangentImpulse, maxNormalImpulse;
    FloatW normalMass, tangentMass;
    FloatW relativeVelocity;
  };
  std::array<Point, 2> points;
};

float& lane(FloatW& w, int i) { return reinterpret_cast<float*>(&w)[i]; }
float lane(const FloatW& w, int i) { return reinterpret_cast<const float*>(&w)[i]; }

/// Velocities (and, for the solve, position deltas) of four bodies, as columns.
struct BodiesW {
  FloatW vx, vy, w, dpx, dpy, dqc, dqs;
};

BodiesW gather(const std::vector<BodyState>& states, const std::array<std::uint32_t, simdWidth>& index) {
  const float* rows[simdWidth];
  for (std::size_t i = 0; i < simdWidth; ++i) {
    rows[i] = &states[index[i]].v.x;
  }
  FloatW columns[8];
  loadRowsW(rows, columns);
  return {columns[0], columns[1], columns[2], columns[4], columns[5], columns[6], columns[7]};
}

/// Velocities only (warm start and restitution need no position deltas).
BodiesW gatherVelocities(const std::vector<BodyState>& states, const std::array<std::uint32_t, simdWidth>& index) {
  const float* rows[simdWidth];
  for (std::size_t i = 0; i < simdWidth; ++i) {
    rows[i] = &states[index[i]].v.x;
  }
  BodiesW b;
  FloatW unused;
  loadRowHeadsW(rows, b.vx, b.vy, b.w, unused);
  return b;
}

/// Writes the velocities back, except to the static state.
void scatter(std::vector<BodyState>& states, const std::array<std::uint32_t, simdWidth>& index,
             std::uint32_t staticIndex, const BodiesW& b) {
  float* rows[simdWidth];
  for (std::size_t i = 0; i < simdWidth; ++i) {
    rows[i] = index[i] == staticIndex ? nullptr : &states[index[i]].v.x;
  }
  storeRowHeadsW(rows, b.vx, b.vy, b.w, zeroW());
}

} // namespace

struct ContactSolverData {
  std::vector<ContactConstraintWide> wide;                  ///< batches, colour by colour
  std::vector<std::array<std::uint32_t, simdWidth>> slots;  ///< contact slot per lane (or ~0)
  std::array<std::uint32_t, colourCount + 1> colourStart{}; ///< first batch of each colour
  std::vector<ContactConstraint> overflow;
  std::array<std::vector<std::uint64_t>, colourCount> bodyBits; ///< moving bodies used per colour
  std::array<std::vector<std::uint32_t>, colourCount> colourContacts;
  Softness soft, staticSoft;
  float pushSpeed = 0.0f;
  float restitutionThreshold = 0.0f;
};

WorldState::WorldState() = default;
WorldState::~WorldState() = default;
WorldState::WorldState(WorldState&&) noexcept = default;
WorldState& WorldState::operator=(WorldState&&) noexcept = default;

namespace {

constexpr std::uint32_t noContact = ~std::uint32_t{0};

/// The first colour in [first, last) free for both moving bodies (static ones pass as null), or -1.
int findColour(ContactSolverData& d, std::uint32_t a, std::uint32_t b, std::uint32_t staticIndex, int first, int last) {
  for (int c = first; c < last; ++c) {
    std::vector<std::uint64_t>& bits = d.bodyBits[static_cast<std::size_t>(c)];
    const bool aBusy = a != staticIndex && ((bits[a / 64] >> (a % 64)) & 1U) != 0;
    const bool bBusy = b != staticIndex && ((bits[b / 64] >> (b % 64)) & 1U) != 0;
    if (aBusy || bBusy) {
      continue;
    }
    if (a != staticIndex) {
      bits[a / 64] |= std::uint64_t{1} << (a % 64);
    }
    if (b != staticIndex) {
      bits[b / 64] |= std::uint64_t{1} << (b % 64);
    }
    return c;
  }
  return -1;
}

/// Fills one constraint (or one lane) from its contact: anchors relative to the centres of mass,
/// effective masses, and the approach speed before the step.
ContactConstraint makeConstraint(const WorldState& w, Contact& contact, std::uint32_t slot,
                                 const ContactSolverData& d) {
  const Body& a = w.bodies[contact.bodyA];
  const Body& b = w.bodies[contact.bodyB];
  const Manifold& m = contact.manifold;
  ContactConstraint c;
  c.indexA = a.moving() ? a.solverIndex : w.staticIndex();
  c.indexB = b.moving() ? b.solverIndex : w.staticIndex();
  c.contact = slot;
  c.mA = a.inverseMass;
  c.iA = a.inverseInertia;
  c.mB = b.inverseMass;
  c.iB = b.inverseInertia;
  c.normal = m.normal;
  c.friction = contact.friction;
  c.restitution = contact.restitution;
  c.rollingResistance = contact.rollingResistance;
  const float kRolling = c.iA + c.iB;
  c.rollingMass = (c.rollingResistance > 0.0f && kRolling > 0.0f) ? 1.0f / kRolling : 0.0f;
  c.rollingImpulse = contact.rollingImpulse;
  c.softness = (c.mA == 0.0f || c.mB == 0.0f) ? d.staticSoft : d.soft;
  c.pointCount = m.pointCount;
  const Vec2f tangent{m.normal.y, -m.normal.x};
  const Vec2f offsetA = a.center - a.transform.p;
  const Vec2f offsetB = b.center - b.transform.p;
  const BodyState& stA = w.states[c.indexA];
  const BodyState& stB = w.states[c.indexB];
  for (int k = 0; k < m.pointCount; ++k) {
    const ManifoldPoint& mp = m.points[static_cast<std::size_t>(k)];
    ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
    p.rA = mp.anchorA - offsetA;
    p.rB = mp.anchorB - offsetB;
    p.adjustedSeparation = mp.separation - dot(p.rB - p.rA, m.normal);
    p.normalImpulse = mp.normalImpulse;
    p.tangentImpulse = mp.tangentImpulse;
    const float rnA = cross(p.rA, m.normal);
    const float rnB = cross(p.rB, m.normal);
    const float kNormal = c.mA + c.mB + c.iA * rnA * rnA + c.iB * rnB * rnB;
    p.normalMass = kNormal > 0.0f ? 1.0f / kNormal : 0.0f;
    const float rtA = cross(p.rA, tangent);
    const float rtB = cross(p.rB, tangent);
    const float kTangent = c.mA + c.mB + c.iA * rtA * rtA + c.iB * rtB * rtB;
    p.tangentMass = kTangent > 0.0f ? 1.0f / kTangent : 0.0f;
    const Vec2f vA = stA.v + cross(stA.w, p.rA);
    const Vec2f vB = stB.v + cross(stB.w, p.rB);
    p.relativeVelocity = dot(vB - vA, m.normal);
    contact.approachBefore[static_cast<std::size_t>(k)] = -p.relativeVelocity;
  }
  return c;
}

/// Copies a constraint into lane i of a wide constraint.
void setLane(ContactConstraintWide& wc, int i, const ContactConstraint& c) {
  const auto li = static_cast<std::size_t>(i);
  wc.indexA[li] = c.indexA;
  wc.indexB[li] = c.indexB;
  lane(wc.invMassA, i) = c.mA;
  lane(wc.invMassB, i) = c.mB;
  lane(wc.invIA, i) = c.iA;
  lane(wc.invIB, i) = c.iB;
  lane(wc.normalX, i) = c.normal.x;
  lane(wc.normalY, i) = c.normal.y;
  lane(wc.friction, i) = c.friction;
  lane(wc.restitution, i) = c.restitution;
  lane(wc.rollingResistance, i) = c.rollingResistance;
  lane(wc.rollingMass, i) = c.rollingMass;
  lane(wc.rollingImpulse, i) = c.rollingImpulse;
  lane(wc.biasRate, i) = c.softness.biasRate;
  lane(wc.massScale, i) = c.softness.massScale;
  lane(wc.impulseScale, i) = c.softness.impulseScale;
  for (std::size_t k = 0; k < 2; ++k) {
    const ConstraintPoint& p = c.points[k];
    ContactConstraintWide::Point& wp = wc.points[k];
    lane(wp.rAx, i) = p.rA.x;
    lane(wp.rAy, i) = p.rA.y;
    lane(wp.rBx, i) = p.rB.x;
    lane(wp.rBy, i) = p.rB.y;
    lane(wp.adjustedSeparation, i) = p.adjustedSeparation;
    lane(wp.normalImpulse, i) = p.normalImpulse;
    lane(wp.tangentImpulse, i) = p.tangentImpulse;
    lane(wp.maxNormalImpulse, i) = 0.0f;
    lane(wp.normalMass, i) = p.normalMass;
    lane(wp.tangentMass, i) = p.tangentMass;
    lane(wp.relativeVelocity, i) = p.relativeVelocity;
  }
}

Vec2f velocityAt(const BodyState& s, const Vec2f& r) { return s.v + cross(s.w, r); }

void applyImpulse(BodyState& a, BodyState& b, const ContactConstraint& c, const ConstraintPoint& p,
                  const Vec2f& impulse) {
  a.v -= impulse * c.mA;
  a.w -= c.iA * cross(p.rA, impulse);
  b.v += impulse * c.mB;
  b.w += c.iB * cross(p.rB, impulse);
}

/// Rolling resistance: an angular impulse against the relative spin, at most the coefficient
/// (times radius) times the normal impulse.
void solveRolling(BodyState& a, BodyState& b, ContactConstraint& c) {
  if (c.rollingMass == 0.0f) {
    return;
  }
  float normal = 0.0f;
  for (int k = 0; k < c.pointCount; ++k) {
    normal += c.points[static_cast<std::size_t>(k)].normalImpulse;
  }
  const float limit = c.rollingResistance * normal;
  const float total = std::clamp(c.rollingImpulse - c.rollingMass * (b.w - a.w), -limit, limit);
  const float applied = total - c.rollingImpulse;
  c.rollingImpulse = total;
  a.w -= c.iA * applied;
  b.w += c.iB * applied;
}

void solveOne(ContactConstraint& c, std::vector<BodyState>& states, std::uint32_t staticIndex,
              const ContactSolverData& d, float inverseH, bool useBias) {
  BodyState a = states[c.indexA];
  BodyState b = states[c.indexB];
  const Vec2f dp = b.dp - a.dp;
  for (int k = 0; k < c.pointCount; ++k) {
    ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
    // Current separation from the deltas: the anchors turn with their bodies.
    const Vec2f dd = dp + rotate(b.dq, p.rB) - rotate(a.dq, p.rA);
    const float s = dot(dd, c.normal) + p.adjustedSeparation;
    float bias = 0.0f;
    float massScale = 1.0f;
    float impulseScale = 0.0f;
    if (s > 0.0f) {
      bias = s * inverseH; // speculative: may close the gap this substep, no more
    } else if (useBias) {
      bias = std::max(c.softness.biasRate * s, -d.pushSpeed);
      massScale = c.softness.massScale;
      impulseScale = c.softness.impulseScale;
    }
    const float vn = dot(velocityAt(b, p.rB) - velocityAt(a, p.rA), c.normal);
    if (useBias && s <= 0.0f) {
      // The approach speed at impact, for restitution: gravity may have sped the bodies up
      // since the step began (2% of e^2 h in a dropped ball's rebound).
      p.relativeVelocity = std::min(p.relativeVelocity, vn);
    }
    const float impulse = -p.normalMass * massScale * (vn + bias) - impulseScale * p.normalImpulse;
    const float total = std::max(p.normalImpulse + impulse, 0.0f);
    const float applied = total - p.normalImpulse;
    p.normalImpulse = total;
    p.maxNormalImpulse = std::max(p.maxNormalImpulse, applied);
    applyImpulse(a, b, c, p, c.normal * applied);
  }
  const Vec2f tangent{c.normal.y, -c.normal.x};
  for (int k = 0; k < c.pointCount; ++k) {
    ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
    const float vt = dot(velocityAt(b, p.rB) - velocityAt(a, p.rA), tangent);
    const float limit = c.friction * p.normalImpulse;
    const float total = std::clamp(p.tangentImpulse - p.tangentMass * vt, -limit, limit);
    const float applied = total - p.tangentImpulse;
    p.tangentImpulse = total;
    applyImpulse(a, b, c, p, tangent * applied);
  }
  solveRolling(a, b, c);
  if (c.indexA != staticIndex) {
    states[c.indexA].v = a.v;
    states[c.indexA].w = a.w;
  }
  if (c.indexB != staticIndex) {
    states[c.indexB].v = b.v;
    states[c.indexB].w = b.w;
  }
}

/// Cross product of a scalar angular velocity and a vector, per lane: w x r = (-w ry, w rx).
void addAngular(FloatW& vx, FloatW& vy, FloatW w, FloatW rx, FloatW ry) {
  vx = vx - w * ry;
  vy = vy + w * rx;
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

void solveWide(ContactConstraintWide& c, std::vector<BodyState>& states, std::uint32_t staticIndex,
               const ContactSolverData& d, float inverseH, bool useBias) {
  BodiesW a = gather(states, c.indexA);
  BodiesW b = gather(states, c.indexB);
  const FloatW zero = zeroW();
  const FloatW one = splatW(1.0f);
  const FloatW invH = splatW(inverseH);
  const FloatW minBias = splatW(-d.pushSpeed);
  const FloatW dpx = b.dpx - a.dpx;
  const FloatW dpy = b.dpy - a.dpy;
  FloatW totalNormal = zero;
  for (ContactConstraintWide::Point& p : c.points) {
    // Separation now: the anchors turned by each body's rotation delta.
    const FloatW prBx = b.dqc * p.rBx - b.dqs * p.rBy;
    const FloatW prBy = b.dqs * p.rBx + b.dqc * p.rBy;
    const FloatW prAx = a.dqc * p.rAx - a.dqs * p.rAy;
    const FloatW prAy = a.dqs * p.rAx + a.dqc * p.rAy;
    const FloatW s = (dpx + prBx - prAx) * c.normalX + (dpy + prBy - prAy) * c.normalY + p.adjustedSeparation;
    const FloatW speculative = greaterW(s, zero);
    FloatW bias = s * invH;
    FloatW massScale = one;
    FloatW impulseScale = zero;
    const FloatW vn = relativeVelocity(a, b, p, c.normalX, c.normalY);
    if (useBias) {
      bias = selectW(speculative, bias, maxW(c.biasRate * s, minBias));
      massScale = selectW(speculative, one, c.massScale);
      impulseScale = selectW(speculative, zero, c.impulseScale);
      p.relativeVelocity = selectW(speculative, p.relativeVelocity, minW(p.relativeVelocity, vn));
    } else {
      bias = selectW(speculative, bias, zero);
    }
    const FloatW impulse = -(p.normalMass * massScale * (vn + bias)) - impulseScale * p.normalImpulse;
    const FloatW total = maxW(p.normalImpulse + impulse, zero);
    const FloatW applied = total - p.normalImpulse;
    p.normalImpulse = total;
    p.maxNormalImpulse = maxW(p.maxNormalImpulse, applied);
    totalNormal = totalNormal + total;
    applyW(a, b, c, p, applied * c.normalX, applied * c.normalY);
  }
  const FloatW tx = c.normalY;
  const FloatW ty = -c.normalX;
  for (ContactConstraintWide::Point& p : c.points) {
    const FloatW vt = relativeVelocity(a, b, p, tx, ty);
    const FloatW limit = c.friction * p.normalImpulse;
    const FloatW total = maxW(minW(p.tangentImpulse - p.tangentMass * vt, limit), -limit);
    const FloatW applied = total - p.tangentImpulse;
    p.tangentImpulse = total;
    applyW(a, b, c, p, applied * tx, applied * ty);
  }
  if (anyNonZeroW(c.rollingMass)) {
    // Rolling resistance (zero rolling mass in lanes without).
    const FloatW limit = c.rollingResistance * totalNormal;
    const FloatW total = maxW(minW(c.rollingImpulse - c.rollingMass * (b.w - a.w), limit), -limit);
    const FloatW applied = total - c.rollingImpulse;
    c.rollingImpulse = total;
    a.w = a.w - c.invIA * applied;
    b.w = b.w + c.invIB * applied;
  }
  scatter(states, c.indexA, staticIndex, a);
  scatter(states, c.indexB, staticIndex, b);
}

void warmStartWide(ContactConstraintWide& c, std::vector<BodyState>& states, std::uint32_t staticIndex) {
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

void restitutionWide(ContactConstraintWide& c, std::vector<BodyState>& states, std::uint32_t staticIndex,
                     float threshold) {
  if (!anyNonZeroW(c.restitution)) {
    return; // nothing bounces in this batch (the common case): skip the gather and scatter
  }
  BodiesW a = gatherVelocities(states, c.indexA);
  BodiesW b = gatherVelocities(states, c.indexB);
  const FloatW zero = zeroW();
  const FloatW minusThreshold = splatW(-threshold);
  for (ContactConstraintWide::Point& p : c.points) {
    // Only points that approached faster than the threshold and took an impulse bounce.
    const FloatW skip = orW(orW(greaterW(p.relativeVelocity, minusThreshold), equalW(p.maxNormalImpulse, zero)),
                            equalW(c.restitution, zero));
    const FloatW vn = relativeVelocity(a, b, p, c.normalX, c.normalY);
    const FloatW impulse = -(p.normalMass * (vn + c.restitution * p.relativeVelocity));
    const FloatW total = maxW(p.normalImpulse + impulse, zero);
    const FloatW applied = selectW(skip, zero, total - p.normalImpulse);
    p.normalImpulse = p.normalImpulse + applied;
    applyW(a, b, c, p, applied * c.normalX, applied * c.normalY);
  }
  scatter(states, c.indexA, staticIndex, a);
  scatter(states, c.indexB, staticIndex, b);
}

void restitutionOne(ContactConstraint& c, std::vector<BodyState>& states, std::uint32_t staticIndex, float threshold) {
  if (c.restitution == 0.0f) {
    return;
  }
  BodyState a = states[c.indexA];
  BodyState b = states[c.indexB];
  for (int k = 0; k < c.pointCount; ++k) {
    ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
    if (p.relativeVelocity > -threshold || p.maxNormalImpulse == 0.0f) {
      continue;
    }
    const float vn = dot(velocityAt(b, p.rB) - velocityAt(a, p.rA), c.normal);
    const float impulse = -p.normalMass * (vn + c.restitution * p.relativeVelocity);
    const float total = std::max(p.normalImpulse + impulse, 0.0f);
    const float applied = total - p.normalImpulse;
    p.normalImpulse = total;
    applyImpulse(a, b, c, p, c.normal * applied);
  }
  if (c.indexA != staticIndex) {
    states[c.indexA].v = a.v;
    states[c.indexA].w = a.w;
  }
  if (c.indexB != staticIndex) {
    states[c.indexB].v = b.v;
    states[c.indexB].w = b.w;
  }
}

/// Notes the fastest impact for hit events and keeps the impulses for the next warm start.
void storePoint(Contact& contact, int k, float normalImpulse, float tangentImpulse, float maxNormalImpulse) {
  const float approach = contact.approachBefore[static_cast<std::size_t>(k)];
  if (maxNormalImpulse > 0.0f && approach > contact.approachSpeed) {
    contact.approachSpeed = approach;
    contact.fastestPoint = k;
  }
  ManifoldPoint& mp = contact.manifold.points[static_cast<std::size_t>(k)];
  mp.normalImpulse = normalImpulse;
  mp.tangentImpulse = tangentImpulse;
}

/// Runs `perBatch` over every batch of every colour, colour after colour (batches of a colour
/// in parallel), after the overflow contacts (`perOverflow`, in order).
template <class PerBatch, class PerOverflow>
void forEachColour(WorldState& w, PerBatch&& perBatch, PerOverflow&& perOverflow) {
  ContactSolverData& d = *w.contactSolver;
  for (ContactConstraint& c : d.overflow) {
    perOverflow(c);
  }
  for (std::size_t colour = 0; colour < colourCount; ++colour) {
    const std::uint32_t first = d.colourStart[colour];
    const std::uint32_t count = d.colourStart[colour + 1] - first;
    w.parallelFor(count, 16, [&](std::uint32_t begin, std::uint32_t end) {
      for (std::uint32_t i = begin; i < end; ++i) {
        perBatch(d.wide[first + i]);
      }
    });
  }
}

} // namespace

void prepareContacts(WorldState& w, const StepContext& context) {
  if (!w.contactSolver) {
    w.contactSolver = std::make_unique<ContactSolverData>();
  }
  ContactSolverData& d = *w.contactSolver;
  // Stiffer than a quarter of the substep rate cannot be resolved by the substeps.
  const float hertz = std::min(w.def.contactHertz, 0.25f * context.inverseH);
  d.soft = makeSoft(hertz, w.def.contactDampingRatio, context.h);
  d.staticSoft = makeSoft(2.0f * hertz, w.def.contactDampingRatio, context.h);
  d.pushSpeed = w.def.maxContactPushSpeed;
  d.restitutionThreshold = w.def.restitutionThreshold;

  // Colour the touching contacts that involve a moving body, in pool order.
  const std::uint32_t staticIndex = w.staticIndex();
  const std::size_t words = staticIndex / 64 + 1;
  for (std::size_t c = 0; c < colourCount; ++c) {
    d.bodyBits[c].assign(words, 0);
    d.colourContacts[c].clear();
  }
  d.overflow.clear();
  for (std::uint32_t slot = 0; slot < w.contacts.size(); ++slot) {
    Contact& contact = w.contacts[slot];
    if (!contact.alive || contact.sensor || contact.manifold.pointCount == 0) {
      continue;
    }
    const Body& a = w.bodies[contact.bodyA];
    const Body& b = w.bodies[contact.bodyB];
    if (!a.moving() && !b.moving()) {
      continue; // asleep (the world wakes a sleeper touched by a moving body before the solve)
    }
    contact.approachSpeed = 0.0f;
    const std::uint32_t ia = a.moving() ? a.solverIndex : staticIndex;
    const std::uint32_t ib = b.moving() ? b.solverIndex : staticIndex;
    const bool withStatic = ia == staticIndex || ib == staticIndex;
    const int colour = withStatic ? findColour(d, ia, ib, staticIndex, 0, colourCount)
                                  : findColour(d, ia, ib, staticIndex, 0, dynamicColourCount);
    if (colour < 0) {
      d.overflow.push_back(makeConstraint(w, contact, slot, d));
    } else {
      d.colourContacts[static_cast<std::size_t>(colour)].push_back(slot);
    }
  }
  // Batches of four per colour.
  std::uint32_t batches = 0;
  for (std::size_t c = 0; c < colourCount; ++c) {
    d.colourStart[c] = batches;
    batches += static_cast<std::uint32_t>((d.colourContacts[c].size() + simdWidth - 1) / simdWidth);
  }
  d.colourStart[colourCount] = batches;
  d.wide.resize(batches);
  d.slots.resize(batches);
  for (std::size_t colour = 0; colour < colourCount; ++colour) {
    const std::vector<std::uint32_t>& list = d.colourContacts[colour];
    const std::uint32_t first = d.colourStart[colour];
    w.parallelFor(d.colourStart[colour + 1] - first, 64, [&](std::uint32_t begin, std::uint32_t end) {
      for (std::uint32_t batch = begin; batch < end; ++batch) {
        ContactConstraintWide& wc = d.wide[first + batch];
        std::array<std::uint32_t, simdWidth>& slots = d.slots[first + batch];
        ContactConstraint none;
        none.indexA = none.indexB = staticIndex;
        for (int i = 0; i < simdWidth; ++i) {
          const std::size_t k = std::size_t{batch} * simdWidth + static_cast<std::size_t>(i);
          if (k < list.size()) {
            slots[static_cast<std::size_t>(i)] = list[k];
            setLane(wc, i, makeConstraint(w, w.contacts[list[k]], list[k], d));
          } else {
            slots[static_cast<std::size_t>(i)] = noContact;
            setLane(wc, i, none);
          }
        }
      }
    });
  }
}

void warmStartContacts(WorldState& w) {
  const std::uint32_t staticIndex = w.staticIndex();
  forEachColour(
      w, [&](ContactConstraintWide& c) { warmStartWide(c, w.states, staticIndex); },
      [&](ContactConstraint& c) {
        BodyState& a = w.states[c.indexA];
        BodyState& b = w.states[c.indexB];
        const Vec2f tangent{c.normal.y, -c.normal.x};
        BodyState sa = a, sb = b;
        for (int k = 0; k < c.pointCount; ++k) {
          const ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
          applyImpulse(sa, sb, c, p, c.normal * p.normalImpulse + tangent * p.tangentImpulse);
        }
        sa.w -= c.iA * c.rollingImpulse;
        sb.w += c.iB * c.rollingImpulse;
        if (c.indexA != staticIndex) {
          a = sa;
        }
        if (c.indexB != staticIndex) {
          b = sb;
        }
      });
}

void solveContacts(WorldState& w, const StepContext& context, bool useBias) {
  const std::uint32_t staticIndex = w.staticIndex();
  const ContactSolverData& d = *w.contactSolver;
  forEachColour(
      w, [&](ContactConstraintWide& c) { solveWide(c, w.states, staticIndex, d, context.inverseH, useBias); },
      [&](ContactConstraint& c) { solveOne(c, w.states, staticIndex, d, context.inverseH, useBias); });
}

void applyRestitution(WorldState& w) {
  const std::uint32_t staticIndex = w.staticIndex();
  const float threshold = w.contactSolver->restitutionThreshold;
  forEachColour(
      w, [&](ContactConstraintWide& c) { restitutionWide(c, w.states, staticIndex, threshold); },
      [&](ContactConstraint& c) { restitutionOne(c, w.states, staticIndex, threshold); });
}

void storeImpulses(WorldState& w) {
  ContactSolverData& d = *w.contactSolver;
  for (const ContactConstraint& c : d.overflow) {
    Contact& contact = w.contacts[c.contact];
    contact.rollingImpulse = c.rollingImpulse;
    for (int k = 0; k < c.pointCount; ++k) {
      const ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
      storePoint(contact, k, p.normalImpulse, p.tangentImpulse, p.maxNormalImpulse);
    }
  }
  w.parallelFor(static_cast<std::uint32_t>(d.wide.size()), 64, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t batch = begin; batch < end; ++batch) {
      const ContactConstraintWide& wc = d.wide[batch];
      for (int i = 0; i < simdWidth; ++i) {
        const std::uint32_t slot = d.slots[batch][static_cast<std::size_t>(i)];
        if (slot == noContact) {
          continue;
        }
        Contact& contact = w.contacts[slot];
        contact.rollingImpulse = lane(wc.rollingImpulse, i);
        for (int k = 0; k < contact.manifold.pointCount; ++k) {
          const ContactConstraintWide::Point& p = wc.points[static_cast<std::size_t>(k)];
          storePoint(contact, k, lane(p.normalImpulse, i), lane(p.tangentImpulse, i), lane(p.maxNormalImpulse, i));
        }
      }
    }
  });
}

} // namespace impetus::rigid2d::detail
