// A contact point's normal row in the soft step, shared by every world's scalar contact solver
// (the solver layer: no dimension in it; the caller measures the separation and the normal
// velocity in its own geometry).
#pragma once

#include "solver/softness.hpp"

#include <algorithm>

namespace impetus::solver {

/// What a normal row drives toward this pass: the bias speed (m/s) and the soft mass and impulse
/// scales.
struct NormalTarget {
  float bias = 0.0f;
  float massScale = 1.0f;
  float impulseScale = 0.0f;
};

/// A point `separation` apart (m, negative overlapping): a gap may close within the substep and
/// no more (speculative contact, rigid); an overlap is pushed apart softly, no faster than
/// `maxPushSpeed` (m/s), in the pass with bias only (the relax pass holds it rigidly).
[[nodiscard]] inline NormalTarget normalTarget(float separation, const Softness& soft, bool useBias, float inverseH,
                                               float maxPushSpeed) {
  NormalTarget t;
  if (separation > 0.0f) {
    t.bias = separation * inverseH;
  } else if (useBias) {
    t.bias = std::max(soft.biasRate * separation, -maxPushSpeed);
    t.massScale = soft.massScale;
    t.impulseScale = soft.impulseScale;
  }
  return t;
}

/// The row's impulse for normal velocity `vn` (m/s): added to the accumulated impulse `total`
/// (N s), which stays within [0, bound] (a contact pushes, never pulls); the most pushed in one
/// pass is kept in `maxApplied`. Returns what to apply now.
[[nodiscard]] inline float accumulateNormalImpulse(float& total, float& maxApplied, float normalMass, float bound,
                                                   float vn, const NormalTarget& t) {
  const float impulse = -normalMass * t.massScale * (vn + t.bias) - t.impulseScale * total;
  const float next = std::min(std::max(total + impulse, 0.0f), bound);
  const float applied = next - total;
  total = next;
  maxApplied = std::max(maxApplied, applied);
  return applied;
}

} // namespace impetus::solver
