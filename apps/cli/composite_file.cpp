#include "composite_file.hpp"
#include "json_fields.hpp"

#include <impetus/core/constants.hpp>
#include <impetus/core/solid.hpp>
#include <impetus/error.hpp>
#include <impetus/math/quat.hpp>

#include <nlohmann/json.hpp>

#include <set>

namespace impetus::cli {
namespace {

using nlohmann::json;

using json_fields::fail;

double number(const json& j, const std::string& field) {
  if (!j.is_number()) {
    fail(field, "expected a number, got " + j.dump());
  }
  return requireFinite(j.get<double>(), field);
}

Vec3d vec3(const json& j, const std::string& field) {
  if (!j.is_array() || j.size() != 3) {
    fail(field, "expected an array of 3 numbers, got " + j.dump());
  }
  return {number(j[0], field + "[0]"), number(j[1], field + "[1]"), number(j[2], field + "[2]")};
}

Mat33d mat33(const json& j, const std::string& field) {
  if (!j.is_array() || j.size() != 3) {
    fail(field, "expected 3 rows of 3 numbers");
  }
  return Mat33d::fromRows(vec3(j[0], field + "[0]"), vec3(j[1], field + "[1]"), vec3(j[2], field + "[2]"));
}

void requireKnownKeys(const json& object, const std::set<std::string>& known, const std::string& where) {
  for (const auto& item : object.items()) {
    if (!known.contains(item.key())) {
      fail(where + "." + item.key(), "unknown key");
    }
  }
}

const json& member(const json& object, const std::string& key, const std::string& where) {
  if (!object.contains(key)) {
    fail(where + "." + key, "missing");
  }
  return object.at(key);
}

/// The part's orientation: {"axis": [x, y, z], "angle_deg": a} or {"yaw_deg", "pitch_deg",
/// "roll_deg"} (z-y-x), rotating the part's axes into the body's.
Mat33d orientation(const json& j, const std::string& where) {
  if (!j.is_object()) {
    fail(where, "expected an object");
  }
  if (j.contains("axis")) {
    requireKnownKeys(j, {"axis", "angle_deg"}, where);
    const Vec3d axis = vec3(j.at("axis"), where + ".axis");
    const double angle = degToRad(number(member(j, "angle_deg", where), where + ".angle_deg"));
    try {
      return toMat33(Quatd::fromAxisAngle(axis, angle));
    } catch (const Error&) {
      fail(where + ".axis", "rotation axis must be non-zero");
    }
  }
  requireKnownKeys(j, {"yaw_deg", "pitch_deg", "roll_deg"}, where);
  const auto angle = [&](const char* key) {
    return j.contains(key) ? degToRad(number(j.at(key), where + "." + key)) : 0.0;
  };
  return toMat33(Quatd::fromEuler(angle("yaw_deg"), angle("pitch_deg"), angle("roll_deg")));
}

Solid solid(const json& part, const std::string& where, std::set<std::string>& used) {
  const auto dim = [&](const char* key) {
    used.insert(key);
    return number(member(part, key, where), where + "." + key);
  };
  const json& shapeJson = member(part, "shape", where);
  if (!shapeJson.is_string()) {
    fail(where + ".shape", "expected a string");
  }
  const std::string shape = shapeJson.get<std::string>();
  if (shape == "point" || shape == "custom")
    return PointSolid{};
  if (shape == "solid-sphere")
    return SolidSphere{dim("radius")};
  if (shape == "spherical-shell")
    return SphericalShell{dim("radius")};
  if (shape == "hollow-sphere")
    return HollowSphere{dim("inner_radius"), dim("outer_radius")};
  if (shape == "solid-cylinder")
    return SolidCylinder{dim("radius"), dim("length")};
  if (shape == "cylindrical-shell")
    return CylindricalShell{dim("radius"), dim("length")};
  if (shape == "hollow-cylinder")
    return HollowCylinder{dim("inner_radius"), dim("outer_radius"), dim("length")};
  if (shape == "box") {
    used.insert("size");
    return Box{vec3(member(part, "size", where), where + ".size")};
  }
  if (shape == "rod")
    return Rod{dim("length")};
  if (shape == "solid-cone")
    return SolidCone{dim("radius"), dim("height")};
  fail(where + ".shape", "unknown shape '" + shape +
                             "' (point, custom, solid-sphere, spherical-shell, hollow-sphere, solid-cylinder, "
                             "cylindrical-shell, hollow-cylinder, box, rod, solid-cone)");
}

MassPart parsePart(const json& part, const std::string& where, double gravity) {
  std::set<std::string> used{"name", "shape", "position", "orientation", "mass", "weight", "density", "inertia"};
  const Solid shape = solid(part, where, used);
  requireKnownKeys(part, used, where);

  const int given = int(part.contains("mass")) + int(part.contains("weight")) + int(part.contains("density"));
  if (given != 1) {
    fail(where, "give exactly one of mass (kg), weight (N) or density (kg/m^3)");
  }
  MassPart mp;
  if (part.contains("mass")) {
    mp.mass = requirePositive(number(part.at("mass"), where + ".mass"), where + ".mass");
  } else if (part.contains("weight")) {
    mp.mass = requirePositive(number(part.at("weight"), where + ".weight"), where + ".weight") / gravity;
  } else {
    const double density = requirePositive(number(part.at("density"), where + ".density"), where + ".density");
    const double v = volume(shape);
    if (!(v > 0.0)) {
      fail(where + ".density", "shape '" + std::string(solidName(shape)) + "' has no volume: give its mass");
    }
    mp.mass = density * v;
  }
  const bool custom = part.at("shape") == "custom";
  if (custom) {
    mp.inertia = mat33(member(part, "inertia", where), where + ".inertia");
    requirePhysicalInertia(mp.inertia, where + ".inertia");
  } else if (part.contains("inertia")) {
    fail(where + ".inertia", "only a \"custom\" part takes an explicit inertia tensor");
  } else {
    mp.inertia = inertiaTensor(shape, mp.mass);
  }
  mp.position = part.contains("position") ? vec3(part.at("position"), where + ".position") : Vec3d{};
  if (part.contains("orientation")) {
    mp.orientation = orientation(part.at("orientation"), where + ".orientation");
  }
  if (part.contains("name") && !part.at("name").is_string()) {
    fail(where + ".name", "expected a string");
  }
  return mp;
}

} // namespace

CompositeBody parseComposite(const std::string& jsonText) {
  const json doc = json_fields::parseObject(jsonText, "a JSON object with a \"parts\" array");
  requireKnownKeys(doc, {"gravity", "parts", "description"}, "document");
  CompositeBody body;
  body.gravity = doc.contains("gravity") ? requirePositive(number(doc.at("gravity"), "gravity"), "gravity")
                                         : constants::standardGravity;
  const json& parts = member(doc, "parts", "document");
  if (!parts.is_array() || parts.empty()) {
    fail("parts", "expected a non-empty array");
  }
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string where = "parts[" + std::to_string(i) + "]";
    const json& part = parts[i];
    if (!part.is_object()) {
      fail(where, "expected an object");
    }
    try {
      body.parts.push_back(parsePart(part, where, body.gravity));
    } catch (const Error& e) {
      // Errors raised by the core name the bare field ("radius"): say which part it was.
      if (e.field().rfind("parts[", 0) == 0) {
        throw;
      }
      throw Error(where + "." + e.field(), where + "." + e.what());
    }
    body.names.push_back(part.contains("name") && part.at("name").is_string() ? part.at("name").get<std::string>()
                                                                              : where);
  }
  return body;
}

CompositeBody loadComposite(const std::string& path) { return parseComposite(json_fields::readFile(path)); }

} // namespace impetus::cli
