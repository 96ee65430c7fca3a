// The rigid2d scene loader's internals, shared by its files: rigid2d_scene.cpp (the document's
// top level, world settings, materials, bodies and shapes), rigid2d_scene_joints.cpp (joints,
// and the body names and anchors effectors use too) and rigid2d_scene_effectors.cpp. Not for use
// outside the loader: parseRigid2dScene (rigid2d_scene.hpp) is its interface.
#pragma once

#include "json_fields.hpp"
#include "rigid2d_scene.hpp"

#include <impetus/core/task_runner.hpp>
#include <impetus/math/vec2.hpp>
#include <impetus/rigid2d/world.hpp>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace impetus::cli::rigid2d_loader {

/// A name that can go in a CSV field as it is.
[[nodiscard]] std::string nameOf(json_fields::Fields& f);

struct Material {
  float density = 1.0f;
  float friction = 0.6f;
  float restitution = 0.0f;
  float rollingResistance = 0.0f;
  float tangentSpeed = 0.0f; ///< m/s (a conveyor belt's surface)
};

/// Fills a scene from a document: world settings, materials, then bodies, joints and effectors
/// in that order (joints and effectors name bodies).
class Loader {
public:
  Loader(Rigid2dScene& scene, TaskRunner* runner) : scene_(scene), runner_(runner) {}

  void load(const nlohmann::json& doc);

private:
  // World, materials, bodies and shapes (rigid2d_scene.cpp) -----------------------------------

  static rigid2d::WorldDef worldDef(const nlohmann::json& j);
  /// "materials": {"name": {density, friction, restitution, rolling_resistance}}.
  void materials(const nlohmann::json& j);
  static Material material(json_fields::Fields& f, Material m);
  void body(const nlohmann::json& j, const std::string& where);
  /// {"mass", "center", "inertia"}: overrides what the shapes' densities give. Without a
  /// centre the shapes' centre of mass stays; without an inertia the shapes' inertia about the
  /// centre of mass is scaled by the new mass (the same shapes, a uniformly scaled density).
  void massProperties(rigid2d::BodyId id, const nlohmann::json& j, const std::string& where);
  rigid2d::ShapeDef shapeDef(json_fields::Fields& f);
  void shape(rigid2d::BodyId id, rigid2d::BodyType bodyType, const nlohmann::json& j, const std::string& where);

  // Joints (rigid2d_scene_joints.cpp) ---------------------------------------------------------

  /// A body named in a joint or an effector.
  rigid2d::BodyId bodyNamed(json_fields::Fields& f, const std::string& key);
  float initialAngle(rigid2d::BodyId id) const { return angles_[scene_.bodyNumber(id)]; }
  /// One end's anchor in its body's frame: "local_anchor_<e>" (body frame), "anchor_<e>"
  /// (a world point) or the shared "anchor" (a world point); at most one; default the origin.
  Vec2f anchor(json_fields::Fields& f, rigid2d::BodyId id, const char* end, bool shared) const;
  /// An axis in body A's frame: "local_axis_a" or "axis" (a world direction).
  Vec2f axis(json_fields::Fields& f, rigid2d::BodyId a, const Vec2f& fallbackWorld) const;
  /// What every joint has. B's anchor, A's anchor, collide_connected, break limits.
  void base(json_fields::Fields& f, rigid2d::JointDefBase& d, bool anchors);
  void bodies(json_fields::Fields& f, rigid2d::JointDefBase& d);
  /// Lower and upper limits (lower <= upper); angles in degrees when `degrees`.
  static void limits(json_fields::Fields& f, const std::string& lowerKey, const std::string& upperKey, float& lower,
                     float& upper, bool degrees);
  void joint(const nlohmann::json& j, const std::string& where);

  // Effectors (rigid2d_scene_effectors.cpp) ---------------------------------------------------

  template <class E, class S> void addEffector(json_fields::Fields& f, const std::string& where, const S& settings);
  void effector(const nlohmann::json& j, const std::string& where);

  Rigid2dScene& scene_;
  TaskRunner* runner_ = nullptr; ///< steps the world's parallel loops (not owned)
  Vec2f gravity_;
  std::map<std::string, Material> materials_;
  std::map<std::string, std::size_t> names_;
  std::set<std::string> jointNames_;
  std::vector<float> angles_; ///< each body's initial angle, rad, as the file gave it
};

} // namespace impetus::cli::rigid2d_loader
