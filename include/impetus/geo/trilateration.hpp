// Trilateration (ch. 22): a position from distances to known points, as GPS finds the receiver
// from its ranges to the satellites.
//
// Closed forms (the book's circles): in a frame with centre 1 at the origin, centre 2 at (d, 0)
// and centre 3 at (i, j),
//   x = (r1^2 - r2^2 + d^2) / (2 d),  y = (r1^2 - r3^2 + i^2 + j^2) / (2 j) - (i/j) x,
// and in 3D z = +-sqrt(r1^2 - x^2 - y^2); the world point is S1 + x e_x + y e_y (+ z e_z) with
// e_x = (S2 - S1)/|S2 - S1|, e_y the unit part of S3 - S1 normal to e_x, e_z = e_x x e_y.
//
// With a receiver clock bias b (s) every measured range is off by the same c b: a pseudorange
//   rho_k = c (t_receive - t_transmit,k) = |P - S_k| + c b.
// The unknowns (P, c b) need one more satellite than the dimension (4 in 3D), and the equations
// are nonlinear (the book's ch. 23 calls them linear). solvePseudoranges minimises the squared
// residuals rho_k - (|P - S_k| + c b) by Gauss-Newton: Jacobian rows [(P - S_k)^T/|P - S_k|, 1],
// normal equations solved by Cholesky. Geometry that cannot be solved (too few satellites,
// satellites collinear (2D) or coplanar with the receiver (3D): a singular normal matrix, an
// infinite dilution of precision) is an impetus::Error naming "satellites", never NaN.
#pragma once

#include <impetus/core/constants.hpp>
#include <impetus/math/vec2.hpp>
#include <impetus/math/vec3.hpp>

#include <array>
#include <span>

namespace impetus::geo {

/// The point at distances ranges[k] (>= 0) from the three centres in the plane, by the closed
/// form above (circle 3 picks the sign of y). Throws impetus::Error naming "centres" when they
/// are collinear or coincide, "ranges" for a negative or non-finite range. Inconsistent ranges
/// (circles that do not meet at one point) give the closed form's least-committal answer: x
/// from circles 1 and 2, y from circles 1 and 3.
[[nodiscard]] Vec2d trilaterate(const std::array<Vec2d, 3>& centres, const std::array<double, 3>& ranges);

/// The two points at distances ranges[k] from three centres in space, mirror images through
/// the centres' plane: [0] on the side of e_z = e_x x e_y (e_x toward centre 2, e_y toward centre
/// 3), [1] on the other (equal when the point lies in the plane). Throws impetus::Error naming
/// "centres" (collinear) or "ranges" (negative, or spheres that do not meet: r1^2 - x^2 - y^2
/// below -1e-9 r1^2; slightly negative from rounding is taken as 0).
[[nodiscard]] std::array<Vec3d, 2> trilaterate(const std::array<Vec3d, 3>& centres,
                                               const std::array<double, 3>& ranges);

/// rho = |receiver - satellite| + c clockBias: the range a receiver whose clock is clockBias
/// (s) ahead measures, m.
[[nodiscard]] double pseudorange(const Vec3d& receiver, const Vec3d& satellite, double clockBias,
                                 double speedOfLight = constants::speedOfLight);

struct PseudorangeOptions {
  Vec3d initialPosition{};                       ///< start of the iteration, m (the Earth's centre works for GPS)
  double initialRangeBias = 0.0;                 ///< start for c b, m
  int maxIterations = 30;                        ///< > 0
  double tolerance = 1e-9;                       ///< stop when the step is below tolerance (1 + |P|), m
  double speedOfLight = constants::speedOfLight; ///< m/s, > 0: converts c b to b
};

struct PseudorangeFix {
  Vec3d position{};         ///< receiver, m (z = 0 for the 2D solver)
  double rangeBias = 0.0;   ///< c b, m
  double clockBias = 0.0;   ///< b = rangeBias / c, s
  int iterations = 0;       ///< Gauss-Newton steps taken
  double residualRms = 0.0; ///< sqrt(mean of squared residuals) at the fix, m
  /// Dilutions of precision from Q = (H^T H)^-1 at the fix (range-error units): geometric
  /// sqrt(tr Q), position sqrt(Q_xx + Q_yy (+ Q_zz)), time sqrt(Q_bb). Errors of sigma in the
  /// ranges give errors of about DOP sigma in the fix.
  double gdop = 0.0;
  double pdop = 0.0;
  double tdop = 0.0;
};

/// The receiver position and clock bias from pseudoranges (m) to satellites at known
/// positions (m), N >= 4, by Gauss-Newton. Throws impetus::Error naming "satellites" (fewer
/// than 4, or geometry that cannot be solved), "pseudoranges" (a count that differs, a value
/// that is not finite, or an iteration that does not converge) or the option at fault.
[[nodiscard]] PseudorangeFix solvePseudoranges(std::span<const Vec3d> satellites, std::span<const double> pseudoranges,
                                               const PseudorangeOptions& options = {});

/// The same in the plane (N >= 3): position (x, y, 0) and c b. initialPosition's z is ignored.
[[nodiscard]] PseudorangeFix solvePseudoranges(std::span<const Vec2d> satellites, std::span<const double> pseudoranges,
                                               const PseudorangeOptions& options = {});

} // namespace impetus::geo
