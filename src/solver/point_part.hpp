// The point part: two anchors held together, C = (cB + rB) - (cA + rA) = 0, its rows solved as
// one block (the pin of a revolute joint, the linear half of a weld, the drive of a motor or
// mouse joint). The part is written once over the dimension's algebra: a point has as many rows
// as the space has axes, and K = J M^-1 J^T is the dimension's small symmetric matrix. The plane's
// algebra is here; the 3D world adds its 3x3 overloads of pointMatrix, solvePoint, pointSpeed,
// applyPoint and pointImpulseBound.
//
// In the plane K = (mA + mB) I + iA rA_perp rA_perp^T + iB rB_perp rB_perp^T, whose determinant
//   det K = m^2 + m (iA |rA|^2 + iB |rB|^2) + iA iB cross(rA, rB)^2,   m = mA + mB,
// is a sum of terms that are never negative: computed that way, in float, it keeps its digits
// however long the lever arms and however light the bodies (the difference k11 k22 - k12^2 loses
// them all once iA |rA|^2 is 10^4 times m).
#pragma once

#include "solver/joint_parts.hpp"

#include <impetus/math/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace impetus::solver {

/// K of a point constraint in the plane, with its inverse determinant (0 when no body moves).
struct PointMatrix2 {
  float xx = 0.0f, xy = 0.0f, yy = 0.0f;
  float inverseDeterminant = 0.0f;
};

/// K for anchors rA on A and rB on B (relative to the centres of mass, m); `Mass` has the inverse
/// masses mA, mB and inverse inertias iA, iB.
template <class Mass> [[nodiscard]] inline PointMatrix2 pointMatrix(const Vec2f& rA, const Vec2f& rB, const Mass& m) {
  const float linear = m.mA + m.mB;
  PointMatrix2 k;
  k.xx = linear + m.iA * rA.y * rA.y + m.iB * rB.y * rB.y;
  k.xy = -m.iA * rA.x * rA.y - m.iB * rB.x * rB.y;
  k.yy = linear + m.iA * rA.x * rA.x + m.iB * rB.x * rB.x;
  const float armCross = cross(rA, rB);
  const float determinant =
      linear * linear + linear * (m.iA * dot(rA, rA) + m.iB * dot(rB, rB)) + m.iA * m.iB * armCross * armCross;
  k.inverseDeterminant = determinant > 0.0f ? 1.0f / determinant : 0.0f;
  return k;
}

/// K^-1 r.
[[nodiscard]] inline Vec2f solvePoint(const PointMatrix2& k, const Vec2f& r) {
  return Vec2f{k.yy * r.x - k.xy * r.y, k.xx * r.y - k.xy * r.x} * k.inverseDeterminant;
}

/// The anchors' relative velocity (B's minus A's), m/s.
template <class Body>
[[nodiscard]] inline Vec2f pointSpeed(const Vec2f& rA, const Vec2f& rB, const Body& a, const Body& b) {
  return (b.v + cross(b.w, rB)) - (a.v + cross(a.w, rA));
}

/// Applies an impulse P (N s) at the anchors: +P on B at rB, -P on A at rA.
template <class Mass, class Body>
inline void applyPoint(const Vec2f& rA, const Vec2f& rB, const Mass& m, Body& a, Body& b, const Vec2f& p) {
  a.v -= p * m.mA;
  a.w -= m.iA * cross(rA, p);
  b.v += p * m.mB;
  b.w += m.iB * cross(rB, p);
}

/// Each axis' largest impulse (maxRowImpulse of the x row and of the y row).
template <class Pair>
[[nodiscard]] inline Vec2f pointImpulseBound(const PointMatrix2& k, const Vec2f& rA, const Vec2f& rB, const Pair& p) {
  const float spinX = p.maxSpin * (std::abs(rA.y) + std::abs(rB.y)); // |cross(r, x axis)|
  const float spinY = p.maxSpin * (std::abs(rA.x) + std::abs(rB.x));
  const float speed = 2.0f * p.maxSpeed;
  return {k.xx > 0.0f ? (speed + spinX) / k.xx : 0.0f, k.yy > 0.0f ? (speed + spinY) / k.yy : 0.0f};
}

/// Each axis' bias speed for the separation c (m) at `soft`.
[[nodiscard]] inline Vec2f biasSpeed(const Softness& soft, const Vec2f& c) {
  return {biasSpeed(soft, c.x), biasSpeed(soft, c.y)};
}

/// v with each axis held within +-bound.
[[nodiscard]] inline Vec2f clampEach(const Vec2f& v, const Vec2f& bound) {
  return {std::clamp(v.x, -bound.x, bound.x), std::clamp(v.y, -bound.y, bound.y)};
}

/// Two anchors held together, soft at the given softness, the impulse optionally bounded in
/// magnitude (a drive of bounded force). Owns its accumulated impulse (N s per substep).
template <class Vec> struct PointPart {
  Vec impulse{};
  /// Each axis' largest impulse this step (pointImpulseBound at the step's anchors: a bound on
  /// runaway impulses, which the anchors' turn within a step cannot make matter).
  Vec bound{};

  /// The step's bound, from the anchors at its start.
  template <class M> void prepare(const Vec& rA, const Vec& rB, const M& m) {
    bound = pointImpulseBound(pointMatrix(rA, rB, m), rA, rB, m);
  }

  template <class M, class B> void warmStart(const Vec& rA, const Vec& rB, const M& m, B& a, B& b) const {
    applyPoint(rA, rB, m, a, b, impulse);
  }
  /// Drives the anchors' relative velocity toward -biasRate separation (m: B's anchor minus
  /// A's), each axis' bias within maxBias.
  /// Always inlined: the joints' solve is one function per type, its bodies' velocities kept in
  /// registers from part to part (a call would pass them through memory).
  template <class M, class B>
  [[gnu::always_inline]] inline void solve(const Vec& rA, const Vec& rB, const M& m, B& a, B& b, const Vec& separation,
                                           const Softness& soft,
                                           float maxMagnitude = std::numeric_limits<float>::infinity()) {
    const auto k = pointMatrix(rA, rB, m);
    const Vec target = pointSpeed(rA, rB, a, b) + biasSpeed(soft, separation);
    accumulate(rA, rB, m, a, b, impulse - solvePoint(k, target) * soft.massScale - impulse * soft.impulseScale,
               maxMagnitude);
  }
  /// solve at rigidRow (the relax pass): the relative velocity driven to zero, no bias, so no
  /// separation to compute. The same result as solve(..., separation, rigidRow, maxMagnitude).
  template <class M, class B>
  [[gnu::always_inline]] inline void solveRigid(const Vec& rA, const Vec& rB, const M& m, B& a, B& b,
                                                float maxMagnitude = std::numeric_limits<float>::infinity()) {
    accumulate(rA, rB, m, a, b, impulse - solvePoint(pointMatrix(rA, rB, m), pointSpeed(rA, rB, a, b)), maxMagnitude);
  }

private:
  /// The new accumulated impulse, held within maxMagnitude and each axis' bound, applied as the
  /// change from the old.
  template <class M, class B> [[gnu::always_inline]] inline void accumulate(const Vec& rA, const Vec& rB, const M& m,
                                                                            B& a, B& b, Vec total, float maxMagnitude) {
    if (const float squared = dot(total, total); squared > maxMagnitude * maxMagnitude) {
      total = total * (maxMagnitude / std::sqrt(squared));
    }
    total = clampEach(total, bound);
    applyPoint(rA, rB, m, a, b, total - impulse);
    impulse = total;
  }
};

} // namespace impetus::solver
