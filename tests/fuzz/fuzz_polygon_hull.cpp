// Fuzzes polygon creation (include/impetus/rigid2d/geometry.hpp): arbitrary points (0 to 10 of
// them, any float bit pattern or finite values at a scale from 1e-4 to 1e11) through computeHull
// and makePolygon with a rounding radius, and box parameters through makeOffsetBox.
//
// Either creation throws impetus::Error (and nothing else), or the result is a valid polygon:
//  - 3 to 8 vertices, each one of the input points (the hull adds no point), none closer than
//    linearSlop to another (duplicates are welded);
//  - counter-clockwise and strictly convex, with no vertex within linearSlop of the line through
//    its neighbours (collinear points are removed);
//  - every normal of unit length, perpendicular to its edge and pointing out;
//  - every input point inside the hull or outside it by at most hullTolerance (the welding and the
//    collinear-point removal may cut off a sliver that thin, no more);
//  - the centroid inside; the mass data (computeMass at density 1) finite and positive with its
//    centre inside; the bounding box finite and holding every vertex;
//  - every vertex coordinate and the radius within maxPolygonCoordinate (1e6 m);
//  - accepted by validateShape (World::createShape's check of a polygon built by hand).
// A rounded polygon keeps the radius it was given; a negative or non-finite radius is an error.
// A box has 4 vertices and half-widths of at least linearSlop.
#include "fuzz_support.hpp"

#include <impetus/error.hpp>
#include <impetus/rigid2d/geometry.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <limits>
#include <span>
#include <string>
#include <typeinfo>
#include <vector>

namespace {

using impetus::Vec2f;
using impetus::fuzz::str;
namespace r2 = impetus::rigid2d;

/// How far outside the hull an input point may lie: collinear removal drops a vertex within
/// linearSlop of the line through its neighbours, and welding a point within linearSlop of a
/// kept one; a few of those in a row may add up, to a few linearSlop.
constexpr double hullTolerance = 4.0 * r2::linearSlop;

struct V {
  double x;
  double y;
};
V d(const Vec2f& v) { return {v.x, v.y}; }
double cross(V a, V b) { return a.x * b.y - a.y * b.x; }
double dot(V a, V b) { return a.x * b.x + a.y * b.y; }
V sub(V a, V b) { return {a.x - b.x, a.y - b.y}; }
double len(V a) { return std::hypot(a.x, a.y); }

std::string describe(std::span<const Vec2f> points) {
  std::string s;
  for (const Vec2f& p : points) {
    s += s.empty() ? "" : " ";
    s += str(p);
  }
  return s;
}

/// Signed distance of p outside edge i of the (counter-clockwise) vertex loop, in double.
double outside(std::span<const Vec2f> v, std::size_t i, V p) {
  const V a = d(v[i]);
  const V b = d(v[(i + 1) % v.size()]);
  const V e = sub(b, a);
  return -cross(e, sub(p, a)) / len(e);
}

/// Checks a vertex loop: from the input points, welded, counter-clockwise, convex,
/// without collinear vertices, holding every input point.
void checkHull(std::span<const Vec2f> hull, std::span<const Vec2f> input, double scale) {
  const auto where = [&] { return std::string("hull [") + describe(hull) + "] of [" + describe(input) + "]"; };
  FUZZ_CHECK(hull.size() >= 3 && hull.size() <= 8, where() + ": vertex count");
  // Rounding: the library decides in float what is checked here in double.
  const double eps = 1e-5 * scale;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    bool fromInput = false;
    for (const Vec2f& p : input) {
      fromInput = fromInput || (p.x == hull[i].x && p.y == hull[i].y);
    }
    FUZZ_CHECK(fromInput, where() + ": vertex " + std::to_string(i) + " is not an input point");
    FUZZ_CHECK(std::abs(hull[i].x) <= r2::maxPolygonCoordinate && std::abs(hull[i].y) <= r2::maxPolygonCoordinate,
               where() + ": vertex " + std::to_string(i) + " beyond maxPolygonCoordinate");
    for (std::size_t j = i + 1; j < hull.size(); ++j) {
      FUZZ_CHECK(len(sub(d(hull[i]), d(hull[j]))) >= r2::linearSlop - eps,
                 where() + ": vertices " + std::to_string(i) + " and " + std::to_string(j) + " not welded");
    }
    const V prev = d(hull[(i + hull.size() - 1) % hull.size()]);
    const V here = d(hull[i]);
    const V next = d(hull[(i + 1) % hull.size()]);
    // A left turn at every vertex; by eps at most the other way (float at large coordinates).
    FUZZ_CHECK(cross(sub(here, prev), sub(next, here)) / len(sub(here, prev)) > -eps,
               where() + ": not strictly convex and counter-clockwise at vertex " + std::to_string(i));
    // Convex as a whole, not only turning left at each vertex (a loop that winds twice does).
    for (std::size_t j = 0; j < hull.size(); ++j) {
      FUZZ_CHECK(outside(hull, i, d(hull[j])) <= eps,
                 where() + ": vertex " + std::to_string(j) + " is outside edge " + std::to_string(i));
    }
    const double offset = cross(sub(next, prev), sub(here, prev)) / len(sub(next, prev));
    FUZZ_CHECK(std::abs(offset) > r2::linearSlop - eps, where() + ": vertex " + std::to_string(i) +
                                                            " is within linearSlop of its neighbours' line (" +
                                                            str(offset) + ")");
  }
  // Removing collinear vertices one at a time against their current neighbours keeps a dropped
  // point within a few linearSlop (regressions/polygon_hull/collinear-removal-drops-point*).
  for (const Vec2f& p : input) {
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const double out = outside(hull, i, d(p));
      FUZZ_CHECK(out <= hullTolerance + eps,
                 where() + ": input point " + str(p) + " lies " + str(out) + " m outside edge " + std::to_string(i));
    }
  }
}

void checkPolygon(const r2::Polygon& polygon, std::span<const Vec2f> input, float radius, double scale) {
  const std::span<const Vec2f> vertices(polygon.vertices.data(), static_cast<std::size_t>(polygon.count));
  checkHull(vertices, input, scale);
  const auto where = [&] { return std::string("polygon [") + describe(vertices) + "] radius " + str(polygon.radius); };
  FUZZ_CHECK(polygon.radius == radius, where() + ": the radius given was " + str(radius));
  FUZZ_CHECK(polygon.radius <= r2::maxPolygonCoordinate, where() + ": radius beyond maxPolygonCoordinate");
  const double eps = 1e-5 * scale;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const V n = d(polygon.normals[i]);
    const V e = sub(d(vertices[(i + 1) % vertices.size()]), d(vertices[i]));
    FUZZ_CHECK(std::abs(len(n) - 1.0) <= 1e-5,
               where() + ": normal " + std::to_string(i) + " " + str(polygon.normals[i]) + " is not a unit vector");
    FUZZ_CHECK(std::abs(dot(n, e)) <= 1e-5 * len(e) && cross(e, n) < 0.0,
               where() + ": normal " + std::to_string(i) + " is not the outward perpendicular of its edge");
    FUZZ_CHECK(outside(vertices, i, d(polygon.centroid)) < eps,
               where() + ": centroid " + str(polygon.centroid) + " is outside edge " + std::to_string(i));
  }
  // World::createShape takes it: validateShape, which checks a polygon built by hand, accepts
  // every polygon the makers return.
  try {
    r2::validateShape(polygon);
  } catch (const impetus::Error& e) {
    FUZZ_CHECK(false, where() + ": refused by validateShape (createShape would refuse it): " + e.what());
  }
  const r2::MassData mass = r2::computeMass(polygon, 1.0f);
  FUZZ_CHECK(std::isfinite(mass.mass) && mass.mass > 0.0f && std::isfinite(mass.rotationalInertia) &&
                 mass.rotationalInertia > 0.0f && isFinite(mass.center),
             where() + ": mass data: mass " + str(mass.mass) + ", inertia " + str(mass.rotationalInertia) +
                 ", center " + str(mass.center));
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    FUZZ_CHECK(outside(vertices, i, d(mass.center)) < polygon.radius + eps,
               where() + ": centre of mass " + str(mass.center) + " is outside edge " + std::to_string(i));
  }
  const r2::AABB box = r2::computeAABB(polygon, impetus::Transform2f::identity());
  FUZZ_CHECK(isFinite(box.lower) && isFinite(box.upper), where() + ": bounding box not finite");
  for (const Vec2f& v : vertices) {
    FUZZ_CHECK(v.x >= box.lower.x && v.y >= box.lower.y && v.x <= box.upper.x && v.y <= box.upper.y,
               where() + ": vertex " + str(v) + " outside the bounding box");
  }
}

/// Runs `f`, which may throw impetus::Error and nothing else; true when it returned.
template <class F> bool returnsOrThrowsImpetusError(const char* what, F&& f) {
  try {
    f();
    return true;
  } catch (const impetus::Error&) {
    return false;
  } catch (const std::exception& e) {
    FUZZ_CHECK(false, std::string(what) + " threw " + typeid(e).name() + ": " + e.what());
  }
  return false;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  impetus::fuzz::Reader in(data, size);
  // Byte 0: the number of points (0 to 10: fewer than 3 and more than 8 must be refused) and the
  // path. Byte 1: raw float bits (NaN, infinities, 1e38 included) or finite values at a scale
  // of 10^(k - 4), k = 0 to 15.
  const std::uint8_t shape = in.byte();
  const std::uint8_t mode = in.byte();
  const bool raw = (mode & 1) != 0;
  const double scale = std::pow(10.0, static_cast<double>((mode >> 1) % 16) - 4.0);
  const auto number = [&] { return raw ? in.rawFloat() : in.bounded(static_cast<float>(scale)); };

  if ((shape & 0x80) != 0) {
    // A box: half-widths, centre and angle.
    const float hx = number();
    const float hy = number();
    const Vec2f center{number(), number()};
    const float angle = number();
    r2::Polygon box;
    if (returnsOrThrowsImpetusError("makeOffsetBox", [&] { box = r2::makeOffsetBox(hx, hy, center, angle); })) {
      const auto where = [&] {
        return std::string("box ") + str(hx) + " x " + str(hy) + " at " + str(center) + ", " + str(angle) + " rad";
      };
      const double extent = std::abs(hx) + std::abs(hy) + std::abs(center.x) + std::abs(center.y);
      // A side below 2 linearSlop used to come out a triangle, one pair of corners welded and the
      // other not (regressions/polygon_hull/box-side-near-slop-is-triangle*): it is refused now.
      FUZZ_CHECK(std::min(hx, hy) >= r2::linearSlop, where() + ": a side below 2 linearSlop accepted");
      FUZZ_CHECK(box.count == 4, where() + ": " + std::to_string(box.count) + " vertices");
      // The corners are the input points of the hull.
      const impetus::Transform2f xf{center, impetus::Rot2f::fromAngle(angle)};
      const std::array<Vec2f, 4> corners{transformPoint(xf, {-hx, -hy}), transformPoint(xf, {hx, -hy}),
                                         transformPoint(xf, {hx, hy}), transformPoint(xf, {-hx, hy})};
      checkPolygon(box, corners, 0.0f, std::max(1.0, extent));
    }
    return 0;
  }

  const std::size_t count = shape % 11;
  std::vector<Vec2f> points(count);
  double extent = 1.0;
  for (Vec2f& p : points) {
    p = {number(), number()};
    if (isFinite(p)) {
      extent = std::max(extent, static_cast<double>(std::max(std::abs(p.x), std::abs(p.y))));
    }
  }
  const float radius = number();
  if (std::isfinite(radius)) {
    extent = std::max(extent, static_cast<double>(std::abs(radius)));
  }

  // Coordinates beyond maxPolygonCoordinate overflowed the mass data (from about 1e10 m) and the
  // hull's squared distances (1e19 m, regressions/polygon_hull/huge-*): the vertex check in
  // checkHull makes them refused.
  std::array<Vec2f, 8> storage{};
  std::span<const Vec2f> hull;
  if (returnsOrThrowsImpetusError("computeHull", [&] { hull = r2::computeHull(points, storage); })) {
    checkHull(hull, points, extent);
  }
  r2::Polygon polygon;
  if (returnsOrThrowsImpetusError("makePolygon", [&] { polygon = r2::makePolygon(points, radius); })) {
    checkPolygon(polygon, points, radius, extent);
    // makePolygon is the hull, as computeHull gives it.
    FUZZ_CHECK(static_cast<std::size_t>(polygon.count) == hull.size(),
               std::string("makePolygon and computeHull disagree on [") + describe(points) + "]");
  }
  return 0;
}
