#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/sensors/touch_calibration.hpp>

#include <cmath>

namespace impetus::sensors {

TouchCalibration TouchCalibration::fit(std::span<const Vec2d> raw, std::span<const Vec2d> screen) {
  if (raw.size() != screen.size()) {
    throwInvalid("points", static_cast<double>(screen.size()), "screen points must match the raw points in number");
  }
  if (raw.size() < 3) {
    throwInvalid("points", static_cast<double>(raw.size()), "needs at least 3 reference touches");
  }
  // Centre both point sets: the normal equations of the centred problem decouple the offset and
  // are far better conditioned (raw ADC counts are ~2000, their squares ~4e6).
  const double n = static_cast<double>(raw.size());
  Vec2d rawMean{};
  Vec2d screenMean{};
  for (std::size_t i = 0; i < raw.size(); ++i) {
    rawMean += requireFinite(raw[i], "raw");
    screenMean += requireFinite(screen[i], "screen");
  }
  rawMean /= n;
  screenMean /= n;
  // Normal equations of the linear part: [Sxx Sxy; Sxy Syy] [a; b] = [Sxu; Syu], etc.
  double sxx = 0.0, sxy = 0.0, syy = 0.0, sxu = 0.0, syu = 0.0, sxv = 0.0, syv = 0.0;
  double spread = 0.0;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const Vec2d r = raw[i] - rawMean;
    const Vec2d s = screen[i] - screenMean;
    sxx += r.x * r.x;
    sxy += r.x * r.y;
    syy += r.y * r.y;
    sxu += r.x * s.x;
    syu += r.y * s.x;
    sxv += r.x * s.y;
    syv += r.y * s.y;
    spread += lengthSquared(r);
  }
  const double det = sxx * syy - sxy * sxy;
  // det / spread^2 is sin^2 of how far the points are from a line (0 collinear, up to 1/4).
  if (!(det > 1e-12 * spread * spread)) {
    throwInvalid("raw", det, "reference touches are in a line (or coincide): the map is not determined");
  }
  TouchCalibration c;
  c.a_ = (syy * sxu - sxy * syu) / det;
  c.b_ = (sxx * syu - sxy * sxu) / det;
  c.d_ = (syy * sxv - sxy * syv) / det;
  c.e_ = (sxx * syv - sxy * sxv) / det;
  c.c_ = screenMean.x - c.a_ * rawMean.x - c.b_ * rawMean.y;
  c.f_ = screenMean.y - c.d_ * rawMean.x - c.e_ * rawMean.y;
  return c;
}

} // namespace impetus::sensors
