// The convex hull of a point cloud by quickhull (Barber, Dobkin and Huhdanpaa 1996): start from
// the largest tetrahedron of the extreme points, then again and again add the point farthest out
// of a face, replacing the faces it sees by a cone from their horizon to it. Then the triangles
// of each plane are merged into one face and the hull is built from the faces' loops. In double,
// with a tolerance scaled to the cloud's extent (points that close to a face count as on it).
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/rigid3d/hull.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace impetus::rigid3d {

namespace {

/// How near a point may be to a face's plane and count as on it, relative to the sum of the
/// cloud's largest coordinates: a few float epsilons (the points are floats), as Qhull's default.
constexpr double planeToleranceFactor = 3.0 * std::numeric_limits<float>::epsilon();
/// How close two triangles' normals must be to merge into one face (1 - cos of the angle): a
/// thousandth of a degree.
constexpr double coplanarNormalTolerance = 1.0e-10;

struct Triangle {
  std::array<std::uint32_t, 3> v{};
  Vec3d normal;
  double offset = 0.0;
  std::vector<std::uint32_t> outside; ///< points in front of it
  bool alive = true;
};

class QuickHull {
public:
  explicit QuickHull(std::span<const Vec3f> cloud) {
    Vec3d largest;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      requireFinite(cloud[i], "points[" + std::to_string(i) + "]");
      const Vec3d& p = points_.emplace_back(cloud[i].x, cloud[i].y, cloud[i].z);
      largest = max(largest, Vec3d{std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
    tolerance_ = planeToleranceFactor * std::max(largest.x + largest.y + largest.z, 1e-30);
  }

  /// The hull's triangles, each wound counter-clockwise seen from outside.
  std::vector<std::array<std::uint32_t, 3>> run(int maxVertices) {
    startTetrahedron();
    int vertices = 4;
    for (;;) {
      // The face with the farthest outside point, the first in face order on a tie.
      double farthest = 0.0;
      std::uint32_t face = 0;
      std::uint32_t eye = 0;
      bool any = false;
      for (std::uint32_t f = 0; f < triangles_.size(); ++f) {
        const Triangle& t = triangles_[f];
        if (!t.alive) {
          continue;
        }
        for (const std::uint32_t p : t.outside) {
          if (const double d = distance(t, p); d > farthest) {
            farthest = d;
            face = f;
            eye = p;
            any = true;
          }
        }
      }
      if (!any || vertices >= maxVertices) {
        break;
      }
      addPoint(face, eye);
      ++vertices;
    }
    std::vector<std::array<std::uint32_t, 3>> out;
    for (const Triangle& t : triangles_) {
      if (t.alive) {
        out.push_back(t.v);
      }
    }
    return out;
  }

  [[nodiscard]] const std::vector<Vec3d>& points() const { return points_; }

private:
  [[nodiscard]] double distance(const Triangle& t, std::uint32_t p) const {
    return dot(t.normal, points_[p]) - t.offset;
  }

  std::uint32_t addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    Triangle t;
    t.v = {a, b, c};
    t.normal = normalize(cross(points_[b] - points_[a], points_[c] - points_[a]));
    t.offset = dot(t.normal, points_[a]);
    const auto index = static_cast<std::uint32_t>(triangles_.size());
    for (int k = 0; k < 3; ++k) {
      edges_[{t.v[static_cast<std::size_t>(k)], t.v[static_cast<std::size_t>((k + 1) % 3)]}] = index;
    }
    triangles_.push_back(std::move(t));
    return index;
  }

  void startTetrahedron() {
    const auto n = static_cast<std::uint32_t>(points_.size());
    if (n < 4) {
      throwInvalid("points", n, "a hull needs at least four points");
    }
    // The two extreme points farthest apart along an axis, the point farthest from their line,
    // and the point farthest from the plane of the three.
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    double widest = -1.0;
    for (int axis = 0; axis < 3; ++axis) {
      std::uint32_t lo = 0;
      std::uint32_t hi = 0;
      for (std::uint32_t i = 1; i < n; ++i) {
        lo = points_[i][axis] < points_[lo][axis] ? i : lo;
        hi = points_[i][axis] > points_[hi][axis] ? i : hi;
      }
      if (const double d = length(points_[hi] - points_[lo]); d > widest) {
        widest = d;
        a = lo;
        b = hi;
      }
    }
    if (!(widest > tolerance_)) {
      throwInvalid("points extent", widest, "the points are all at one place: a hull needs volume");
    }
    std::uint32_t c = 0;
    double farFromLine = -1.0;
    const Vec3d line = normalize(points_[b] - points_[a]);
    for (std::uint32_t i = 0; i < n; ++i) {
      if (const double d = length(cross(points_[i] - points_[a], line)); d > farFromLine) {
        farFromLine = d;
        c = i;
      }
    }
    if (!(farFromLine > tolerance_)) {
      throwInvalid("points width", farFromLine, "the points are on one line: a hull needs volume");
    }
    const Vec3d normal = normalize(cross(points_[b] - points_[a], points_[c] - points_[a]));
    std::uint32_t d = 0;
    double farFromPlane = 0.0;
    for (std::uint32_t i = 0; i < n; ++i) {
      if (const double h = dot(points_[i] - points_[a], normal); std::abs(h) > std::abs(farFromPlane)) {
        farFromPlane = h;
        d = i;
      }
    }
    if (!(std::abs(farFromPlane) > tolerance_)) {
      throwInvalid("points thickness", std::abs(farFromPlane), "the points are in one plane: a hull needs volume");
    }
    // Wound so that every face looks away from the fourth point.
    if (farFromPlane > 0.0) {
      std::swap(b, c);
    }
    addTriangle(a, b, c);
    addTriangle(a, d, b);
    addTriangle(b, d, c);
    addTriangle(c, d, a);
    std::vector<std::uint32_t> all(n);
    std::iota(all.begin(), all.end(), 0U);
    assignOutside(all, {0, 1, 2, 3});
  }

  /// Gives each point to the first of `faces` it is in front of (beyond the tolerance).
  void assignOutside(const std::vector<std::uint32_t>& candidates, const std::vector<std::uint32_t>& faces) {
    for (const std::uint32_t p : candidates) {
      for (const std::uint32_t f : faces) {
        if (distance(triangles_[f], p) > tolerance_) {
          triangles_[f].outside.push_back(p);
          break;
        }
      }
    }
  }

  void addPoint(std::uint32_t face, std::uint32_t eye) {
    // The faces the eye sees, grown from the one it is farthest out of.
    std::vector<std::uint32_t> visible{face};
    triangles_[face].alive = false;
    for (std::size_t k = 0; k < visible.size(); ++k) {
      const Triangle& t = triangles_[visible[k]];
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t across =
            edges_.at({t.v[static_cast<std::size_t>((e + 1) % 3)], t.v[static_cast<std::size_t>(e)]});
        if (triangles_[across].alive && distance(triangles_[across], eye) > tolerance_) {
          triangles_[across].alive = false;
          visible.push_back(across);
        }
      }
    }
    // The horizon: the visible faces' edges whose other side is not visible, each coned to the eye.
    std::vector<std::uint32_t> orphans;
    std::vector<std::uint32_t> cone;
    for (const std::uint32_t f : visible) {
      const std::array<std::uint32_t, 3> v = triangles_[f].v;
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t from = v[static_cast<std::size_t>(e)];
        const std::uint32_t to = v[static_cast<std::size_t>((e + 1) % 3)];
        if (triangles_[edges_.at({to, from})].alive) {
          cone.push_back(addTriangle(from, to, eye));
        }
      }
      for (const std::uint32_t p : triangles_[f].outside) {
        if (p != eye) {
          orphans.push_back(p);
        }
      }
      triangles_[f].outside.clear();
    }
    assignOutside(orphans, cone);
  }

  std::vector<Vec3d> points_;
  std::vector<Triangle> triangles_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edges_; ///< directed edge -> its triangle
  double tolerance_ = 0.0;
};

/// Merges the triangles that lie in one plane into the hull's faces: each group's boundary,
/// followed from edge to edge, is its loop (counter-clockwise seen from outside, as the
/// triangles are).
std::vector<std::vector<std::uint32_t>> mergeCoplanar(const std::vector<Vec3d>& points,
                                                      const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  const std::size_t count = triangles.size();
  std::vector<Vec3d> normals(count);
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> owner;
  for (std::size_t t = 0; t < count; ++t) {
    const auto& v = triangles[t];
    normals[t] = normalize(cross(points[v[1]] - points[v[0]], points[v[2]] - points[v[0]]));
    for (int e = 0; e < 3; ++e) {
      owner[{v[static_cast<std::size_t>(e)], v[static_cast<std::size_t>((e + 1) % 3)]}] = t;
    }
  }
  std::vector<std::size_t> group(count);
  std::iota(group.begin(), group.end(), std::size_t{0});
  const auto find = [&](std::size_t t) {
    while (group[t] != t) {
      t = group[t] = group[group[t]];
    }
    return t;
  };
  for (std::size_t t = 0; t < count; ++t) {
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t from = triangles[t][static_cast<std::size_t>(e)];
      const std::uint32_t to = triangles[t][static_cast<std::size_t>((e + 1) % 3)];
      const std::size_t other = owner.at({to, from});
      if (1.0 - dot(normals[t], normals[other]) < coplanarNormalTolerance) {
        const std::size_t a = find(t);
        const std::size_t b = find(other);
        group[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  // Each group's boundary edges (an edge whose other side is in another group), as from -> to.
  std::map<std::size_t, std::map<std::uint32_t, std::uint32_t>> boundary;
  for (std::size_t t = 0; t < count; ++t) {
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t from = triangles[t][static_cast<std::size_t>(e)];
      const std::uint32_t to = triangles[t][static_cast<std::size_t>((e + 1) % 3)];
      if (find(owner.at({to, from})) != find(t)) {
        boundary[find(t)][from] = to;
      }
    }
  }
  std::vector<std::vector<std::uint32_t>> faces;
  for (const auto& [root, next] : boundary) {
    std::vector<std::uint32_t> loop;
    const std::uint32_t start = next.begin()->first;
    std::uint32_t at = start;
    do {
      // A point where the loop runs straight on (its neighbours' edges in line) stays: it is a
      // vertex of the hull, as the points the faces share must be.
      loop.push_back(at);
      at = next.at(at);
    } while (at != start && loop.size() <= next.size());
    faces.push_back(std::move(loop));
  }
  return faces;
}

} // namespace

Hull computeHull(std::span<const Vec3f> points, int maxVertices) {
  if (maxVertices < 4 || maxVertices > maxHullVertices) {
    throwInvalid("maxVertices", maxVertices,
                 "must be between 4 and maxHullVertices (" + std::to_string(maxHullVertices) + ")");
  }
  QuickHull quickHull(points);
  const std::vector<std::array<std::uint32_t, 3>> triangles = quickHull.run(maxVertices);
  const std::vector<std::vector<std::uint32_t>> loops = mergeCoplanar(quickHull.points(), triangles);
  // The hull's own points, renumbered in the order the faces first use them.
  std::vector<std::int64_t> index(points.size(), -1);
  std::vector<Vec3f> hullPoints;
  std::vector<std::vector<std::uint16_t>> faces;
  for (const std::vector<std::uint32_t>& loop : loops) {
    std::vector<std::uint16_t> face;
    for (const std::uint32_t p : loop) {
      if (index[p] < 0) {
        index[p] = static_cast<std::int64_t>(hullPoints.size());
        hullPoints.push_back(points[p]);
      }
      face.push_back(static_cast<std::uint16_t>(index[p]));
    }
    faces.push_back(std::move(face));
  }
  return makeHullFromFaces(std::move(hullPoints), faces);
}

} // namespace impetus::rigid3d
