// Box2D v3's "rain" (its shared/benchmarks.c, with its shared/human.c ragdoll at scale 1): ragdolls
// spawned above three floors and destroyed again, as plain data and a script (rigid2d_scenes.hpp).
// The geometry, joints, filters, frictions and the spawn schedule are v3's.
#include "rigid2d_scene_parts.hpp"

#include <array>
#include <memory>

namespace impetus::bench {
using namespace parts;

namespace {

/// v3's human: the pin friction torque, N m at scale 1, and the joints' spring.
constexpr float ragdollJointFriction = 0.05f;
constexpr float ragdollJointHertz = 5.0f;
constexpr float ragdollJointDampingRatio = 0.5f;
constexpr float ragdollFriction = 0.2f;      ///< bones
constexpr float ragdollFootFriction = 0.05f; ///< feet
/// The filter: ragdolls in category 2 collide with the floors (1) and each other; feet only
/// with the floors.
constexpr std::uint64_t floorCategory = 1;
constexpr std::uint64_t ragdollCategory = 2;

/// The rain's floors: rows of square static boxes, gridSize on a side, 45 m apart.
constexpr float rainGridSize = 0.5f; ///< m
constexpr int rainGridCount = 500;   ///< boxes per floor, less one
constexpr float rainFloorSpacing = 45.0f;
constexpr float rainSpawnHeight = 40.0f;   ///< m above the floor
constexpr float rainRagdollSpacing = 0.5f; ///< m between the ragdolls of a group

/// One bone: the body's place (relative to the feet), its capsule (centres along the body's y,
/// radius), its linear damping; and the joint to its parent: the pivot (relative to the feet),
/// the angle limits (fractions of pi), the pin friction's share and the reference angle.
struct Bone {
  float y;
  float capsuleLow, capsuleHigh, radius;
  float linearDamping;
  int parent; ///< -1: the root (the hip)
  float pivotY;
  float lower, upper; ///< x pi rad
  float frictionScale;
  float referenceAngle = 0.0f; ///< rad
};

constexpr float quarterTurn = 0.25f * pi<float>;

// v3's bones, in its order: hip, torso, head, upper and lower left leg, upper and lower right
// leg, upper and lower left arm, upper and lower right arm (scale 1).
constexpr std::array<Bone, 11> bones{{
    {0.95f, -0.02f, 0.02f, 0.095f, 0.0f, -1, 0.0f, 0.0f, 0.0f, 1.0f},
    {1.2f, -0.135f, 0.135f, 0.09f, 0.0f, 0, 1.0f, -0.25f, 0.0f, 0.5f},
    {1.475f, -0.038f, 0.039f, 0.075f, 0.1f, 1, 1.4f, -0.3f, 0.1f, 0.25f},
    {0.775f, -0.125f, 0.125f, 0.06f, 0.0f, 0, 0.9f, -0.05f, 0.4f, 1.0f},
    {0.475f, -0.155f, 0.125f, 0.045f, 0.0f, 3, 0.625f, -0.5f, -0.02f, 0.5f},
    {0.775f, -0.125f, 0.125f, 0.06f, 0.0f, 0, 0.9f, -0.05f, 0.4f, 1.0f},
    {0.475f, -0.155f, 0.125f, 0.045f, 0.0f, 5, 0.625f, -0.5f, -0.02f, 0.5f},
    {1.225f, -0.125f, 0.125f, 0.035f, 0.0f, 1, 1.35f, -0.1f, 0.8f, 0.5f},
    {0.975f, -0.125f, 0.125f, 0.03f, 0.1f, 7, 1.1f, -0.2f, 0.3f, 0.1f, quarterTurn},
    {1.225f, -0.125f, 0.125f, 0.035f, 0.0f, 1, 1.35f, -0.1f, 0.8f, 0.5f},
    {0.975f, -0.125f, 0.125f, 0.03f, 0.1f, 9, 1.1f, -0.2f, 0.3f, 0.1f, quarterTurn},
}};
constexpr std::array<std::size_t, 2> lowerLegs{4, 6};

} // namespace

SceneContent humanRagdoll(const Vec2f& feet, std::int32_t group) {
  SceneContent human;
  for (std::size_t i = 0; i < bones.size(); ++i) {
    const Bone& bone = bones[i];
    SceneBody body;
    body.type = BodyType::dynamicBody;
    body.position = feet + Vec2f{0.0f, bone.y};
    body.linearDamping = bone.linearDamping;
    human.bodies.push_back(body);
    SceneShape capsule;
    capsule.kind = SceneShape::Kind::capsule;
    capsule.body = static_cast<std::uint32_t>(i);
    capsule.point1 = {0.0f, bone.capsuleLow};
    capsule.point2 = {0.0f, bone.capsuleHigh};
    capsule.radius = bone.radius;
    capsule.friction = ragdollFriction;
    capsule.group = group;
    capsule.categoryBits = ragdollCategory;
    capsule.maskBits = floorCategory | ragdollCategory;
    human.shapes.push_back(capsule);
    if (i == lowerLegs[0] || i == lowerLegs[1]) {
      SceneShape foot = capsule;
      foot.kind = SceneShape::Kind::polygon;
      foot.points = {{-0.03f, -0.185f}, {0.11f, -0.185f}, {0.11f, -0.16f}, {-0.03f, -0.14f}};
      foot.radius = 0.015f;
      foot.friction = ragdollFootFriction;
      foot.maskBits = floorCategory;
      human.shapes.push_back(foot);
    }
    if (bone.parent >= 0) {
      SceneJoint j;
      j.bodyA = static_cast<std::uint32_t>(bone.parent);
      j.bodyB = static_cast<std::uint32_t>(i);
      j.anchor = feet + Vec2f{0.0f, bone.pivotY};
      j.enableLimit = true;
      j.lowerAngle = bone.lower * pi<float>;
      j.upperAngle = bone.upper * pi<float>;
      j.enableMotor = true; // at speed 0: the pin's friction
      j.maxMotorTorque = bone.frictionScale * ragdollJointFriction;
      j.referenceAngle = bone.referenceAngle;
      j.enableSpring = true;
      j.hertz = ragdollJointHertz;
      j.dampingRatio = ragdollJointDampingRatio;
      human.joints.push_back(j);
    }
  }
  return human;
}

Rigid2dScene rainScene() {
  Rigid2dScene scene;
  scene.name = "rain";
  scene.enableSleep = true;
  scene.sleepThreshold = 0.1f; // v3's human's
  scene.box2d241 = false;
  scene.defaultSteps = 1000;
  const std::uint32_t ground = addBody(scene, BodyType::staticBody, {0.0f, 0.0f});
  const float left = -0.5f * static_cast<float>(rainGridCount) * rainGridSize;
  for (int floor = 0; floor < rainFloors; ++floor) {
    for (int j = 0; j <= rainGridCount; ++j) {
      addBox(scene, ground, 0.5f * rainGridSize, 0.5f * rainGridSize,
             {left + static_cast<float>(j) * rainGridSize, static_cast<float>(floor) * rainFloorSpacing});
    }
  }
  scene.makeScript = [] {
    struct State {
      int columnsSpawned = 0;
      int nextToReplace = 0;
      std::array<std::uint32_t, rainFloors * rainColumns> groups{};
    };
    auto state = std::make_shared<State>();
    const auto group = [](int floor, int column) {
      const float span = static_cast<float>(rainGridCount) * rainGridSize;
      const float pitch = span / static_cast<float>(rainColumns);
      Vec2f feet{-0.5f * span + pitch * (static_cast<float>(column) + 0.5f),
                 rainSpawnHeight + rainFloorSpacing * static_cast<float>(floor)};
      SceneContent content;
      for (int k = 0; k < rainGroupSize; ++k) {
        const SceneContent human = humanRagdoll(feet, -(k + 1));
        const auto offset = static_cast<std::uint32_t>(content.bodies.size());
        content.bodies.insert(content.bodies.end(), human.bodies.begin(), human.bodies.end());
        for (SceneShape s : human.shapes) {
          s.body += offset;
          content.shapes.push_back(s);
        }
        for (SceneJoint j : human.joints) {
          j.bodyA += offset;
          j.bodyB += offset;
          content.joints.push_back(j);
        }
        feet.x += rainRagdollSpacing;
      }
      return content;
    };
    return SceneScript([state, group](int step, SceneSpawner& spawner) {
      if (step % rainSpawnInterval != 0) {
        return;
      }
      // A new column while there are fewer than rainColumns; then the oldest is replaced.
      const bool filling = state->columnsSpawned < rainColumns;
      const int column = filling ? state->columnsSpawned : state->nextToReplace;
      for (int floor = 0; floor < rainFloors; ++floor) {
        std::uint32_t& handle = state->groups[static_cast<std::size_t>(floor * rainColumns + column)];
        if (!filling) {
          spawner.destroy(handle);
        }
        handle = spawner.spawn(group(floor, column));
      }
      if (filling) {
        ++state->columnsSpawned;
      } else {
        state->nextToReplace = (state->nextToReplace + 1) % rainColumns;
      }
    });
  };
  return scene;
}

} // namespace impetus::bench
