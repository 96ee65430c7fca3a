// The parts every joint is built from (the manner of Jolt's constraint parts; the solver layer:
// no dimension in it). Each part owns its accumulated impulse and offers a warm start and a solve
// on rows (constraint_row.hpp) that the joint builds from its geometry each time:
//   RowPart    an equality row C = 0, soft with the joint's stiffness or rigid;
//   SpringPart a spring toward C = 0 of its own frequency and damping ratio;
//   MotorPart  a row driven to a target speed with a bounded impulse (motors, joint friction);
//   LimitPart  a pair of one-sided rows lower <= C <= upper;
//   BlockPart  N coupled equality rows solved together (a slider's line and angle), optionally
//              with the impulse bounded in magnitude;
//   PointPart  two anchors held together (point_part.hpp): a point's rows as one block, in the
//              closed form of the dimension's K.
// Every row's accumulated impulse is held within what the world's speed caps could ever ask of it
// (maxRowImpulse), so that an unstable system outside the envelope stays finite.
// A joint type is a short composition of these: a revolute joint is a point part, a spring, a
// motor, friction and a limit on the angle row. The accumulated impulses are per substep (N s,
// or N m s on angle rows); the joint's force is the impulse times the substep rate.
#pragma once

#include "solver/constraint_row.hpp"
#include "solver/softness.hpp"

#include <impetus/math/scalar.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace impetus::solver {

/// The softness of a rigid row: no bias, full mass (the relax pass solves rigid rows with it).
inline constexpr Softness rigidRow{};

/// A row's bias speed for the error c (m or rad) at `soft`, within its maxBias.
[[nodiscard]] inline float biasSpeed(const Softness& soft, float c) {
  return std::clamp(soft.biasRate * c, -soft.maxBias, soft.maxBias);
}

/// An equality row C = 0.
struct RowPart {
  float impulse = 0.0f;

  template <class R, class M, class B> void warmStart(const R& row, const M& m, B& a, B& b) const {
    applyRow(row, m, a, b, impulse);
  }
  /// Drives the row's speed toward -biasRate c (c: the position error, m or rad) at `soft`.
  template <class R, class M, class B> void solve(const R& row, const M& m, B& a, B& b, float c, const Softness& soft) {
    const float mass = rowMass(row, m);
    const float old = impulse;
    const float bound = maxRowImpulse(row, mass, m);
    impulse =
        std::clamp(old - soft.massScale * mass * (rowSpeed(row, a, b) + biasSpeed(soft, c)) - soft.impulseScale * old,
                   -bound, bound);
    applyRow(row, m, a, b, impulse - old);
  }
  /// solve at rigidRow (the relax pass): no bias, so no error to compute.
  template <class R, class M, class B> void solveRigid(const R& row, const M& m, B& a, B& b) {
    const float mass = rowMass(row, m);
    const float old = impulse;
    const float bound = maxRowImpulse(row, mass, m);
    impulse = std::clamp(old - mass * rowSpeed(row, a, b), -bound, bound);
    applyRow(row, m, a, b, impulse - old);
  }
};

/// A spring's coefficients over one substep h (SpringPart). With k = m omega^2 and
/// c = 2 zeta m omega for the row's effective mass m, the spring's impulse over a substep is
///   lambda = -h k (x1 + theta h v2) - h c v2,   i.e.   lambda = -m (A v2 + B x1),
/// with x1 the stretch at the substep's start, v2 the stretch rate after it, B = h omega^2 and
/// A = 2 zeta omega h + theta (h omega)^2. With theta = 1, applied again in the relax pass, this
/// is the soft constraint of Box2D v3's springs (backward Euler): stable at any stiffness, but
/// with the position update x2 = x1 + h v2 it takes a fraction of about A of the energy every
/// substep (an undamped 2 Hz spring at 240 substeps a second loses half its energy a period).
/// With theta = 0, applied once, the stiffness is symplectic Euler, whose energy does not drift
/// (the damping stays implicit, exact to O(h omega)), but it is stable only for h omega < 2, less
/// in chains. So a soft spring (h omega <= 1/4: up to 9.5 Hz at 240 substeps a second) is
/// symplectic; from there theta rises to 1 at h omega = 1/2, and the relax share from 0 at 1/2 to
/// 1 at 3/4 (28.6 Hz at 240/s), beyond which it is exactly the backward Euler spring. On chains of
/// six springs with mass ratios 1 and 50 no frequency up to 60 Hz gains energy.
struct SpringCoefficients {
  float stiffness = 0.0f;  ///< B, 1/s
  float damping = 0.0f;    ///< A, dimensionless
  float relaxShare = 0.0f; ///< of the spring's impulse applied again in the relax pass
};

/// h omega below which a spring is integrated symplectically, and the two widths (in h omega)
/// over which the implicit share of its stiffness and its relax share rise to 1 (SpringCoefficients).
inline constexpr float symplecticSpringBelow = 0.25f;
inline constexpr float springBlendWidth = 0.25f;

[[nodiscard]] inline SpringCoefficients springCoefficients(float hertz, float dampingRatio, float h) {
  if (!(hertz > 0.0f)) {
    return {};
  }
  const float omega = 2.0f * pi<float> * hertz;
  const float hw = h * omega;
  const float theta = std::clamp((hw - symplecticSpringBelow) / springBlendWidth, 0.0f, 1.0f);
  const float relax = std::clamp((hw - symplecticSpringBelow - springBlendWidth) / springBlendWidth, 0.0f, 1.0f);
  return {h * omega * omega, 2.0f * dampingRatio * hw + theta * hw * hw, relax};
}

/// A spring toward C = 0 (a rest length or angle), with its own frequency and damping ratio: the
/// same hertz is the same stiffness k = m (2 pi f)^2 on every joint, m the row's effective mass.
struct SpringPart {
  float impulse = 0.0f;
  SpringCoefficients coefficients;

  /// This step's coefficients; a spring of 0 Hz applies nothing (and holds no impulse).
  void prepare(float hertz, float dampingRatio, float h) {
    coefficients = springCoefficients(hertz, dampingRatio, h);
    if (coefficients.stiffness == 0.0f) {
      impulse = 0.0f;
    }
  }
  template <class R, class M, class B> void warmStart(const R& row, const M& m, B& a, B& b) const {
    applyRow(row, m, a, b, impulse);
  }
  /// c: the stretch now (m or rad). The impulse that makes lambda = -m (A v2 + B x) hold, where v2
  /// moves by 1/m per unit impulse, so that the residual lambda + m (A v + B x) moves by (1 + A).
  template <class R, class M, class B> void solve(const R& row, const M& m, B& a, B& b, float c, bool useBias) {
    const SpringCoefficients& k = coefficients;
    if (k.stiffness == 0.0f || !(useBias || k.relaxShare > 0.0f)) {
      return;
    }
    const float mass = rowMass(row, m);
    const float residual = impulse + mass * (k.damping * rowSpeed(row, a, b) + k.stiffness * c);
    const float old = impulse;
    const float bound = maxRowImpulse(row, mass, m);
    impulse = std::clamp(old - (useBias ? 1.0f : k.relaxShare) * residual / (1.0f + k.damping), -bound, bound);
    applyRow(row, m, a, b, impulse - old);
  }
};

/// A row driven toward a target speed with at most `maxImpulse` a substep: a motor (maxImpulse =
/// its force or torque times h) or joint friction (target 0).
struct MotorPart {
  float impulse = 0.0f;

  template <class R, class M, class B> void warmStart(const R& row, const M& m, B& a, B& b) const {
    applyRow(row, m, a, b, impulse);
  }
  template <class R, class M, class B>
  void solve(const R& row, const M& m, B& a, B& b, float targetSpeed, float maxImpulse) {
    const float old = impulse;
    impulse = std::clamp(old - rowMass(row, m) * (rowSpeed(row, a, b) - targetSpeed), -maxImpulse, maxImpulse);
    applyRow(row, m, a, b, impulse - old);
  }
};

/// Limits lower <= C <= upper on a row: two one-sided rows, each with an accumulated impulse >= 0
/// (the lower one pushes along +row, the upper one along -row). While a limit is not reached it
/// is speculative: the row may close the gap this substep, no more (so a fast approach stops at
/// the limit instead of passing it); once passed it is pushed back at `soft` with bias, rigid
/// without.
struct LimitPart {
  float lowerImpulse = 0.0f;
  float upperImpulse = 0.0f;

  template <class R, class M, class B> void warmStart(const R& row, const M& m, B& a, B& b) const {
    applyRow(row, m, a, b, lowerImpulse - upperImpulse);
  }
  /// The lower side: c = C - lower (>= 0 allowed).
  template <class R, class M, class B>
  void solveLower(const R& row, const M& m, B& a, B& b, float c, const Softness& soft, float inverseH, bool useBias) {
    const float mass = rowMass(row, m);
    applyRow(
        row, m, a, b,
        oneSided(lowerImpulse, c, rowSpeed(row, a, b), mass, maxRowImpulse(row, mass, m), soft, inverseH, useBias));
  }
  /// The upper side: c = upper - C (>= 0 allowed).
  template <class R, class M, class B>
  void solveUpper(const R& row, const M& m, B& a, B& b, float c, const Softness& soft, float inverseH, bool useBias) {
    const float mass = rowMass(row, m);
    applyRow(
        row, m, a, b,
        -oneSided(upperImpulse, c, -rowSpeed(row, a, b), mass, maxRowImpulse(row, mass, m), soft, inverseH, useBias));
  }
  template <class R, class M, class B> void solve(const R& row, const M& m, B& a, B& b, float position, float lower,
                                                  float upper, const Softness& soft, float inverseH, bool useBias) {
    solveLower(row, m, a, b, position - lower, soft, inverseH, useBias);
    solveUpper(row, m, a, b, upper - position, soft, inverseH, useBias);
  }
  void clear() { lowerImpulse = upperImpulse = 0.0f; }

private:
  /// The change of a one-sided row's accumulated impulse (kept >= 0) for its gap c and speed cdot.
  static float oneSided(float& accumulated, float c, float cdot, float mass, float bound, const Softness& soft,
                        float inverseH, bool useBias) {
    Softness s = rigidRow;
    if (c > 0.0f) {
      s.biasRate = inverseH; // speculative: close the gap in this substep, no more
    } else if (useBias) {
      s = soft;
    }
    const float lambda = -mass * s.massScale * (cdot + biasSpeed(s, c)) - s.impulseScale * accumulated;
    const float total = std::clamp(accumulated + lambda, 0.0f, bound);
    const float applied = total - accumulated;
    accumulated = total;
    return applied;
  }
};

/// A pivot below this share of its row's own diagonal means the row is, to rounding, a
/// combination of the rows before it (two rows that say the same thing: a slider's line and
/// angle when a body of almost no inertia carries it on a long arm). Dimensionless: about 10^7
/// times double's rounding, well below any block a game builds (the worst in the envelope,
/// 10:1 masses on 0.1 m to 10 m arms, stays above 10^-5).
inline constexpr double dependentRowPivot = 1e-9;

/// Solves K x = r for a small symmetric positive semi-definite K by Gaussian elimination (such a
/// K needs no pivoting), in double: a block between a light body of little inertia and a long
/// lever arm is conditioned as badly as 10^8, and in float the elimination's differences of large
/// terms lose every digit. A row dependent on those before it (dependentRowPivot) takes no part:
/// its share of the answer is zero, instead of the huge value a near-zero pivot would give.
template <int N> [[nodiscard]] inline std::array<double, N> solveSymmetric(std::array<std::array<double, N>, N> k,
                                                                           std::array<double, N> r) {
  std::array<bool, N> dependent{};
  for (int i = 0; i < N; ++i) {
    const double diagonal = k[i][i];
    for (int p = 0; p < i; ++p) {
      if (dependent[p]) {
        continue;
      }
      const double f = k[i][p] / k[p][p];
      for (int c = p; c < N; ++c) {
        k[i][c] -= f * k[p][c];
      }
      r[i] -= f * r[p];
    }
    dependent[i] = !(k[i][i] > dependentRowPivot * diagonal) || !(diagonal > 0.0);
  }
  std::array<double, N> x{};
  for (int i = N - 1; i >= 0; --i) {
    if (dependent[i]) {
      continue;
    }
    double s = r[i];
    for (int c = i + 1; c < N; ++c) {
      s -= k[i][c] * x[c];
    }
    x[i] = s / k[i][i];
  }
  return x;
}

/// N coupled equality rows C_i = 0 solved as one block with K_ij = J_i M^-1 J_j^T, so that
/// rows sharing a body (a point's two or three axes, a slider's line and angle) do not undo one
/// another within a pass. A row that no body can move along (an angle row between two bodies of
/// fixed rotation), or one the others already say, takes no impulse (solveSymmetric).
template <int N> struct BlockPart {
  std::array<float, N> impulse{};

  template <class R, class M, class B> void warmStart(const std::array<R, N>& rows, const M& m, B& a, B& b) const {
    for (int i = 0; i < N; ++i) {
      applyRow(rows[i], m, a, b, impulse[i]);
    }
  }
  /// Drives the rows' speeds toward -biasRate c at `soft`; with `maxMagnitude`, the accumulated
  /// impulse is held within that length (a drive of bounded force, whatever its direction).
  template <class R, class M, class B> void solve(const std::array<R, N>& rows, const M& m, B& a, B& b,
                                                  const std::array<float, N>& c, const Softness& soft,
                                                  float maxMagnitude = std::numeric_limits<float>::infinity()) {
    std::array<std::array<double, N>, N> k{};
    std::array<double, N> r{};
    for (int i = 0; i < N; ++i) {
      for (int j = 0; j < N; ++j) {
        k[i][j] = rowCouplingPrecise(rows[i], rows[j], m);
      }
      r[i] = rowSpeed(rows[i], a, b) + biasSpeed(soft, c[i]);
    }
    const std::array<double, N> x = solveSymmetric<N>(k, r);
    std::array<float, N> lambda{};
    float squared = 0.0f;
    for (int i = 0; i < N; ++i) {
      lambda[i] = -soft.massScale * static_cast<float>(x[i]) - soft.impulseScale * impulse[i];
      const float total = impulse[i] + lambda[i];
      squared += total * total;
    }
    if (squared > maxMagnitude * maxMagnitude) {
      const float scale = maxMagnitude / std::sqrt(squared);
      for (int i = 0; i < N; ++i) {
        lambda[i] = (impulse[i] + lambda[i]) * scale - impulse[i];
      }
    }
    for (int i = 0; i < N; ++i) {
      const float old = impulse[i];
      const float bound = maxRowImpulse(rows[i], static_cast<float>(k[i][i] > 0.0 ? 1.0 / k[i][i] : 0.0), m);
      impulse[i] = std::clamp(old + lambda[i], -bound, bound);
      applyRow(rows[i], m, a, b, impulse[i] - old);
    }
  }
};

} // namespace impetus::solver
