// Book/Great circle (ch. 22): the great circle against the rhumb line on a world map. Two points
// (drag them, or pick a route) are joined by the great circle (geo/great_circle.hpp: the
// shortest path, its heading changing all the way) and the rhumb line (geo/rhumb.hpp: one
// constant compass bearing, a straight line on a Mercator chart, longer). The map is
// equirectangular (x = longitude, y = latitude, in degrees) or Mercator (y = the stretched
// latitude psi = asinh(tan phi), in degrees), with a 15-degree graticule and the coastlines of
// Natural Earth's 1:110m map (coastlines.hpp).
//
// Two aircraft fly the routes at the same speed, so the great circle's arrives first. Plots:
// the great circle's heading along the route (it turns) against the rhumb line's constant one;
// the panel gives both distances, the ellipsoidal distance by Vincenty on WGS 84 and the
// bearings.
#include "sample.hpp"

#include "coastlines.hpp"
#include "plot.hpp"
#include "ui.hpp"

#include <impetus/geo/geo.hpp>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace impetus::samples {
namespace {

using geo::LatLon;

struct Route {
  const char* name;
  LatLon from;
  LatLon to;
};

constexpr Route routes[] = {
    {"New York - London", {40.7128, -74.0060}, {51.5074, -0.1278}},
    {"New York - Beijing", {40.7128, -74.0060}, {39.9042, 116.4074}},
    {"Los Angeles - Tokyo", {33.94, -118.40}, {35.55, 139.78}},
    {"Land's End - John o' Groats", {50.0663, -5.7147}, {58.6439, -3.0700}},
    {"Cape Town - Perth", {-33.9249, 18.4241}, {-31.9505, 115.8605}},
};

constexpr double cruise = 250.0;       // m/s, an airliner
constexpr double timeScale = 1800.0;   // simulated seconds per real second: a crossing in seconds
constexpr double mercatorLimit = 85.0; // degrees: the Mercator map stops short of the poles

class GreatCircle final : public Sample {
public:
  void setup() override {
    t_ = 0.0;
    rebuild();
  }

  void step(float dt) override {
    t_ += static_cast<double>(dt) * timeScale;
    if (t_ * cruise > rhumbDistance_ + 2.0 * cruise * timeScale) {
      t_ = 0.0; // both have landed, and the rhumb's for two seconds: fly again
    }
  }

  [[nodiscard]] bool finite() const override {
    return std::isfinite(greatCircleDistance_) && std::isfinite(rhumbDistance_) && std::isfinite(t_);
  }

  [[nodiscard]] CameraView initialView() const override { return {{0.0f, 0.0f}, 95.0f, 190.0f}; }

  [[nodiscard]] std::string summary() const override {
    char text[160];
    std::snprintf(text, sizeof text, "great circle %.1f km, rhumb line %.1f km (%+.1f %%), initial bearing %.2f deg",
                  greatCircleDistance_ / 1000.0, rhumbDistance_ / 1000.0,
                  100.0 * (rhumbDistance_ / greatCircleDistance_ - 1.0), initialBearing_);
    return text;
  }

  [[nodiscard]] std::string_view controls() const override { return "drag either end of the route"; }

  bool mouseDown(const Vec2f& p, MouseButton /*button*/) override {
    const float dFrom = length(p - toMap(from_));
    const float dTo = length(p - toMap(to_));
    if (std::min(dFrom, dTo) > 10.0f) {
      return false;
    }
    dragging_ = dFrom <= dTo ? &from_ : &to_;
    return true;
  }

  void mouseMove(const Vec2f& p) override {
    if (dragging_ != nullptr) {
      *dragging_ = fromMap(p);
      rebuild();
    }
  }

  void mouseUp(const Vec2f& /*p*/, MouseButton /*button*/) override { dragging_ = nullptr; }

  void draw(DebugDraw& draw) override {
    drawGraticule(draw);
    drawCoastlines(draw);
    drawPath(draw, greatCirclePath_, palette::series[2]);
    drawPath(draw, rhumbPath_, palette::series[0]);
    draw.point(toMap(from_), 9.0f, palette::text);
    draw.point(toMap(to_), 9.0f, palette::reference);
    draw.text(toMap(from_) + Vec2f{2.0f, 3.0f}, "from", palette::text);
    draw.text(toMap(to_) + Vec2f{2.0f, 3.0f}, "to", palette::text);
    // The two aircraft, the same speed along each route.
    const double flown = t_ * cruise;
    const LatLon onGreatCircle = greatCircleDistance_ > 0.0
                                     ? geo::intermediatePoint(from_, to_, std::min(1.0, flown / greatCircleDistance_))
                                     : from_;
    const LatLon onRhumb = geo::rhumbDestination(from_, rhumbBearing_, std::min(flown, rhumbDistance_), radius_);
    draw.point(toMap(onGreatCircle), 7.0f, palette::series[2]);
    draw.point(toMap(onRhumb), 7.0f, palette::series[0]);
    draw.text({-178.0f, -mapTop() - 8.0f}, "blue: great circle (shortest)", palette::text);
    draw.text({-178.0f, -mapTop() - 8.0f - DebugDraw::textLinePixels * draw.pixelSize()},
              "red: rhumb line (constant bearing)", palette::text);
  }

  void ui() override {
    bool changed = false;
    labelColumn("route");
    if (ImGui::Combo(
            "##route", &route_,
            [](void*, int i, const char** out) {
              *out = routes[i].name;
              return true;
            },
            nullptr, static_cast<int>(std::size(routes)))) {
      from_ = routes[route_].from;
      to_ = routes[route_].to;
      changed = true;
    }
    auto fromLat = static_cast<float>(from_.latitude);
    auto fromLon = static_cast<float>(from_.longitude);
    auto toLat = static_cast<float>(to_.latitude);
    auto toLon = static_cast<float>(to_.longitude);
    changed |= slider("from latitude", &fromLat, -89.0f, 89.0f, "%.2f deg");
    changed |= slider("from longitude", &fromLon, -180.0f, 180.0f, "%.2f deg");
    changed |= slider("to latitude", &toLat, -89.0f, 89.0f, "%.2f deg");
    changed |= slider("to longitude", &toLon, -180.0f, 180.0f, "%.2f deg");
    changed |= checkbox("Mercator chart (rhumb lines straight)", &mercator_);
    if (changed) {
      from_ = {fromLat, fromLon};
      to_ = {toLat, toLon};
      rebuild();
    }
    textWrapped("great circle  %.1f km", greatCircleDistance_ / 1000.0);
    textWrapped("rhumb line    %.1f km  (%+.2f %%)", rhumbDistance_ / 1000.0,
                100.0 * (rhumbDistance_ / std::max(greatCircleDistance_, 1e-9) - 1.0));
    if (vincenty_) {
      textWrapped("WGS 84 (Vincenty) %.1f km", *vincenty_ / 1000.0);
    } else {
      textWrapped("WGS 84 (Vincenty) did not converge (nearly antipodal)");
    }
    textWrapped("initial bearing %.2f deg, final %.2f deg", initialBearing_, finalBearing_);
    textWrapped("rhumb bearing   %.2f deg (held all the way)", rhumbBearing_);
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "%.1f -> %.1f deg; rhumb %.1f deg", initialBearing_, finalBearing_,
                  rhumbBearing_);
    plotCurve("great-circle heading along the route (deg)", headings_, overlay, 80.0f, 0.0f, 360.0f);
  }

private:
  [[nodiscard]] float mapTop() const { return mercator_ ? static_cast<float>(mercatorY(mercatorLimit)) : 90.0f; }

  static double mercatorY(double latitude) {
    return radToDeg(geo::mercatorLatitude(std::clamp(latitude, -mercatorLimit, mercatorLimit)));
  }

  [[nodiscard]] Vec2f toMap(const LatLon& p) const {
    const double y = mercator_ ? mercatorY(p.latitude) : p.latitude;
    return {static_cast<float>(geo::wrapLongitude(p.longitude)), static_cast<float>(y)};
  }

  [[nodiscard]] LatLon fromMap(const Vec2f& p) const {
    double lat = p.y;
    if (mercator_) {
      lat = radToDeg(std::atan(std::sinh(degToRad(static_cast<double>(p.y)))));
    }
    return {std::clamp(lat, -89.0, 89.0), std::clamp(static_cast<double>(p.x), -180.0, 180.0)};
  }

  void rebuild() {
    greatCircleDistance_ = geo::haversineDistance(from_, to_, radius_);
    rhumbDistance_ = geo::rhumbDistance(from_, to_, radius_);
    initialBearing_ = geo::initialBearing(from_, to_);
    finalBearing_ = geo::finalBearing(from_, to_);
    rhumbBearing_ = geo::rhumbBearing(from_, to_);
    const std::optional<geo::VincentyResult> v = geo::vincentyInverse(from_, to_);
    vincenty_ = v ? std::optional<double>(v->distance) : std::nullopt;
    greatCirclePath_.clear();
    rhumbPath_.clear();
    headings_.clear();
    constexpr int n = 240;
    const bool antipodal = geo::haversineAngle(from_, to_) > pi<double> - 1e-6;
    for (int i = 0; i <= n; ++i) {
      const double f = static_cast<double>(i) / n;
      if (!antipodal) {
        const LatLon p = geo::intermediatePoint(from_, to_, f);
        greatCirclePath_.push_back(p);
        if (i < n) {
          headings_.push_back(static_cast<float>(geo::initialBearing(p, to_)));
        }
      }
      rhumbPath_.push_back(geo::rhumbDestination(from_, rhumbBearing_, f * rhumbDistance_, radius_));
    }
    t_ = 0.0;
  }

  /// A path on the map, broken where it crosses the date line (a jump of more than 180 degrees).
  void drawPath(DebugDraw& draw, const std::vector<LatLon>& path, const Color& color) const {
    std::vector<Vec2f> piece;
    for (const LatLon& p : path) {
      const Vec2f m = toMap(p);
      if (!piece.empty() && std::abs(m.x - piece.back().x) > 180.0f) {
        draw.polyline(piece, color);
        piece.clear();
      }
      piece.push_back(m);
    }
    draw.polyline(piece, color);
  }

  void drawGraticule(DebugDraw& draw) const {
    const float top = mapTop();
    for (int lon = -180; lon <= 180; lon += 15) {
      const Color c = lon == 0 || std::abs(lon) == 180 ? palette::grid.scaled(2.2f) : palette::grid.scaled(1.4f);
      draw.segment({static_cast<float>(lon), -top}, {static_cast<float>(lon), top}, c);
    }
    for (int lat = -75; lat <= 75; lat += 15) {
      const float y = toMap({static_cast<double>(lat), 0.0}).y;
      draw.segment({-180.0f, y}, {180.0f, y}, lat == 0 ? palette::grid.scaled(2.2f) : palette::grid.scaled(1.4f));
    }
    draw.box({-180.0f, -top}, {180.0f, top}, palette::staticBody.withAlpha(0.6f));
    // Labels every 30 degrees, or 60 or 90 when the map is drawn too small for them.
    const Color labelColor = palette::grid.scaled(3.0f);
    constexpr float labelSpacingPixels = 56.0f; // room for "150 W" between two labels
    int every = 30;
    for (const int degrees : {30, 60, 90}) {
      every = degrees;
      if (static_cast<float>(degrees) >= labelSpacingPixels * draw.pixelSize()) {
        break;
      }
    }
    for (int lat = -90 + every; lat < 90; lat += every) {
      char label[16];
      std::snprintf(label, sizeof label, "%d%s", std::abs(lat), lat > 0 ? " N" : (lat < 0 ? " S" : ""));
      draw.text({-179.0f, toMap({static_cast<double>(lat), 0.0}).y + 1.0f}, label, labelColor);
    }
    for (int lon = -180 + every; lon < 180; lon += every) {
      char label[16];
      std::snprintf(label, sizeof label, "%d%s", std::abs(lon), lon > 0 ? " E" : (lon < 0 ? " W" : ""));
      draw.text({static_cast<float>(lon) + 1.0f, -top + 1.0f}, label, labelColor);
    }
    draw.text({-178.0f, top + 8.0f},
              mercator_ ? "degrees N/S, E/W; Mercator: y = asinh(tan latitude)" : "degrees N/S, E/W", labelColor);
  }

  void drawCoastlines(DebugDraw& draw) const {
    const std::span<const CoastPoint> points = coastPoints();
    const std::span<const int> starts = coastLineStarts();
    const Color coast = palette::staticBody.scaled(1.3f);
    std::vector<Vec2f> line;
    for (std::size_t i = 0; i + 1 < starts.size(); ++i) {
      line.clear();
      for (int k = starts[i]; k < starts[i + 1]; ++k) {
        const CoastPoint& p = points[static_cast<std::size_t>(k)];
        // Not through toMap(): it would wrap the outlines' 180 E to 180 W.
        line.emplace_back(static_cast<float>(p.longitude) / 100.0f, toMap({p.latitude / 100.0, 0.0}).y);
      }
      draw.polyline(line, coast);
    }
  }

  LatLon from_ = routes[0].from;
  LatLon to_ = routes[0].to;
  int route_ = 0;
  bool mercator_ = false;
  LatLon* dragging_ = nullptr;
  double radius_ = geo::bookEarthRadius;
  double t_ = 0.0;
  double greatCircleDistance_ = 0.0;
  double rhumbDistance_ = 0.0;
  double initialBearing_ = 0.0;
  double finalBearing_ = 0.0;
  double rhumbBearing_ = 0.0;
  std::optional<double> vincenty_;
  std::vector<LatLon> greatCirclePath_;
  std::vector<LatLon> rhumbPath_;
  std::vector<float> headings_;
};

const SampleRegistrar registrar{"Book", "Great circle",
                                "GPS navigation (ch. 22): the great circle against the rhumb line on a world map, "
                                "their distances and headings, two aircraft flying them.",
                                [] { return std::make_unique<GreatCircle>(); }};

} // namespace
} // namespace impetus::samples
