// The 3D shapes' validation and mass properties.
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/rigid3d/constants.hpp>
#include <impetus/rigid3d/geometry.hpp>

#include <cmath>

namespace impetus::rigid3d {

namespace {

Vec3d toDouble(const Vec3f& v) { return {v.x, v.y, v.z}; }

void requireRadius(float radius) {
  if (!(std::isfinite(radius) && radius >= linearSlop)) {
    throwInvalid("radius", radius, "must be finite and at least linearSlop (0.005 m)");
  }
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
