#include <impetus/error.hpp>
#include <impetus/geo/coordinates.hpp>

#include <cmath>
#include <string>

namespace impetus::geo {

void requireValid(const LatLon& point, std::string_view name) {
  const std::string prefix(name);
  if (!(std::isfinite(point.latitude) && point.latitude >= -90.0 && point.latitude <= 90.0)) {
    throwInvalid(prefix + ".latitude", point.latitude, "must be a finite latitude within [-90, 90] degrees");
  }
  if (!std::isfinite(point.longitude)) {
    throwInvalid(prefix + ".longitude", point.longitude, "must be finite (degrees)");
  }
}

double wrapLongitude(double degrees) noexcept {
  double w = std::fmod(degrees + 180.0, 360.0);
  if (w < 0.0) {
    w += 360.0;
  }
  // fmod of a value just below a multiple of 360 plus 360 can round to 360 exactly.
  return w >= 360.0 ? -180.0 : w - 180.0;
}

double wrapBearing(double degrees) noexcept {
  double w = std::fmod(degrees, 360.0);
  if (w < 0.0) {
    w += 360.0;
  }
  return w >= 360.0 ? 0.0 : w + 0.0; // + 0.0: -0 becomes 0
}

} // namespace impetus::geo
