// The contact constraint of the soft-step solver, as the scalar solver holds it, and the table
// of wide kernels that solve many at once in SIMD lanes.
//
// The wide kernels are compiled once per instruction set (contact_wide_sse2.cpp and, on x86-64,
// contact_wide_avx2.cpp) from contact_wide_kernels.hpp; the solver picks the widest the CPU
// runs when the world is made. Every lane computes exactly what the scalar solver computes (no
// fused multiply-add, the same operations in the same order), and a colour's contacts share no
// moving body, so the width changes the speed, never the result.
#pragma once

#include "rigid2d/world_impl.hpp"

#include <array>
#include <cstddef>
#include <cstdint>

namespace impetus::rigid2d::detail {

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

/// One contact: solved alone (the overflow), or copied into a lane of a wide batch.
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
  float tangentSpeed = 0.0f; ///< m/s: the relative sliding speed friction drives toward
  Softness softness;
  int pointCount = 0;
  std::array<ConstraintPoint, 2> points{};
};

/// Fills one constraint (or one lane) from its contact: anchors relative to the centres of mass,
/// effective masses, and the approach speed before the step.
/// Inline: the wide kernels write it straight into a lane (contact_wide_kernels.hpp). Internal
/// linkage, as everything the AVX2 object compiles: no copy built for AVX2 may stand in for the
/// baseline's.
[[gnu::always_inline]] static inline ContactConstraint makeContactConstraint(const WorldState& w, Contact& contact,
                                                                             std::uint32_t slot, const Softness& soft,
                                                                             const Softness& staticSoft) {
  const SolverBodyInfo& a = w.bodyInfo[contact.bodyA];
  const SolverBodyInfo& b = w.bodyInfo[contact.bodyB];
  const Manifold& m = contact.manifold;
  ContactConstraint c;
  c.indexA = a.solverIndex;
  c.indexB = b.solverIndex;
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
  c.tangentSpeed = contact.tangentSpeed;
  c.softness = (c.mA == 0.0f || c.mB == 0.0f) ? staticSoft : soft;
  c.pointCount = m.pointCount;
  const Vec2f tangent{m.normal.y, -m.normal.x};
  const Vec2f offsetA = a.centerOffset;
  const Vec2f offsetB = b.centerOffset;
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

/// The restitution pass solves a two-point manifold's normal rows as one 2x2 block (Box2D 2.4's
/// block solver). One pass over the points, one after the other, is not enough: the first point's
/// impulse turns the body, and the second point's then leaves it spinning (a box landing flat
/// with e = 0.8 rebounded to 46% of e^2 h at 3 rad/s). The block is used while its condition
/// number k11^2 / det K stays below this bound; nearer to singular (the points almost coincide,
/// so the two rows say the same thing) the points are solved one after the other. Dimensionless.
inline constexpr float maxBlockConditionNumber = 1000.0f;

// The scalar forms of the lane operations solveNormalBlock uses (masks are bools).
[[gnu::always_inline]] static inline bool greaterW(float a, float b) { return a > b; }
[[gnu::always_inline]] static inline bool andW(bool a, bool b) { return a && b; }
[[gnu::always_inline]] static inline bool orW(bool a, bool b) { return a || b; }
[[gnu::always_inline]] static inline float selectW(bool mask, float ifTrue, float ifFalse) {
  return mask ? ifTrue : ifFalse;
}

/// The accumulated normal impulses (N s) of a two-point manifold whose normal velocities must
/// reach `target1` and `target2` (m/s), or more if the point separates anyway: the linear
/// complementarity problem vn' = vn + K (x - x0), x >= 0, vn' >= target, x_i (vn'_i - target_i) = 0,
/// solved by trying its four cases in turn (both points push; only the first; only the second;
/// neither). K = [k11 k12; k12 k22] is the rows' effective mass matrix inverse (1/kg), x0 the
/// impulses so far, vn the normal velocities now. Where no case holds, x0 is kept. `one` is 1 in
/// the float type; K must be invertible (the caller passes the identity in lanes it discards).
/// Written over the float type F (float or a SIMD type) with its lane operations, so the scalar
/// solver and every lane of the wide solver do the same arithmetic and get the same bits.
template <class F> [[gnu::always_inline]] static inline void
solveNormalBlock(F k11, F k12, F k22, F vn1, F vn2, F target1, F target2, F zero, F& x1, F& x2) {
  // vn' = K x + b: b is what the normal velocities would be without any normal impulse.
  const F b1 = vn1 - (k11 * x1 + k12 * x2);
  const F b2 = vn2 - (k12 * x1 + k22 * x2);
  const F r1 = target1 - b1;
  const F r2 = target2 - b2;
  // From the least to the most preferred case, each taking over where it holds (ties go to the
  // case before: the result is the same).
  // Neither point pushes: both separate fast enough as they are.
  const auto neither = andW(greaterW(b1, target1), greaterW(b2, target2));
  F n1 = selectW(neither, zero, x1);
  F n2 = selectW(neither, zero, x2);
  // Only the second point pushes, and the first separates fast enough.
  const F only2 = r2 / k22;
  const auto second = andW(greaterW(only2, zero), greaterW(k12 * only2 + b1, target1));
  n1 = selectW(second, zero, n1);
  n2 = selectW(second, only2, n2);
  // Only the first point pushes, and the second separates fast enough.
  const F only1 = r1 / k11;
  const auto first = andW(greaterW(only1, zero), greaterW(k12 * only1 + b2, target2));
  n1 = selectW(first, only1, n1);
  n2 = selectW(first, zero, n2);
  // Both push: K x = target - b.
  const F det = k11 * k22 - k12 * k12;
  const F both1 = (k22 * r1 - k12 * r2) / det;
  const F both2 = (k11 * r2 - k12 * r1) / det;
  const auto both = andW(greaterW(both1, zero), greaterW(both2, zero));
  x1 = selectW(both, both1, n1);
  x2 = selectW(both, both2, n2);
}

/// The effective mass matrix inverse K (1/kg) of two normal rows (lever arms rnA_k = rA_k x n and
/// rnB_k = rB_k x n, m): K_jk = mA + mB + iA rnA_j rnA_k + iB rnB_j rnB_k.
template <class F>
[[gnu::always_inline]] static inline F normalCoupling(F mA, F mB, F iA, F iB, F rnAj, F rnAk, F rnBj, F rnBk) {
  return mA + mB + iA * rnAj * rnAk + iB * rnBj * rnBk;
}

/// A lane without a contact, in the solver's slot lists.
inline constexpr std::uint32_t noContact = ~std::uint32_t{0};

/// Notes the fastest impact for hit events and keeps the impulses for the next warm start.
[[gnu::always_inline]] static inline void storePoint(Contact& contact, int k, float normalImpulse, float tangentImpulse,
                                                     float maxNormalImpulse) {
  const float approach = contact.approachBefore[static_cast<std::size_t>(k)];
  if (maxNormalImpulse > 0.0f && approach > contact.approachSpeed) {
    contact.approachSpeed = approach;
    contact.fastestPoint = k;
  }
  ManifoldPoint& mp = contact.manifold.points[static_cast<std::size_t>(k)];
  mp.normalImpulse = normalImpulse;
  mp.tangentImpulse = tangentImpulse;
}

/// The per-substep constants of a solve pass.
struct ContactSolveParams {
  float inverseH = 0.0f;  ///< 1/s
  float pushSpeed = 0.0f; ///< the most the bias may push apart, m/s
  bool useBias = true;    ///< false: the relax pass
};

/// Wide kernels over batches [begin, end) of an array of `width`-lane constraints (opaque here:
/// batchBytes each, aligned to wideAlignment). Unused lanes hold the static index and zero
/// masses, so they compute zero impulses.
struct WideKernels {
  const char* name = "";
  int width = 0;
  std::size_t batchBytes = 0;
  /// Prepares batch `batch` from the contacts in slots[0, count), count <= width (the rest of
  /// the lanes: unused), with makeContactConstraint.
  void (*prepare)(void* batches, std::uint32_t batch, WorldState& w, const std::uint32_t* slots, int count,
                  const Softness& soft, const Softness& staticSoft) = nullptr;
  void (*warmStart)(void* batches, std::uint32_t begin, std::uint32_t end, BodyState* states,
                    std::uint32_t staticIndex) = nullptr;
  void (*solve)(void* batches, std::uint32_t begin, std::uint32_t end, BodyState* states, std::uint32_t staticIndex,
                const ContactSolveParams& params) = nullptr;
  void (*restitution)(void* batches, std::uint32_t begin, std::uint32_t end, BodyState* states,
                      std::uint32_t staticIndex, float threshold) = nullptr;
  /// Stores batch `batch`'s impulses into the contacts in slots[0, width) (noContact: none) for
  /// the next warm start, with the fastest approach and the hit flag (approachMayHit).
  void (*store)(const void* batches, std::uint32_t batch, WorldState& w, const std::uint32_t* slots,
                float hitThreshold) = nullptr;
};

/// The most lanes a kernel table may have (AVX2's eight floats).
inline constexpr int maxWideLanes = 8;

/// Alignment of the wide batches' storage, bytes (enough for 8-lane AVX registers).
inline constexpr std::size_t wideAlignment = 32;

/// The portable kernels: SSE2 on x86-64 (4 lanes), plain floats elsewhere.
[[nodiscard]] const WideKernels& baselineWideKernels();
/// The 8-lane AVX2 kernels where they are built (x86-64), else null. Run them only on a CPU
/// that supports AVX2 (contact_solver.cpp asks).
[[nodiscard]] const WideKernels* avx2WideKernelsBuilt();

} // namespace impetus::rigid2d::detail
