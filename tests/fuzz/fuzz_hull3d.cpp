// Fuzzes the 3D hull maker (include/impetus/rigid3d/hull.hpp): a cloud of 4 to 80 points
// through computeHull with a vertex cap. The clouds: random ones, with duplicates, coplanar
// (exactly, in an axis plane, or up to rounding, in a turned one, with a point or all of them a
// little off the plane), on a sphere (more extreme points than the cap), on an integer lattice
// (many points on each face and edge), prisms (two parallel polygons), and clouds with special
// values (NaN, infinities, 1e38, denormals); at scales from 1e-4 to 1e11, near the origin or far
// from it.
//
// Either computeHull throws impetus::Error (and nothing else) for what it documents (a cap
// outside 4..maxHullVertices, a non-finite point, a cloud without volume: a refused cloud with a
// tetrahedron of its points wider than 16 times the maker's coplanarity tolerance is a finding),
// or the hull is valid:
//  - 4 to maxVertices vertices, each one of the input points, no two equal, each on at least
//    three faces; at least 4 faces, one plane each;
//  - half-edges: each face's loop closes (at least 3 edges, all naming the face), every half-edge
//    in exactly one loop, each half-edge's twin's twin is itself, on another face, running the
//    other way (from the next half-edge's origin to this one's);
//  - every plane's normal finite and of unit length, every face's points on its plane and every
//    hull point behind every plane within `tol` (1e-5 of the cloud's largest point distance from
//    the origin: the world's convexityTolerance, relative at any scale); every face wound
//    counter-clockwise seen from outside (its loop's Newell normal along the plane's);
//  - when the cloud has no more distinct points than the cap, every input point behind every plane
//    within `tol` (the hull holds the cloud; beyond the cap, points may lie outside, as documented);
//  - accepted by requireValidGeometry (World::createShape's check);
//  - massProperties(hull, 1000 kg/m^3) finite, with positive mass (no more than the cloud's
//    bounding box holds), positive inertia diagonal, the centre of mass inside.
#include "fuzz_support3d.hpp"

#include <impetus/error.hpp>
#include <impetus/rigid3d/geometry.hpp>
#include <impetus/rigid3d/hull.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <limits>
#include <span>
#include <string>
#include <tuple>
#include <typeinfo>
#include <vector>

namespace {

using impetus::Quatf;
using impetus::Vec3f;
using impetus::fuzz::d3;
using impetus::fuzz::str;
using impetus::fuzz::V3;
namespace r3 = impetus::rigid3d;

/// computeHull's coplanarity tolerance (src/rigid3d/quickhull.cpp: 3 float epsilons of the sum
/// of the cloud's largest coordinates), recomputed to judge its refusals.
double makerTolerance(std::span<const Vec3f> cloud) {
  V3 largest;
  for (const Vec3f& p : cloud) {
    largest = {std::max(largest.x, std::abs(static_cast<double>(p.x))),
               std::max(largest.y, std::abs(static_cast<double>(p.y))),
               std::max(largest.z, std::abs(static_cast<double>(p.z)))};
  }
  return 3.0 * std::numeric_limits<float>::epsilon() * std::max(largest.x + largest.y + largest.z, 1e-30);
}

/// The distance between the lines through p, q and through r, s (0 for parallel ones).
double lineDistance(V3 p, V3 q, V3 r, V3 s) {
  const V3 n = impetus::fuzz::cross(q - p, s - r);
  const double l = impetus::fuzz::len(n);
  return l > 0.0 ? std::abs(impetus::fuzz::dot(r - p, n)) / l : 0.0;
}

/// The height of p over the plane of a, b, c (0 for a degenerate triangle).
double height(V3 a, V3 b, V3 c, V3 p) {
  const V3 n = impetus::fuzz::cross(b - a, c - a);
  const double l = impetus::fuzz::len(n);
  return l > 0.0 ? std::abs(impetus::fuzz::dot(p - a, n)) / l : 0.0;
}

/// A lower bound on the cloud's width (its thinnest extent over all directions): the width of a
/// tetrahedron of its points, picked greedily in double (two extreme points farthest apart, the
/// point farthest from their line, the point farthest from the plane of the three). A
/// tetrahedron's width is the least of its four heights and its three pairs of opposite edges'
/// distances; the cloud holds the tetrahedron, so it is at least that wide.
double widthLowerBound(std::span<const Vec3f> cloud) {
  // The extreme points along 13 directions (the axes, the face and the body diagonals).
  std::vector<std::size_t> extremes;
  const std::array<V3, 13> directions{{{1, 0, 0},
                                       {0, 1, 0},
                                       {0, 0, 1},
                                       {1, 1, 0},
                                       {1, -1, 0},
                                       {1, 0, 1},
                                       {1, 0, -1},
                                       {0, 1, 1},
                                       {0, 1, -1},
                                       {1, 1, 1},
                                       {1, 1, -1},
                                       {1, -1, 1},
                                       {-1, 1, 1}}};
  for (const V3& dir : directions) {
    std::size_t lo = 0;
    std::size_t hi = 0;
    for (std::size_t i = 1; i < cloud.size(); ++i) {
      const double s = impetus::fuzz::dot(d3(cloud[i]), dir);
      lo = s < impetus::fuzz::dot(d3(cloud[lo]), dir) ? i : lo;
      hi = s > impetus::fuzz::dot(d3(cloud[hi]), dir) ? i : hi;
    }
    extremes.push_back(lo);
    extremes.push_back(hi);
  }
  std::size_t a = 0;
  std::size_t b = 0;
  double widest = -1.0;
  for (const std::size_t i : extremes) {
    for (const std::size_t j : extremes) {
      if (const double dist = impetus::fuzz::len(d3(cloud[j]) - d3(cloud[i])); dist > widest) {
        widest = dist;
        a = i;
        b = j;
      }
    }
  }
  const V3 pa = d3(cloud[a]);
  const V3 pb = d3(cloud[b]);
  std::size_t c = 0;
  double farFromLine = -1.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const V3 ab = pb - pa;
    const double l = impetus::fuzz::len(ab);
    const double dist = l > 0.0 ? impetus::fuzz::len(impetus::fuzz::cross(d3(cloud[i]) - pa, ab)) / l : 0.0;
    if (dist > farFromLine) {
      farFromLine = dist;
      c = i;
    }
  }
  const V3 pc = d3(cloud[c]);
  std::size_t d = 0;
  double farFromPlane = -1.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (const double h = height(pa, pb, pc, d3(cloud[i])); h > farFromPlane) {
      farFromPlane = h;
      d = i;
    }
  }
  const V3 pd = d3(cloud[d]);
  return std::min({height(pa, pb, pc, pd), height(pa, pb, pd, pc), height(pa, pc, pd, pb), height(pb, pc, pd, pa),
                   lineDistance(pa, pb, pc, pd), lineDistance(pa, pc, pb, pd), lineDistance(pa, pd, pb, pc)});
}

/// The cloud from the bytes; see the file's comment for the patterns.
std::vector<Vec3f> makeCloud(impetus::fuzz::Reader& in, std::size_t count, int pattern, float scale) {
  std::vector<Vec3f> cloud;
  cloud.reserve(count);
  const float E = scale;
  switch (pattern) {
  case 0: // anywhere in a cube
    for (std::size_t i = 0; i < count; ++i) {
      cloud.push_back(impetus::fuzz::vec3(in, E));
    }
    break;
  case 1: // with duplicates of earlier points
    for (std::size_t i = 0; i < count; ++i) {
      const std::uint8_t b = in.byte();
      cloud.push_back((b & 1) != 0 && i > 0 ? cloud[(b >> 1) % i] : impetus::fuzz::vec3(in, E));
    }
    break;
  case 2: { // in an axis plane, exactly; one point off it by a thickness from E to 1e-11 E
    const std::uint8_t axis = in.byte() % 3;
    const float level = in.bounded(E);
    const std::uint8_t off = in.byte();
    for (std::size_t i = 0; i < count; ++i) {
      Vec3f p = impetus::fuzz::vec3(in, E);
      p[axis] = level;
      cloud.push_back(p);
    }
    if ((off & 1) != 0) {
      cloud[(off >> 1) % count][axis] += E * std::pow(10.0f, -static_cast<float>((off >> 1) % 12));
    }
    break;
  }
  case 3: { // in a turned plane (coplanar up to rounding), each point off it by up to a thickness
    const Quatf q = impetus::fuzz::rotation(in);
    const Vec3f origin = impetus::fuzz::vec3(in, E);
    const float thickness = E * std::pow(10.0f, -static_cast<float>(in.byte() % 14));
    const std::uint8_t which = in.byte(); // bit 0: every point off the plane, else only the first
    const Vec3f e1 = rotate(q, Vec3f{1.0f, 0.0f, 0.0f});
    const Vec3f e2 = rotate(q, Vec3f{0.0f, 1.0f, 0.0f});
    const Vec3f n = rotate(q, Vec3f{0.0f, 0.0f, 1.0f});
    for (std::size_t i = 0; i < count; ++i) {
      const float u = in.bounded(E);
      const float v = in.bounded(E);
      const float h = (which & 1) != 0 || i == 0 ? in.bounded(thickness) : 0.0f;
      cloud.push_back(origin + e1 * u + e2 * v + n * h);
    }
    break;
  }
  case 4: { // on a sphere (many extreme points: the cap matters), some inside
    const Vec3f center = impetus::fuzz::vec3(in, E);
    for (std::size_t i = 0; i < count; ++i) {
      Vec3f dir = normalize(impetus::fuzz::vec3(in, 1.0f));
      if (lengthSquared(dir) == 0.0f) {
        dir = {1.0f, 0.0f, 0.0f};
      }
      const std::uint8_t depth = in.byte();
      cloud.push_back(center + dir * (depth < 192 ? E : E * static_cast<float>(depth) / 255.0f));
    }
    break;
  }
  case 5: { // an integer lattice, turned or not: many points on each face and edge
    const std::uint8_t form = in.byte();
    const Quatf q = (form & 1) != 0 ? impetus::fuzz::rotation(in) : Quatf::identity();
    const Vec3f origin = (form & 2) != 0 ? impetus::fuzz::vec3(in, E) : Vec3f{};
    const int span = 2 + (form >> 2) % 4; // coordinates 0..span-1
    for (std::size_t i = 0; i < count; ++i) {
      const Vec3f k{static_cast<float>(in.byte() % span), static_cast<float>(in.byte() % span),
                    static_cast<float>(in.byte() % span)};
      cloud.push_back(origin + rotate(q, k * E));
    }
    break;
  }
  case 6: { // a prism: a polygon and its copy moved along the prism's axis
    const Quatf q = impetus::fuzz::rotation(in);
    const float h = in.bounded(E);
    const float r = std::max(std::abs(in.bounded(E)), E * 1e-3f);
    for (std::size_t i = 0; i < count; ++i) {
      const float angle = in.bounded(3.2f);
      const Vec3f local{r * std::cos(angle), r * std::sin(angle), i % 2 == 0 ? h : -h};
      cloud.push_back(rotate(q, local));
    }
    break;
  }
  default: { // special values among ordinary points
    constexpr float inf = std::numeric_limits<float>::infinity();
    const std::array<float, 10> specials{
        std::numeric_limits<float>::quiet_NaN(), inf,   -inf,  std::numeric_limits<float>::max(),
        -std::numeric_limits<float>::max(),      1e38f, 1e30f, std::numeric_limits<float>::denorm_min(),
        std::numeric_limits<float>::min(),       -0.0f};
    for (std::size_t i = 0; i < count; ++i) {
      const std::uint8_t kind = in.byte();
      Vec3f p;
      if (kind < 24) {
        p = impetus::fuzz::rawVec3(in);
      } else {
        p = impetus::fuzz::vec3(in, E);
        if (kind < 48) {
          p[kind % 3] = specials[static_cast<std::size_t>(kind - 24) % specials.size()];
        }
      }
      cloud.push_back(p);
    }
    break;
  }
  }
  return cloud;
}

/// Checks a hull computeHull returned for `cloud` with cap `maxVertices`.
void checkHull(const r3::Hull& hull, std::span<const Vec3f> cloud, int maxVertices) {
  // Whether the world takes it, said with every failure (and checked below).
  const r3::ShapeGeometry geometry = hull;
  std::string refusal;
  try {
    r3::requireValidGeometry(geometry);
  } catch (const impetus::Error& e) {
    refusal = e.what();
  }
  const auto where = [&] {
    return "hull of " + std::to_string(hull.points.size()) + " points, " + std::to_string(hull.faceEdges.size()) +
           " faces (cap " + std::to_string(maxVertices) + "; requireValidGeometry " +
           (refusal.empty() ? std::string("accepts it") : "refuses it: " + refusal) + ") of [" +
           impetus::fuzz::describe(cloud) + "]";
  };
  // Open findings (IMPETUS_FUZZ_SKIP_OPEN=1 lets them through, to search past them):
  //  1. regressions/hull3d/open-merge-thin-slab-two-faces: computeHull merges triangles into one
  //     face when their normals are within 1.4e-5 rad, whatever their distance from each other's
  //     plane: a cloud thinner than that angle over its extent (nine points in the plane z = 0
  //     within 0.85 m of the origin, one 1e-6 m above it: more than the 5.9e-7 m coplanarity
  //     tolerance) becomes a two-faced "hull", top and bottom on the same four points; a disk
  //     7.6e-3 m across and 9e-9 m thick (open-merge-thin-disk-not-closed) a hull whose top and
  //     bottom faces share vertices that are not neighbours in their loops (no convex solid's
  //     faces do), so their fans take the same diagonal twice: massProperties throws "not
  //     closed". Let through: hulls of fewer than 4 faces or thinner than 1e-4 of the cloud's
  //     size along a face's normal, faces off their planes up to 1e-3 of the cloud's size
  //     instead of 1e-5 (and the world's refusals, "point off its plane" and "point ahead", that
  //     follow from such faces).
  //  2. regressions/hull3d/open-sliver-face-*: makeHullFromFaces takes a face's normal in float
  //     from the points' absolute coordinates (Newell's sum of p x q): for a thin face the terms,
  //     of the size of the coordinates squared, cancel to twice its area and their rounding tilts
  //     the normal: a 2 m triangle 2.8e-5 m wide, 1e-3 rad, its own vertex 1.9e-3 m off its plane
  //     (open-sliver-face-normal; on a sphere of 100 m, 1.6e-3 m, open-sliver-face-large-sphere,
  //     refused by requireValidGeometry); near-duplicate points 1e-5 m apart on a unit sphere, a zero
  //     normal (open-sliver-face-zero-normal); three points nearly on a line through the origin,
  //     a normal 0.3 rad off, a vertex 1e-3 m off the plane (open-sliver-face-collinear). Let
  //     through: each face's tolerance grown by that rounding, a tilt of 64 float epsilons of
  //     sum |p| |q| over the face's doubled area, times the cloud's diameter; faces whose tilt may
  //     exceed 1e-4 rad unchecked.
  //  3. regressions/hull3d/open-tiny-*-zero-normal*: a face whose doubled area is below 1e-18 m^2
  //     (Newell's normal, in float, is then shorter than normalize's tolerance) gets a zero
  //     normal, and requireValidGeometry accepts the hull (its tolerance is absolute): a
  //     tetrahedron of 1e-10 m (it has volume by computeHull's relative tolerance), or the 1e-9 m
  //     base of a 6.7e-4 m needle. Let through: clouds within 1e-6 m of the origin, and faces of
  //     doubled area below 1e-16 m^2 unchecked.
  //  4. regressions/hull3d/open-degree-two-vertex-*, open-straight-vertex-not-closed: computeHull
  //     keeps a point on a hull edge as a vertex on only two faces. Quickhull's first tetrahedron
  //     takes the first of the points tied at an axis' extreme, which need not be a vertex: of
  //     (0, 1, 0), (0, 0, 0), (2, 0, 2), (1, 2, 0), (0, 2, 0) it takes (0, 1, 0), the midpoint of
  //     the edge from (0, 0, 0) to (0, 2, 0), and the merge keeps it (open-degree-two-vertex-on-
  //     edge). The two faces then share two consecutive edges; their fans from one vertex
  //     (massProperties, requireValidGeometry) may hold the same diagonal twice, and the mesh
  //     counts as not closed: massProperties throws and createShape refuses the hull
  //     (open-straight-vertex-not-closed, open-degree-two-vertex-not-closed); where the vertex
  //     lies on its neighbours' line one face may be a sliver triangle whose plane is anything
  //     (0.6 rad off the other's, a vertex 0.1 m in front of it: open-degree-two-vertex-sliver-
  //     face). Let through: hulls with a vertex on two faces.
  //  5. regressions/hull3d/open-huge-coordinates-nan-planes: coordinates up to float's largest
  //     are accepted, but Newell's products overflow from about 1e19 m: the planes come out NaN,
  //     and requireValidGeometry accepts them (its comparisons with NaN are false). Let through:
  //     clouds with a point beyond 1e18 m.
  //  6. regressions/hull3d/open-nonconvex-*: quickhull leaves a concave edge at a thin triangle
  //     (its least height far below the cloud's size: near-duplicate points, or two points close
  //     together relative to a far one); the triangle's plane, turned by the concavity, has other
  //     vertices in front of it: in open-nonconvex-concave-edge 1.8e-3 of the cloud's size at
  //     any scale (2.4 mm for a 1.3 m cloud, refused by requireValidGeometry; accepted at 1.3 mm),
  //     in open-nonconvex-thin-face-far 5 km for a 96 km cloud, a triangle 0.56 m wide. Let
  //     through: vertices, input points and the centre of mass in front of a face whose doubled
  //     area over its longest edge is below 1e-3 of the cloud's size.
  const bool skipOpen = impetus::fuzz::skipOpenFindings();
  if (skipOpen && hull.faceEdges.size() < 4) {
    return;
  }
  const std::size_t n = hull.points.size();
  FUZZ_CHECK(n >= 4 && n <= static_cast<std::size_t>(maxVertices), where() + ": vertex count");
  FUZZ_CHECK(hull.faceEdges.size() >= 4, where() + ": fewer than 4 faces");
  FUZZ_CHECK(hull.planes.size() == hull.faceEdges.size(), where() + ": not one plane per face");
  for (std::size_t i = 0; i < n; ++i) {
    FUZZ_CHECK(std::find(cloud.begin(), cloud.end(), hull.points[i]) != cloud.end(),
               where() + ": vertex " + str(hull.points[i]) + " is not an input point");
    for (std::size_t j = i + 1; j < n; ++j) {
      FUZZ_CHECK(hull.points[i] != hull.points[j],
                 where() + ": vertices " + std::to_string(i) + " and " + std::to_string(j) + " are equal");
    }
  }

  // The half-edges.
  const std::size_t edgeCount = hull.edges.size();
  std::vector<int> loopOf(edgeCount, -1);
  std::vector<bool> used(n, false);
  for (std::size_t f = 0; f < hull.faceEdges.size(); ++f) {
    const std::uint16_t first = hull.faceEdges[f];
    FUZZ_CHECK(first < edgeCount, where() + ": face " + std::to_string(f) + "'s first half-edge out of range");
    std::uint16_t e = first;
    std::size_t length = 0;
    do {
      const r3::HullHalfEdge& he = hull.edges[e];
      FUZZ_CHECK(loopOf[e] < 0, where() + ": half-edge " + std::to_string(e) + " in two loops, or a loop of face " +
                                    std::to_string(f) + " that does not close");
      loopOf[e] = static_cast<int>(f);
      FUZZ_CHECK(he.face == f, where() + ": half-edge " + std::to_string(e) + " in face " + std::to_string(f) +
                                   "'s loop names face " + std::to_string(he.face));
      FUZZ_CHECK(he.origin < n && he.next < edgeCount && he.twin < edgeCount,
                 where() + ": half-edge " + std::to_string(e) + " has an index out of range");
      used[he.origin] = true;
      ++length;
      e = he.next;
    } while (e != first);
    FUZZ_CHECK(length >= 3, where() + ": face " + std::to_string(f) + " has " + std::to_string(length) + " edges");
  }
  for (std::size_t e = 0; e < edgeCount; ++e) {
    FUZZ_CHECK(loopOf[e] >= 0, where() + ": half-edge " + std::to_string(e) + " is in no face's loop");
    const r3::HullHalfEdge& he = hull.edges[e];
    const r3::HullHalfEdge& twin = hull.edges[he.twin];
    FUZZ_CHECK(twin.twin == e,
               where() + ": half-edge " + std::to_string(e) + "'s twin's twin is " + std::to_string(twin.twin));
    FUZZ_CHECK(twin.face != he.face, where() + ": half-edge " + std::to_string(e) + " and its twin on one face");
    FUZZ_CHECK(twin.origin == hull.edges[he.next].origin && hull.edges[twin.next].origin == he.origin,
               where() + ": half-edge " + std::to_string(e) + "'s twin does not run the other way");
  }
  for (std::size_t i = 0; i < n; ++i) {
    FUZZ_CHECK(used[i], where() + ": vertex " + std::to_string(i) + " is on no face");
  }

  // Every vertex on at least three faces (a solid's corner; open finding 4).
  std::vector<int> degree(n, 0);
  for (const r3::HullHalfEdge& he : hull.edges) {
    ++degree[he.origin];
  }
  const bool degreeTwo = std::find(degree.begin(), degree.end(), 2) != degree.end();
  if (skipOpen && degreeTwo) {
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    FUZZ_CHECK(degree[i] >= 3,
               where() + ": vertex " + str(hull.points[i]) + " is on " + std::to_string(degree[i]) + " faces");
  }

  // The planes: flat faces, a convex hull holding the cloud. Tolerances relative to the cloud's
  // size (its farthest point from the origin: float rounding of the points and planes).
  double size = 0.0;
  for (const Vec3f& p : cloud) {
    size = std::max(size, impetus::fuzz::len(d3(p)));
  }
  if (skipOpen && (size < 1e-6 || size > 1e18)) {
    return; // open findings 3 and 5
  }
  if (skipOpen) { // open finding 1: a hull thinner than 1e-4 of its size along a face's normal
    for (const r3::HullPlane& plane : hull.planes) {
      double thickness = 0.0;
      for (const Vec3f& p : hull.points) {
        thickness = std::max(thickness, plane.offset - impetus::fuzz::dot(d3(plane.normal), d3(p)));
      }
      if (std::abs(impetus::fuzz::len(d3(plane.normal)) - 1.0) <= 1e-4 && thickness < 1e-4 * size) {
        return;
      }
    }
  }
  const double tol = 1e-5 * size;
  // The hull holds every input point when the cap cannot have stopped quickhull early: when the
  // cloud has no more distinct points than the cap. (Not "fewer vertices than the cap": a point
  // quickhull added can end inside a merged face and leave the hull, so a hull stopped by the
  // cap, with points outside, may have fewer vertices than the cap.)
  std::vector<Vec3f> distinct(cloud.begin(), cloud.end());
  std::sort(distinct.begin(), distinct.end(),
            [](const Vec3f& p, const Vec3f& q) { return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z); });
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  const bool holdsCloud = distinct.size() <= static_cast<std::size_t>(maxVertices);
  std::vector<bool> unchecked(hull.planes.size(), false); // faces let through (open findings 2, 3, 6)
  for (std::size_t f = 0; f < hull.planes.size(); ++f) {
    const r3::HullPlane& plane = hull.planes[f];
    const V3 normal = d3(plane.normal);
    // Newell's normal of the loop, in double, and what bounds the rounding of its terms in float.
    V3 newell;
    double terms = 0.0;
    double longest = 0.0;
    const std::uint16_t first = hull.faceEdges[f];
    std::uint16_t e = first;
    do {
      const V3 p = d3(hull.points[hull.edges[e].origin]);
      const V3 q = d3(hull.points[hull.edges[hull.edges[e].next].origin]);
      newell = newell + impetus::fuzz::cross(p, q);
      terms += impetus::fuzz::len(p) * impetus::fuzz::len(q); // bounds each product's rounding
      longest = std::max(longest, impetus::fuzz::len(q - p));
      e = hull.edges[e].next;
    } while (e != first);
    // A thin face: its doubled area over its longest edge (a triangle's least height) below 1e-3
    // of the cloud's size (open finding 6).
    const bool thin = impetus::fuzz::len(newell) < 1e-3 * size * longest;
    // How far float rounding of those terms may tilt the library's normal (open finding 2), rad.
    const double tilt = 64.0 * std::numeric_limits<float>::epsilon() * terms / impetus::fuzz::len(newell);
    if (skipOpen && (!(tilt <= 1e-4) || impetus::fuzz::len(newell) <= 1e-16)) {
      unchecked[f] = true;
      continue; // a sliver whose normal is anything, or a face too small for one (findings 2, 3)
    }
    FUZZ_CHECK(impetus::fuzz::finite(normal) && std::isfinite(plane.offset) &&
                   std::abs(impetus::fuzz::len(normal) - 1.0) <= 1e-4,
               where() + ": face " + std::to_string(f) + "'s plane: normal " + str(plane.normal) + ", offset " +
                   str(plane.offset));
    // Wound counter-clockwise seen from outside (Newell's normal along the plane's).
    FUZZ_CHECK(impetus::fuzz::dot(newell, normal) > 0.0,
               where() + ": face " + std::to_string(f) + " is wound clockwise seen from outside");
    const double faceTol = skipOpen ? std::max(1e-3 * size, tol + tilt * 2.0 * size) : tol;
    const double convexTol = skipOpen && thin ? std::numeric_limits<double>::infinity() : faceTol; // finding 6
    unchecked[f] = skipOpen && thin;
    // Planar.
    e = first;
    do {
      const double off = impetus::fuzz::dot(normal, d3(hull.points[hull.edges[e].origin])) - plane.offset;
      FUZZ_CHECK(std::abs(off) <= faceTol, where() + ": face " + std::to_string(f) + "'s point " +
                                               str(hull.points[hull.edges[e].origin]) + " is " + str(off) +
                                               " m off its plane (tolerance " + str(faceTol) + ")");
      e = hull.edges[e].next;
    } while (e != first);
    for (std::size_t i = 0; i < n; ++i) {
      const double ahead = impetus::fuzz::dot(normal, d3(hull.points[i])) - plane.offset;
      FUZZ_CHECK(ahead <= convexTol, where() + ": vertex " + str(hull.points[i]) + " is " + str(ahead) +
                                         " m in front of face " + std::to_string(f) + " (not convex; tolerance " +
                                         str(convexTol) + ")");
    }
    if (holdsCloud) {
      for (const Vec3f& p : cloud) {
        const double ahead = impetus::fuzz::dot(normal, d3(p)) - plane.offset;
        FUZZ_CHECK(ahead <= convexTol,
                   where() + ": input point " + str(p) + " is " + str(ahead) + " m in front of face " +
                       std::to_string(f) +
                       " (the hull must hold a cloud of no more distinct points than the cap; tolerance " +
                       str(convexTol) + ")");
      }
    }
  }

  const auto openRefusal = [&](const std::string& message) {
    return skipOpen &&
           (message.find("off its plane") != std::string::npos || message.find("point ahead") != std::string::npos);
  };

  // The world takes it (createShape checks requireValidGeometry), and its mass is a solid's.
  FUZZ_CHECK(refusal.empty() || openRefusal(refusal), where() + ": createShape would refuse it");
  impetus::MassProperties3 mass;
  try {
    mass = r3::massProperties(geometry, 1000.0);
  } catch (const impetus::Error& e) {
    FUZZ_CHECK(false, where() + ": massProperties threw: " + e.what());
  }
  V3 lower{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  V3 upper = lower * -1.0;
  for (const Vec3f& p : cloud) {
    lower = {std::min(lower.x, static_cast<double>(p.x)), std::min(lower.y, static_cast<double>(p.y)),
             std::min(lower.z, static_cast<double>(p.z))};
    upper = {std::max(upper.x, static_cast<double>(p.x)), std::max(upper.y, static_cast<double>(p.y)),
             std::max(upper.z, static_cast<double>(p.z))};
  }
  const V3 box = upper - lower;
  const double boxMass = 1000.0 * box.x * box.y * box.z;
  const impetus::Vec3d c = mass.centerOfMass;
  const auto& I = mass.inertia;
  const auto massText = [&] {
    return "mass " + str(mass.mass) + " (the bounding box's " + str(boxMass) + "), centre (" + str(c.x) + ", " +
           str(c.y) + ", " + str(c.z) + "), inertia diagonal (" + str(I(0, 0)) + ", " + str(I(1, 1)) + ", " +
           str(I(2, 2)) + ")";
  };
  bool inertiaFinite = true;
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) {
      inertiaFinite = inertiaFinite && std::isfinite(I(r, k));
    }
  }
  FUZZ_CHECK(std::isfinite(mass.mass) && mass.mass > 0.0 && mass.mass <= boxMass * (1.0 + 1e-4),
             where() + ": " + massText());
  FUZZ_CHECK(inertiaFinite && I(0, 0) > 0.0 && I(1, 1) > 0.0 && I(2, 2) > 0.0, where() + ": " + massText());
  FUZZ_CHECK(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z), where() + ": " + massText());
  for (std::size_t f = 0; f < hull.planes.size(); ++f) {
    if (unchecked[f]) {
      continue;
    }
    const double ahead = impetus::fuzz::dot(d3(hull.planes[f].normal), V3{c.x, c.y, c.z}) - hull.planes[f].offset;
    FUZZ_CHECK(ahead <= (skipOpen ? 1e-3 * size : tol), where() + ": the centre of mass is " + str(ahead) +
                                                            " m in front of face " + std::to_string(f) + "; " +
                                                            massText());
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  impetus::fuzz::Reader in(data, size);
  // Byte 0: the number of points (4 to 80). Byte 1: the scale 10^(k - 4), k = 0 to 15 (bits
  // 0-3), the pattern (bits 4-6) and whether the cloud is moved 100 sizes from the origin (bit
  // 7). Byte 2: the cap, 4 to 64, or (from 240) one out of range that must be refused.
  const std::size_t count = 4 + in.byte() % 77;
  const std::uint8_t mode = in.byte();
  const std::uint8_t capByte = in.byte();
  const float scale = std::pow(10.0f, static_cast<float>(mode % 16) - 4.0f);
  const int pattern = (mode >> 4) % 8;
  constexpr std::array<int, 16> badCaps{
      0,   1,    2,     3,     -1,     -4,      65,         66,
      100, 1000, 65535, 65536, -65536, 1 << 30, -(1 << 30), std::numeric_limits<int>::min()};
  const bool capInRange = capByte < 240;
  const int maxVertices = capInRange ? 4 + capByte % 61 : badCaps[capByte % 16];

  std::vector<Vec3f> cloud = makeCloud(in, count, pattern, scale);
  if ((mode & 0x80) != 0) {
    const Vec3f offset = impetus::fuzz::vec3(in, 100.0f * scale);
    for (Vec3f& p : cloud) {
      p = p + offset;
    }
  }

  r3::Hull hull;
  try {
    hull = r3::computeHull(cloud, maxVertices);
  } catch (const impetus::Error& e) {
    // A refusal: for a cap out of range, a non-finite point or a cloud without volume, and only
    // for those.
    if (!capInRange || !std::all_of(cloud.begin(), cloud.end(), [](const Vec3f& p) { return isFinite(p); })) {
      return 0;
    }
    const double width = widthLowerBound(cloud);
    const double tolerance = makerTolerance(cloud);
    FUZZ_CHECK(width <= 16.0 * tolerance, "computeHull refused [" + impetus::fuzz::describe(cloud) + "] (cap " +
                                              std::to_string(maxVertices) + ") but the cloud is at least " +
                                              str(width) + " m thick (coplanarity tolerance " + str(tolerance) +
                                              "): " + e.what());
    return 0;
  } catch (const std::exception& e) {
    FUZZ_CHECK(false, "computeHull of [" + impetus::fuzz::describe(cloud) + "] (cap " + std::to_string(maxVertices) +
                          ") threw " + typeid(e).name() + ": " + e.what());
  }
  FUZZ_CHECK(capInRange, "computeHull accepted the cap " + std::to_string(maxVertices));
  checkHull(hull, cloud, maxVertices);
  return 0;
}
