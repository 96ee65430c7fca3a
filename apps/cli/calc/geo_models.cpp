// `impetus calc` entries for GPS and geodesy (ch. 22): great-circle distance and headings,
// destination, cross-track, rhumb lines, Vincenty (and GeographicLib's geodesic when
// impetus::geo is built), geodetic <-> ECEF, trilateration and the GPS fix with clock bias,
// and what a clock error costs in range. Points are given as "lat,lon" in degrees.
#include "calc/calc.hpp"
#include "calc/values.hpp"

#include <impetus/core/constants.hpp>
#include <impetus/error.hpp>
#include <impetus/geo/geo.hpp>
#include <impetus/math/validate.hpp>
#if IMPETUS_HAVE_GEO
#include <impetus/geo/geodesic.hpp>
#endif

#include <algorithm>
#include <array>
#include <span>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace impetus::cli {
namespace {

using namespace impetus::geo;

constexpr const char* topic = "GPS and geodesy (ch. 22)";

/// Numbers separated by commas, semicolons or spaces.
std::vector<double> parseNumbers(const std::string& name, const std::string& text) {
  std::string normalized = text;
  std::replace_if(
      normalized.begin(), normalized.end(), [](char c) { return c == ',' || c == ';'; }, ' ');
  std::istringstream in(normalized);
  std::vector<double> values;
  for (std::string token; in >> token;) {
    values.push_back(parseParameter(name, token));
  }
  return values;
}

LatLon latLon(const Args& a, const std::string& name) {
  const std::vector<double> v = parseNumbers(name, a.text(name));
  if (v.size() != 2) {
    throw Error(name, "--" + name + " = '" + a.text(name) + "': expected lat,lon in degrees");
  }
  return {v[0], v[1]};
}

Param pointParam(std::string name, std::string help, std::optional<std::string> defaultValue = std::nullopt) {
  return {std::move(name), "deg", std::move(help) + " as lat,lon (north, east positive)", std::move(defaultValue),
          ParamKind::text};
}

Param radiusParam() {
  return {"radius", "m", "sphere radius (mean Earth radius R1; the book's is 6371000)", std::string("6371008.8")};
}

Vector latLonVector(const LatLon& p) { return {p.latitude, p.longitude}; }

Result greatCircle(const Args& a) {
  const LatLon from = latLon(a, "from");
  const LatLon to = latLon(a, "to");
  const double radius = a.number("radius");
  Result r;
  r.add("distance", haversineDistance(from, to, radius), "m", "haversine: R 2 atan2(sqrt a, sqrt(1 - a))");
  r.add("distance_law_of_cosines", sphericalLawOfCosinesDistance(from, to, radius), "m",
        "R acos(sin phi1 sin phi2 + cos phi1 cos phi2 cos dlambda): ill-conditioned for short distances");
  r.add("central_angle", haversineAngle(from, to) * 180.0 / pi<double>, "deg");
  r.add("initial_bearing", initialBearing(from, to), "deg", "compass, clockwise from north");
  r.add("final_bearing", finalBearing(from, to), "deg", "on arrival");
  if (haversineAngle(from, to) < pi<double> - 1e-9) {
    r.add("midpoint", latLonVector(intermediatePoint(from, to, 0.5)), "deg",
          "lat, lon half way along the great circle");
  }
  return r;
}

Result destinationModel(const Args& a) {
  const LatLon from = latLon(a, "from");
  const double bearing = a.number("bearing");
  const double distance = a.number("distance");
  const double radius = a.number("radius");
  Result r;
  r.add("great_circle", latLonVector(destination(from, bearing, distance, radius)), "deg",
        "lat, lon: leaving at the bearing along the great circle");
  r.add("rhumb_line", latLonVector(rhumbDestination(from, bearing, distance, radius)), "deg",
        "lat, lon: holding the bearing (loxodrome)");
  return r;
}

Result crossTrack(const Args& a) {
  const LatLon start = latLon(a, "start");
  const LatLon end = latLon(a, "end");
  const LatLon point = latLon(a, "point");
  const double radius = a.number("radius");
  Result r;
  r.add("cross_track", crossTrackDistance(start, end, point, radius), "m",
        "signed distance from the great circle, + right of travel");
  r.add("along_track", alongTrackDistance(start, end, point, radius), "m",
        "from start to the foot of the perpendicular");
  r.add("within_range", withinRange(point, end, a.number("range"), radius), "",
        "reverse geocaching: point within --range of end");
  return r;
}

Result rhumb(const Args& a) {
  const LatLon from = latLon(a, "from");
  const LatLon to = latLon(a, "to");
  const double radius = a.number("radius");
  Result r;
  const double d = rhumbDistance(from, to, radius);
  const double gc = haversineDistance(from, to, radius);
  r.add("distance", d, "m", "R sqrt(dphi^2 + q^2 dlambda^2), q = dphi/dpsi");
  r.add("bearing", rhumbBearing(from, to), "deg", "constant compass bearing atan2(dlambda, dpsi)");
  r.add("great_circle_distance", gc, "m");
  r.add("longer_by", gc > 0.0 ? d / gc - 1.0 : 0.0, "", "fraction longer than the great circle");
  r.notes.emplace_back("the book's listing writes tan(pi/4 + phi1) (no /2): wrong off the equator and a domain error "
                       "from 45 degrees up; this is the corrected formula, exact to the poles");
  return r;
}

// Checked here under the parameters' own names (the library names them ellipsoid.*).
Ellipsoid ellipsoidArgs(const Args& a) {
  return {requireFinite(a.number("equatorial-radius"), "equatorialRadius"),
          requireFinite(a.number("flattening"), "flattening")};
}

std::vector<Param> ellipsoidParams() {
  return {{"equatorial-radius", "m", "ellipsoid's a (WGS 84)", std::string("6378137")},
          {"flattening", "", "ellipsoid's f (WGS 84: 1/298.257223563)", std::string("0.0033528106647474805")}};
}

Result vincenty(const Args& a) {
  const LatLon from = latLon(a, "from");
  const LatLon to = latLon(a, "to");
  const Ellipsoid e = ellipsoidArgs(a);
  Result r;
  const std::optional<VincentyResult> v = vincentyInverse(from, to, e);
  // A script reads `distance` whatever the points: where Vincenty's iteration fails (nearly
  // antipodal points) the answer is the exact geodesic, said in `method`; a build without
  // GeographicLib has none to give and refuses the pair.
#if IMPETUS_HAVE_GEO
  const GeodesicResult g = geodesicInverse(from, to, e);
#endif
  r.add("converged", v.has_value(), "", "false for nearly antipodal points");
  if (v) {
    r.add("method", std::string("vincenty"), "", "what gave the distance and azimuths");
    r.add("distance", v->distance, "m", "along the ellipsoid");
    r.add("initial_azimuth", v->initialAzimuth, "deg");
    r.add("final_azimuth", v->finalAzimuth, "deg");
    r.add("iterations", static_cast<double>(v->iterations));
  } else {
#if IMPETUS_HAVE_GEO
    r.add("method", std::string("geodesic"), "", "Vincenty did not converge: GeographicLib's geodesic instead");
    r.add("distance", g.distance, "m", "along the ellipsoid (the geodesic)");
    r.add("initial_azimuth", g.initialAzimuth, "deg");
    r.add("final_azimuth", g.finalAzimuth, "deg");
    r.notes.emplace_back("Vincenty's iteration does not converge for these nearly antipodal points; the distance and "
                         "azimuths are the geodesic's (GeographicLib, Karney)");
#else
    throw Error("to", "to = " + a.text("to") + ": nearly antipodal to --from " + a.text("from") +
                          ", where Vincenty's iteration does not converge (a build with GeographicLib answers with "
                          "the geodesic)");
#endif
  }
#if IMPETUS_HAVE_GEO
  r.add("geodesic_distance", g.distance, "m", "GeographicLib (Karney), the reference");
  if (v) {
    r.add("difference", v->distance - g.distance, "m", "Vincenty minus geodesic");
  }
#endif
  return r;
}

#if IMPETUS_HAVE_GEO
Result geodesic(const Args& a) {
  const LatLon from = latLon(a, "from");
  const LatLon to = latLon(a, "to");
  const Ellipsoid e = ellipsoidArgs(a);
  const GeodesicResult g = geodesicInverse(from, to, e);
  Result r;
  r.add("distance", g.distance, "m", "shortest path on the ellipsoid (GeographicLib)");
  r.add("initial_azimuth", g.initialAzimuth, "deg");
  r.add("final_azimuth", g.finalAzimuth, "deg");
  const RhumbResult rh = rhumbInverse(from, to, e);
  r.add("rhumb_distance", rh.distance, "m", "rhumb line on the ellipsoid");
  r.add("rhumb_bearing", rh.bearing, "deg");
  r.add("haversine_distance", haversineDistance(from, to), "m", "sphere of radius R1, for comparison");
  return r;
}
#endif

Result ecef(const Args& a) {
  const LatLon p = latLon(a, "position");
  const Vec3d x = geodeticToEcef({p, requireFinite(a.number("height"), "height")}, ellipsoidArgs(a));
  Result r;
  r.add("ecef", toVector(x), "m", "Earth-centred, Earth-fixed x, y, z");
  return r;
}

Result geodetic(const Args& a) {
  const GeodeticPosition g = ecefToGeodetic(vector3(a, "ecef"), ellipsoidArgs(a));
  Result r;
  r.add("position", latLonVector(g.point), "deg", "lat, lon");
  r.add("height", g.height, "m", "above the ellipsoid");
  return r;
}

/// Points as "x,y,z x,y,z ..." (3D) or "x,y x,y ..." (2D, with --dimensions 2).
template <class V> std::vector<V> parseVectors(const Args& a, const std::string& name, int dim) {
  const std::vector<double> v = parseNumbers(name, a.text(name));
  if (v.empty() || v.size() % static_cast<std::size_t>(dim) != 0) {
    throw Error(name, "--" + name + " = '" + a.text(name) + "': expected points of " + std::to_string(dim) +
                          " coordinates each");
  }
  std::vector<V> out;
  for (std::size_t i = 0; i < v.size(); i += static_cast<std::size_t>(dim)) {
    if constexpr (std::is_same_v<V, Vec2d>) {
      out.push_back({v[i], v[i + 1]});
    } else {
      out.push_back({v[i], v[i + 1], v[i + 2]});
    }
  }
  return out;
}

int dimensions(const Args& a) {
  const double d = a.number("dimensions");
  if (d != 2.0 && d != 3.0) {
    throw Error("dimensions", "--dimensions = " + formatValue(d) + ": must be 2 or 3");
  }
  return static_cast<int>(d);
}

Result trilaterateModel(const Args& a) {
  const int dim = dimensions(a);
  const std::vector<double> ranges = parseNumbers("ranges", a.text("ranges"));
  if (ranges.size() != 3) {
    throw Error("ranges", "--ranges: expected three distances, got " + std::to_string(ranges.size()));
  }
  Result r;
  if (dim == 2) {
    const std::vector<Vec2d> c = parseVectors<Vec2d>(a, "centres", 2);
    if (c.size() != 3) {
      throw Error("centres", "--centres: expected three points");
    }
    const Vec2d p = trilaterate({c[0], c[1], c[2]}, {ranges[0], ranges[1], ranges[2]});
    r.add("position", Vector{p.x, p.y}, "m");
  } else {
    const std::vector<Vec3d> c = parseVectors<Vec3d>(a, "centres", 3);
    if (c.size() != 3) {
      throw Error("centres", "--centres: expected three points");
    }
    const std::array<Vec3d, 2> p = trilaterate({c[0], c[1], c[2]}, {ranges[0], ranges[1], ranges[2]});
    r.add("position", toVector(p[0]), "m", "on the side of (c2 - c1) x (c3 - c1)");
    r.add("mirror_position", toVector(p[1]), "m", "its mirror image through the centres' plane");
  }
  return r;
}

Result gpsFix(const Args& a) {
  const int dim = dimensions(a);
  const std::vector<double> rho = parseNumbers("pseudoranges", a.text("pseudoranges"));
  PseudorangeOptions options;
  options.speedOfLight = a.number("speed-of-light");
  if (!a.text("start").empty()) {
    options.initialPosition = vector3(a, "start");
  }
  PseudorangeFix fix;
  if (dim == 2) {
    const std::vector<Vec2d> sats = parseVectors<Vec2d>(a, "satellites", 2);
    fix = solvePseudoranges(std::span<const Vec2d>(sats), rho, options);
  } else {
    const std::vector<Vec3d> sats = parseVectors<Vec3d>(a, "satellites", 3);
    fix = solvePseudoranges(sats, rho, options);
  }
  Result r;
  r.add("position", dim == 2 ? Vector{fix.position.x, fix.position.y} : toVector(fix.position), "m");
  r.add("clock_bias", fix.clockBias, "s", "receiver clock ahead by");
  r.add("range_bias", fix.rangeBias, "m", "c b");
  r.add("iterations", static_cast<double>(fix.iterations), "", "Gauss-Newton steps");
  r.add("residual_rms", fix.residualRms, "m");
  r.add("gdop", fix.gdop, "", "geometric dilution of precision");
  r.add("pdop", fix.pdop, "", "position dilution of precision");
  if (dim == 3 && length(fix.position) > 1e6) {
    const GeodeticPosition g = ecefToGeodetic(fix.position);
    r.add("geodetic", latLonVector(g.point), "deg", "lat, lon of the fix on WGS 84 (if the frame is ECEF)");
    r.add("height", g.height, "m", "above WGS 84");
  }
  return r;
}

Result clockRange(const Args& a) {
  const double dt = a.number("clock-error");
  const double dr = rangeErrorFromClockError(dt);
  Result r;
  r.add("range_error", dr, "m", "c dt");
  r.add("range_error_feet", dr / 0.3048, "ft");
  r.add("range_error_miles", dr / 1609.344, "mi");
  r.notes.emplace_back("the book says a 1 us receiver error gives 'over 900 miles': c x 1 us = 299.8 m = 984 ft "
                       "(feet mistaken for miles)");
  return r;
}

} // namespace

void registerGeoModels(Registry& registry) {
  registry.add({"great-circle",
                topic,
                "great-circle distance (haversine, law of cosines), initial and final bearing, midpoint",
                {pointParam("from", "start"), pointParam("to", "destination"), radiusParam()},
                greatCircle});
  registry.add({"destination",
                topic,
                "the point reached from a start at a bearing and distance: great circle and rhumb line",
                {pointParam("from", "start"),
                 {"bearing", "deg", "compass bearing, clockwise from north", std::nullopt},
                 {"distance", "m", "distance travelled", std::nullopt},
                 radiusParam()},
                destinationModel});
  registry.add({"cross-track",
                topic,
                "distance of a point from a great-circle route (cross- and along-track), within-range test",
                {pointParam("start", "route start"),
                 pointParam("end", "route end (and the target of --range)"),
                 pointParam("point", "the point"),
                 {"range", "m", "reverse geocaching radius around --end", std::string("100")},
                 radiusParam()},
                crossTrack});
  registry.add({"rhumb-line",
                topic,
                "rhumb line (constant bearing): distance, bearing, and how much longer than the great circle",
                {pointParam("from", "start"), pointParam("to", "destination"), radiusParam()},
                rhumb});
  std::vector<Param> vincentyParams{pointParam("from", "start"), pointParam("to", "destination")};
  for (Param& p : ellipsoidParams()) {
    vincentyParams.push_back(std::move(p));
  }
  registry.add(
      {"vincenty", topic,
       "distance and azimuths on the WGS 84 ellipsoid by Vincenty's inverse formula (non-convergence reported)",
       vincentyParams, vincenty});
#if IMPETUS_HAVE_GEO
  registry.add({"geodesic", topic, "the reference geodesic and rhumb line on the ellipsoid (GeographicLib, Karney)",
                vincentyParams, geodesic});
#endif
  std::vector<Param> ecefParams{pointParam("position", "geodetic position"),
                                {"height", "m", "height above the ellipsoid", std::string("0")}};
  std::vector<Param> geodeticParams{vectorParam("ecef", "m", "Earth-centred, Earth-fixed position", std::nullopt)};
  for (Param& p : ellipsoidParams()) {
    ecefParams.push_back(p);
    geodeticParams.push_back(std::move(p));
  }
  registry.add(
      {"ecef", topic, "geodetic latitude, longitude, height to Earth-centred Cartesian (WGS 84)", ecefParams, ecef});
  registry.add({"geodetic", topic, "Earth-centred Cartesian to geodetic latitude, longitude, height (WGS 84)",
                geodeticParams, geodetic});
  registry.add({"trilaterate",
                topic,
                "the book's closed form: a point from its distances to three centres (2D or 3D, both mirror points)",
                {{"centres", "m", "three points as \"x,y,z x,y,z x,y,z\" (or x,y with --dimensions 2)", std::nullopt,
                  ParamKind::text},
                 {"ranges", "m", "the three distances as \"r1 r2 r3\"", std::nullopt, ParamKind::text},
                 {"dimensions", "", "2 or 3", std::string("3")}},
                trilaterateModel});
  registry.add(
      {"gps-fix",
       topic,
       "receiver position and clock bias from satellite pseudoranges (Gauss-Newton), with dilution of precision",
       {{"satellites", "m", "satellite positions \"x,y,z x,y,z ...\" (>= 4; x,y and >= 3 with --dimensions 2)",
         std::nullopt, ParamKind::text},
        {"pseudoranges", "m", "measured ranges c (t_receive - t_transmit), one per satellite", std::nullopt,
         ParamKind::text},
        {"dimensions", "", "2 or 3", std::string("3")},
        {"speed-of-light", "m/s", "converts the range bias c b to the clock bias b", std::string("299792458")},
        optionalParam("start", "m", "start of the iteration as x,y,z (default the origin)")},
       gpsFix});
  registry.add({"clock-range-error",
                topic,
                "the range error c dt of a receiver clock error dt (1 us: 299.8 m, not the book's 900 miles)",
                {{"clock-error", "s", "clock error dt", std::string("1e-6")}},
                clockRange});
}

} // namespace impetus::cli
