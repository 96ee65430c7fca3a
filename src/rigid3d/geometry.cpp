// The 3D shapes' validation and mass properties.
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/rigid3d/constants.hpp>
#include <impetus/rigid3d/geometry.hpp>

#include <impetus/core/mesh_mass.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace impetus::rigid3d {

namespace {

Vec3d toDouble(const Vec3f& v) { return {v.x, v.y, v.z}; }

void requireRadius(float radius) {
  if (!(std::isfinite(radius) && radius >= linearSlop)) {
    throwInvalid("radius", radius, "must be finite and at least linearSlop (0.005 m)");
  }
}

} // namespace

namespace {

/// How far a hull's point may lie in front of a face's plane, or a face's point off it, and the
/// hull still count as convex and flat-faced, relative to the hull's size: the rounding of its
/// points and planes in float.
constexpr float convexityTolerance = 1.0e-5f;

/// The hull's faces as triangle fans, for the divergence theorem.
std::vector<TriangleIndices> fanTriangles(const Hull& hull) {
  std::vector<TriangleIndices> triangles;
  for (const std::uint16_t first : hull.faceEdges) {
    const std::uint32_t apex = hull.edges[first].origin;
    for (std::uint16_t e = hull.edges[first].next; hull.edges[e].next != first; e = hull.edges[e].next) {
      triangles.push_back({apex, hull.edges[e].origin, hull.edges[hull.edges[e].next].origin});
    }
  }
  return triangles;
}

std::vector<Vec3d> pointsInDouble(const Hull& hull) {
  std::vector<Vec3d> points;
  points.reserve(hull.points.size());
  for (const Vec3f& p : hull.points) {
    points.push_back(toDouble(p));
  }
  return points;
}

void requireValidHull(const Hull& hull) {
  if (hull.points.size() < 4 || hull.faceEdges.size() < 4) {
    throwInvalid("hull points", static_cast<double>(hull.points.size()),
                 "a hull has at least four points and four faces (a solid, not a polygon)");
  }
  float size = 0.0f;
  for (const Vec3f& p : hull.points) {
    size = std::max(size, length(requireFinite(p, "hull point")));
  }
  const float tolerance = convexityTolerance * std::max(size, 1.0f);
  if (hull.planes.size() != hull.faceEdges.size()) {
    throwInvalid("hull planes", static_cast<double>(hull.planes.size()), "must be one per face");
  }
  for (std::size_t f = 0; f < hull.faceEdges.size(); ++f) {
    const std::uint16_t first = hull.faceEdges[f];
    std::uint16_t e = first;
    do {
      const Vec3f& p = hull.points[hull.edges[e].origin];
      if (const float off = dot(hull.planes[f].normal, p) - hull.planes[f].offset; std::abs(off) > tolerance) {
        throwInvalid("hull face " + std::to_string(f) + " point off its plane", off,
                     "a hull's faces are flat, each on its plane");
      }
      e = hull.edges[e].next;
    } while (e != first);
  }
  for (std::size_t f = 0; f < hull.planes.size(); ++f) {
    for (const Vec3f& p : hull.points) {
      if (const float ahead = dot(hull.planes[f].normal, p) - hull.planes[f].offset; ahead > tolerance) {
        throwInvalid("hull face " + std::to_string(f) + " point ahead", ahead, "the hull must be convex");
      }
    }
  }
  // Closed and wound outward: the divergence theorem's checks.
  (void)meshMassProperties(pointsInDouble(hull), fanTriangles(hull), 1.0);
}

} // namespace

void requireValidGeometry(const ShapeGeometry& geometry) {
  if (const auto* sphere = std::get_if<Sphere>(&geometry)) {
    requireFinite(sphere->center, "center");
    requireRadius(sphere->radius);
  } else if (const auto* capsule = std::get_if<Capsule>(&geometry)) {
    requireFinite(capsule->center1, "center1");
    requireFinite(capsule->center2, "center2");
    requireRadius(capsule->radius);
    if (const float length = impetus::length(capsule->center2 - capsule->center1); !(length >= linearSlop)) {
      throwInvalid("capsule length", length, "must be at least linearSlop (0.005 m): a shorter capsule is a sphere");
    }
  } else {
    requireValidHull(std::get<Hull>(geometry));
  }
}

MassProperties3 massProperties(const ShapeGeometry& geometry, double density) {
  constexpr double pi = impetus::pi<double>;
  MassProperties3 out;
  if (const auto* sphere = std::get_if<Sphere>(&geometry)) {
    const double r = sphere->radius;
    out.mass = density * 4.0 / 3.0 * pi * r * r * r;
    out.centerOfMass = toDouble(sphere->center);
    out.inertia = Mat33d::identity() * (0.4 * out.mass * r * r);
    return out;
  }
  if (const auto* hull = std::get_if<Hull>(&geometry)) {
    // The divergence theorem over the faces' fans (core's meshMassProperties), exact for any
    // closed polyhedron.
    return density > 0.0 ? meshMassProperties(pointsInDouble(*hull), fanTriangles(*hull), density) : out;
  }
  const auto& capsule = std::get<Capsule>(geometry);
  // A cylinder of length l and two hemispherical caps, each with its centroid 3r/8 from its
  // flat face: about the centre, axially m_c r^2/2 + 2/5 m_h r^2, across
  //   m_c (l^2/12 + r^2/4) + m_h (2/5 r^2 + l^2/4 + 3 r l / 8)
  // (m_h both caps: each cap's moment about the sphere's centre, 2/5 (m_h/2) r^2, moved to its
  // centroid and then to the capsule's centre, l/2 + 3r/8 away).
  const Vec3d p1 = toDouble(capsule.center1);
  const Vec3d p2 = toDouble(capsule.center2);
  const double r = capsule.radius;
  const double l = length(p2 - p1);
  const double cylinder = density * pi * r * r * l;
  const double caps = density * 4.0 / 3.0 * pi * r * r * r;
  const double axial = cylinder * r * r / 2.0 + caps * 0.4 * r * r;
  const double across =
      cylinder * (l * l / 12.0 + r * r / 4.0) + caps * (0.4 * r * r + l * l / 4.0 + 3.0 * r * l / 8.0);
  const Vec3d axis = (p2 - p1) / l;
  out.mass = cylinder + caps;
  out.centerOfMass = (p1 + p2) * 0.5;
  out.inertia = (Mat33d::identity() - outer(axis, axis)) * across + outer(axis, axis) * axial;
  return out;
}

} // namespace impetus::rigid3d
