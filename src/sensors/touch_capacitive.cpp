#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/sensors/touch_capacitive.hpp>

namespace impetus::sensors {

std::optional<Vec2d> surfaceCapacitivePosition(const CornerCurrents& currents, double width, double height,
                                               double minimumTotal) {
  requireNonNegative(currents.upperLeft, "upperLeft");
  requireNonNegative(currents.upperRight, "upperRight");
  requireNonNegative(currents.lowerLeft, "lowerLeft");
  requireNonNegative(currents.lowerRight, "lowerRight");
  requirePositive(width, "width");
  requirePositive(height, "height");
  requireNonNegative(minimumTotal, "minimumTotal");
  const double total = currents.upperLeft + currents.upperRight + currents.lowerLeft + currents.lowerRight;
  if (total <= minimumTotal) {
    return std::nullopt;
  }
  return Vec2d{width * (currents.upperRight + currents.lowerRight) / total,
               height * (currents.upperLeft + currents.upperRight) / total};
}

CornerCurrents surfaceCapacitiveCurrents(const Vec2d& position, double width, double height, double total) {
  requireFinite(position, "position");
  requirePositive(width, "width");
  requirePositive(height, "height");
  requireNonNegative(total, "total");
  const double fx = position.x / width;  // share of the right-hand corners
  const double fy = position.y / height; // share of the upper corners
  if (fx < 0.0 || fx > 1.0) {
    throwInvalid("position.x", position.x, "must lie on the panel, in [0, width]");
  }
  if (fy < 0.0 || fy > 1.0) {
    throwInvalid("position.y", position.y, "must lie on the panel, in [0, height]");
  }
  return {total * (1.0 - fx) * fy, total * fx * fy, total * (1.0 - fx) * (1.0 - fy), total * fx * (1.0 - fy)};
}

} // namespace impetus::sensors
