// GJK distance and shape casts. GJK (Gilbert, Johnson, Keerthi) finds the point of the Minkowski
// difference B - A closest to the origin with a simplex of at most three support points; that
// point is the vector between the closest points of A and B. The simplex is reduced by Voronoi
// regions with barycentric coordinates (Box2D's formulation), and the search stops when a support
// point repeats, which is exact for polytopes.
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/rigid2d/distance.hpp>

#include <algorithm>
#include <limits>
#include <string>

namespace impetus::rigid2d {
namespace {

constexpr float epsilon = std::numeric_limits<float>::epsilon();

/// A bound far above what a convex polygon of 8 vertices needs (one or two iterations per
/// vertex): it only stops cycling on degenerate, nearly-collinear input.
constexpr int maxGjkIterations = 20;

void requireProxy(const ShapeProxy& p, const char* name) {
  if (p.count < 1 || p.count > maxPolygonVertices) {
    throwInvalid(std::string(name) + ".count", p.count, "must be between 1 and 8");
  }
  if (!(std::isfinite(p.radius) && p.radius >= 0.0f)) {
    throwInvalid(std::string(name) + ".radius", static_cast<double>(p.radius), "must be finite and non-negative");
  }
}

void requireTransform(const Transform2f& xf, const char* name) {
  if (isFinite(xf.p) && std::isfinite(xf.q.c) && std::isfinite(xf.q.s)) {
    return;
  }
  const std::string field(name);
  requireFinite(xf.p, field + ".p");
  requireFinite(static_cast<double>(xf.q.c), field + ".q.c");
  requireFinite(static_cast<double>(xf.q.s), field + ".q.s");
}

/// The index of the point farthest along d (the first of equals).
int findSupport(const ShapeProxy& p, const Vec2f& d) {
  int best = 0;
  float bestValue = dot(p.points[0], d);
  for (int i = 1; i < p.count; ++i) {
    const float value = dot(p.points[static_cast<std::size_t>(i)], d);
    if (value > bestValue) {
      best = i;
      bestValue = value;
    }
  }
  return best;
}

struct SimplexVertex {
  Vec2f wA;       ///< support point of A
  Vec2f wB;       ///< support point of B
  Vec2f w;        ///< wB - wA: a point of the Minkowski difference
  float a = 1.0f; ///< barycentric coordinate of the closest point
  int indexA = 0;
  int indexB = 0;
};

struct Simplex {
  std::array<SimplexVertex, 3> v{};
  int count = 0;
};

SimplexVertex makeVertex(const ShapeProxy& a, const ShapeProxy& b, int indexA, int indexB) {
  SimplexVertex v;
  v.indexA = indexA;
  v.indexB = indexB;
  v.wA = a.points[static_cast<std::size_t>(indexA)];
  v.wB = b.points[static_cast<std::size_t>(indexB)];
  v.w = v.wB - v.wA;
  return v;
}

/// The starting simplex: the cached one when it fits these proxies and is not degenerate (the
/// shapes may have moved so that its points coincide or line up), otherwise one vertex.
Simplex simplexFromCache(const SimplexCache* cache, const ShapeProxy& a, const ShapeProxy& b) {
  Simplex s;
  if (cache != nullptr && cache->count >= 1 && cache->count <= 3) {
    bool valid = true;
    for (int i = 0; i < cache->count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      valid = valid && cache->indexA[k] < a.count && cache->indexB[k] < b.count;
    }
    if (valid) {
      s.count = cache->count;
      for (int i = 0; i < s.count; ++i) {
        const auto k = static_cast<std::size_t>(i);
        s.v[k] = makeVertex(a, b, cache->indexA[k], cache->indexB[k]);
      }
    }
  }
  if (s.count == 2) {
    const Vec2f e12 = s.v[1].w - s.v[0].w;
    if (lengthSquared(e12) <= epsilon * epsilon * std::max(lengthSquared(s.v[0].w), 1.0f)) {
      s.count = 1;
    }
  } else if (s.count == 3) {
    const Vec2f e12 = s.v[1].w - s.v[0].w;
    const Vec2f e13 = s.v[2].w - s.v[0].w;
    if (std::abs(cross(e12, e13)) <= epsilon * length(e12) * length(e13)) {
      s.count = 1;
    }
  }
  if (s.count == 0) {
    s.v[0] = makeVertex(a, b, 0, 0);
    s.count = 1;
  }
  return s;
}

/// Reduces a segment simplex to the Voronoi region of the origin: vertex w1, vertex w2 or the
/// edge (with barycentric weights of the origin's projection).
void solve2(Simplex& s) {
  const Vec2f w1 = s.v[0].w;
  const Vec2f w2 = s.v[1].w;
  const Vec2f e12 = w2 - w1;
  const float d12n2 = -dot(w1, e12); // > 0: the origin is past w1 along the edge
  if (d12n2 <= 0.0f) {
    s.v[0].a = 1.0f;
    s.count = 1;
    return;
  }
  const float d12n1 = dot(w2, e12); // > 0: the origin is before w2
  if (d12n1 <= 0.0f) {
    s.v[1].a = 1.0f;
    s.v[0] = s.v[1];
    s.count = 1;
    return;
  }
  const float inv = 1.0f / (d12n1 + d12n2);
  s.v[0].a = d12n1 * inv;
  s.v[1].a = d12n2 * inv;
  s.count = 2;
}

/// Reduces a triangle simplex to the Voronoi region (vertex, edge or interior) holding the origin.
void solve3(Simplex& s) {
  const Vec2f w1 = s.v[0].w;
  const Vec2f w2 = s.v[1].w;
  const Vec2f w3 = s.v[2].w;

  // Unnormalized barycentric coordinates of the origin on each edge.
  const Vec2f e12 = w2 - w1;
  const float d12n1 = dot(w2, e12);
  const float d12n2 = -dot(w1, e12);
  const Vec2f e13 = w3 - w1;
  const float d13n1 = dot(w3, e13);
  const float d13n2 = -dot(w1, e13);
  const Vec2f e23 = w3 - w2;
  const float d23n1 = dot(w3, e23);
  const float d23n2 = -dot(w2, e23);

  // ... and in the triangle (signed sub-areas, signed by the winding).
  const float n123 = cross(e12, e13);
  const float d123n1 = n123 * cross(w2, w3);
  const float d123n2 = n123 * cross(w3, w1);
  const float d123n3 = n123 * cross(w1, w2);

  if (d12n2 <= 0.0f && d13n2 <= 0.0f) { // vertex 1
    s.v[0].a = 1.0f;
    s.count = 1;
    return;
  }
  if (d12n1 > 0.0f && d12n2 > 0.0f && d123n3 <= 0.0f) { // edge 12
    const float inv = 1.0f / (d12n1 + d12n2);
    s.v[0].a = d12n1 * inv;
    s.v[1].a = d12n2 * inv;
    s.count = 2;
    return;
  }
  if (d13n1 > 0.0f && d13n2 > 0.0f && d123n2 <= 0.0f) { // edge 13
    const float inv = 1.0f / (d13n1 + d13n2);
    s.v[0].a = d13n1 * inv;
    s.v[2].a = d13n2 * inv;
    s.v[1] = s.v[2];
    s.count = 2;
    return;
  }
  if (d12n1 <= 0.0f && d23n2 <= 0.0f) { // vertex 2
    s.v[1].a = 1.0f;
    s.v[0] = s.v[1];
    s.count = 1;
    return;
  }
  if (d13n1 <= 0.0f && d23n1 <= 0.0f) { // vertex 3
    s.v[2].a = 1.0f;
    s.v[0] = s.v[2];
    s.count = 1;
    return;
  }
  if (d23n1 > 0.0f && d23n2 > 0.0f && d123n1 <= 0.0f) { // edge 23
    const float inv = 1.0f / (d23n1 + d23n2);
    s.v[1].a = d23n1 * inv;
    s.v[2].a = d23n2 * inv;
    s.v[0] = s.v[2];
    s.count = 2;
    return;
  }
  // Interior: the origin is inside, the shapes overlap. Round-off on a nearly flat triangle can
  // leave no positive area; any point of the triangle then serves.
  const float sum = d123n1 + d123n2 + d123n3;
  if (sum > 0.0f) {
    const float inv = 1.0f / sum;
    s.v[0].a = d123n1 * inv;
    s.v[1].a = d123n2 * inv;
    s.v[2].a = d123n3 * inv;
  } else {
    s.v[0].a = s.v[1].a = s.v[2].a = 1.0f / 3.0f;
  }
  s.count = 3;
}

/// The direction from the simplex toward the origin. For a segment it is the edge's
/// perpendicular on the origin's side rather than minus the closest point: exact in direction
/// even when the closest point has round-off.
Vec2f searchDirection(const Simplex& s) {
  if (s.count == 1) {
    return -s.v[0].w;
  }
  const Vec2f e12 = s.v[1].w - s.v[0].w;
  return cross(e12, -s.v[0].w) > 0.0f ? perp(e12) : -perp(e12);
}

struct Witness {
  Vec2f pointA;
  Vec2f pointB;
};

Witness witnessPoints(const Simplex& s) {
  switch (s.count) {
  case 1:
    return {s.v[0].wA, s.v[0].wB};
  case 2:
    return {s.v[0].wA * s.v[0].a + s.v[1].wA * s.v[1].a, s.v[0].wB * s.v[0].a + s.v[1].wB * s.v[1].a};
  default: {
    // Overlap: one point, the same for both shapes.
    const Vec2f p = s.v[0].wA * s.v[0].a + s.v[1].wA * s.v[1].a + s.v[2].wA * s.v[2].a;
    return {p, p};
  }
  }
}

/// GJK on two proxies given in the same frame, without radii: the closest points of the cores.
/// Shared by shapeDistance and shapeCast (which moves B's points itself).
DistanceOutput coreDistance(const ShapeProxy& a, const ShapeProxy& b, SimplexCache* cache) {
  Simplex s = simplexFromCache(cache, a, b);

  int iteration = 0;
  while (iteration < maxGjkIterations) {
    // The vertices before this step, to detect a repeated support point.
    const int saveCount = s.count;
    std::array<int, 3> saveA{};
    std::array<int, 3> saveB{};
    for (int i = 0; i < saveCount; ++i) {
      saveA[static_cast<std::size_t>(i)] = s.v[static_cast<std::size_t>(i)].indexA;
      saveB[static_cast<std::size_t>(i)] = s.v[static_cast<std::size_t>(i)].indexB;
    }

    if (s.count == 2) {
      solve2(s);
    } else if (s.count == 3) {
      solve3(s);
    }
    if (s.count == 3) {
      break; // the origin is inside the triangle: overlap
    }

    const Vec2f d = searchDirection(s);
    if (lengthSquared(d) < epsilon * epsilon) {
      // The origin is on the simplex (to round-off): touching or overlapping. A further support
      // point would be computed along a meaningless direction.
      break;
    }

    // New support point of B - A along d: B's farthest along d minus A's farthest along -d.
    SimplexVertex& v = s.v[static_cast<std::size_t>(s.count)];
    v = makeVertex(a, b, findSupport(a, -d), findSupport(b, d));
    ++iteration;

    // A repeated support point means no progress: the simplex holds the closest point.
    bool duplicate = false;
    for (int i = 0; i < saveCount; ++i) {
      const auto k = static_cast<std::size_t>(i);
      duplicate = duplicate || (v.indexA == saveA[k] && v.indexB == saveB[k]);
    }
    if (duplicate) {
      break;
    }
    ++s.count;
  }
  if (iteration == maxGjkIterations) {
    // Out of iterations right after adding a vertex: reduce the simplex so that its weights are
    // current (the closest point so far).
    if (s.count == 2) {
      solve2(s);
    } else if (s.count == 3) {
      solve3(s);
    }
  }

  if (cache != nullptr) {
    cache->count = s.count;
    for (int i = 0; i < s.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      cache->indexA[k] = static_cast<std::uint8_t>(s.v[k].indexA);
      cache->indexB[k] = static_cast<std::uint8_t>(s.v[k].indexB);
    }
  }

  DistanceOutput out;
  const Witness w = witnessPoints(s);
  out.pointA = w.pointA;
  out.pointB = w.pointB;
  out.distance = distance(w.pointA, w.pointB);
  // Below float resolution of the gap there is no reliable direction. Against an edge the normal
  // is the edge's perpendicular: its direction is as exact as the edge, where the difference of
  // the witness points loses digits over a millimetre gap (the normal a shape cast stops on).
  if (out.distance <= epsilon) {
    out.normal = Vec2f{};
  } else if (s.count == 2) {
    out.normal = normalize(-searchDirection(s));
  } else {
    out.normal = (w.pointB - w.pointA) / out.distance;
  }
  out.iterations = iteration;
  out.simplexCount = s.count;
  return out;
}

} // namespace

ShapeProxy makeProxy(std::span<const Vec2f> points, float radius) {
  if (points.empty() || points.size() > static_cast<std::size_t>(maxPolygonVertices)) {
    throwInvalid("points.size", static_cast<double>(points.size()), "must be between 1 and 8");
  }
  requireNonNegative(static_cast<double>(radius), "radius");
  ShapeProxy p;
  for (std::size_t i = 0; i < points.size(); ++i) {
    requireFinite(points[i], "points[" + std::to_string(i) + "]");
    p.points[i] = points[i];
  }
  p.count = static_cast<int>(points.size());
  p.radius = radius;
  return p;
}

ShapeProxy makeProxy(const Polygon& polygon) {
  return makeProxy(std::span<const Vec2f>(polygon.vertices.data(), static_cast<std::size_t>(polygon.count)),
                   polygon.radius);
}

ShapeProxy makeProxy(const Circle& circle) {
  return makeProxy(std::span<const Vec2f>(&circle.center, 1), circle.radius);
}

ShapeProxy makeProxy(const Capsule& capsule) {
  const std::array<Vec2f, 2> points{capsule.center1, capsule.center2};
  return makeProxy(points, capsule.radius);
}

ShapeProxy makeProxy(const Segment& segment) {
  const std::array<Vec2f, 2> points{segment.point1, segment.point2};
  return makeProxy(points, 0.0f);
}

DistanceOutput shapeDistance(const ShapeProxy& a, const Transform2f& xfA, const ShapeProxy& b, const Transform2f& xfB,
                             bool useRadii, SimplexCache* cache) {
  requireProxy(a, "a");
  requireProxy(b, "b");
  requireTransform(xfA, "xfA");
  requireTransform(xfB, "xfB");

  // Work in A's frame: B's points relative to A stay small when both are far from the origin.
  const Transform2f relative = invMul(xfA, xfB);
  ShapeProxy localB = b;
  for (int i = 0; i < b.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    localB.points[k] = transformPoint(relative, b.points[k]);
  }

  DistanceOutput out = coreDistance(a, localB, cache);
  if (useRadii) {
    if (out.distance <= epsilon) {
      // The cores touch or overlap: the shapes overlap by at least the radii, in no direction.
      const Vec2f p = (out.pointA + out.pointB) * 0.5f;
      out.pointA = p;
      out.pointB = p;
      out.distance = 0.0f;
    } else {
      // Points on the rounded surfaces even when they overlap, so they move continuously.
      out.pointA += out.normal * a.radius;
      out.pointB -= out.normal * b.radius;
      out.distance = std::max(0.0f, out.distance - a.radius - b.radius);
    }
  }
  out.pointA = transformPoint(xfA, out.pointA);
  out.pointB = transformPoint(xfA, out.pointB);
  out.normal = rotate(xfA.q, out.normal);
  return out;
}

CastOutput shapeCast(const ShapeCastInput& input) {
  requireProxy(input.a, "a");
  requireProxy(input.b, "b");
  requireTransform(input.xfA, "xfA");
  requireTransform(input.xfB, "xfB");
  requireFinite(input.translationB, "translationB");
  if (!(input.maxFraction >= 0.0f && input.maxFraction <= 1.0f)) {
    throwInvalid("maxFraction", static_cast<double>(input.maxFraction), "must be in [0, 1]");
  }

  // Everything in A's frame (see shapeDistance).
  const ShapeProxy& a = input.a;
  const Transform2f relative = invMul(input.xfA, input.xfB);
  ShapeProxy startB = input.b;
  for (int i = 0; i < startB.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    startB.points[k] = transformPoint(relative, input.b.points[k]);
  }
  const Vec2f translation = inverseRotate(input.xfA.q, input.translationB);

  // Stop with the cores this far apart: rounded shapes just into the slop the contacts tolerate,
  // sharp ones linearSlop apart (GJK gives no normal for touching cores).
  const float radius = a.radius + startB.radius;
  const float target = std::max(linearSlop, radius - linearSlop);
  const float tolerance = 0.25f * linearSlop;

  CastOutput out;
  out.fraction = input.maxFraction;
  ShapeProxy movedB = startB;
  SimplexCache cache;
  float fraction = 0.0f;
  // Conservative advancement converges in a few steps for polytopes (the distance along the
  // closest-point normal is linear in the fraction); the bound only guards grazing approaches.
  constexpr int maxIterations = 20;
  for (int iteration = 0; iteration < maxIterations; ++iteration) {
    const DistanceOutput d = coreDistance(a, movedB, &cache);

    if (d.distance < target + tolerance) {
      out.hit = true;
      if (iteration == 0) {
        // Already within reach at the start: hit at fraction 0, at the point between them.
        out.fraction = 0.0f;
        const Vec2f onA = d.pointA + d.normal * a.radius;
        const Vec2f onB = d.pointB - d.normal * startB.radius;
        out.point = transformPoint(input.xfA, (onA + onB) * 0.5f);
        out.normal = rotate(input.xfA.q, d.normal);
      } else {
        out.fraction = fraction;
        out.point = transformPoint(input.xfA, d.pointA + d.normal * a.radius);
        out.normal = rotate(input.xfA.q, d.normal);
      }
      return out;
    }

    // The gap along the normal closes at rate -dot(translation, normal) per unit fraction, and
    // no other direction closes it faster, so advancing to the target on it never overshoots.
    const float closing = dot(translation, d.normal);
    if (closing >= 0.0f) {
      return out; // moving apart or sideways: miss
    }
    fraction += (target - d.distance) / closing;
    if (fraction >= input.maxFraction) {
      return out; // does not reach A in time
    }
    for (int i = 0; i < movedB.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      movedB.points[k] = startB.points[k] + translation * fraction;
    }
  }
  return out; // did not converge: report a miss rather than a wrong fraction
}

} // namespace impetus::rigid2d
