// GJK distance: the point of the Minkowski difference A - B closest to the origin, from a simplex
// of support points grown toward it. The simplex's closest point comes from Ericson's Voronoi-
// region tests (Real-Time Collision Detection 5.1.5 and 5.1.6), in double: the simplex of two
// nearly touching hulls is thin, and its barycentric weights need the digits.
#include <impetus/rigid3d/distance.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace impetus::rigid3d {

namespace {

/// GJK stops when a new support point brings the distance less than this fraction of its
/// square closer (dimensionless): the rounding of float points.
constexpr double convergenceTolerance = 1.0e-10;
/// A tetrahedron whose volume is below this fraction of the product of its edges from one
/// vertex is flat (dimensionless).
constexpr double flatVolumeTolerance = 1.0e-12;

struct SimplexVertex {
  Vec3d a, b; ///< support points of A and B
  Vec3d w;    ///< a - b
  std::uint32_t indexA = 0, indexB = 0;
  double weight = 0.0; ///< barycentric, in the closest point
};

struct Simplex {
  std::array<SimplexVertex, 4> v;
  int count = 0;
};

Vec3d toDouble(const Vec3f& p) { return {p.x, p.y, p.z}; }

std::uint32_t support(std::span<const Vec3f> points, const Vec3d& direction) {
  std::uint32_t best = 0;
  double bestDot = dot(toDouble(points[0]), direction);
  for (std::uint32_t i = 1; i < points.size(); ++i) {
    if (const double d = dot(toDouble(points[i]), direction); d > bestDot) {
      best = i;
      bestDot = d;
    }
  }
  return best;
}

/// Keeps the vertices `keep` with their weights, in their order.
void reduce(Simplex& s, std::initializer_list<std::pair<int, double>> keep) {
  Simplex out;
  for (const auto& [index, weight] : keep) {
    out.v[static_cast<std::size_t>(out.count)] = s.v[static_cast<std::size_t>(index)];
    out.v[static_cast<std::size_t>(out.count)].weight = weight;
    ++out.count;
  }
  s = out;
}

void closestOnSegment(Simplex& s) {
  const Vec3d& a = s.v[0].w;
  const Vec3d ab = s.v[1].w - a;
  const double t = -dot(a, ab) / dot(ab, ab);
  if (!(t > 0.0)) {
    reduce(s, {{0, 1.0}});
  } else if (t >= 1.0) {
    reduce(s, {{1, 1.0}});
  } else {
    reduce(s, {{0, 1.0 - t}, {1, t}});
  }
}

/// The closest point of triangle (i, j, k) of the simplex to the origin, as the vertices and
/// weights it is made of; its squared distance.
double closestOnTriangle(const Simplex& s, int i, int j, int k, Simplex& out) {
  const Vec3d& a = s.v[static_cast<std::size_t>(i)].w;
  const Vec3d& b = s.v[static_cast<std::size_t>(j)].w;
  const Vec3d& c = s.v[static_cast<std::size_t>(k)].w;
  out = s;
  const Vec3d ab = b - a;
  const Vec3d ac = c - a;
  const double d1 = -dot(ab, a);
  const double d2 = -dot(ac, a);
  const auto finish = [&](std::initializer_list<std::pair<int, double>> keep) {
    reduce(out, keep);
    Vec3d p;
    for (int n = 0; n < out.count; ++n) {
      p += out.v[static_cast<std::size_t>(n)].w * out.v[static_cast<std::size_t>(n)].weight;
    }
    return dot(p, p);
  };
  if (d1 <= 0.0 && d2 <= 0.0) {
    return finish({{i, 1.0}});
  }
  const double d3 = -dot(ab, b);
  const double d4 = -dot(ac, b);
  if (d3 >= 0.0 && d4 <= d3) {
    return finish({{j, 1.0}});
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double t = d1 / (d1 - d3);
    return finish({{i, 1.0 - t}, {j, t}});
  }
  const double d5 = -dot(ab, c);
  const double d6 = -dot(ac, c);
  if (d6 >= 0.0 && d5 <= d6) {
    return finish({{k, 1.0}});
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double t = d2 / (d2 - d6);
    return finish({{i, 1.0 - t}, {k, t}});
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return finish({{j, 1.0 - t}, {k, t}});
  }
  const double inverse = 1.0 / (va + vb + vc);
  const double v = vb * inverse;
  const double w = vc * inverse;
  return finish({{i, 1.0 - v - w}, {j, v}, {k, w}});
}

/// Whether the origin and point d lie on opposite sides of the plane through a, b, c.
bool originOutside(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& d) {
  const Vec3d n = cross(b - a, c - a);
  const double origin = -dot(a, n);
  const double other = dot(d - a, n);
  return origin * other < 0.0;
}

/// Reduces the simplex to the feature closest to the origin; false when the origin is inside
/// the tetrahedron (the cores overlap).
bool closestOnSimplex(Simplex& s) {
  switch (s.count) {
  case 1:
    s.v[0].weight = 1.0;
    return true;
  case 2:
    closestOnSegment(s);
    return true;
  case 3: {
    Simplex out;
    closestOnTriangle(s, 0, 1, 2, out);
    s = out;
    return true;
  }
  default: {
    const Vec3d& a = s.v[0].w;
    const Vec3d& b = s.v[1].w;
    const Vec3d& c = s.v[2].w;
    const Vec3d& d = s.v[3].w;
    constexpr std::array<std::array<int, 4>, 4> faces{{{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}}};
    const std::array<const Vec3d*, 4> w{&a, &b, &c, &d};
    // A flat tetrahedron (the new point in the triangle's plane, where rounding put it) has no
    // inside: the nearest of its faces is the answer.
    const double volume = dot(b - a, cross(c - a, d - a));
    const bool flat = std::abs(volume) <= flatVolumeTolerance * length(b - a) * length(c - a) * length(d - a);
    double best = -1.0;
    Simplex closest;
    for (const auto& f : faces) {
      if (!flat && !originOutside(*w[static_cast<std::size_t>(f[0])], *w[static_cast<std::size_t>(f[1])],
                                  *w[static_cast<std::size_t>(f[2])], *w[static_cast<std::size_t>(f[3])])) {
        continue;
      }
      Simplex out;
      if (const double d2 = closestOnTriangle(s, f[0], f[1], f[2], out); best < 0.0 || d2 < best) {
        best = d2;
        closest = out;
      }
    }
    if (best < 0.0) {
      return false;
    }
    s = closest;
    return true;
  }
  }
}

} // namespace

DistanceOutput coreDistance(const DistanceProxy& a, const DistanceProxy& b) {
  Simplex s;
  const auto add = [&](std::uint32_t ia, std::uint32_t ib) {
    SimplexVertex& v = s.v[static_cast<std::size_t>(s.count++)];
    v.a = toDouble(a.points[ia]);
    v.b = toDouble(b.points[ib]);
    v.w = v.a - v.b;
    v.indexA = ia;
    v.indexB = ib;
  };
  add(0, 0);
  DistanceOutput out;
  Vec3d closest = s.v[0].w;
  for (out.iterations = 0; out.iterations < maxGjkIterations; ++out.iterations) {
    if (!closestOnSimplex(s)) {
      out.overlap = true;
      return out;
    }
    closest = {};
    for (int n = 0; n < s.count; ++n) {
      closest += s.v[static_cast<std::size_t>(n)].w * s.v[static_cast<std::size_t>(n)].weight;
    }
    const double distanceSquared = dot(closest, closest);
    if (distanceSquared == 0.0) {
      out.overlap = true;
      return out;
    }
    // The support point of A - B farthest toward the origin.
    const std::uint32_t ia = support(a.points, -closest);
    const std::uint32_t ib = support(b.points, closest);
    const Vec3d w = toDouble(a.points[ia]) - toDouble(b.points[ib]);
    bool repeated = false;
    for (int n = 0; n < s.count; ++n) {
      repeated =
          repeated || (s.v[static_cast<std::size_t>(n)].indexA == ia && s.v[static_cast<std::size_t>(n)].indexB == ib);
    }
    if (repeated || distanceSquared - dot(closest, w) <= convergenceTolerance * distanceSquared) {
      break; // no point of A - B is nearer the origin than the simplex already is
    }
    add(ia, ib);
  }
  Vec3d pa;
  Vec3d pb;
  for (int n = 0; n < s.count; ++n) {
    pa += s.v[static_cast<std::size_t>(n)].a * s.v[static_cast<std::size_t>(n)].weight;
    pb += s.v[static_cast<std::size_t>(n)].b * s.v[static_cast<std::size_t>(n)].weight;
  }
  out.pointA = {static_cast<float>(pa.x), static_cast<float>(pa.y), static_cast<float>(pa.z)};
  out.pointB = {static_cast<float>(pb.x), static_cast<float>(pb.y), static_cast<float>(pb.z)};
  out.distance = static_cast<float>(length(pa - pb));
  return out;
}

} // namespace impetus::rigid3d
