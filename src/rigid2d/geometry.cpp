#include <impetus/core/polygon_mass.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/rigid2d/geometry.hpp>

#include <algorithm>
#include <limits>

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
  // Weld points closer than the linear slop.
  std::array<Vec2f, 8> unique{};
  std::size_t n = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    requireFinite(points[i], "points[" + std::to_string(i) + "]");
    const bool duplicate = std::any_of(unique.begin(), unique.begin() + static_cast<std::ptrdiff_t>(n),
                                       [&](const Vec2f& u) { return distance(u, points[i]) < linearSlop; });
    if (!duplicate) {
      unique[n++] = points[i];
    }
  }
  // Gift wrapping from the lowest-x (then lowest-y) point, counter-clockwise; on collinear
  // candidates the farthest wins, so collinear points are skipped.
  std::size_t start = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (unique[i].x < unique[start].x || (unique[i].x == unique[start].x && unique[i].y < unique[start].y)) {
      start = i;
    }
  }
  std::size_t count = 0;
  std::size_t current = start;
  do {
    if (count == storage.size()) {
      break;
    }
    storage[count++] = unique[current];
    std::size_t next = current == 0 ? 1 : 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (i == current || i == next) {
        continue;
      }
      const Vec2f e = unique[next] - unique[current];
      const float c = cross(e, unique[i] - unique[current]);
      // Clockwise of the edge (c < 0) means i is "more outside": take it.
      if (c < 0.0f || (c == 0.0f && lengthSquared(unique[i] - unique[current]) > lengthSquared(e))) {
        next = i;
      }
    }
    current = next;
  } while (current != start);
  // Remove vertices that lie (nearly) on the line through their neighbours.
  std::array<Vec2f, 8> kept{};
  std::size_t k = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const Vec2f& prev = storage[(i + count - 1) % count];
    const Vec2f& next = storage[(i + 1) % count];
    const Vec2f edge = next - prev;
    const float len = length(edge);
    const float offset = len > 0.0f ? cross(edge, storage[i] - prev) / len : 0.0f;
    if (std::abs(offset) > linearSlop) {
      kept[k++] = storage[i];
    }
  }
  if (k < 3) {
    throwInvalid("points", static_cast<double>(k), "the points are collinear or coincident: no area");
  }
  std::copy(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(k), storage.begin());
  return {storage.data(), k};
}

Polygon makePolygon(std::span<const Vec2f> points, float radius) {
  requireNonNegative(radius, "radius");
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
  requirePositive(halfWidth, "halfWidth");
  requirePositive(halfHeight, "halfHeight");
  requireFinite(center, "center");
  requireFinite(angle, "angle");
  const Transform2f xf{center, Rot2f::fromAngle(angle)};
  const std::array<Vec2f, 4> corners{
      transformPoint(xf, {-halfWidth, -halfHeight}), transformPoint(xf, {halfWidth, -halfHeight}),
      transformPoint(xf, {halfWidth, halfHeight}), transformPoint(xf, {-halfWidth, halfHeight})};
  return makePolygon(corners);
}

MassData computeMass(const Circle& shape, float density) {
  requirePositive(density, "density");
  requirePositive(shape.radius, "radius");
  const float rr = shape.radius * shape.radius;
  const float mass = density * pi<float> * rr;
  return {mass, shape.center, 0.5f * mass * rr};
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
  return {circleMass + boxMass, (shape.center1 + shape.center2) * 0.5f, circleInertia + boxInertia};
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
  return {static_cast<float>(m.mass),
          {static_cast<float>(m.centroid.x), static_cast<float>(m.centroid.y)},
          static_cast<float>(m.inertia)};
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
