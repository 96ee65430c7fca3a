// The contact constraints of the soft-step solver (after Erin Catto's Solver2D "soft step" and
// Box2D v3): soft contacts with a stiffness in hertz, warm starting, a relax pass, restitution
// as impacts within the passes, Coulomb friction and rolling resistance.
//
// Layout: the constraint graph (constraint_graph.hpp). The touching contacts keep their colours
// from step to step (solver::ColourGraph); the joints keep theirs while the joints and moving
// bodies stay the same (joint_graph.cpp). A colour's joints are solved on several threads, then
// its contacts. A
// colour's contacts are independent: they are solved several at a time in SIMD lanes
// (contact_wide_kernels.hpp: eight with AVX2 where the CPU has it, four with SSE2) and their
// batches may run on several threads, with results that depend on neither. Contacts that find
// no free colour (a body touching very many others) go to a small overflow list solved one by
// one first, in the order they went there. The colours depend only on the order in which
// contacts began and ended, which the collide pass fixes, so the solve is bit-identical run
// after run.
#include "rigid2d/constraint_graph.hpp"
#include "solver/contact_normal.hpp"

#include <impetus/math/scalar.hpp>

#include <algorithm>
#include <array>
#include <span>

namespace impetus::rigid2d::detail {

WorldState::WorldState() = default;
WorldState::~WorldState() = default;
WorldState::WorldState(WorldState&&) noexcept = default;
WorldState& WorldState::operator=(WorldState&&) noexcept = default;

const WideKernels& selectWideKernels(SimdLevel level) {
  if (level == SimdLevel::widest) {
#if defined(__x86_64__)
    // Asked here, in code built for the baseline: the AVX2 object runs only once this said yes.
    static const bool hasAvx2 = __builtin_cpu_supports("avx2") != 0;
    if (const WideKernels* avx2 = avx2WideKernelsBuilt(); hasAvx2 && avx2 != nullptr) {
      return *avx2;
    }
#endif
  }
  return baselineWideKernels();
}

namespace {

/// Fills one constraint of the overflow from its contact: anchors relative to the centres of
/// mass, effective masses, and the approach speed before the step. The wide prepare computes the
/// same in lanes (gatherLane and deriveLanes, contact_wide_kernels.hpp).
ContactConstraint makeContactConstraint(const WorldState& w, Contact& contact, std::uint32_t slot, const Softness& soft,
                                        const Softness& staticSoft, const ContactSpeedCaps& caps) {
  const SolverBodyInfo& a = w.bodyInfo[contact.bodyA];
  const SolverBodyInfo& b = w.bodyInfo[contact.bodyB];
  const Manifold& m = contact.manifold;
  ContactConstraint c;
  c.indexA = w.solverIndexOf(a);
  c.indexB = w.solverIndexOf(b);
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
  c.rollingImpulse = rollingImpulseToWarmStart(contact, w.def.enableWarmStarting);
  c.tangentSpeed = contact.tangentSpeed;
  c.softness = (c.mA == 0.0f || c.mB == 0.0f) ? staticSoft : soft;
  c.pointCount = m.pointCount;
  const Vec2f tangent{m.normal.y, -m.normal.x};
  const Vec2f offsetA = a.centerOffset;
  const Vec2f offsetB = b.centerOffset;
  const BodyState& stA = w.states[c.indexA];
  const BodyState& stB = w.states[c.indexB];
  // Every field of both points is written (a missing point's are zero), so that the record is
  // built without first being cleared.
  for (int k = 0; k < 2; ++k) {
    ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
    if (k >= m.pointCount) {
      p = ConstraintPoint{};
      continue;
    }
    const ManifoldPoint& mp = m.points[static_cast<std::size_t>(k)];
    p.maxNormalImpulse = 0.0f;
    p.rA = mp.anchorA - offsetA;
    p.rB = mp.anchorB - offsetB;
    p.adjustedSeparation = mp.separation - dot(p.rB - p.rA, m.normal);
    // Warm starting: last step's impulses (WorldDef::enableWarmStarting), else from zero.
    p.normalImpulse = w.def.enableWarmStarting ? mp.normalImpulse : 0.0f;
    p.tangentImpulse = w.def.enableWarmStarting ? mp.tangentImpulse : 0.0f;
    const float rnA = cross(p.rA, m.normal);
    const float rnB = cross(p.rB, m.normal);
    const float kNormal = c.mA + c.mB + c.iA * rnA * rnA + c.iB * rnB * rnB;
    p.normalMass = kNormal > 0.0f ? 1.0f / kNormal : 0.0f;
    p.normalBound =
        contactImpulseBound(p.normalMass, std::max(rnA, -rnA) + std::max(rnB, -rnB), caps.twoMaxSpeed, caps.maxSpin);
    const float rtA = cross(p.rA, tangent);
    const float rtB = cross(p.rB, tangent);
    const float kTangent = c.mA + c.mB + c.iA * rtA * rtA + c.iB * rtB * rtB;
    p.tangentMass = kTangent > 0.0f ? 1.0f / kTangent : 0.0f;
    const Vec2f vA = stA.v + cross(stA.w, p.rA);
    const Vec2f vB = stB.v + cross(stB.w, p.rB);
    p.impactSpeed = -dot(vB - vA, m.normal);
  }
  return c;
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

/// The impact of a contact's bouncing points (restitution > 0, approaching faster than the
/// threshold, touching or closing the gap within this substep): an
/// instantaneous collision by Newton's law, each point's normal velocity becoming e times its
/// approach speed (a two-point manifold's as a block: both points, one, or neither push,
/// maxBlockConditionNumber), with Coulomb friction up to mu times the impact's impulse. The
/// approach is measured now, before this contact pushes at any point, so an impact passed on by
/// a neighbour this very pass (a row of touching boxes struck at one end) is a collision of its
/// own: the impulse travels along the row as a sequence of collisions, Newton's cradle. The
/// impulses are not accumulated into the soft contact's (a bounce is not a force to warm start;
/// the soft solve would take it back as the points separate).
void bounceOne(ContactConstraint& c, BodyState& a, BodyState& b, const std::array<float, 2>& separation,
               const ContactSolveParams& params) {
  const auto normalVelocity = [&](const ConstraintPoint& p) {
    return dot(velocityAt(b, p.rB) - velocityAt(a, p.rA), c.normal);
  };
  std::array<float, 2> approach{};
  std::array<bool, 2> bounces{};
  bool any = false;
  for (int k = 0; k < c.pointCount; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const ConstraintPoint& p = c.points[i];
    approach[i] = normalVelocity(p);
    bounces[i] = approach[i] < -params.restitutionThreshold &&
                 approach[i] + std::max(separation[i], 0.0f) * params.inverseH < 0.0f;
    any = any || bounces[i];
  }
  if (!any) {
    return;
  }
  std::array<float, 2> impulse{};
  const auto target = [&](std::size_t i) { return -(c.restitution * approach[i]); };
  bool block = false;
  if (bounces[0] && bounces[1]) {
    const ConstraintPoint& p1 = c.points[0];
    const ConstraintPoint& p2 = c.points[1];
    const float rnA1 = cross(p1.rA, c.normal);
    const float rnA2 = cross(p2.rA, c.normal);
    const float rnB1 = cross(p1.rB, c.normal);
    const float rnB2 = cross(p2.rB, c.normal);
    const float k11 = normalCoupling(c.mA, c.mB, c.iA, c.iB, rnA1, rnA1, rnB1, rnB1);
    const float k12 = normalCoupling(c.mA, c.mB, c.iA, c.iB, rnA1, rnA2, rnB1, rnB2);
    const float k22 = normalCoupling(c.mA, c.mB, c.iA, c.iB, rnA2, rnA2, rnB2, rnB2);
    block = maxBlockConditionNumber * (k11 * k22 - k12 * k12) > k11 * k11;
    if (block) {
      solveNormalBlock(k11, k12, k22, approach[0], approach[1], target(0), target(1), 0.0f, impulse[0], impulse[1]);
      applyImpulse(a, b, c, p1, c.normal * impulse[0]);
      applyImpulse(a, b, c, p2, c.normal * impulse[1]);
    }
  }
  for (std::size_t i = 0; i < 2 && !block; ++i) {
    if (bounces[i]) {
      const ConstraintPoint& p = c.points[i];
      impulse[i] = std::max(-p.normalMass * (normalVelocity(p) - target(i)), 0.0f);
      applyImpulse(a, b, c, p, c.normal * impulse[i]);
    }
  }
  const Vec2f tangent{c.normal.y, -c.normal.x};
  for (std::size_t i = 0; i < 2; ++i) {
    if (bounces[i]) {
      ConstraintPoint& p = c.points[i];
      const float vt = dot(velocityAt(b, p.rB) - velocityAt(a, p.rA), tangent) - c.tangentSpeed;
      const float limit = c.friction * impulse[i];
      applyImpulse(a, b, c, p, tangent * std::clamp(-p.tangentMass * vt, -limit, limit));
      p.maxNormalImpulse = std::max(p.maxNormalImpulse, impulse[i]);
      p.impactSpeed = std::max(p.impactSpeed, -approach[i]);
    }
  }
}

void solveOne(ContactConstraint& c, std::vector<BodyState>& states, std::uint32_t staticIndex,
              const ContactSolveParams& params) {
  BodyState a = states[c.indexA];
  BodyState b = states[c.indexB];
  const Vec2f dp = b.dp - a.dp;
  std::array<float, 2> separation{};
  for (int k = 0; k < c.pointCount; ++k) {
    const ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
    // Current separation from the deltas: the anchors turn with their bodies.
    const Vec2f dd = dp + rotate(b.dq, p.rB) - rotate(a.dq, p.rA);
    separation[static_cast<std::size_t>(k)] = dot(dd, c.normal) + p.adjustedSeparation;
  }
  if (c.restitution != 0.0f) {
    bounceOne(c, a, b, separation, params);
  }
  for (int k = 0; k < c.pointCount; ++k) {
    ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
    const solver::NormalTarget target = solver::normalTarget(separation[static_cast<std::size_t>(k)], c.softness,
                                                             params.useBias, params.inverseH, params.pushSpeed);
    const float vn = dot(velocityAt(b, p.rB) - velocityAt(a, p.rA), c.normal);
    const float applied =
        solver::accumulateNormalImpulse(p.normalImpulse, p.maxNormalImpulse, p.normalMass, p.normalBound, vn, target);
    applyImpulse(a, b, c, p, c.normal * applied);
  }
  // Friction and rolling resistance in the relax pass only (ContactSolveParams::useBias).
  if (!params.useBias) {
    solveRolling(a, b, c);
    const Vec2f tangent{c.normal.y, -c.normal.x};
    for (int k = 0; k < c.pointCount; ++k) {
      ConstraintPoint& p = c.points[static_cast<std::size_t>(k)];
      const float vt = dot(velocityAt(b, p.rB) - velocityAt(a, p.rA), tangent) - c.tangentSpeed;
      const float limit = c.friction * p.normalImpulse;
      const float total = std::clamp(p.tangentImpulse - p.tangentMass * vt, -limit, limit);
      const float applied = total - p.tangentImpulse;
      p.tangentImpulse = total;
      applyImpulse(a, b, c, p, tangent * applied);
    }
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

/// How many batches ahead the contact passes ask for their contacts: a colour's contacts lie
/// one in about colourCount apart in the pool, too sparse for the hardware to see the pattern.
constexpr std::uint32_t prefetchDistance = 2;

/// Asks the cache for bytes [begin, end) of the contacts in slots[0, count) (noContact: none).
/// Always inlined: GCC 12 finds a function of nothing but prefetches free of side effects and
/// deletes its calls.
[[gnu::always_inline]] inline void prefetchContacts(const WorldState& w, const std::uint32_t* slots, std::size_t count,
                                                    std::size_t begin, std::size_t end) {
  for (std::size_t i = 0; i < count; ++i) {
    if (slots[i] != noContact) {
      const auto* bytes = reinterpret_cast<const char*>(&w.contacts[slots[i]]);
      for (std::size_t offset = begin; offset < end; offset += 64) {
        __builtin_prefetch(bytes + offset); // (a write hint needs PRFCHW: not baseline)
      }
    }
  }
}

/// The fewest contact batches worth a task of their own in the prepare (a batch of 4 or 8
/// contacts takes about half a microsecond to gather and prepare).
constexpr std::uint32_t minPrepareBatchesPerTask = 16;

/// Runs a stage over the constraint graph: the overflow joints and contacts first, in order
/// (`jointOne(slot)`, `overflowOne(constraint)`), then colour after colour the colour's joints
/// (`jointOne`, ranges in parallel) and its contact batches (`perRange(begin, end)`, ranges in
/// parallel). A colour's constraints share no moving body, so the order within it cannot matter.
template <class JointOne, class PerRange, class PerOverflow>
void forEachColour(WorldState& w, JointOne&& jointOne, PerRange&& perRange, PerOverflow&& perOverflow) {
  ContactSolverData& d = *w.contactSolver;
  for (std::uint32_t k = 0; k < d.jointColourStart[0]; ++k) {
    jointOne(d.jointSims[k]);
  }
  for (ContactConstraint& c : d.overflow) {
    perOverflow(c);
  }
  for (std::size_t colour = 0; colour < colourCount; ++colour) {
    const std::uint32_t firstJoint = d.jointColourStart[colour];
    w.parallelFor(d.jointColourStart[colour + 1] - firstJoint, minJointsPerTask,
                  [&](std::uint32_t begin, std::uint32_t end) {
                    for (std::uint32_t k = firstJoint + begin; k < firstJoint + end; ++k) {
                      jointOne(d.jointSims[k]);
                    }
                  });
    const std::uint32_t first = d.colourStart[colour];
    const std::uint32_t count = d.colourStart[colour + 1] - first;
    w.parallelFor(count, 16, [&](std::uint32_t begin, std::uint32_t end) { perRange(first + begin, first + end); });
  }
}

} // namespace

ContactSolverData& contactSolverOf(WorldState& w) {
  if (!w.contactSolver) {
    w.contactSolver = std::make_unique<ContactSolverData>();
    w.contactSolver->kernels = &selectWideKernels(w.def.simd);
  }
  return *w.contactSolver;
}

void prepareConstraints(WorldState& w, const StepContext& context) {
  ContactSolverData& d = contactSolverOf(w);
  const WideKernels& kernels = *d.kernels;
  // Stiffer than a quarter of the substep rate cannot be resolved by the substeps.
  const float hertz = std::min(w.def.contactHertz, 0.25f * context.inverseH);
  d.soft = makeSoft(hertz, w.def.contactDampingRatio, context.h);
  d.staticSoft = makeSoft(2.0f * hertz, w.def.contactDampingRatio, context.h);
  d.pushSpeed = w.def.maxContactPushSpeed;
  d.caps = {2.0f * context.maxLinearSpeed, context.maxAngularSpeed};
  d.restitutionThreshold = w.def.restitutionThreshold;

  // The joints are coloured here (joint_graph.cpp); the contacts have their colours already
  // (WorldState::contactGraph). The overflow's contacts are solved from copies.
  const bool keptJoints = colourJoints(w, d);
  prepareJointSims(w, d, context, keptJoints);
  const solver::ColourGraph& graph = w.contactGraph;
  d.overflow.clear();
  for (const std::uint32_t slot : graph.members(solver::ColourGraph::overflow)) {
    d.overflow.push_back(makeContactConstraint(w, w.contacts[slot], slot, d.soft, d.staticSoft, d.caps));
  }
  // Batches of `width` per colour.
  const auto width = static_cast<std::uint32_t>(kernels.width);
  std::uint32_t batches = 0;
  for (std::size_t c = 0; c < colourCount; ++c) {
    d.colourStart[c] = batches;
    batches += static_cast<std::uint32_t>((graph.members(static_cast<std::uint32_t>(c)).size() + width - 1) / width);
  }
  d.colourStart[colourCount] = batches;
  d.wide.resize(batches * kernels.batchBytes / sizeof(WideBlock) + 1);
  d.slots.resize(std::size_t{batches} * width);
  // The batches' contact slots, colour after colour (noContact fills a colour's last batch) ...
  for (std::size_t colour = 0; colour < colourCount; ++colour) {
    const std::span<const std::uint32_t> list = graph.members(static_cast<std::uint32_t>(colour));
    // By pointer, not by index: an empty colour's start may be the end of the slots.
    std::uint32_t* slots = d.slots.data() + std::size_t{d.colourStart[colour]} * width;
    const std::size_t filled = std::size_t{d.colourStart[colour + 1] - d.colourStart[colour]} * width;
    std::copy(list.begin(), list.end(), slots);
    std::fill(slots + list.size(), slots + filled, noContact);
  }
  // ... then every batch prepared at once, on threads: a batch writes only its own lanes and
  // its own contacts, whatever its colour.
  w.parallelFor(batches, minPrepareBatchesPerTask, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t batch = begin; batch < end; ++batch) {
      const std::uint32_t* slots = &d.slots[std::size_t{batch} * width];
      if (batch + prefetchDistance < batches) {
        prefetchContacts(w, slots + std::size_t{prefetchDistance} * width, width, 0, contactPrepareBytes);
      }
      const auto count = static_cast<int>(std::find(slots, slots + width, noContact) - slots);
      kernels.prepare(d.batches(), batch, w, slots, count, d.soft, d.staticSoft, d.caps);
    }
  });
}

void warmStartConstraints(WorldState& w) {
  const std::uint32_t staticIndex = w.staticIndex();
  ContactSolverData& d = *w.contactSolver;
  BodyState* states = w.states.data();
  forEachColour(
      w, [&](JointSim& joint) { warmStartJoint(joint, w.states, staticIndex); },
      [&](std::uint32_t begin, std::uint32_t end) {
        d.kernels->warmStart(d.batches(), begin, end, states, staticIndex);
      },
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

void solveConstraints(WorldState& w, const StepContext& context, bool useBias) {
  const std::uint32_t staticIndex = w.staticIndex();
  ContactSolverData& d = *w.contactSolver;
  BodyState* states = w.states.data();
  const ContactSolveParams params{context.inverseH, d.pushSpeed, d.restitutionThreshold, useBias};
  forEachColour(
      w, [&](JointSim& joint) { solveJoint(joint, w.states, staticIndex, context, useBias); },
      [&](std::uint32_t begin, std::uint32_t end) {
        d.kernels->solve(d.batches(), begin, end, states, staticIndex, params);
      },
      [&](ContactConstraint& c) { solveOne(c, w.states, staticIndex, params); });
}

void storeImpulses(WorldState& w) {
  ContactSolverData& d = *w.contactSolver;
  const float hitThreshold = w.def.hitEventThreshold;
  for (const ContactConstraint& c : d.overflow) {
    std::array<SolvedPoint, 2> points;
    for (std::size_t k = 0; k < 2; ++k) {
      const ConstraintPoint& p = c.points[k];
      points[k] = {p.normalImpulse, p.tangentImpulse, p.maxNormalImpulse, p.impactSpeed};
    }
    const bool rollingSolved = c.rollingMass != 0.0f || !w.def.enableWarmStarting;
    w.maybeHit[c.contact] =
        storeContact(w.contacts[c.contact], points, c.rollingImpulse, rollingSolved, hitThreshold) ? 1 : 0;
  }
  const int width = d.kernels->width;
  const auto batches = static_cast<std::uint32_t>(d.slots.size() / static_cast<std::size_t>(width));
  w.parallelFor(batches, 64, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t batch = begin; batch < end; ++batch) {
      if (batch + prefetchDistance < end) {
        prefetchContacts(w, &d.slots[std::size_t{batch + prefetchDistance} * static_cast<std::size_t>(width)],
                         static_cast<std::size_t>(width), contactStoreLine, contactStoreLine + 1);
      }
      d.kernels->store(d.batches(), batch, w, &d.slots[std::size_t{batch} * static_cast<std::size_t>(width)],
                       hitThreshold);
    }
  });
}

ConstraintGraphCounts constraintGraph(const WorldState& w) {
  static_assert(ConstraintGraphCounts::colours == colourCount);
  ConstraintGraphCounts counts;
  if (!w.contactSolver) {
    return counts;
  }
  const ContactSolverData& d = *w.contactSolver;
  for (std::size_t c = 0; c < colourCount; ++c) {
    counts.colourJoints[c] = static_cast<std::uint32_t>(d.colourJoints[c].size());
    counts.colourContacts[c] = static_cast<std::uint32_t>(w.contactGraph.members(static_cast<std::uint32_t>(c)).size());
  }
  counts.overflowJoints = static_cast<std::uint32_t>(d.overflowJoints.size());
  counts.overflowContacts = static_cast<std::uint32_t>(w.contactGraph.members(solver::ColourGraph::overflow).size());
  return counts;
}

int contactLanes(const WorldState& w) { return selectWideKernels(w.def.simd).width; }
const char* contactSimd(const WorldState& w) { return selectWideKernels(w.def.simd).name; }

} // namespace impetus::rigid2d::detail
