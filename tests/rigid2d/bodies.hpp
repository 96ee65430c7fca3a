// Bodies the 2D joint tests build again and again.
#pragma once

#include <impetus/rigid2d/world.hpp>

namespace impetus::rigid2d::test {

/// A dynamic disc that never sleeps, of the given radius (m) and areal density (kg/m^2).
inline BodyId addBall(World& world, const Vec2f& position, float radius, float density = 1.0f) {
  BodyDef def;
  def.type = BodyType::dynamicBody;
  def.position = position;
  def.enableSleep = false;
  const BodyId b = world.createBody(def);
  ShapeDef shape;
  shape.density = density;
  world.createShape(b, shape, Circle{{}, radius});
  return b;
}

} // namespace impetus::rigid2d::test
