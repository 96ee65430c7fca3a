// The pieces the benchmark scenes are built from (rigid2d_scenes.cpp, box2d3_benchmark_scenes.cpp):
// bodies, boxes, circles, segments, revolute joints and pyramids appended to a scene's plain data.
#pragma once

#include "rigid2d_scenes.hpp"

namespace impetus::bench::parts {

using rigid2d::BodyType;

inline std::uint32_t addBody(SceneContent& scene, BodyType type, const Vec2f& position, float angularVelocity = 0.0f) {
  SceneBody b;
  b.type = type;
  b.position = position;
  b.angularVelocity = angularVelocity;
  scene.bodies.push_back(b);
  return static_cast<std::uint32_t>(scene.bodies.size() - 1);
}

inline void addBox(SceneContent& scene, std::uint32_t body, float halfWidth, float halfHeight, const Vec2f& center = {},
                   float angle = 0.0f) {
  SceneShape s;
  s.kind = SceneShape::Kind::box;
  s.body = body;
  s.center = center;
  s.halfWidth = halfWidth;
  s.halfHeight = halfHeight;
  s.angle = angle;
  scene.shapes.push_back(s);
}

inline void addCircle(SceneContent& scene, std::uint32_t body, float radius, std::int32_t group = 0,
                      const Vec2f& center = {}) {
  SceneShape s;
  s.kind = SceneShape::Kind::circle;
  s.body = body;
  s.radius = radius;
  s.group = group;
  s.center = center;
  scene.shapes.push_back(s);
}

/// A two-sided segment from point1 to point2 in the body frame (static bodies only).
inline void addSegment(SceneContent& scene, std::uint32_t body, const Vec2f& point1, const Vec2f& point2) {
  SceneShape s;
  s.kind = SceneShape::Kind::segment;
  s.body = body;
  s.point1 = point1;
  s.point2 = point2;
  scene.shapes.push_back(s);
}

inline void addJoint(SceneContent& scene, std::uint32_t a, std::uint32_t b, const Vec2f& anchor, float lower = 0.0f,
                     float upper = 0.0f) {
  SceneJoint j;
  j.bodyA = a;
  j.bodyB = b;
  j.anchor = anchor;
  j.enableLimit = lower != upper;
  j.lowerAngle = lower;
  j.upperAngle = upper;
  scene.joints.push_back(j);
}

/// A pyramid of `base` boxes of half-size `h` at the bottom, centred on x = centerX, standing on
/// y = baseY; its top box is recorded in scene.tops.
inline void addPyramid(Rigid2dScene& scene, int base, float centerX, float h = pyramidBoxHalfSize, float baseY = 0.0f) {
  for (int i = 0; i < base; ++i) {
    const int rowCount = base - i;
    const float y = baseY + static_cast<float>(2 * i + 1) * h;
    for (int j = 0; j < rowCount; ++j) {
      // Row i: boxes 2h apart, centred on centerX.
      const float x = centerX + (static_cast<float>(2 * j) - static_cast<float>(rowCount - 1)) * h;
      const std::uint32_t b = addBody(scene, BodyType::dynamicBody, {x, y});
      addBox(scene, b, h, h);
    }
  }
  scene.tops.push_back(static_cast<std::uint32_t>(scene.bodies.size() - 1));
}

} // namespace impetus::bench::parts
