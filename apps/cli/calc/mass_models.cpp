// `impetus calc` entries for chapter 1: the primitive solids, the parallel-axis transfer, a
// composite body from a JSON file and a planar polygon.
#include "calc/calc.hpp"
#include "calc/values.hpp"
#include "composite_file.hpp"

#include <impetus/core/mass_properties.hpp>
#include <impetus/core/polygon_mass.hpp>
#include <impetus/core/solid.hpp>
#include <impetus/error.hpp>

#include <algorithm>
#include <sstream>

namespace impetus::cli {
namespace {

constexpr const char* topic = "mass properties (ch. 1)";
constexpr const char* inertiaUnit = "kg m^2";

Param massParam() { return {"mass", "kg", "mass of the solid", std::nullopt}; }
Param lengthParam(std::string name, std::string help) { return {std::move(name), "m", std::move(help), std::nullopt}; }

/// Volume, density and the three principal moments of a primitive solid.
Result solidResult(const Solid& solid, double mass) {
  const Mat33d inertia = inertiaTensor(solid, mass);
  Result r;
  const double v = volume(solid);
  r.add("volume", v, "m^3");
  if (v > 0.0) {
    r.add("density", mass / v, "kg/m^3");
  }
  r.add("Ixx", inertia(0, 0), inertiaUnit, "about the x axis through the centroid");
  r.add("Iyy", inertia(1, 1), inertiaUnit, "about the y axis through the centroid");
  r.add("Izz", inertia(2, 2), inertiaUnit, "about the z axis through the centroid");
  r.add("inertia_tensor", toMatrix(inertia), inertiaUnit);
  return r;
}

void addSolid(Registry& registry, std::string name, std::string summary, std::vector<Param> dims,
              const std::function<Solid(const Args&)>& make) {
  dims.insert(dims.begin(), massParam());
  registry.add({std::move(name), topic, std::move(summary), std::move(dims),
                [make](const Args& a) { return solidResult(make(a), a.number("mass")); }});
}

Result composite(const Args& args) {
  const CompositeBody body = loadComposite(args.text("file"));
  const MassProperties3 props = combine(body.parts);
  const PrincipalInertia principal = principalAxes(props.inertia);
  Result r;
  r.add("mass", props.mass, "kg");
  r.add("weight", props.mass * body.gravity, "N", "at the file's gravity");
  r.add("center_of_mass", toVector(props.centerOfMass), "m");
  r.add("inertia_tensor", toMatrix(props.inertia), inertiaUnit, "about the centre of mass, body axes");
  r.add("principal_moments", toVector(principal.moments), inertiaUnit, "ascending");
  r.add("principal_axes", toMatrix(transpose(principal.axes)), "", "one unit axis per row");
  for (std::size_t i = 0; i < body.parts.size(); ++i) {
    const Vec3d d = body.parts[i].position - props.centerOfMass;
    r.add("part." + body.names[i] + ".mass", body.parts[i].mass, "kg");
    r.add("part." + body.names[i] + ".offset", toVector(d), "m", "part centroid relative to the centre of mass");
  }
  return r;
}

/// "x,y x,y ..." (spaces or semicolons between points).
std::vector<Vec2d> parsePoints(const std::string& text) {
  std::string normalized = text;
  std::replace_if(
      normalized.begin(), normalized.end(), [](char c) { return c == ';' || c == ','; }, ' ');
  std::istringstream in(normalized);
  std::vector<double> values;
  std::string token;
  while (in >> token) {
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(token, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != token.size()) {
      throw Error("vertices", "vertices: '" + token + "' is not a number");
    }
    values.push_back(v);
  }
  if (values.size() % 2 != 0) {
    throw Error("vertices", "vertices: odd number of coordinates (" + std::to_string(values.size()) + ")");
  }
  std::vector<Vec2d> points;
  for (std::size_t i = 0; i < values.size(); i += 2) {
    points.emplace_back(values[i], values[i + 1]);
  }
  return points;
}

} // namespace

void registerMassModels(Registry& registry) {
  addSolid(registry, "inertia-solid-sphere", "uniform solid sphere: I = 2/5 m r^2", {lengthParam("radius", "radius")},
           [](const Args& a) { return SolidSphere{a.number("radius")}; });
  addSolid(registry, "inertia-spherical-shell", "thin spherical shell: I = 2/3 m r^2",
           {lengthParam("radius", "radius")}, [](const Args& a) { return SphericalShell{a.number("radius")}; });
  addSolid(registry, "inertia-hollow-sphere", "thick spherical shell: I = 2/5 m (ro^5 - ri^5)/(ro^3 - ri^3)",
           {lengthParam("inner-radius", "inner radius"), lengthParam("outer-radius", "outer radius")},
           [](const Args& a) {
             return HollowSphere{a.number("inner-radius"), a.number("outer-radius")};
           });
  addSolid(registry, "inertia-solid-cylinder", "solid cylinder, axis z: Izz = 1/2 m r^2, Ixx = 1/4 m r^2 + 1/12 m l^2",
           {lengthParam("radius", "radius"), lengthParam("length", "length along z")}, [](const Args& a) {
             return SolidCylinder{a.number("radius"), a.number("length")};
           });
  addSolid(registry, "inertia-cylindrical-shell",
           "thin cylindrical shell without caps, axis z: Izz = m r^2, Ixx = 1/2 m r^2 + 1/12 m l^2",
           {lengthParam("radius", "radius"), lengthParam("length", "length along z")}, [](const Args& a) {
             return CylindricalShell{a.number("radius"), a.number("length")};
           });
  addSolid(registry, "inertia-hollow-cylinder", "thick-walled tube, axis z: Izz = 1/2 m (ri^2 + ro^2)",
           {lengthParam("inner-radius", "inner radius"), lengthParam("outer-radius", "outer radius"),
            lengthParam("length", "length along z")},
           [](const Args& a) {
             return HollowCylinder{a.number("inner-radius"), a.number("outer-radius"), a.number("length")};
           });
  addSolid(registry, "inertia-box", "uniform box: Ixx = 1/12 m (y^2 + z^2) and cyclic",
           {lengthParam("size-x", "edge along x"), lengthParam("size-y", "edge along y"),
            lengthParam("size-z", "edge along z")},
           [](const Args& a) {
             // Checked under the parameters' names: the library would name size.x, size.y, size.z.
             return Box{{requireNonNegative(a.number("size-x"), "size-x"),
                         requireNonNegative(a.number("size-y"), "size-y"),
                         requireNonNegative(a.number("size-z"), "size-z")}};
           });
  addSolid(registry, "inertia-rod", "thin rod along z about its centre: I = 1/12 m l^2",
           {lengthParam("length", "length")}, [](const Args& a) { return Rod{a.number("length")}; });
  addSolid(registry, "inertia-solid-cone", "solid cone, axis z, about its centroid: Izz = 3/10 m r^2",
           {lengthParam("radius", "base radius"), lengthParam("height", "height")}, [](const Args& a) {
             return SolidCone{a.number("radius"), a.number("height")};
           });

  registry.add({"parallel-axis",
                topic,
                "transfer of axes: I = I_cm + m d^2",
                {{"inertia", inertiaUnit, "moment of inertia about the axis through the centre of mass", std::nullopt},
                 massParam(),
                 {"distance", "m", "distance between the two parallel axes", std::nullopt}},
                [](const Args& a) {
                  Result r;
                  r.add("inertia", parallelAxis(a.number("inertia"), a.number("mass"), a.number("distance")),
                        inertiaUnit, "about the parallel axis");
                  return r;
                }});
  registry.add(
      {"composite",
       topic,
       "composite body from a JSON file: mass, centre of mass, inertia tensor, principal axes",
       {{"file", "", "path of the composite-body JSON file (docs/composite-format.md)", std::nullopt, ParamKind::path}},
       composite});
  registry.add({"polygon",
                topic,
                "planar polygon lamina: area, centroid, mass and polar moment",
                {{"vertices", "m", "points as \"x,y x,y ...\" in either winding order", std::nullopt, ParamKind::text},
                 {"density", "kg/m^2", "areal density", "1"}},
                [](const Args& a) {
                  const std::vector<Vec2d> points = parsePoints(a.text("vertices"));
                  const PolygonMass p = polygonMass(points, a.number("density"));
                  Result r;
                  r.add("area", p.area, "m^2");
                  r.add("centroid", Vector{p.centroid.x, p.centroid.y}, "m");
                  r.add("mass", p.mass, "kg");
                  r.add("inertia", p.inertia, inertiaUnit, "about the z axis through the centroid");
                  return r;
                }});
}

} // namespace impetus::cli
