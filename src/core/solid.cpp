#include <impetus/core/solid.hpp>
#include <impetus/error.hpp>

namespace impetus {
namespace {

template <class... Ts> struct Overloaded : Ts... { using Ts::operator()...; };
template <class... Ts> Overloaded(Ts...) -> Overloaded<Ts...>;

double size(double value, std::string_view field) { return requireNonNegative(value, field); }

void requireInnerWithinOuter(double inner, double outer) {
  if (inner > outer) {
    throwInvalid("innerRadius", inner, "must not exceed outerRadius");
  }
}

Mat33d diag(double ixx, double iyy, double izz) { return Mat33d::diagonal({ixx, iyy, izz}); }

} // namespace

std::string_view solidName(const Solid& solid) noexcept {
  return std::visit(
      Overloaded{[](const PointSolid&) { return "point"; }, [](const SolidSphere&) { return "solid-sphere"; },
                 [](const SphericalShell&) { return "spherical-shell"; },
                 [](const HollowSphere&) { return "hollow-sphere"; },
                 [](const SolidCylinder&) { return "solid-cylinder"; },
                 [](const CylindricalShell&) { return "cylindrical-shell"; },
                 [](const HollowCylinder&) { return "hollow-cylinder"; }, [](const Box&) { return "box"; },
                 [](const Rod&) { return "rod"; }, [](const SolidCone&) { return "solid-cone"; }},
      solid);
}

double volume(const Solid& solid) {
  constexpr double pi = std::numbers::pi;
  return std::visit(
      Overloaded{
          [](const PointSolid&) { return 0.0; },
          [&](const SolidSphere& s) { return 4.0 / 3.0 * pi * std::pow(size(s.radius, "radius"), 3); },
          [](const SphericalShell& s) {
            size(s.radius, "radius");
            return 0.0;
          },
          [&](const HollowSphere& s) {
            const double ri = size(s.innerRadius, "innerRadius");
            const double ro = size(s.outerRadius, "outerRadius");
            requireInnerWithinOuter(ri, ro);
            return 4.0 / 3.0 * pi * (ro * ro * ro - ri * ri * ri);
          },
          [&](const SolidCylinder& s) {
            const double r = size(s.radius, "radius");
            return pi * r * r * size(s.length, "length");
          },
          [](const CylindricalShell& s) {
            size(s.radius, "radius");
            size(s.length, "length");
            return 0.0;
          },
          [&](const HollowCylinder& s) {
            const double ri = size(s.innerRadius, "innerRadius");
            const double ro = size(s.outerRadius, "outerRadius");
            requireInnerWithinOuter(ri, ro);
            return pi * (ro * ro - ri * ri) * size(s.length, "length");
          },
          [](const Box& s) { return size(s.size.x, "size.x") * size(s.size.y, "size.y") * size(s.size.z, "size.z"); },
          [](const Rod& s) {
            size(s.length, "length");
            return 0.0;
          },
          [&](const SolidCone& s) {
            const double r = size(s.radius, "radius");
            return pi * r * r * size(s.height, "height") / 3.0;
          }},
      solid);
}

Mat33d inertiaTensor(const Solid& solid, double mass) {
  const double m = requireNonNegative(mass, "mass");
  static_cast<void>(volume(solid)); // validates every dimension
  return std::visit(Overloaded{[](const PointSolid&) { return Mat33d::zero(); },
                               // I = 2/5 m r^2 about any diameter.
                               [&](const SolidSphere& s) {
                                 const double i = 0.4 * m * s.radius * s.radius;
                                 return diag(i, i, i);
                               },
                               // I = 2/3 m r^2.
                               [&](const SphericalShell& s) {
                                 const double i = 2.0 / 3.0 * m * s.radius * s.radius;
                                 return diag(i, i, i);
                               },
                               // I = 2/5 m (ro^5 - ri^5) / (ro^3 - ri^3); tends to 2/3 m r^2 as ri -> ro.
                               [&](const HollowSphere& s) {
                                 const double ri = s.innerRadius;
                                 const double ro = s.outerRadius;
                                 // (ro^5 - ri^5)/(ro^3 - ri^3) written without the cancelling difference.
                                 const double num = ro * ro * ro * ro + ro * ro * ro * ri + ro * ro * ri * ri +
                                                    ro * ri * ri * ri + ri * ri * ri * ri;
                                 const double den = ro * ro + ro * ri + ri * ri;
                                 const double i = den > 0.0 ? 0.4 * m * num / den : 0.0;
                                 return diag(i, i, i);
                               },
                               // Ixx = Iyy = 1/4 m r^2 + 1/12 m l^2, Izz = 1/2 m r^2.
                               [&](const SolidCylinder& s) {
                                 const double r2 = s.radius * s.radius;
                                 const double ixx = m * (r2 / 4.0 + s.length * s.length / 12.0);
                                 return diag(ixx, ixx, 0.5 * m * r2);
                               },
                               // Ixx = Iyy = 1/2 m r^2 + 1/12 m l^2, Izz = m r^2.
                               [&](const CylindricalShell& s) {
                                 const double r2 = s.radius * s.radius;
                                 const double ixx = m * (r2 / 2.0 + s.length * s.length / 12.0);
                                 return diag(ixx, ixx, m * r2);
                               },
                               // Ixx = Iyy = 1/12 m (3 (ri^2 + ro^2) + l^2), Izz = 1/2 m (ri^2 + ro^2).
                               [&](const HollowCylinder& s) {
                                 const double r2 = s.innerRadius * s.innerRadius + s.outerRadius * s.outerRadius;
                                 const double ixx = m * (3.0 * r2 + s.length * s.length) / 12.0;
                                 return diag(ixx, ixx, 0.5 * m * r2);
                               },
                               // Ixx = 1/12 m (y^2 + z^2) and cyclic.
                               [&](const Box& s) {
                                 const Vec3d d = hadamard(s.size, s.size);
                                 return diag(m * (d.y + d.z) / 12.0, m * (d.z + d.x) / 12.0, m * (d.x + d.y) / 12.0);
                               },
                               // Ixx = Iyy = 1/12 m l^2 about the centre, Izz = 0.
                               [&](const Rod& s) {
                                 const double i = m * s.length * s.length / 12.0;
                                 return diag(i, i, 0.0);
                               },
                               // About the centroid: Ixx = Iyy = 3/20 m r^2 + 3/80 m h^2, Izz = 3/10 m r^2.
                               [&](const SolidCone& s) {
                                 const double r2 = s.radius * s.radius;
                                 const double ixx = m * (3.0 / 20.0 * r2 + 3.0 / 80.0 * s.height * s.height);
                                 return diag(ixx, ixx, 0.3 * m * r2);
                               }},
                    solid);
}

} // namespace impetus
