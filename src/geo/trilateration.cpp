#include <impetus/error.hpp>
#include <impetus/geo/trilateration.hpp>
#include <impetus/math/validate.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace impetus::geo {
namespace {

void requireRanges(const std::array<double, 3>& ranges) {
  for (const double r : ranges) {
    requireNonNegative(r, "ranges");
  }
}

/// A symmetric positive-definite system of at most 4 unknowns (position and c b), solved by
/// Cholesky. The smallest pivot relative to the largest diagonal entry measures how close the
/// geometry is to singular (0: some combination of unknowns is not observable).
struct Normal {
  static constexpr int maxSize = 4;
  int n = 0;
  std::array<std::array<double, maxSize>, maxSize> m{};
  std::array<std::array<double, maxSize>, maxSize> l{};
  double worstPivotRatio = 1.0;

  /// Factorises; false when a pivot is not positive (exactly singular or worse). The pivots
  /// are compared with the largest diagonal entry: the Jacobian's entries are direction
  /// cosines and 1, so that is the problem's own scale.
  bool factor() {
    worstPivotRatio = 1.0;
    double largest = 0.0;
    for (int j = 0; j < n; ++j) {
      largest = std::max(largest, m[j][j]);
    }
    for (int j = 0; j < n; ++j) {
      double pivot = m[j][j];
      for (int k = 0; k < j; ++k) {
        pivot -= l[j][k] * l[j][k];
      }
      if (!(pivot > 0.0)) {
        worstPivotRatio = 0.0;
        return false;
      }
      worstPivotRatio = std::min(worstPivotRatio, pivot / largest);
      l[j][j] = std::sqrt(pivot);
      for (int i = j + 1; i < n; ++i) {
        double s = m[i][j];
        for (int k = 0; k < j; ++k) {
          s -= l[i][k] * l[j][k];
        }
        l[i][j] = s / l[j][j];
      }
    }
    return true;
  }

  /// Solves M x = rhs in place with the factor.
  void solve(double* x) const {
    for (int i = 0; i < n; ++i) {
      double s = x[i];
      for (int k = 0; k < i; ++k) {
        s -= l[i][k] * x[k];
      }
      x[i] = s / l[i][i];
    }
    for (int i = n - 1; i >= 0; --i) {
      double s = x[i];
      for (int k = i + 1; k < n; ++k) {
        s -= l[k][i] * x[k];
      }
      x[i] = s / l[i][i];
    }
  }
};

/// Below this relative pivot the normal matrix is treated as singular: the geometry leaves a
/// direction unobserved (a dilution of precision above ~1e5).
constexpr double singularPivotRatio = 1e-10;

/// Gauss-Newton on the pseudorange residuals in `dim` (2 or 3) dimensions; the satellites as
/// 3D points (z = 0 in the plane).
PseudorangeFix solve(std::span<const Vec3d> satellites, std::span<const double> pseudoranges, int dim,
                     const PseudorangeOptions& options) {
  const std::size_t count = satellites.size();
  const int unknowns = dim + 1;
  if (count < static_cast<std::size_t>(unknowns)) {
    throwInvalid("satellites", static_cast<double>(count),
                 dim == 3 ? "need at least 4 satellites in 3D (position and clock bias)"
                          : "need at least 3 satellites in 2D (position and clock bias)");
  }
  if (pseudoranges.size() != count) {
    throwInvalid("pseudoranges", static_cast<double>(pseudoranges.size()), "must give one range per satellite");
  }
  double scale = 1.0;
  for (std::size_t k = 0; k < count; ++k) {
    const Vec3d& s = satellites[k];
    requireFinite(s, "satellites");
    requireFinite(pseudoranges[k], "pseudoranges");
    scale = std::max({scale, length(s), std::abs(pseudoranges[k])});
  }
  if (options.maxIterations <= 0) {
    throwInvalid("maxIterations", options.maxIterations, "must be positive");
  }
  requirePositive(options.tolerance, "tolerance");
  requirePositive(options.speedOfLight, "speedOfLight");
  const Vec3d& p0 = requireFinite(options.initialPosition, "initialPosition");
  requireFinite(options.initialRangeBias, "initialRangeBias");

  double x[4] = {p0.x, p0.y, dim == 3 ? p0.z : 0.0, options.initialRangeBias};
  const int biasIndex = dim; // unknowns: x, y, (z,) c b
  auto position = [&] { return Vec3d{x[0], x[1], dim == 3 ? x[2] : 0.0}; };

  Normal normal{};
  normal.n = unknowns;
  double residualSq = 0.0;
  // Builds the normal equations at the current iterate; false when the iterate sits on a
  // satellite (the Jacobian row, a unit vector, is undefined there).
  auto build = [&](double* rhs) {
    for (int i = 0; i < unknowns; ++i) {
      rhs[i] = 0.0;
      for (int j = 0; j < unknowns; ++j) {
        normal.m[i][j] = 0.0;
      }
    }
    residualSq = 0.0;
    const Vec3d p = position();
    for (std::size_t k = 0; k < count; ++k) {
      const Vec3d d = p - satellites[k];
      const double range = length(d);
      if (range < 1e-9 * scale) {
        return false;
      }
      double h[4] = {d.x / range, d.y / range, d.z / range, 0.0};
      h[biasIndex] = 1.0;
      const double r = pseudoranges[k] - (range + x[biasIndex]);
      residualSq += r * r;
      for (int i = 0; i < unknowns; ++i) {
        rhs[i] += h[i] * r;
        for (int j = 0; j < unknowns; ++j) {
          normal.m[i][j] += h[i] * h[j];
        }
      }
    }
    return true;
  };

  // Deterministic nudges off a degenerate iterate (on a satellite, or in the satellites' plane
  // where the out-of-plane direction is not observed to first order).
  const Vec3d nudges[3] = {{0.0, 0.0, 1.0}, {0.0, 1.0, 0.0}, {1.0, 0.0, 0.0}};
  int nudgesUsed = 0;
  auto nudge = [&] {
    const Vec3d n = nudges[dim == 3 ? nudgesUsed : nudgesUsed + 1]; // 2D: y, then x
    ++nudgesUsed;
    x[0] += 1e-3 * scale * n.x;
    x[1] += 1e-3 * scale * n.y;
    if (dim == 3) {
      x[2] += 1e-3 * scale * n.z;
    }
  };
  const int maxNudges = dim == 3 ? 3 : 2;
  auto unsolvable = [&] {
    throwInvalid("satellites", static_cast<double>(count),
                 "geometry cannot be solved: the satellites and the receiver leave a direction unobserved "
                 "(collinear in 2D, coplanar with the receiver in 3D; infinite dilution of precision)");
  };

  PseudorangeFix fix;
  bool converged = false;
  int iteration = 0;
  while (iteration < options.maxIterations) {
    double step[4] = {};
    if (!build(step) || !normal.factor() || normal.worstPivotRatio < singularPivotRatio) {
      if (nudgesUsed >= maxNudges) {
        unsolvable();
      }
      nudge();
      continue;
    }
    ++iteration;
    normal.solve(step);
    double stepSq = 0.0;
    for (int i = 0; i < unknowns; ++i) {
      x[i] += step[i];
      stepSq += step[i] * step[i];
    }
    if (std::sqrt(stepSq) < options.tolerance * (1.0 + length(position()))) {
      converged = true;
      break;
    }
  }
  double scratch[4] = {};
  const bool built = build(scratch) && normal.factor();
  if (!built || normal.worstPivotRatio < singularPivotRatio) {
    unsolvable();
  }
  if (!converged) {
    throwInvalid("pseudoranges", std::sqrt(residualSq / static_cast<double>(count)),
                 "Gauss-Newton did not converge (RMS residual given, m): inconsistent ranges or a poor start");
  }
  // Q = (H^T H)^-1, column by column.
  double q[4][4] = {};
  for (int c = 0; c < unknowns; ++c) {
    double e[4] = {};
    e[c] = 1.0;
    normal.solve(e);
    for (int r = 0; r < unknowns; ++r) {
      q[r][c] = e[r];
    }
  }
  double positionTrace = 0.0;
  for (int i = 0; i < dim; ++i) {
    positionTrace += q[i][i];
  }
  fix.position = position();
  fix.rangeBias = x[biasIndex];
  fix.clockBias = x[biasIndex] / options.speedOfLight;
  fix.iterations = iteration;
  fix.residualRms = std::sqrt(residualSq / static_cast<double>(count));
  fix.pdop = std::sqrt(positionTrace);
  fix.tdop = std::sqrt(q[biasIndex][biasIndex]);
  fix.gdop = std::sqrt(positionTrace + q[biasIndex][biasIndex]);
  return fix;
}

} // namespace

Vec2d trilaterate(const std::array<Vec2d, 3>& centres, const std::array<double, 3>& ranges) {
  for (const Vec2d& c : centres) {
    requireFinite(c, "centres");
  }
  requireRanges(ranges);
  const Vec2d s21 = centres[1] - centres[0];
  const Vec2d s31 = centres[2] - centres[0];
  const double d = length(s21);
  if (!(d > 0.0)) {
    throwInvalid("centres", d, "centres 1 and 2 coincide");
  }
  const Vec2d ex = s21 / d;
  const Vec2d ey{-ex.y, ex.x};
  const double i = dot(ex, s31);
  const double j = dot(ey, s31);
  if (!(std::abs(j) > 1e-12 * std::max(d, length(s31)))) {
    throwInvalid("centres", j, "are collinear: the mirror image of the point through their line fits as well");
  }
  const double r1 = ranges[0];
  const double r2 = ranges[1];
  const double r3 = ranges[2];
  const double x = (r1 * r1 - r2 * r2 + d * d) / (2.0 * d);
  const double y = (r1 * r1 - r3 * r3 + i * i + j * j) / (2.0 * j) - (i / j) * x;
  return centres[0] + ex * x + ey * y;
}

std::array<Vec3d, 2> trilaterate(const std::array<Vec3d, 3>& centres, const std::array<double, 3>& ranges) {
  for (const Vec3d& c : centres) {
    requireFinite(c, "centres");
  }
  requireRanges(ranges);
  const Vec3d s21 = centres[1] - centres[0];
  const Vec3d s31 = centres[2] - centres[0];
  const double d = length(s21);
  if (!(d > 0.0)) {
    throwInvalid("centres", d, "centres 1 and 2 coincide");
  }
  const Vec3d ex = s21 / d;
  const double i = dot(ex, s31);
  const Vec3d normalPart = s31 - ex * i;
  const double j = length(normalPart);
  if (!(j > 1e-12 * std::max(d, length(s31)))) {
    throwInvalid("centres", j, "are collinear: every point on a circle about their line fits");
  }
  const Vec3d ey = normalPart / j;
  const Vec3d ez = cross(ex, ey);
  const double r1 = ranges[0];
  const double r2 = ranges[1];
  const double r3 = ranges[2];
  const double x = (r1 * r1 - r2 * r2 + d * d) / (2.0 * d);
  const double y = (r1 * r1 - r3 * r3 + i * i + j * j) / (2.0 * j) - (i / j) * x;
  const double zSq = r1 * r1 - x * x - y * y;
  if (zSq < -1e-9 * std::max(r1 * r1, 1e-300)) {
    throwInvalid("ranges", zSq, "the three spheres do not meet (r1^2 - x^2 - y^2 given, m^2)");
  }
  const double z = std::sqrt(std::max(0.0, zSq));
  const Vec3d base = centres[0] + ex * x + ey * y;
  return {base + ez * z, base - ez * z};
}

double pseudorange(const Vec3d& receiver, const Vec3d& satellite, double clockBias, double speedOfLight) {
  requireFinite(receiver, "receiver");
  requireFinite(satellite, "satellite");
  requireFinite(clockBias, "clockBias");
  requirePositive(speedOfLight, "speedOfLight");
  const double r = distance(receiver, satellite);
  if (!std::isfinite(r)) {
    throwInvalid("satellite", r, "is too far from the receiver: the distance overflows a double");
  }
  return r + speedOfLight * clockBias;
}

PseudorangeFix solvePseudoranges(std::span<const Vec3d> satellites, std::span<const double> pseudoranges,
                                 const PseudorangeOptions& options) {
  return solve(satellites, pseudoranges, 3, options);
}

PseudorangeFix solvePseudoranges(std::span<const Vec2d> satellites, std::span<const double> pseudoranges,
                                 const PseudorangeOptions& options) {
  std::vector<Vec3d> flat;
  flat.reserve(satellites.size());
  for (const Vec2d& s : satellites) {
    flat.emplace_back(s.x, s.y, 0.0);
  }
  return solve(flat, pseudoranges, 2, options);
}

} // namespace impetus::geo
