#include <impetus/core/polygon_mass.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/rigid2d/geometry.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace impetus::rigid2d {
namespace {

/// Distance from p to the segment a-b, and the closest point.
Vec2f closestOnSegment(const Vec2f& a, const Vec2f& b, const Vec2f& p) {
  const Vec2f ab = b - a;
  const float ab2 = lengthSquared(ab);
  const float t = ab2 > 0.0f ? std::clamp(dot(p - a, ab) / ab2, 0.0f, 1.0f) : 0.0f;
  return a + ab * t;
}

/// The first crossing of the ray with a circle, from outside.
CastOutput castCircle(const Vec2f& center, float radius, const RayCastInput& ray) {
  // |s + t d|^2 = r^2 with s = origin - center: t^2 dd + 2 t sd + ss - rr = 0.
  const Vec2f s = ray.origin - center;
  const Vec2f& d = ray.translation;
  const float dd = dot(d, d);
  const float ss = dot(s, s) - radius * radius;
  if (dd == 0.0f || ss < 0.0f) {
    return {};
  }
  const float sd = dot(s, d);
  const float disc = sd * sd - dd * ss;
  if (disc < 0.0f) {
    return {};
  }
  const float t = (-sd - std::sqrt(disc)) / dd;
  if (t < 0.0f || t > ray.maxFraction) {
    return {};
  }
  const Vec2f point = ray.origin + d * t;
  return {normalize(point - center), point, t, true};
}

/// The first crossing of the ray with the front side (normal `n`) of the segment a-b.
CastOutput castFrontSide(const Vec2f& a, const Vec2f& b, const Vec2f& n, const RayCastInput& ray) {
  const float denominator = dot(n, ray.translation);
  if (denominator >= 0.0f) {
    return {}; // parallel or from behind
  }
  const float t = dot(n, a - ray.origin) / denominator;
  if (t < 0.0f || t > ray.maxFraction) {
    return {};
  }
  const Vec2f point = ray.origin + ray.translation * t;
  const Vec2f ab = b - a;
  const float u = dot(point - a, ab);
  if (u < 0.0f || u > dot(ab, ab)) {
    return {};
  }
  return {n, point, t, true};
}

/// The earlier of two hits.
CastOutput first(const CastOutput& a, const CastOutput& b) {
  if (!a.hit) {
    return b;
  }
  if (!b.hit) {
    return a;
  }
  return b.fraction < a.fraction ? b : a;
}

/// Shape coordinates and radii are bounded (maxPolygonCoordinate).
void requireCoordinate(float value, const std::string& field) {
  if (std::abs(value) > maxPolygonCoordinate) {
    throwInvalid(field, value, "must be within 1e6 m of the body origin");
  }
}

/// A point of a shape: finite, and each coordinate bounded (`field.x`, `field.y`).
void requirePoint(const Vec2f& p, const std::string& field) {
  requireFinite(p, field);
  requireCoordinate(p.x, field + ".x");
  requireCoordinate(p.y, field + ".y");
}

/// A radius: finite, positive (or, for a polygon's rounding, zero) and bounded.
void requireRadius(float value, const std::string& field, bool zeroAllowed) {
  if (zeroAllowed) {
    requireNonNegative(value, field);
  } else {
    requirePositive(value, field);
  }
  if (value > maxPolygonCoordinate) {
    throwInvalid(field, value, "must be at most 1e6 m");
  }
}

/// Mass data a body can use: mass and inertia finite, and at least the smallest normal float
/// (1.2e-38), so that their inverses are finite too. Only the density can take a bounded shape
/// out of that range (at 1 kg/m^2 a 1e6 m square has inertia 2.7e24 kg m^2, float's limit is
/// 3.4e38), so it is the density that is refused.
MassData requireUsableMass(const MassData& m, float density) {
  constexpr float smallest = std::numeric_limits<float>::min();
  if (!std::isfinite(m.mass) || !std::isfinite(m.rotationalInertia)) {
    throwInvalid("density", density,
                 "the shape's mass (" + formatValue(m.mass) + " kg) or rotational inertia (" +
                     formatValue(m.rotationalInertia) + " kg m^2) overflows float at this density");
  }
  if (!(m.mass >= smallest) || !(m.rotationalInertia >= smallest)) {
    throwInvalid("density", density,
                 "the shape's mass (" + formatValue(m.mass) + " kg) or rotational inertia (" +
                     formatValue(m.rotationalInertia) +
                     " kg m^2) underflows float at this density (no finite inverse)");
  }
  return m;
}

/// A box half-extent: finite, at least linearSlop (a side of 2 linearSlop) and bounded.
void requireBoxHalfExtent(float value, const char* field) {
  requirePositive(value, field);
  if (value < linearSlop) {
    throwInvalid(field, value, "must be at least linearSlop (0.005 m): a thinner box loses corners");
  }
  requireCoordinate(value, field);
}

void requireRay(const RayCastInput& ray) {
  requireFinite(ray.origin, "origin");
  requireFinite(ray.translation, "translation");
  if (!(ray.maxFraction >= 0.0f) || !std::isfinite(ray.maxFraction)) {
    throwInvalid("maxFraction", ray.maxFraction, "must be finite and non-negative");
  }
}

} // namespace

std::span<const Vec2f> computeHull(std::span<const Vec2f> points, std::array<Vec2f, 8>& storage) {
  if (points.size() < 3 || points.size() > static_cast<std::size_t>(maxPolygonVertices)) {
    throwInvalid("points.size", static_cast<double>(points.size()), "a polygon needs 3 to 8 points");
  }
  // Everything below is decided in double on the float inputs: within maxPolygonCoordinate the
  // rounding of a difference, a distance or a cross product is below 1e-9 m, far inside the
  // linearSlop margins the decisions use, so no rounding can make the hull wind or lose a corner.
  std::array<Vec2d, 8> unique{};
  std::size_t n = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string field = "points[" + std::to_string(i) + "]";
    requirePoint(points[i], field);
    // Weld points closer than linearSlop to one already kept: contact could not tell them apart.
    const Vec2d p{points[i].x, points[i].y};
    const bool duplicate = std::any_of(unique.begin(), unique.begin() + static_cast<std::ptrdiff_t>(n),
                                       [&](const Vec2d& u) { return distance(u, p) < linearSlop; });
    if (!duplicate) {
      unique[n++] = p;
    }
  }
  // Andrew's monotone chain: sorted by x then y, the lower chain left to right and the upper one
  // right to left, each popping what does not turn left. Both chains are monotone in x and each
  // point enters a chain once, so the loop closes and cannot wind twice, whatever the orientation
  // tests decide (the gift wrapping this replaces could, misjudging a point on an edge next to
  // its start); their rounding can only leave a vertex a hair off its neighbours' line, which the
  // removal below takes out. The loop starts at the lowest x (then lowest y), as before.
  // Insertion sort: at most 8 points (std::sort trips a false -Warray-bounds in g++ 12 here).
  const auto before = [](const Vec2d& a, const Vec2d& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  for (std::size_t i = 1; i < n; ++i) {
    for (std::size_t j = i; j > 0 && before(unique[j], unique[j - 1]); --j) {
      std::swap(unique[j], unique[j - 1]);
    }
  }
  std::array<Vec2d, 16> chain{};
  std::size_t count = 0;
  const auto push = [&](const Vec2d& p, std::size_t floor) {
    while (count >= floor + 2 && cross(chain[count - 1] - chain[count - 2], p - chain[count - 2]) <= 0.0) {
      --count;
    }
    chain[count++] = p;
  };
  for (std::size_t i = 0; i < n; ++i) {
    push(unique[i], 0);
  }
  const std::size_t lower = count - 1; // the upper chain starts at the rightmost point
  for (std::size_t i = n - 1; i-- > 0;) {
    push(unique[i], lower);
  }
  --count; // the last point is the first again
  // Drop vertices within linearSlop of the line through their neighbours, the flattest first and
  // one at a time, testing again against the current neighbours: dropping two adjacent ones
  // together could cut a corner far outside either's own tolerance.
  const auto offset = [&](std::size_t i) {
    const Vec2d& prev = chain[(i + count - 1) % count];
    const Vec2d edge = chain[(i + 1) % count] - prev;
    const double len = length(edge);
    // Outward (right of prev -> next) for a counter-clockwise loop; a reflex vertex is negative.
    return len > 0.0 ? cross(chain[i] - prev, edge) / len : 0.0;
  };
  while (count >= 3) {
    std::size_t flattest = 0;
    double smallest = offset(0);
    for (std::size_t i = 1; i < count; ++i) {
      const double o = offset(i);
      if (o < smallest) {
        flattest = i;
        smallest = o;
      }
    }
    if (smallest > static_cast<double>(linearSlop)) {
      break;
    }
    std::copy(chain.begin() + static_cast<std::ptrdiff_t>(flattest + 1),
              chain.begin() + static_cast<std::ptrdiff_t>(count),
              chain.begin() + static_cast<std::ptrdiff_t>(flattest));
    --count;
  }
  if (count < 3) {
    throwInvalid("points", 0.0, "the points are collinear or coincident: no area");
  }
  // The vertices are input points, exactly: doubles converted from floats convert back unchanged.
  for (std::size_t i = 0; i < count; ++i) {
    storage[i] = {static_cast<float>(chain[i].x), static_cast<float>(chain[i].y)};
  }
  return {storage.data(), count};
}

Polygon makePolygon(std::span<const Vec2f> points, float radius) {
  requireRadius(radius, "radius", true);
  std::array<Vec2f, 8> storage{};
  const std::span<const Vec2f> hull = computeHull(points, storage);
  Polygon p;
  p.count = static_cast<int>(hull.size());
  p.radius = radius;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    p.vertices[i] = hull[i];
  }
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2f edge = hull[(i + 1) % hull.size()] - hull[i];
    p.normals[i] = normalize(Vec2f{edge.y, -edge.x}); // clockwise perpendicular: outward for CCW
  }
  std::array<Vec2d, 8> v{};
  for (std::size_t i = 0; i < hull.size(); ++i) {
    v[i] = {hull[i].x, hull[i].y};
  }
  const PolygonMass area = polygonMass(std::span<const Vec2d>(v.data(), hull.size()), 1.0);
  p.centroid = {static_cast<float>(area.centroid.x), static_cast<float>(area.centroid.y)};
  return p;
}

Polygon makeBox(float halfWidth, float halfHeight) { return makeOffsetBox(halfWidth, halfHeight, {}, 0.0f); }

Polygon makeOffsetBox(float halfWidth, float halfHeight, const Vec2f& center, float angle) {
  requireBoxHalfExtent(halfWidth, "halfWidth");
  requireBoxHalfExtent(halfHeight, "halfHeight");
  requireFinite(center, "center");
  requireCoordinate(center.x, "center.x");
  requireCoordinate(center.y, "center.y");
  requireFinite(angle, "angle");
  const Transform2f xf{center, Rot2f::fromAngle(angle)};
  const std::array<Vec2f, 4> corners{
      transformPoint(xf, {-halfWidth, -halfHeight}), transformPoint(xf, {halfWidth, -halfHeight}),
      transformPoint(xf, {halfWidth, halfHeight}), transformPoint(xf, {-halfWidth, halfHeight})};
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const std::string field = "corners[" + std::to_string(i) + "]";
    requireCoordinate(corners[i].x, field + ".x");
    requireCoordinate(corners[i].y, field + ".y");
  }
  // Sides of at least 2 linearSlop keep all four corners in exact arithmetic (a corner lies at
  // least sqrt(2) linearSlop from the diagonal through its neighbours), but far from the origin
  // float rounding of the corners (0.06 m at 1e6 m) can still weld two or flatten one: the
  // thinner side is then refused rather than returned as a triangle.
  const char* thinner = halfWidth <= halfHeight ? "halfWidth" : "halfHeight";
  const float thinnerValue = std::min(halfWidth, halfHeight);
  Polygon box;
  try {
    box = makePolygon(corners);
  } catch (const Error&) {
    box.count = 0;
  }
  if (box.count != 4) {
    throwInvalid(thinner, thinnerValue, "too thin at this centre: float rounding welds corners");
  }
  return box;
}

void validateShape(const Circle& shape) {
  requirePoint(shape.center, "center");
  requireRadius(shape.radius, "radius", false);
}

void validateShape(const Capsule& shape) {
  requirePoint(shape.center1, "center1");
  requirePoint(shape.center2, "center2");
  requireRadius(shape.radius, "radius", false);
  if (const float gap = distance(shape.center1, shape.center2); gap <= linearSlop) {
    throwInvalid("center2", gap, "capsule ends coincide: use a circle");
  }
}

void validateShape(const Segment& shape) {
  requirePoint(shape.point1, "point1");
  requirePoint(shape.point2, "point2");
  if (const float gap = distance(shape.point1, shape.point2); gap <= linearSlop) {
    throwInvalid("point2", gap, "segment is too short");
  }
}

void validateShape(const Polygon& shape) {
  if (shape.count < 3 || shape.count > maxPolygonVertices) {
    throwInvalid("polygon.count", shape.count, "must be 3 to 8 (build polygons with makePolygon or makeBox)");
  }
  const auto n = static_cast<std::size_t>(shape.count);
  const auto vertexField = [](std::size_t i) { return "polygon.vertices[" + std::to_string(i) + "]"; };
  const auto normalField = [](std::size_t i) { return "polygon.normals[" + std::to_string(i) + "]"; };
  std::array<Vec2d, 8> v{};
  double scale = 0.0; // the largest coordinate, m
  for (std::size_t i = 0; i < n; ++i) {
    requirePoint(shape.vertices[i], vertexField(i));
    v[i] = {shape.vertices[i].x, shape.vertices[i].y};
    scale = std::max({scale, std::abs(v[i].x), std::abs(v[i].y)});
  }
  requireRadius(shape.radius, "polygon.radius", true);
  requireFinite(shape.centroid, "polygon.centroid");
  for (std::size_t i = 0; i < n; ++i) {
    requireFinite(shape.normals[i], normalField(i));
    if (const float len = length(shape.normals[i]); std::abs(len - 1.0f) > 1e-3f) {
      throwInvalid(normalField(i), len, "must be a unit vector (build polygons with makePolygon or makeBox)");
    }
  }
  // What makePolygon guarantees, decided as computeHull decides it: in double on the float
  // vertices (exact to 1e-9 m within the bound), so every polygon it returns passes.
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t next = (i + 1) % n;
    const Vec2d edge = v[next] - v[i];
    const double len = length(edge);
    // Welded by makePolygon: contact could not tell the two vertices apart.
    if (!(len >= static_cast<double>(linearSlop))) {
      throwInvalid(vertexField(next), len,
                   "is closer than linearSlop (0.005 m) to the vertex before it (build polygons with makePolygon)");
    }
    // The outward normal of edge i -> i+1 (its clockwise perpendicular, for a counter-clockwise
    // polygon), to the same 1e-3 as the unit length.
    const Vec2d outward = Vec2d{edge.y, -edge.x} / len;
    const Vec2d normal{shape.normals[i].x, shape.normals[i].y};
    if (const double off = length(normal - outward); !(off <= 1e-3)) {
      throwInvalid(normalField(i), off,
                   "is this far from the outward unit normal of edge " + std::to_string(i) + " -> " +
                       std::to_string(next) + " (must be within 1e-3; build polygons with makePolygon or makeBox)");
    }
  }
  // Strictly convex and counter-clockwise: every vertex more than linearSlop outside the line
  // through its neighbours (computeHull's test, the same expression), and the turns add up to
  // one revolution (all turns left but twice round is a star).
  double turning = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2d& prev = v[(i + n - 1) % n];
    const Vec2d& next = v[(i + 1) % n];
    const Vec2d edge = next - prev;
    const double len = length(edge);
    const double offset = len > 0.0 ? cross(v[i] - prev, edge) / len : 0.0;
    if (!(offset > static_cast<double>(linearSlop))) {
      throwInvalid(vertexField(i), offset,
                   "must lie more than linearSlop (0.005 m) outside the line through its neighbours, to its right: "
                   "the polygon must be convex and counter-clockwise (build polygons with makePolygon)");
    }
    const Vec2d in = v[i] - prev;
    const Vec2d out = next - v[i];
    turning += std::atan2(cross(in, out), dot(in, out));
  }
  if (turning > 3.0 * pi<double>) {
    throwInvalid("polygon.vertices", std::round(turning / (2.0 * pi<double>)),
                 "turns this many times round: a convex polygon turns once (build polygons with makePolygon)");
  }
  // The centroid inside, within linearSlop and its float rounding (a quarter metre at 1e6 m).
  const Vec2d c{shape.centroid.x, shape.centroid.y};
  const double tolerance = static_cast<double>(linearSlop) + 4.0 * std::numeric_limits<float>::epsilon() * scale;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2d edge = v[(i + 1) % n] - v[i];
    const double outside = cross(c - v[i], edge) / length(edge);
    if (outside > tolerance) {
      throwInvalid("polygon.centroid", outside,
                   "lies this far outside edge " + std::to_string(i) + ": must be inside the polygon");
    }
  }
}

MassData computeMass(const Circle& shape, float density) {
  requirePositive(density, "density");
  requirePositive(shape.radius, "radius");
  const float rr = shape.radius * shape.radius;
  const float mass = density * pi<float> * rr;
  return requireUsableMass({mass, shape.center, 0.5f * mass * rr}, density);
}

MassData computeMass(const Capsule& shape, float density) {
  requirePositive(density, "density");
  requirePositive(shape.radius, "radius");
  const float r = shape.radius;
  const float rr = r * r;
  const float len = distance(shape.center1, shape.center2);
  const float circleMass = density * pi<float> * rr; // the two half discs
  const float boxMass = density * 2.0f * r * len;
  // Each half disc: its own inertia about its centroid (1/2 m r^2 about the disc centre moved by
  // the centroid offset lc = 4 r / (3 pi)), then moved to h + lc from the capsule's centre:
  // m (1/2 r^2 + (h + lc)^2 - lc^2) = m (1/2 r^2 + h^2 + 2 h lc).
  const float lc = 4.0f * r / (3.0f * pi<float>);
  const float h = 0.5f * len;
  const float circleInertia = circleMass * (0.5f * rr + h * h + 2.0f * h * lc);
  const float boxInertia = boxMass * (4.0f * rr + len * len) / 12.0f;
  return requireUsableMass({circleMass + boxMass, (shape.center1 + shape.center2) * 0.5f, circleInertia + boxInertia},
                           density);
}

MassData computeMass(const Polygon& shape, float density) {
  requirePositive(density, "density");
  std::array<Vec2d, 8> v{};
  const auto n = static_cast<std::size_t>(shape.count);
  for (std::size_t i = 0; i < n; ++i) {
    Vec2f p = shape.vertices[i];
    if (shape.radius > 0.0f) {
      // A rounded polygon is approximated by pushing each vertex out along its corner's bisector
      // (by r sqrt 2, as Box2D does): exact area for a square corner's bounding box, within a
      // few percent of the true rounded area for typical radii.
      const Vec2f n1 = shape.normals[(i + n - 1) % n];
      const Vec2f n2 = shape.normals[i];
      p += normalize(n1 + n2) * (std::sqrt(2.0f) * shape.radius);
    }
    v[i] = {p.x, p.y};
  }
  const PolygonMass m = polygonMass(std::span<const Vec2d>(v.data(), n), static_cast<double>(density));
  return requireUsableMass({static_cast<float>(m.mass),
                            {static_cast<float>(m.centroid.x), static_cast<float>(m.centroid.y)},
                            static_cast<float>(m.inertia)},
                           density);
}

AABB computeAABB(const Circle& shape, const Transform2f& xf) {
  const Vec2f p = transformPoint(xf, shape.center);
  const Vec2f r{shape.radius, shape.radius};
  return {p - r, p + r};
}

AABB computeAABB(const Capsule& shape, const Transform2f& xf) {
  const Vec2f a = transformPoint(xf, shape.center1);
  const Vec2f b = transformPoint(xf, shape.center2);
  const Vec2f r{shape.radius, shape.radius};
  return {min(a, b) - r, max(a, b) + r};
}

AABB computeAABB(const Polygon& shape, const Transform2f& xf) {
  Vec2f lower = transformPoint(xf, shape.vertices[0]);
  Vec2f upper = lower;
  for (int i = 1; i < shape.count; ++i) {
    const Vec2f v = transformPoint(xf, shape.vertices[static_cast<std::size_t>(i)]);
    lower = min(lower, v);
    upper = max(upper, v);
  }
  const Vec2f r{shape.radius, shape.radius};
  return {lower - r, upper + r};
}

AABB computeAABB(const Segment& shape, const Transform2f& xf) {
  const Vec2f a = transformPoint(xf, shape.point1);
  const Vec2f b = transformPoint(xf, shape.point2);
  return {min(a, b), max(a, b)};
}

CastOutput rayCast(const Circle& shape, const RayCastInput& ray) {
  requireRay(ray);
  return castCircle(shape.center, shape.radius, ray);
}

CastOutput rayCast(const Capsule& shape, const RayCastInput& ray) {
  requireRay(ray);
  if (containsPoint(shape, ray.origin)) {
    return {};
  }
  // The stadium is the union of its two end discs and the rectangle between them: the first
  // hit on any of their outer boundaries is the hit on the stadium (it is convex).
  const Vec2f axis = shape.center2 - shape.center1;
  CastOutput hit = first(castCircle(shape.center1, shape.radius, ray), castCircle(shape.center2, shape.radius, ray));
  if (lengthSquared(axis) > 0.0f) {
    const Vec2f n = normalize(Vec2f{axis.y, -axis.x});
    const Vec2f offset = n * shape.radius;
    hit = first(hit, castFrontSide(shape.center1 + offset, shape.center2 + offset, n, ray));
    hit = first(hit, castFrontSide(shape.center2 - offset, shape.center1 - offset, -n, ray));
  }
  return hit;
}

CastOutput rayCast(const Polygon& shape, const RayCastInput& ray) {
  requireRay(ray);
  const auto n = static_cast<std::size_t>(shape.count);
  if (shape.radius > 0.0f) {
    if (containsPoint(shape, ray.origin)) {
      return {};
    }
    // Rounded: the Minkowski sum of the core polygon and a disc is bounded by the edges pushed
    // out by r and the discs at the vertices.
    CastOutput hit;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2f offset = shape.normals[i] * shape.radius;
      hit = first(
          hit, castFrontSide(shape.vertices[i] + offset, shape.vertices[(i + 1) % n] + offset, shape.normals[i], ray));
      hit = first(hit, castCircle(shape.vertices[i], shape.radius, ray));
    }
    return hit;
  }
  // Cyrus-Beck: clip the parameter range against each edge's half-plane.
  float lower = 0.0f;
  float upper = ray.maxFraction;
  int index = -1;
  for (std::size_t i = 0; i < n; ++i) {
    const float numerator = dot(shape.normals[i], shape.vertices[i] - ray.origin);
    const float denominator = dot(shape.normals[i], ray.translation);
    if (denominator == 0.0f) {
      if (numerator < 0.0f) {
        return {}; // parallel and outside this edge
      }
    } else if (denominator < 0.0f && numerator < lower * denominator) {
      lower = numerator / denominator; // entering
      index = static_cast<int>(i);
    } else if (denominator > 0.0f && numerator < upper * denominator) {
      upper = numerator / denominator; // leaving
    }
    if (upper < lower) {
      return {};
    }
  }
  if (index < 0) {
    return {}; // the ray starts inside
  }
  return {shape.normals[static_cast<std::size_t>(index)], ray.origin + ray.translation * lower, lower, true};
}

CastOutput rayCast(const Segment& shape, const RayCastInput& ray) {
  requireRay(ray);
  const Vec2f edge = shape.point2 - shape.point1;
  if (lengthSquared(edge) == 0.0f) {
    return {};
  }
  Vec2f n = normalize(Vec2f{edge.y, -edge.x});
  if (dot(n, ray.translation) > 0.0f) {
    n = -n; // two-sided: face the ray
  }
  return castFrontSide(dot(n, Vec2f{edge.y, -edge.x}) > 0.0f ? shape.point1 : shape.point2,
                       dot(n, Vec2f{edge.y, -edge.x}) > 0.0f ? shape.point2 : shape.point1, n, ray);
}

bool containsPoint(const Circle& shape, const Vec2f& p) {
  return lengthSquared(p - shape.center) <= shape.radius * shape.radius;
}

bool containsPoint(const Capsule& shape, const Vec2f& p) {
  return lengthSquared(p - closestOnSegment(shape.center1, shape.center2, p)) <= shape.radius * shape.radius;
}

bool containsPoint(const Polygon& shape, const Vec2f& p) {
  const auto n = static_cast<std::size_t>(shape.count);
  float separation = -std::numeric_limits<float>::max();
  for (std::size_t i = 0; i < n; ++i) {
    separation = std::max(separation, dot(shape.normals[i], p - shape.vertices[i]));
  }
  if (separation <= 0.0f || shape.radius == 0.0f) {
    return separation <= 0.0f;
  }
  float nearest = std::numeric_limits<float>::max();
  for (std::size_t i = 0; i < n; ++i) {
    nearest = std::min(nearest, lengthSquared(p - closestOnSegment(shape.vertices[i], shape.vertices[(i + 1) % n], p)));
  }
  return nearest <= shape.radius * shape.radius;
}

} // namespace impetus::rigid2d
