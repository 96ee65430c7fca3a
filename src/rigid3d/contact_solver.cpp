// The 3D world's contact solver: soft contacts (a normal row and two friction rows per point),
// warm started from the last step's impulses, solved with bias and relaxed each substep, then
// restitution. The rows are the shared solver's (solver/constraint_row.hpp) on 3D vectors.
#include "rigid3d/world_impl.hpp"
#include "solver/colour_graph.hpp"
#include "solver/constraint_row.hpp"
#include "solver/contact_normal.hpp"

#include <impetus/rigid3d/constants.hpp>

#include <algorithm>
#include <cmath>

namespace impetus::rigid3d::detail {

namespace {

/// How many passes the restitution makes over a manifold's bouncing points. One pass, point
/// after point, is not enough: the first point's impulse turns the body and the next ones then
/// leave it spinning (a box landing flat on four corners). Repeated, the passes converge to the
/// impulses that give every point its bounce together (projected Gauss-Seidel on the impact's
/// linear complementarity problem), and the flat box rebounds without spin (restitution tests).
constexpr int restitutionPasses = 16;

/// The most passes the relax makes over the normal rows of a manifold of several points. One
/// pass, point after point, leaves an impact's impulse on the first points it meets (a box
/// landing flat is stopped at one corner first, and turns): repeated, the passes share it out as
/// the points' rows together ask (projected Gauss-Seidel on the manifold's block), and the box
/// lands level. Four bring a flat landing's spin under 1e-5 rad/s; two leave 1e-4.
constexpr int maxRelaxNormalPasses = 4;

/// A relax pass that moved no point's normal impulse by more than this fraction of the
/// manifold's total has converged (a resting contact's passes: one), dimensionless.
constexpr float relaxConvergence = 0.01f;

/// The slowest approach that raises a hit event whatever the threshold, m/s: a resting contact
/// approaches at rounding speeds, and a threshold of 0 should not make every one a hit.
constexpr float minHitSpeed = 1.0e-3f;

/// The inverse masses and world inverse inertias of a constraint's bodies, as the shared rows
/// read them.
struct PairMass {
  float mA, mB;
  Mat33f iA, iB;
};

PairMass pairMass(const ContactConstraint& c) { return {c.mA, c.mB, c.iA, c.iB}; }

/// The world's speed caps as the rows' impulse bound reads them.
struct SpeedCaps {
  float maxSpeed;
  float maxSpin;
};

using Row3 = solver::Row<Vec3f, Vec3f>;

Row3 rowAlong(const ConstraintPoint& p, const Vec3f& direction) {
  return {direction, cross(p.rA, direction), cross(p.rB, direction)};
}

/// The velocity of B's point relative to A's, m/s.
Vec3f relativeVelocity(const BodyState& a, const BodyState& b, const ConstraintPoint& p) {
  return (b.v + cross(b.w, p.rB)) - (a.v + cross(a.w, p.rA));
}

/// An impulse (N s, world) at a point: +impulse on B, -impulse on A.
void applyImpulse(BodyState& a, BodyState& b, const ContactConstraint& c, const ConstraintPoint& p,
                  const Vec3f& impulse) {
  a.v -= impulse * c.mA;
  a.w -= c.iA * cross(p.rA, impulse);
  b.v += impulse * c.mB;
  b.w += c.iB * cross(p.rB, impulse);
}

/// A point's separation now, m, from the bodies' moves so far this step: the anchors turn with
/// them.
float currentSeparation(const ContactConstraint& c, const ConstraintPoint& p, const BodyState& a, const BodyState& b) {
  return dot(b.dp - a.dp + rotate(b.dq, p.coreB) - rotate(a.dq, p.coreA), c.normal) + p.adjustedSeparation;
}

/// A constraint's bodies' new velocities into their states (the static state is never written).
void writeBack(std::vector<BodyState>& states, std::uint32_t staticIndex, const ContactConstraint& c,
               const BodyState& a, const BodyState& b) {
  if (c.indexA != staticIndex) {
    states[c.indexA].v = a.v;
    states[c.indexA].w = a.w;
  }
  if (c.indexB != staticIndex) {
    states[c.indexB].v = b.v;
    states[c.indexB].w = b.w;
  }
}

ContactConstraint makeConstraint(const WorldState& w, const Contact& contact, std::uint32_t index,
                                 const StepContext& context) {
  const Body& a = w.bodies[contact.bodyA];
  const Body& b = w.bodies[contact.bodyB];
  const std::uint32_t staticIndex = w.staticIndex();
  ContactConstraint c;
  c.indexA = a.moving() ? a.solverIndex : staticIndex;
  c.indexB = b.moving() ? b.solverIndex : staticIndex;
  c.contact = index;
  c.mA = a.inverseMass;
  c.mB = b.inverseMass;
  // The inverse inertias at the step's start: the bodies turn little in a step, and the rows'
  // masses are made from them once.
  c.iA = a.inverseMass > 0.0f ? worldInverseInertia(a.transform.q, a.inertia, a.inverseInertia, a.locks) : Mat33f{};
  c.iB = b.inverseMass > 0.0f ? worldInverseInertia(b.transform.q, b.inertia, b.inverseInertia, b.locks) : Mat33f{};
  const Manifold& m = contact.manifold;
  c.normal = m.normal;
  c.tangent1 = contact.tangent1;
  c.tangent2 = contact.tangent2;
  c.friction = contact.friction;
  c.restitution = contact.restitution;
  c.stiffer = c.mA == 0.0f || c.mB == 0.0f;
  c.rollingResistance = contact.rollingResistance;
  if (c.rollingResistance > 0.0f) {
    const Mat33f k = c.iA + c.iB;
    const float k11 = dot(c.tangent1, k * c.tangent1);
    const float k12 = dot(c.tangent1, k * c.tangent2);
    const float k22 = dot(c.tangent2, k * c.tangent2);
    if (const float det = k11 * k22 - k12 * k12; det > 0.0f) {
      c.rollingInverse11 = k22 / det;
      c.rollingInverse12 = -k12 / det;
      c.rollingInverse22 = k11 / det;
    }
    if (w.def.enableWarmStarting) {
      c.rollingImpulse1 = dot(contact.rollingImpulse, c.tangent1);
      c.rollingImpulse2 = dot(contact.rollingImpulse, c.tangent2);
    }
  }
  c.pointCount = m.pointCount;
  const PairMass mass = pairMass(c);
  const SpeedCaps caps{context.maxLinearSpeed, context.maxAngularSpeed};
  const BodyState& stateA = w.states[c.indexA];
  const BodyState& stateB = w.states[c.indexB];
  const Vec3f offsetA = a.center - a.transform.p;
  const Vec3f offsetB = b.center - b.transform.p;
  for (int k = 0; k < m.pointCount; ++k) {
    const ManifoldPoint& mp = m.points[static_cast<std::size_t>(k)];
    ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
    p.rA = mp.anchorA - offsetA;
    p.rB = mp.anchorB - offsetB;
    p.coreA = p.rA - m.normal * contact.roundingA;
    p.coreB = p.rB + m.normal * contact.roundingB;
    p.adjustedSeparation = mp.separation - dot(p.coreB - p.coreA, m.normal);
    p.impulse = w.def.enableWarmStarting ? contact.impulses[static_cast<std::size_t>(k)] : PointImpulse{};
    const Row3 normalRow = rowAlong(p, m.normal);
    p.normalMass = solver::rowMass(normalRow, mass);
    p.normalBound = solver::maxRowImpulse(normalRow, p.normalMass, caps);
    p.tangentMass1 = solver::rowMass(rowAlong(p, c.tangent1), mass);
    p.tangentMass2 = solver::rowMass(rowAlong(p, c.tangent2), mass);
    p.approachSpeed = dot(relativeVelocity(stateA, stateB, p), m.normal);
    p.maxNormalImpulse = 0.0f;
  }
  return c;
}

/// Rolling resistance: an angular impulse against the relative spin about the tangents (the
/// rolling), held within the disc of c_rr r times the manifold's normal impulse.
void solveRolling(BodyState& a, BodyState& b, ContactConstraint& c) {
  if (c.rollingResistance == 0.0f) {
    return;
  }
  float normal = 0.0f;
  for (int k = 0; k < c.pointCount; ++k) {
    normal += c.points[static_cast<std::size_t>(k)].impulse.normal;
  }
  const Vec3f spin = b.w - a.w;
  const float s1 = dot(spin, c.tangent1);
  const float s2 = dot(spin, c.tangent2);
  const float old1 = c.rollingImpulse1;
  const float old2 = c.rollingImpulse2;
  float new1 = old1 - (c.rollingInverse11 * s1 + c.rollingInverse12 * s2);
  float new2 = old2 - (c.rollingInverse12 * s1 + c.rollingInverse22 * s2);
  const float limit = c.rollingResistance * normal;
  if (const float squared = new1 * new1 + new2 * new2; squared > limit * limit) {
    const float scale = limit / std::sqrt(squared);
    new1 *= scale;
    new2 *= scale;
  }
  c.rollingImpulse1 = new1;
  c.rollingImpulse2 = new2;
  const Vec3f applied = c.tangent1 * (new1 - old1) + c.tangent2 * (new2 - old2);
  a.w -= c.iA * applied;
  b.w += c.iB * applied;
}

/// Coulomb friction at a point: the two tangent rows solved together and their accumulated
/// impulse held within the disc of radius mu times the normal impulse (a round cone, so a body
/// slides along the fall line whatever the tangents' directions).
void solveFriction(BodyState& a, BodyState& b, ContactConstraint& c, ConstraintPoint& p) {
  const Vec3f dv = relativeVelocity(a, b, p);
  const float old1 = p.impulse.tangent1;
  const float old2 = p.impulse.tangent2;
  float new1 = old1 - p.tangentMass1 * dot(dv, c.tangent1);
  float new2 = old2 - p.tangentMass2 * dot(dv, c.tangent2);
  const float limit = c.friction * p.impulse.normal;
  if (const float squared = new1 * new1 + new2 * new2; squared > limit * limit) {
    const float scale = limit / std::sqrt(squared);
    new1 *= scale;
    new2 *= scale;
  }
  p.impulse.tangent1 = new1;
  p.impulse.tangent2 = new2;
  applyImpulse(a, b, c, p, c.tangent1 * (new1 - old1) + c.tangent2 * (new2 - old2));
}

void solveOne(ContactConstraint& c, std::vector<BodyState>& states, std::uint32_t staticIndex,
              const StepContext& context, bool useBias) {
  BodyState a = states[c.indexA];
  BodyState b = states[c.indexB];
  const solver::Softness& soft = c.stiffer ? context.staticContactSoftness : context.contactSoftness;
  std::array<float, 4> separation{};
  for (int k = 0; k < c.pointCount; ++k) {
    separation[static_cast<std::size_t>(k)] = currentSeparation(c, c.points[static_cast<std::size_t>(k)], a, b);
  }
  // One pass over the points, then, in the relax pass of a manifold of several points, more
  // while the last one still moved impulse between them.
  const int passes = useBias || c.pointCount == 1 ? 1 : maxRelaxNormalPasses;
  for (int pass = 0; pass < passes; ++pass) {
    float largest = 0.0f;
    float sum = 0.0f;
    for (int k = 0; k < c.pointCount; ++k) {
      ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
      const solver::NormalTarget target = solver::normalTarget(separation[static_cast<std::size_t>(k)], soft, useBias,
                                                               context.inverseH, context.maxContactPushSpeed);
      const float vn = dot(relativeVelocity(a, b, p), c.normal);
      const float applied = solver::accumulateNormalImpulse(p.impulse.normal, p.maxNormalImpulse, p.normalMass,
                                                            p.normalBound, vn, target);
      applyImpulse(a, b, c, p, c.normal * applied);
      largest = std::max(largest, std::abs(applied));
      sum += p.impulse.normal;
    }
    if (largest <= relaxConvergence * sum) {
      break;
    }
  }
  // Friction in the relax pass only: it acts on the velocities the step keeps.
  if (!useBias) {
    solveRolling(a, b, c);
    for (int k = 0; k < c.pointCount; ++k) {
      solveFriction(a, b, c, c.points[static_cast<std::size_t>(k)]);
    }
  }
  writeBack(states, staticIndex, c, a, b);
}

/// A bouncing point as the bodies are at the step's end: one world point, midway between where
/// the two bodies' anchors have moved, with each body's arm to it, and the normal mass for those
/// arms. Impulses at one point, equal and opposite, keep the angular momentum about any origin;
/// at the step's start anchors, left behind by bodies that moved apart sideways in the step,
/// they would not (a glancing hit would gain or lose a third of its angular momentum).
ConstraintPoint bounceAnchors(const ContactConstraint& c, const ConstraintPoint& p, const BodyState& a,
                              const BodyState& b) {
  // Relative to A's centre at the step's start; B's centre was at rA - rB from it.
  const Vec3f onA = a.dp + rotate(a.dq, p.coreA) + (p.rA - p.coreA);
  const Vec3f bCenter = (p.rA - p.rB) + b.dp;
  const Vec3f onB = bCenter + rotate(b.dq, p.coreB) + (p.rB - p.coreB);
  const Vec3f point = (onA + onB) * 0.5f;
  ConstraintPoint q = p;
  q.rA = point - a.dp;
  q.rB = point - bCenter;
  q.normalMass = solver::rowMass(rowAlong(q, c.normal), pairMass(c));
  return q;
}

/// Puts the constraints in the order of the constraint graph's colours (the overflow first, then
/// colour after colour; within each, the contacts' key order): each colour's constraints share no
/// moving body. Solved one after another in key order, a pile's contacts run bottom to top (its
/// shapes were made row by row) and the support of each row reaches the next only a substep
/// later: Box3D's large pyramid of 5050 cubes sank 1.4 m in 200 steps and came apart, and stands
/// with its top 0.7 m down in colour order, as in Box3D. The colours are found anew each step
/// for now; they become the persistent graph of the shared solver with the persistent pairs.
void orderByColour(WorldState& w) {
  solver::ColourGraph& graph = w.contactColours;
  graph.clear();
  const auto graphBody = [&](const ContactConstraint& c, bool a) {
    // Bodies the solver does not move (static, kinematic) take no colour.
    const float inverseMass = a ? c.mA : c.mB;
    return inverseMass > 0.0f ? (a ? w.awakeBodies[c.indexA] : w.awakeBodies[c.indexB]) : solver::ColourGraph::noBody;
  };
  for (std::size_t i = 0; i < w.constraints.size(); ++i) {
    const ContactConstraint& c = w.constraints[i];
    graph.add(static_cast<std::uint32_t>(i), graphBody(c, true), graphBody(c, false));
  }
  w.orderedConstraints.clear();
  const auto take = [&](std::uint32_t colour) {
    for (const std::uint32_t i : graph.members(colour)) {
      w.orderedConstraints.push_back(w.constraints[i]);
    }
  };
  take(solver::ColourGraph::overflow);
  for (std::uint32_t colour = 0; colour < solver::graphColourCount; ++colour) {
    take(colour);
  }
  std::swap(w.constraints, w.orderedConstraints);
}

} // namespace

void prepareContacts(WorldState& w, const StepContext& context) {
  w.constraints.clear();
  for (std::size_t i = 0; i < w.contacts.size(); ++i) {
    const Contact& contact = w.contacts[i];
    const Body& a = w.bodies[contact.bodyA];
    const Body& b = w.bodies[contact.bodyB];
    // Between two bodies out of this step's motion (asleep, or asleep on a static body): not
    // solved.
    const bool inMotion = (a.awake && a.moving()) || (b.awake && b.moving());
    if (contact.touching && !contact.sensor && inMotion) {
      w.constraints.push_back(makeConstraint(w, contact, static_cast<std::uint32_t>(i), context));
    }
  }
  orderByColour(w);
}

void warmStartContacts(WorldState& w) {
  const std::uint32_t staticIndex = w.staticIndex();
  for (const ContactConstraint& c : w.constraints) {
    BodyState a = w.states[c.indexA];
    BodyState b = w.states[c.indexB];
    for (int k = 0; k < c.pointCount; ++k) {
      const ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
      applyImpulse(a, b, c, p,
                   c.normal * p.impulse.normal + c.tangent1 * p.impulse.tangent1 + c.tangent2 * p.impulse.tangent2);
    }
    if (c.rollingResistance > 0.0f) {
      const Vec3f rolling = c.tangent1 * c.rollingImpulse1 + c.tangent2 * c.rollingImpulse2;
      a.w -= c.iA * rolling;
      b.w += c.iB * rolling;
    }
    writeBack(w.states, staticIndex, c, a, b);
  }
}

void solveContacts(WorldState& w, const StepContext& context, bool useBias) {
  const std::uint32_t staticIndex = w.staticIndex();
  for (ContactConstraint& c : w.constraints) {
    solveOne(c, w.states, staticIndex, context, useBias);
  }
}

void applyRestitution(WorldState& w) {
  const std::uint32_t staticIndex = w.staticIndex();
  const float threshold = w.def.restitutionThreshold;
  for (const ContactConstraint& c : w.constraints) {
    if (c.restitution == 0.0f) {
      continue;
    }
    // The points that approached faster than the threshold and met the other body this step
    // bounce: those that pushed, and those touching at the step's end (a box landing flat on
    // speculative points may be stopped by two of its corners; all four land).
    std::array<ConstraintPoint, 4> bouncing{};
    int count = 0;
    BodyState a = w.states[c.indexA];
    BodyState b = w.states[c.indexB];
    for (int k = 0; k < c.pointCount; ++k) {
      const ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
      const bool met = p.maxNormalImpulse > 0.0f || currentSeparation(c, p, a, b) <= linearSlop;
      if (p.approachSpeed < -threshold && met) {
        bouncing[static_cast<std::size_t>(count++)] = bounceAnchors(c, p, a, b);
      }
    }
    // Their normal velocity is driven to e times their approach by impulses that only push,
    // accumulated apart from the contact's (which warm start the next step's rest).
    std::array<float, 4> total{};
    for (int pass = 0; pass < restitutionPasses; ++pass) {
      for (int k = 0; k < count; ++k) {
        const ConstraintPoint& p = bouncing[static_cast<std::size_t>(k)];
        const float vn = dot(relativeVelocity(a, b, p), c.normal);
        float& sum = total[static_cast<std::size_t>(k)];
        const float next = std::max(sum - p.normalMass * (vn + c.restitution * p.approachSpeed), 0.0f);
        applyImpulse(a, b, c, p, c.normal * (next - sum));
        sum = next;
      }
    }
    writeBack(w.states, staticIndex, c, a, b);
  }
}

void storeImpulses(WorldState& w) {
  for (const ContactConstraint& c : w.constraints) {
    Contact& contact = w.contacts[c.contact];
    contact.rollingImpulse = c.tangent1 * c.rollingImpulse1 + c.tangent2 * c.rollingImpulse2;
    int fastest = -1;
    float approach = std::max(w.def.hitEventThreshold, minHitSpeed);
    for (int k = 0; k < c.pointCount; ++k) {
      const ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
      contact.impulses[static_cast<std::size_t>(k)] = p.impulse;
      if (p.maxNormalImpulse > 0.0f && -p.approachSpeed >= approach) {
        approach = -p.approachSpeed;
        fastest = k;
      }
    }
    if (fastest >= 0) {
      const ManifoldPoint& mp = contact.manifold.points[static_cast<std::size_t>(fastest)];
      w.contactEvents.hits.push_back(
          {w.shapeIdOf(contact.keyA), w.shapeIdOf(contact.keyB), mp.point, contact.manifold.normal, approach});
    }
  }
}

} // namespace impetus::rigid3d::detail
