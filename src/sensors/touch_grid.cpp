#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/sensors/touch_grid.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace impetus::sensors {
namespace {

void requireGeometry(const GridGeometry& g) {
  if (g.rows < 1 || g.rows > 4096) {
    throwInvalid("rows", g.rows, "must be between 1 and 4096");
  }
  if (g.columns < 1 || g.columns > 4096) {
    throwInvalid("columns", g.columns, "must be between 1 and 4096");
  }
  requirePositive(g.pitchX, "pitchX");
  requirePositive(g.pitchY, "pitchY");
  requireFinite(g.origin, "origin");
}

std::size_t findRoot(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

} // namespace

std::vector<GridTouch> findGridTouches(std::span<const double> deltas, const GridGeometry& geometry, double threshold) {
  requireGeometry(geometry);
  requireNonNegative(threshold, "threshold");
  const int rows = geometry.rows;
  const int cols = geometry.columns;
  const auto cellCount = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  if (deltas.size() != cellCount) {
    throwInvalid("deltas", static_cast<double>(deltas.size()), "must hold rows x columns values");
  }
  for (const double d : deltas) {
    requireFinite(d, "deltas");
  }
  const auto index = [cols](int r, int c) {
    return static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c);
  };
  // Each active cell points at its highest active neighbour (itself when none is higher: a
  // peak). Neighbours of equal height that are both peaks are joined below, so a flat top is one
  // touch.
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> up(cellCount, none);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const std::size_t i = index(r, c);
      if (!(deltas[i] > threshold)) {
        continue;
      }
      std::size_t best = i;
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          const int rr = r + dr;
          const int cc = c + dc;
          if ((dr == 0 && dc == 0) || rr < 0 || rr >= rows || cc < 0 || cc >= cols) {
            continue;
          }
          const std::size_t j = index(rr, cc);
          if (deltas[j] > deltas[best]) {
            best = j;
          }
        }
      }
      up[i] = best;
    }
  }
  // Peaks: union the adjacent ones of equal height.
  std::vector<std::size_t> parent(cellCount);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const std::size_t i = index(r, c);
      if (up[i] != i) {
        continue;
      }
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          const int rr = r + dr;
          const int cc = c + dc;
          if (rr < 0 || rr >= rows || cc < 0 || cc >= cols) {
            continue;
          }
          const std::size_t j = index(rr, cc);
          if (j != i && up[j] == j && deltas[j] == deltas[i]) {
            parent[findRoot(parent, std::max(i, j))] = findRoot(parent, std::min(i, j));
          }
        }
      }
    }
  }
  // Follow each cell up to its peak and accumulate the weighted centroid per peak.
  std::vector<std::size_t> blobOf(cellCount, none);
  std::vector<GridTouch> touches;
  std::vector<Vec2d> weighted;
  std::vector<double> weights;
  for (std::size_t i = 0; i < cellCount; ++i) {
    if (up[i] == none) {
      continue;
    }
    std::size_t p = i;
    while (up[p] != p) {
      p = up[p]; // strictly increasing DeltaC: terminates
    }
    const std::size_t root = findRoot(parent, p);
    if (blobOf[root] == none) {
      blobOf[root] = touches.size();
      GridTouch t;
      t.row = static_cast<int>(root / static_cast<std::size_t>(cols));
      t.column = static_cast<int>(root % static_cast<std::size_t>(cols));
      t.peak = deltas[root];
      touches.push_back(t);
      weighted.push_back({});
      weights.push_back(0.0);
    }
    GridTouch& t = touches[blobOf[root]];
    const int r = static_cast<int>(i / static_cast<std::size_t>(cols));
    const int c = static_cast<int>(i % static_cast<std::size_t>(cols));
    weighted[blobOf[root]] += geometry.cellCentre(r, c) * (deltas[i] - threshold);
    weights[blobOf[root]] += deltas[i] - threshold;
    t.signal += deltas[i];
    t.cells += 1;
  }
  for (std::size_t k = 0; k < touches.size(); ++k) {
    touches[k].position = weighted[k] / weights[k]; // > 0: every cell is above the threshold
  }
  std::stable_sort(touches.begin(), touches.end(), [](const GridTouch& a, const GridTouch& b) {
    if (a.signal != b.signal) {
      return a.signal > b.signal;
    }
    return a.row != b.row ? a.row < b.row : a.column < b.column;
  });
  return touches;
}

std::vector<double> simulateGridScan(const GridGeometry& geometry, std::span<const Vec2d> centres, double amplitude,
                                     double sigma) {
  requireGeometry(geometry);
  requireNonNegative(amplitude, "amplitude");
  requirePositive(sigma, "sigma");
  for (const Vec2d& c : centres) {
    requireFinite(c, "centres");
  }
  std::vector<double> scan(static_cast<std::size_t>(geometry.rows) * static_cast<std::size_t>(geometry.columns), 0.0);
  std::size_t k = 0;
  for (int r = 0; r < geometry.rows; ++r) {
    for (int c = 0; c < geometry.columns; ++c, ++k) {
      for (const Vec2d& centre : centres) {
        const double d2 = lengthSquared(geometry.cellCentre(r, c) - centre);
        scan[k] += amplitude * std::exp(-d2 / (2.0 * sigma * sigma));
      }
    }
  }
  return scan;
}

} // namespace impetus::sensors
