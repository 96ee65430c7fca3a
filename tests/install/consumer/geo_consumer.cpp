// Links the installed impetus::geo (GeographicLib underneath) and checks one geodesic.
#include <impetus/geo/geodesic.hpp>

#include <cmath>
#include <cstdio>

int main() {
  using namespace impetus::geo;
  // One degree of longitude along the WGS 84 equator is an arc of the equatorial circle:
  // 2 pi a / 360 with a = 6378137 m, 111319.490793 m. GeographicLib is accurate to ~15 nm;
  // 1 mm of tolerance only catches a wrong link, not rounding.
  const GeodesicResult r = geodesicInverse({0.0, 0.0}, {0.0, 1.0});
  const double expected = 2.0 * 3.14159265358979323846 * 6378137.0 / 360.0;
  std::printf("geodesic along the equator over 1 degree: %.6f m (expected %.6f m)\n", r.distance, expected);
  return std::fabs(r.distance - expected) < 1e-3 ? 0 : 1;
}
