// Two coupled normal rows solved together: the linear complementarity problem of a two-point
// manifold (Box2D 2.4's block solver), shared by every world (the solver layer: no dimension in
// it; the caller forms the 2x2 matrix from its own geometry).
#pragma once

namespace impetus::solver {

/// A contact's impact (restitution) solves a two-point manifold's normal rows as one 2x2 block (Box2D 2.4's
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
/// impulses so far, vn the normal velocities now. Where no case holds, x0 is kept. `zero` is 0 in
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

} // namespace impetus::solver
