// Reads a 2D rigid-body scene ("kind": "rigid2d": world settings, materials, bodies with their
// shapes, joints and force effectors) from a JSON document into a rigid2d::World: the input of
// `impetus run` for 2D scenes. Format: docs/scene-format-2d.md.
#pragma once

#include <impetus/core/task_runner.hpp>
#include <impetus/rigid2d/effectors.hpp>
#include <impetus/rigid2d/world.hpp>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace impetus::cli {

/// The most bodies a rigid2d scene file may hold.
inline constexpr std::size_t maxSceneBodies = 1'000'000;

/// A loaded 2D scene: the world, ready to step, its effectors, and what the file asked for.
struct Rigid2dScene {
  std::string description;
  rigid2d::World world;
  /// Applied (in file order) right before each world step.
  rigid2d::ForceEffectorSet effectors;
  /// Every body in file order: body k of the output is bodies[k].
  std::vector<rigid2d::BodyId> bodies;
  std::vector<std::string> bodyNames; ///< "" when unnamed
  std::vector<float> gravityScales;   ///< each body's, for the potential energy
  /// Every joint in file order, with its name ("" when unnamed).
  std::vector<rigid2d::JointId> joints;
  std::vector<std::string> jointNames;
  std::size_t shapeCount = 0; ///< shapes the file described (a chain counts once)
  /// Body and joint numbers by the ids' slots (the loader fills them).
  std::vector<std::size_t> bodyBySlot;
  std::vector<std::size_t> jointBySlot;

  /// The number (file order) of a body of this scene.
  [[nodiscard]] std::size_t bodyNumber(rigid2d::BodyId id) const;
  /// The number (file order) of a joint of this scene.
  [[nodiscard]] std::size_t jointNumber(rigid2d::JointId id) const;
};

/// The document's "kind": "particles" (also when absent) or "rigid2d". Throws impetus::Error
/// ("kind: ...") for anything else.
[[nodiscard]] std::string sceneKind(const nlohmann::json& doc);

/// Builds a rigid2d scene from a parsed document. Throws impetus::Error whose message starts
/// with the JSON path of the offending value (e.g. "bodies[3].shapes[0].density = -1: must be
/// finite and non-negative") for unknown keys, missing or invalid values, unknown body names
/// and degenerate geometry; nothing of a scene that fails is returned.
/// `runner` (optional, not owned; must outlive the scene) steps the world's parallel loops.
[[nodiscard]] Rigid2dScene parseRigid2dScene(const nlohmann::json& doc, TaskRunner* runner = nullptr);

/// Parses JSON text (malformed JSON is "json: malformed JSON: ...") and builds the scene.
[[nodiscard]] Rigid2dScene parseRigid2dScene(const std::string& jsonText);

} // namespace impetus::cli
