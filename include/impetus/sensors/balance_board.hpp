// The four-cell balance board (ch. 23): centre of gravity and body motions from load cells.
//
// Nintendo's Wii Balance Board stands on four load cells, one under each corner. The person's
// weight splits between them by statics (the sum of the moments about the centre of gravity is
// zero), so the centre of gravity over the board is the load-weighted mean of the cells'
// positions:
//   x = sum W_k x_k / sum W_k,   y = sum W_k y_k / sum W_k.
// The book's example: cells at (1, 1), (-1, 1), (-1, -1), (1, -1) reading 30, 15, 20 and 35
// (total 100) put it at (0.30, -0.10), towards the lower right. With the true cell coordinates
// (m) the result is in m; with the corners at +-1 it is normalized to [-1, 1].
//
// Nintendo's patent tells motions apart from the load ratio (total over the body weight) and the
// normalized x of the centre of gravity (the book's Table 23-3). The rules overlap, so they form
// an ordered table: the first rule that matches wins.
#pragma once

#include <impetus/math/vec2.hpp>

#include <array>
#include <optional>
#include <span>
#include <string_view>

namespace impetus::sensors {

/// The load-weighted mean of `positions`, or none when the total load is at or below
/// `minimumTotal` (nobody on the board). Loads may be slightly negative (noise around a tared
/// zero). Throws impetus::Error: "loads" when the sizes differ, the spans are empty or a value is
/// not finite, "positions" when a position is not finite.
[[nodiscard]] std::optional<Vec2d> centreOfGravity(std::span<const Vec2d> positions, std::span<const double> loads,
                                                   double minimumTotal = 0.0);

/// The book's board: cells at (1, 1), (-1, 1), (-1, -1), (1, -1) (top right, top left, bottom
/// left, bottom right) and the normalized centre of gravity of their loads.
[[nodiscard]] std::array<Vec2d, 4> normalizedBoardCells() noexcept;
[[nodiscard]] std::optional<Vec2d> boardCentreOfGravity(const std::array<double, 4>& loads, double minimumTotal = 0.0);

struct MotionRule {
  std::string_view motion;
  double minLoadRatio = 0.0; ///< total load / body weight, exclusive bound
  double maxLoadRatio = 0.0; ///< exclusive bound (infinity: none)
  bool usesCog = true;       ///< false: the centre of gravity is not looked at
  double minCogX = -1.0;     ///< inclusive, normalized
  double maxCogX = 1.0;      ///< inclusive
};

/// Table 23-3 in the book's order: right foot on (25-75 %, x in [+0.01, +1]), both feet on
/// (> 95 %, [-0.7, +0.7]), left foot on (25-75 %, [-1, -0.01]), left thigh lifting (> 100 %,
/// [+0.01, +1]), right thigh lifting (> 100 %, [-1, -0.01]), both feet off (< 5 %).
[[nodiscard]] std::span<const MotionRule> bookMotionRules() noexcept;

/// The first rule matching the load ratio and normalized x, or "" when none does. Throws
/// impetus::Error naming "loadRatio" or "cogX" when not finite.
[[nodiscard]] std::string_view classifyMotion(double loadRatio, double cogX,
                                              std::span<const MotionRule> rules = bookMotionRules());

} // namespace impetus::sensors
