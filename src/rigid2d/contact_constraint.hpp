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
  Softness softness;
  int pointCount = 0;
  std::array<ConstraintPoint, 2> points{};
};

/// The per-substep constants of a solve pass.
struct ContactSolveParams {
  float inverseH = 0.0f;  ///< 1/s
  float pushSpeed = 0.0f; ///< the most the bias may push apart, m/s
  bool useBias = true;    ///< false: the relax pass
};

/// What a lane's contact keeps for the next step's warm start and for hit events.
struct LaneImpulses {
  float rollingImpulse = 0.0f;
  std::array<float, 2> normal{}, tangent{}, maxNormal{};
};

/// Wide kernels over batches [begin, end) of an array of `width`-lane constraints (opaque here:
/// batchBytes each, aligned to wideAlignment). Unused lanes hold the static index and zero
/// masses, so they compute zero impulses.
struct WideKernels {
  const char* name = "";
  int width = 0;
  std::size_t batchBytes = 0;
  /// Fills batch `batch` from `count` <= width constraints (the rest of the lanes: unused).
  void (*fill)(void* batches, std::uint32_t batch, const ContactConstraint* lanes, int count,
               std::uint32_t staticIndex) = nullptr;
  void (*warmStart)(void* batches, std::uint32_t begin, std::uint32_t end, BodyState* states,
                    std::uint32_t staticIndex) = nullptr;
  void (*solve)(void* batches, std::uint32_t begin, std::uint32_t end, BodyState* states, std::uint32_t staticIndex,
                const ContactSolveParams& params) = nullptr;
  void (*restitution)(void* batches, std::uint32_t begin, std::uint32_t end, BodyState* states,
                      std::uint32_t staticIndex, float threshold) = nullptr;
  /// Every lane's impulses of batch `batch` into lanes[0, width).
  void (*read)(const void* batches, std::uint32_t batch, LaneImpulses* lanes) = nullptr;
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
