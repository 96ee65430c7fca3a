#include <impetus/core/mass_properties.hpp>
#include <impetus/error.hpp>
#include <impetus/math/validate.hpp>

#include <string>
#include <vector>

namespace impetus {
namespace {

std::string partField(std::size_t index, std::string_view field) {
  std::string name = "parts[";
  name.append(std::to_string(index)).append("].").append(field);
  return name;
}

double requireTotalMass(double total) {
  if (!(total > 0.0)) {
    throwInvalid("total mass", total, "a composite body needs a positive total mass");
  }
  return total;
}

} // namespace

double parallelAxis(double inertiaAboutCenterOfMass, double mass, double distance) {
  requireNonNegative(inertiaAboutCenterOfMass, "inertia");
  requireNonNegative(mass, "mass");
  requireFinite(distance, "distance");
  return inertiaAboutCenterOfMass + mass * distance * distance;
}

Mat33d parallelAxis(const Mat33d& inertiaAboutCenterOfMass, double mass, const Vec3d& offset) {
  requireFinite(inertiaAboutCenterOfMass, "inertia");
  requireNonNegative(mass, "mass");
  requireFinite(offset, "offset");
  return inertiaAboutCenterOfMass + (Mat33d::identity() * lengthSquared(offset) - outer(offset, offset)) * mass;
}

Mat33d rotateInertia(const Mat33d& inertia, const Mat33d& rotation) {
  requireFinite(inertia, "inertia");
  requireFinite(rotation, "rotation");
  return rotation * inertia * transpose(rotation);
}

Vec3d centerOfMass(std::span<const PointMass> points) { return combine(points).centerOfMass; }

MassProperties3 combine(std::span<const PointMass> points) {
  std::vector<MassPart> parts;
  parts.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const PointMass& p = points[i];
    // Moments about the point's own axes: a negative one belongs to no body.
    for (int axis = 0; axis < 3; ++axis) {
      requireNonNegative(p.localInertia[axis], partField(i, std::string("localInertia.") + "xyz"[axis]));
    }
    parts.push_back({p.mass, p.position, Mat33d::diagonal(p.localInertia), Mat33d::identity()});
  }
  return combine(parts);
}

MassProperties3 combine(std::span<const MassPart> parts) {
  if (parts.empty()) {
    throwInvalid("parts.size", 0.0, "a composite body needs at least one part");
  }
  // First moments give the centre of mass.
  double total = 0.0;
  Vec3d firstMoment{};
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const MassPart& part = parts[i];
    requireNonNegative(part.mass, partField(i, "mass"));
    requireFinite(part.position, partField(i, "position"));
    requireFinite(part.inertia, partField(i, "inertia"));
    requireFinite(part.orientation, partField(i, "orientation"));
    total += part.mass;
    firstMoment += part.position * part.mass;
  }
  MassProperties3 result;
  result.mass = requireTotalMass(total);
  result.centerOfMass = firstMoment / total;
  // Each part's tensor, turned into body axes and moved to the common centre of mass.
  for (const MassPart& part : parts) {
    const Mat33d local = rotateInertia(part.inertia, part.orientation);
    result.inertia += parallelAxis(local, part.mass, part.position - result.centerOfMass);
  }
  return result;
}

PrincipalInertia principalAxes(const Mat33d& inertia) {
  requireFinite(inertia, "inertia");
  const SymmetricEigen3d eigen = symmetricEigen(inertia);
  return {eigen.values, eigen.vectors};
}

void requirePhysicalInertia(const Mat33d& inertia, std::string_view field, double relativeTolerance) {
  requireFinite(inertia, field);
  const double scale = std::fmax(1e-300, std::abs(trace(inertia)));
  const double tol = relativeTolerance * scale;
  for (int r = 0; r < 3; ++r) {
    for (int c = r + 1; c < 3; ++c) {
      if (std::abs(inertia(r, c) - inertia(c, r)) > tol) {
        throwInvalid(std::string(field) + "(" + std::to_string(r) + "," + std::to_string(c) + ")", inertia(r, c),
                     "inertia tensor must be symmetric");
      }
    }
  }
  const Vec3d m = symmetricEigen(inertia).values;
  if (m.x < -tol) {
    throwInvalid(std::string(field) + " principal moment", m.x, "must be non-negative");
  }
  if (m.x + m.y < m.z - tol) {
    throwInvalid(std::string(field) + " principal moment", m.z,
                 "violates the triangle inequality I1 + I2 >= I3 that every body obeys");
  }
}

} // namespace impetus
