#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/sensors/tilt.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace impetus::sensors {

double tiltAngle(double ax, double ay) {
  requireFinite(ax, "ax");
  requireFinite(ay, "ay");
  if (ax == 0.0 && ay == 0.0) {
    throwInvalid("ay", ay, "and ax are both zero: no gravity in the screen's plane, no tilt angle");
  }
  // atan2(x, y): measured from +y (upright) towards +x. With x to the right, +x "up" means the
  // device turned counter-clockwise (to the left).
  const double deg = radToDeg(std::atan2(ax, ay));
  const double wrapped = deg < 0.0 ? deg + 360.0 : deg;
  return wrapped >= 360.0 ? 0.0 : wrapped; // -tiny + 360 rounds to 360
}

double angle360(double ax, double ay) {
  requireFinite(ax, "ax");
  requireFinite(ay, "ay");
  if (ax == 0.0 && ay == 0.0) {
    throwInvalid("ay", ay, "and ax are both zero: no angle");
  }
  const double deg = radToDeg(std::atan2(ay, ax));
  const double wrapped = deg < 0.0 ? deg + 360.0 : deg;
  return wrapped >= 360.0 ? 0.0 : wrapped;
}

double bookFind2dAngle(double ax, double ay) noexcept {
  // The listing: alpha = atan2(y, x); if alpha >= 0 -> alpha * 180 / PI, else -alpha * 180 / PI + 180
  // (with PI = 3.14159, as printed).
  constexpr double bookPi = 3.14159;
  const double alpha = std::atan2(ay, ax);
  return alpha >= 0.0 ? alpha * 180.0 / bookPi : -alpha * 180.0 / bookPi + 180.0;
}

Tilt tiltFromGravity(const Vec3d& reading, AccelConvention convention) {
  requireFinite(reading, "reading");
  if (lengthSquared(reading) == 0.0) {
    throwInvalid("reading", 0.0, "is zero (free fall): no gravity, no tilt");
  }
  const Vec3d f = toSpecificForce(reading, convention);
  Tilt t;
  t.roll = std::atan2(f.y, f.z);
  t.pitch = std::atan2(-f.x, std::hypot(f.y, f.z));
  return t;
}

Vec3d gravityReading(const Tilt& tilt, AccelConvention convention) {
  requireFinite(tilt.pitch, "pitch");
  requireFinite(tilt.roll, "roll");
  const Vec3d f{-std::sin(tilt.pitch), std::sin(tilt.roll) * std::cos(tilt.pitch),
                std::cos(tilt.roll) * std::cos(tilt.pitch)};
  return toSpecificForce(f, convention); // the map is its own inverse
}

GrossOrientation grossOrientation(const Vec3d& readingG, AccelConvention convention, double deadBand) {
  requireFinite(readingG, "reading");
  requireNonNegative(deadBand, "deadBand");
  // In the book's (gravity-direction) terms: face down reads z = +1, right side down x = +1,
  // standing on its bottom y = -1.
  const Vec3d g = convention == AccelConvention::gravityDirection ? readingG : -readingG;
  const std::array<double, 3> mag{std::abs(g.x), std::abs(g.y), std::abs(g.z)};
  const auto axis = static_cast<int>(std::max_element(mag.begin(), mag.end()) - mag.begin());
  std::array<double, 3> others = mag;
  others[static_cast<std::size_t>(axis)] = 0.0;
  const double largest = mag[static_cast<std::size_t>(axis)];
  const double next = std::max({others[0], others[1], others[2]});
  if (largest < 0.5 || largest - next < deadBand) {
    return GrossOrientation::unknown;
  }
  const bool positive = g[axis] > 0.0;
  switch (axis) {
  case 0:
    return positive ? GrossOrientation::rightSideDown : GrossOrientation::leftSideDown;
  case 1:
    return positive ? GrossOrientation::topDown : GrossOrientation::bottomDown;
  default:
    return positive ? GrossOrientation::faceDown : GrossOrientation::faceUp;
  }
}

const char* toString(GrossOrientation orientation) noexcept {
  switch (orientation) {
  case GrossOrientation::faceUp:
    return "face up";
  case GrossOrientation::faceDown:
    return "face down";
  case GrossOrientation::rightSideDown:
    return "right side down";
  case GrossOrientation::leftSideDown:
    return "left side down";
  case GrossOrientation::bottomDown:
    return "standing, bottom down";
  case GrossOrientation::topDown:
    return "standing, top down";
  case GrossOrientation::unknown:
    break;
  }
  return "unknown";
}

} // namespace impetus::sensors
