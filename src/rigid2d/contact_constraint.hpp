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
#include "solver/normal_block.hpp"

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
  float normalBound = 0.0f; ///< the most normal impulse the point may hold (contactImpulseBound), N s
  /// The point's fastest approach this step, m/s (positive approaching; hit events): its normal
  /// approach before the step (what a hit reports, unaffected by the order the points are solved
  /// in), or faster where a bounce met one within it (an impact passed along a row of touching
  /// bodies).
  float impactSpeed = 0.0f;
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

using solver::andW;
using solver::greaterW;
using solver::maxBlockConditionNumber;
using solver::solveNormalBlock;

/// The effective mass matrix inverse K (1/kg) of two normal rows (lever arms rnA_k = rA_k x n and
/// rnB_k = rB_k x n, m): K_jk = mA + mB + iA rnA_j rnA_k + iB rnB_j rnB_k.
template <class F>
[[gnu::always_inline]] static inline F normalCoupling(F mA, F mB, F iA, F iB, F rnAj, F rnAk, F rnBj, F rnBk) {
  return mA + mB + iA * rnAj * rnAk + iB * rnBj * rnBk;
}

/// The world's speed caps as the contact rows see them (StepContext): 2 maxLinearSpeed, m/s, and
/// the spin cap, rad/s.
struct ContactSpeedCaps {
  float twoMaxSpeed = 0.0f;
  float maxSpin = 0.0f;
};

/// The most normal impulse a contact point may hold in a substep, N s: what stops the fastest
/// approach the speed caps allow (twice the speed cap along the normal and the spin cap on each
/// lever arm) at the point's normal mass, as a joint row's (solver::maxRowImpulse). A resting
/// load needs far less (at 10:1 masses a stack's weight over a substep is thousands of times
/// under it); only the impulses of a jam running away (a light body crushed between a wall and
/// a heavy one) reach it, and it keeps them finite. `leverArms`: |rnA| + |rnB|, m (each as
/// max(x, -x), the wide kernels' way).
template <class F>
[[gnu::always_inline]] static inline F contactImpulseBound(F normalMass, F leverArms, F twoMaxSpeed, F maxSpin) {
  return normalMass * (twoMaxSpeed + maxSpin * leverArms);
}

/// A lane without a contact, in the solver's slot lists.
inline constexpr std::uint32_t noContact = ~std::uint32_t{0};

/// What the solve leaves of one contact point: the impulses to warm start from next step, N s,
/// and the point's fastest approach, m/s, where it pushed (maxNormalImpulse > 0).
struct SolvedPoint {
  float normalImpulse = 0.0f;
  float tangentImpulse = 0.0f;
  float maxNormalImpulse = 0.0f;
  float impactSpeed = 0.0f;
};

/// Keeps a contact's impulses for the next warm start: its points' and, where the solve may have
/// changed it (`rollingSolved`, see storeContact), its rolling impulse.
[[gnu::always_inline]] static inline void storeContactImpulses(Contact& contact,
                                                               const std::array<SolvedPoint, 2>& points,
                                                               float rollingImpulse, bool rollingSolved) {
  for (int k = 0; k < contact.manifold.pointCount; ++k) {
    ManifoldPoint& mp = contact.manifold.points[static_cast<std::size_t>(k)];
    mp.normalImpulse = points[static_cast<std::size_t>(k)].normalImpulse;
    mp.tangentImpulse = points[static_cast<std::size_t>(k)].tangentImpulse;
  }
  if (rollingSolved) {
    contact.rollingImpulse = rollingImpulse;
  }
}

/// Keeps a contact's impulses for the next warm start and notes its fastest impact; returns
/// whether that may raise a hit event (approachMayHit). It writes only the record's store line
/// (Contact) as a rule: the fastest impact only where it may be a hit (the hit pass reads it only
/// then), the rolling impulse only where the solve may have changed it (rolling resistance on:
/// `rollingSolved`, or no warm start, which began it from zero).
[[gnu::always_inline]] static inline bool storeContact(Contact& contact, const std::array<SolvedPoint, 2>& points,
                                                       float rollingImpulse, bool rollingSolved, float hitThreshold) {
  storeContactImpulses(contact, points, rollingImpulse, rollingSolved);
  float approach = 0.0f;
  int fastest = 0;
  for (int k = 0; k < contact.manifold.pointCount; ++k) {
    const SolvedPoint& p = points[static_cast<std::size_t>(k)];
    if (p.maxNormalImpulse > 0.0f && p.impactSpeed > approach) {
      approach = p.impactSpeed;
      fastest = k;
    }
  }
  const bool hit = approachMayHit(approach, hitThreshold);
  if (hit) {
    contact.approachSpeed = approach;
    contact.fastestPoint = fastest;
  }
  return hit;
}

/// The per-substep constants of a solve pass.
struct ContactSolveParams {
  float inverseH = 0.0f;             ///< 1/s
  float pushSpeed = 0.0f;            ///< the most the bias may push apart, m/s
  float restitutionThreshold = 0.0f; ///< m/s: slower impacts do not bounce
  /// true: the solve pass, whose normal rows push overlaps apart (the soft bias). false: the
  /// relax pass, which takes that push back and is the only one to solve friction and rolling
  /// resistance (as Box2D v3.2): they act on the velocities the step keeps, and solving them
  /// against the biased ones as well cost a third of the solve pass and slowed a tall pile's
  /// convergence (large_pyramid's top sank 0.734 m rather than 0.729 m; docs/performance.md).
  bool useBias = true;
};

/// Wide kernels over batches [begin, end) of an array of `width`-lane constraints (opaque here:
/// batchBytes each, aligned to wideAlignment). Unused lanes hold the static index and zero
/// masses, so they compute zero impulses.
struct WideKernels {
  const char* name = "";
  int width = 0;
  std::size_t batchBytes = 0;
  /// Prepares batch `batch` from the contacts in slots[0, count), count <= width (the rest of
  /// the lanes: unused): in each lane what the overflow's makeContactConstraint computes.
  void (*prepare)(void* batches, std::uint32_t batch, WorldState& w, const std::uint32_t* slots, int count,
                  const Softness& soft, const Softness& staticSoft, const ContactSpeedCaps& caps) = nullptr;
  void (*warmStart)(void* batches, std::uint32_t begin, std::uint32_t end, BodyState* states,
                    std::uint32_t staticIndex) = nullptr;
  void (*solve)(void* batches, std::uint32_t begin, std::uint32_t end, BodyState* states, std::uint32_t staticIndex,
                const ContactSolveParams& params) = nullptr;
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
