// Projected-capacitive (mutual-capacitance) touch screens (ch. 20): from a scanned grid of
// capacitance changes to touch positions finer than the grid.
//
// Rows and columns of transparent electrodes cross under the glass; each crossing is a small
// capacitor. The controller scans them one row (or column) at a time, so it reads every crossing
// independently, and a finger near a crossing steals part of its field: the reading drops by
// DeltaC. The scan is an image of DeltaC; each finger is a blob a few cells wide (a fingertip is
// ~7-10 mm, a typical pitch 4-5 mm). A blob's position is its weighted centroid
//   p = sum_ij w_ij c_ij / sum_ij w_ij,   w_ij = DeltaC_ij - threshold    (c_ij the centre of cell ij)
// which places the touch between the electrodes: sub-cell resolution from a coarse grid (the
// same weighted average as the balance board's centre of gravity, balance_board.hpp). Weighing
// by DeltaC above the threshold rather than DeltaC itself means a cell that crosses the threshold
// as the finger moves enters the average with no weight, so the position does not jump; for a
// Gaussian finger profile it is about 4 times more accurate (0.5 % of a pitch against 2 % in the
// tests).
//
// Cells above the threshold are grouped by hill climbing: each climbs to its highest neighbour
// (8 around it) until it reaches a peak, and the cells that reach the same peak form one touch.
// Two fingers close enough to merge into one connected region still give two touches as long
// as there is a dip between their peaks.
#pragma once

#include <impetus/math/vec2.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace impetus::sensors {

struct GridGeometry {
  int rows = 16;          ///< electrodes along y (> 0)
  int columns = 9;        ///< electrodes along x (> 0)
  double pitchX = 4.5e-3; ///< spacing of the columns, m (> 0)
  double pitchY = 4.5e-3; ///< spacing of the rows, m (> 0)
  Vec2d origin{};         ///< corner of cell (0, 0), m; cell (i, j) is centred at origin + ((j+1/2) px, (i+1/2) py)

  [[nodiscard]] Vec2d cellCentre(int row, int column) const noexcept {
    return {origin.x + (column + 0.5) * pitchX, origin.y + (row + 0.5) * pitchY};
  }
};

struct GridTouch {
  Vec2d position;    ///< weighted centroid (weights DeltaC - threshold), m
  double signal = 0; ///< sum of DeltaC over the blob (any unit; grows with the contact area)
  double peak = 0;   ///< the largest DeltaC of the blob
  int row = 0;       ///< the peak cell
  int column = 0;
  int cells = 0; ///< cells in the blob
};

/// The touches in one scan. `deltas` holds rows x columns values DeltaC >= 0 row by row
/// (row 0 first); cells with DeltaC > threshold take part. Touches come strongest first (ties
/// by peak cell). Throws impetus::Error: "deltas" when the size does not match the geometry or a
/// value is not finite, "rows"/"columns"/"pitchX"/"pitchY" for a bad geometry, "threshold" when
/// negative.
[[nodiscard]] std::vector<GridTouch> findGridTouches(std::span<const double> deltas, const GridGeometry& geometry,
                                                     double threshold);

/// A scan of fingers modelled as Gaussian bumps DeltaC = amplitude exp(-r^2 / (2 sigma^2)) at
/// `centres` (m), summed: for simulations, samples and tests. sigma > 0 m.
[[nodiscard]] std::vector<double> simulateGridScan(const GridGeometry& geometry, std::span<const Vec2d> centres,
                                                   double amplitude, double sigma);

} // namespace impetus::sensors
