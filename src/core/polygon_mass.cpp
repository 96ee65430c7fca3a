#include <impetus/core/polygon_mass.hpp>
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>

#include <string>

namespace impetus {

PolygonMass polygonMass(std::span<const Vec2d> vertices, double density) {
  requirePositive(density, "density");
  if (vertices.size() < 3) {
    throwInvalid("vertices.size", static_cast<double>(vertices.size()), "a polygon needs at least 3 vertices");
  }
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    requireFinite(vertices[i], "vertices[" + std::to_string(i) + "]");
  }
  // Work relative to the first vertex so that polygons far from the origin keep their precision.
  const Vec2d origin = vertices[0];
  double area = 0.0;
  Vec2d firstMoment{};
  double polar = 0.0;
  double extent = 0.0;
  for (std::size_t i = 1; i + 1 < vertices.size(); ++i) {
    const Vec2d e1 = vertices[i] - origin;
    const Vec2d e2 = vertices[i + 1] - origin;
    const double triangleArea = 0.5 * cross(e1, e2);
    area += triangleArea;
    firstMoment += (e1 + e2) * (triangleArea / 3.0);
    polar += triangleArea / 6.0 * (dot(e1, e1) + dot(e1, e2) + dot(e2, e2));
    extent = std::fmax(extent, std::fmax(lengthSquared(e1), lengthSquared(e2)));
  }
  // A polygon whose area is rounding noise next to its size has no interior.
  if (!(std::abs(area) > 1e-12 * extent)) {
    throwInvalid("area", area, "polygon is degenerate (collinear or repeated vertices)");
  }
  // Clockwise input gives negative signed area and moment; the ratios are unaffected.
  const double sign = area > 0.0 ? 1.0 : -1.0;
  const Vec2d centroid = firstMoment / area;
  PolygonMass result;
  result.area = sign * area;
  result.centroid = origin + centroid;
  result.mass = density * result.area;
  result.inertia = density * sign * (polar - area * lengthSquared(centroid));
  return result;
}

} // namespace impetus
