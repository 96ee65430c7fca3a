// The world's coastlines for the map samples: Natural Earth's 1:110m countries with the land
// borders removed (public domain; tools/make_coastlines.py made coastlines_data.cpp from the copy
// Debian ships in python3-geopandas).
#pragma once

#include <cstdint>
#include <span>

namespace impetus::samples {

/// A point of a coastline, in hundredths of a degree.
struct CoastPoint {
  std::int16_t longitude;
  std::int16_t latitude;
};

/// Every coastline's points, one polyline after another.
std::span<const CoastPoint> coastPoints();
/// Where each polyline starts in coastPoints(), and one past the last: line i is
/// [starts[i], starts[i + 1]).
std::span<const int> coastLineStarts();

} // namespace impetus::samples
