// The primitive solids of chapter 1's table and the usual others, each with its volume and its
// inertia tensor about its own centroid. Shape frames: the centroid is the origin, and the
// long axis of cylinders, rods and cones is z (as in the book's figures 1-3 to 1-7).
#pragma once

#include <impetus/math/mat33.hpp>

#include <string_view>
#include <variant>

namespace impetus {

/// A point mass: no extent, no inertia about its own centre.
struct PointSolid {};
/// A uniform solid ball of radius r, m.
struct SolidSphere {
  double radius;
};
/// A thin spherical shell (the book's "hollow sphere") of radius r, m.
struct SphericalShell {
  double radius;
};
/// A thick spherical shell between an inner and an outer radius, m.
struct HollowSphere {
  double innerRadius;
  double outerRadius;
};
/// A uniform solid circular cylinder of radius r and length l along z, m.
struct SolidCylinder {
  double radius;
  double length;
};
/// A thin circular cylindrical shell without end caps (the book's "hollow cylinder"), m.
struct CylindricalShell {
  double radius;
  double length;
};
/// A thick-walled tube between an inner and an outer radius, length along z, m.
struct HollowCylinder {
  double innerRadius;
  double outerRadius;
  double length;
};
/// A uniform box with full edge lengths along x, y and z, m (the book's "rectangular cylinder"
/// with cross-section b (x) by a (y) and length l (z)).
struct Box {
  Vec3d size;
};
/// A thin uniform rod of length l along z, m.
struct Rod {
  double length;
};
/// A uniform solid right circular cone of base radius r and height h along z, m. Its frame is
/// centred on the centroid, h/4 above the base.
struct SolidCone {
  double radius;
  double height;
};

using Solid = std::variant<PointSolid, SolidSphere, SphericalShell, HollowSphere, SolidCylinder, CylindricalShell,
                           HollowCylinder, Box, Rod, SolidCone>;

/// The solid's kind as a lower-case word ("box", "solid-sphere", ...).
[[nodiscard]] std::string_view solidName(const Solid& solid) noexcept;

/// Volume in m^3. Points, thin shells and thin rods have none: give their mass, not a density.
/// Throws impetus::Error naming the dimension when a size is negative or not finite.
[[nodiscard]] double volume(const Solid& solid);

/// The inertia tensor about the centroid in the shape frame, kg m^2 (diagonal for all of these).
/// Throws impetus::Error when mass or a size is negative or not finite, or when an inner radius
/// exceeds the outer one.
[[nodiscard]] Mat33d inertiaTensor(const Solid& solid, double mass);

} // namespace impetus
