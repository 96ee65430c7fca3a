#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/sensors/balance_board.hpp>

#include <limits>

namespace impetus::sensors {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

constexpr std::array<MotionRule, 6> bookRules{{
    {"right foot on", 0.25, 0.75, true, 0.01, 1.0},
    {"both feet on", 0.95, inf, true, -0.7, 0.7},
    {"left foot on", 0.25, 0.75, true, -1.0, -0.01},
    {"left thigh lifting", 1.0, inf, true, 0.01, 1.0},
    {"right thigh lifting", 1.0, inf, true, -1.0, -0.01},
    {"both feet off", -inf, 0.05, false, -1.0, 1.0},
}};

} // namespace

std::optional<Vec2d> centreOfGravity(std::span<const Vec2d> positions, std::span<const double> loads,
                                     double minimumTotal) {
  if (positions.size() != loads.size() || loads.empty()) {
    throwInvalid("loads", static_cast<double>(loads.size()), "must be one per cell position, at least one");
  }
  requireFinite(minimumTotal, "minimumTotal");
  double total = 0.0;
  Vec2d moment{};
  for (std::size_t k = 0; k < loads.size(); ++k) {
    requireFinite(loads[k], "loads");
    moment += requireFinite(positions[k], "positions") * loads[k];
    total += loads[k];
  }
  if (total <= minimumTotal || total <= 0.0) {
    return std::nullopt;
  }
  return moment / total;
}

std::array<Vec2d, 4> normalizedBoardCells() noexcept { return {{{1.0, 1.0}, {-1.0, 1.0}, {-1.0, -1.0}, {1.0, -1.0}}}; }

std::optional<Vec2d> boardCentreOfGravity(const std::array<double, 4>& loads, double minimumTotal) {
  const std::array<Vec2d, 4> cells = normalizedBoardCells();
  return centreOfGravity(cells, loads, minimumTotal);
}

std::span<const MotionRule> bookMotionRules() noexcept { return bookRules; }

std::string_view classifyMotion(double loadRatio, double cogX, std::span<const MotionRule> rules) {
  requireFinite(loadRatio, "loadRatio");
  requireFinite(cogX, "cogX");
  for (const MotionRule& r : rules) {
    if (!(loadRatio > r.minLoadRatio && loadRatio < r.maxLoadRatio)) {
      continue;
    }
    if (r.usesCog && !(cogX >= r.minCogX && cogX <= r.maxCogX)) {
      continue;
    }
    return r.motion;
  }
  return {};
}

} // namespace impetus::sensors
