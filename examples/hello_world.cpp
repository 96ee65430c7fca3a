// Hello world for a game: drop a box on the ground and see where it comes to rest.
#include <impetus/rigid2d/world.hpp>

#include <cstdio>

int main() {
  using namespace impetus;
  using namespace impetus::rigid2d;

  World world; // gravity (0, -10) m/s^2, 4 substeps a step

  // The ground: a static body with a 100 m x 1 m box whose top is at y = 0.
  const BodyId ground = world.createBody({});
  world.createShape(ground, {}, makeOffsetBox(50.0f, 0.5f, {0.0f, -0.5f}, 0.0f));

  // A 1 m box dropped from 4 m, a little bouncy.
  BodyDef boxDef;
  boxDef.type = BodyType::dynamicBody;
  boxDef.position = {0.0f, 4.0f};
  const BodyId box = world.createBody(boxDef);
  ShapeDef material; // density 1 kg/m^2, friction 0.6
  material.restitution = 0.2f;
  world.createShape(box, material, makeBox(0.5f, 0.5f));

  // Two seconds of 60 Hz game frames.
  for (int frame = 0; frame < 120; ++frame) {
    world.step(1.0f / 60.0f);
  }
  // Its centre, half its height above the ground, if it has come to rest.
  std::printf("the box rests at y = %.3f m, %s\n", world.position(box).y, world.isAwake(box) ? "awake" : "asleep");
  return 0;
}
