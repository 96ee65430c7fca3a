// The polygon narrowphase: two convex polygons, each with a radius (capsules and segments as
// 2-vertex polygons, rounded polygons), by the separating-axis test, a reference face and the
// clip of the incident edge to it, or, with the cores apart beyond the face's side planes, their
// closest points (the steps in polygon_narrowphase.hpp). Two shortcuts give the general path's
// manifold bit for bit on fewer floats: two plain boxes (makeBox, box_manifold.cpp), and A an
// axis-aligned rectangle (here). Circles are in manifold.cpp.
#include "rigid2d/polygon_narrowphase.hpp"

namespace impetus::rigid2d {
namespace {

using namespace narrowphase;

/// The empty manifold, to copy from. Not const on purpose: a Manifold's zero initialisation
/// compiles to a string store (rep stos), a few ns per call here, where copying this one is six
/// vector moves; as a constant the compiler would fold it back into that zero initialisation.
constinit Manifold emptyManifold{};

/// The general path: B in A's frame, both separating-axis searches in full, then the clip.
void collideGeneral(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB, Manifold& m) {
  const Transform2f relative = invMul(xfA, xfB);
  std::array<Vec2f, maxPolygonVertices> vertices;
  std::array<Vec2f, maxPolygonVertices> normals;
  for (int i = 0; i < b.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    vertices[k] = transformPoint(relative, b.vertices[k]);
    normals[k] = rotate(relative.q, b.normals[k]);
  }
  const PolygonView pa = view(a);
  const PolygonView pb{vertices.data(), normals.data(), b.count};
  const float radius = a.radius + b.radius;
  const EdgeSeparation sa = maxSeparation(pa, pb);
  if (sa.separation - radius > speculativeDistance) {
    m.separationBound = sa.separation - radius;
    return;
  }
  const EdgeSeparation sb = maxSeparation(pb, pa);
  if (sb.separation - radius > speculativeDistance) {
    m.separationBound = sb.separation - radius;
    return;
  }
  clipContact<0, 0>(pa, a.radius, pb, b.radius, sa, sb, xfA, xfB, m);
}

/// Whether `p` is a rectangle along its own frame's axes (makeBox; makeOffsetBox at angle 0):
/// its corners are {x0, x2} x {y0, y2} and each normal has an exactly zero component.
bool isAxisAlignedRectangle(const Polygon& p) {
  if (p.count != 4) {
    return false;
  }
  const auto& v = p.vertices;
  const bool grid = (v[1].x == v[0].x && v[1].y == v[2].y && v[3].x == v[2].x && v[3].y == v[0].y) ||
                    (v[1].y == v[0].y && v[1].x == v[2].x && v[3].y == v[2].y && v[3].x == v[0].x);
  const auto axial = [](const Vec2f& n) { return n.x == 0.0f || n.y == 0.0f; };
  return grid && axial(p.normals[0]) && axial(p.normals[1]) && axial(p.normals[2]) && axial(p.normals[3]);
}

/// collidePolygons when A is an axis-aligned rectangle (CountB > 0: B has that many vertices).
/// The two separating-axis searches shrink from count x count dot products each to one per
/// edge, with exactly the general search's float results, so the manifold is the same:
/// - A's normal has one zero component, so its dot product with (vertex of B - vertex of A)
///   depends on one coordinate of B's vertex, and monotonically (float rounding is monotone):
///   B's least or greatest x (or y) in A's frame gives the minimum.
/// - For B's normal, the dot product with (corner of A - vertex of B) is monotone in the
///   corner's x and in its y separately, and A's corners are all four combinations of its two
///   x and two y values: the corner with the x and the y against the normal gives the minimum.
template <int CountB>
void collideRectangle(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB, Manifold& m) {
  const int countB = CountB > 0 ? CountB : b.count;
  const Transform2f relative = invMul(xfA, xfB);
  std::array<Vec2f, maxPolygonVertices> vertices;
  std::array<Vec2f, maxPolygonVertices> normals;
  vertices[0] = transformPoint(relative, b.vertices[0]);
  normals[0] = rotate(relative.q, b.normals[0]);
  Vec2f lower = vertices[0];
  Vec2f upper = vertices[0];
  for (int i = 1; i < countB; ++i) {
    const auto k = static_cast<std::size_t>(i);
    vertices[k] = transformPoint(relative, b.vertices[k]);
    normals[k] = rotate(relative.q, b.normals[k]);
    lower = {std::min(lower.x, vertices[k].x), std::min(lower.y, vertices[k].y)};
    upper = {std::max(upper.x, vertices[k].x), std::max(upper.y, vertices[k].y)};
  }
  const float radius = a.radius + b.radius;
  EdgeSeparation sa;
  for (int i = 0; i < 4; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec2f n = a.normals[k];
    const Vec2f deepest{n.x > 0.0f ? lower.x : upper.x, n.y > 0.0f ? lower.y : upper.y};
    const float separation = dot(n, deepest - a.vertices[k]);
    if (separation > sa.separation) {
      sa = {i, separation};
    }
  }
  if (sa.separation - radius > speculativeDistance) {
    m.separationBound = sa.separation - radius;
    return;
  }
  const Vec2f aLower{std::min(a.vertices[0].x, a.vertices[2].x), std::min(a.vertices[0].y, a.vertices[2].y)};
  const Vec2f aUpper{std::max(a.vertices[0].x, a.vertices[2].x), std::max(a.vertices[0].y, a.vertices[2].y)};
  EdgeSeparation sb;
  for (int i = 0; i < countB; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec2f n = normals[k];
    const Vec2f deepest{n.x > 0.0f ? aLower.x : aUpper.x, n.y > 0.0f ? aLower.y : aUpper.y};
    const float separation = dot(n, deepest - vertices[k]);
    if (separation > sb.separation) {
      sb = {i, separation};
    }
  }
  if (sb.separation - radius > speculativeDistance) {
    m.separationBound = sb.separation - radius;
    return;
  }
  clipContact<4, CountB>(view(a), a.radius, {vertices.data(), normals.data(), countB}, b.radius, sa, sb, xfA, xfB, m);
}

/// collidePolygons' choice of path (detail::polygonPath).
detail::PolygonPath pathFor(const Polygon& a, const Polygon& b) {
  if (isPlainBox(a, false) && isPlainBox(b, true)) {
    return detail::PolygonPath::boxes;
  }
  return isAxisAlignedRectangle(a) ? detail::PolygonPath::rectangle : detail::PolygonPath::general;
}

} // namespace

namespace detail {

Manifold collidePolygonsGeneral(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB) {
  Manifold m = emptyManifold;
  collideGeneral(a, xfA, b, xfB, m);
  return m;
}

PolygonPath polygonPath(const Polygon& a, const Polygon& b) { return pathFor(a, b); }

} // namespace detail

Manifold collidePolygons(const Polygon& a, const Transform2f& xfA, const Polygon& b, const Transform2f& xfB) {
  // One named result for every path: built in place, not copied out.
  Manifold m = emptyManifold;
  switch (pathFor(a, b)) {
  case detail::PolygonPath::boxes:
    collideBoxes(a, xfA, b, xfB, m);
    break;
  case detail::PolygonPath::rectangle:
    if (b.count == 4) {
      collideRectangle<4>(a, xfA, b, xfB, m);
    } else {
      collideRectangle<0>(a, xfA, b, xfB, m);
    }
    break;
  case detail::PolygonPath::general:
    collideGeneral(a, xfA, b, xfB, m);
    break;
  }
  return m;
}

} // namespace impetus::rigid2d
