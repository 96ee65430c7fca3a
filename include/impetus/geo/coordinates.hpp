// Geographic coordinates (ch. 22): latitude and longitude in degrees, as a GPS receiver reports
// them and as the book's Coordinate2D {lat, longi} holds them.
//
// Latitude phi is the angle north (+) or south (-) of the equator, -90..90 degrees; longitude
// lambda the angle east (+) or west (-) of the prime meridian (Greenwich). A meridian is a line
// of constant longitude (the book says latitude). Every function of the geo layer checks its
// points: a latitude outside [-90, 90] or a non-finite value is an impetus::Error naming the
// point and the field ("from.latitude = 91: ..."); longitudes may be any finite value and are
// wrapped to [-180, 180).
#pragma once

#include <string_view>

namespace impetus::geo {

/// A point on the Earth's surface, degrees.
struct LatLon {
  double latitude = 0.0;  ///< degrees north, -90..90
  double longitude = 0.0; ///< degrees east, any finite value (wrapped to [-180, 180) where returned)
};

/// The book's Earth radius, m: a sphere of 6371 km (its haversine and rhumb-line listings).
inline constexpr double bookEarthRadius = 6.371e6;

/// Throws impetus::Error naming "<name>.latitude" or "<name>.longitude" unless the latitude is
/// finite and within [-90, 90] degrees and the longitude finite.
void requireValid(const LatLon& point, std::string_view name);

/// lambda wrapped to [-180, 180) degrees (finite input).
[[nodiscard]] double wrapLongitude(double degrees) noexcept;

/// A compass bearing: degrees clockwise from north wrapped to [0, 360) (finite input).
[[nodiscard]] double wrapBearing(double degrees) noexcept;

} // namespace impetus::geo
