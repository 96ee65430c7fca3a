// A pile of every kind of shape poured into a box: every pair of kinds meets, and the pile comes
// to rest without overlap, without gaining energy, and the same way run after run.
#include <impetus/rigid3d/world.hpp>

#include "test_random.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace impetus::rigid3d {
namespace {

constexpr float dt = 1.0f / 60.0f;

/// A 4 x 4 m floor with walls 2 m high, and 64 bodies above it: spheres, capsules, boxes and
/// hulls of random points, turned at random.
std::vector<BodyId> pourPile(World& world) {
  BodyDef groundDef;
  const BodyId ground = world.createBody(groundDef);
  world.createShape(ground, ShapeDef{}, makeBoxHull({2.5f, 0.5f, 2.5f}, {0.0f, -0.5f, 0.0f}));
  for (const Vec3f& wall : {Vec3f{2.25f, 1.0f, 0.0f}, Vec3f{-2.25f, 1.0f, 0.0f}}) {
    world.createShape(ground, ShapeDef{}, makeBoxHull({0.25f, 1.0f, 2.5f}, wall));
  }
  for (const Vec3f& wall : {Vec3f{0.0f, 1.0f, 2.25f}, Vec3f{0.0f, 1.0f, -2.25f}}) {
    world.createShape(ground, ShapeDef{}, makeBoxHull({2.5f, 1.0f, 0.25f}, wall));
  }
  Lcg random(7);
  std::vector<BodyId> bodies;
  for (int i = 0; i < 64; ++i) {
    BodyDef def;
    def.type = BodyType::dynamicBody;
    def.position = {0.9f * static_cast<float>(i % 4) - 1.35f, 0.8f + 0.7f * static_cast<float>(i / 16),
                    0.9f * static_cast<float>((i / 4) % 4) - 1.35f};
    def.rotation = normalize(Quatf{random.next(), random.next(), random.next(), random.next() + 1.5f});
    def.angularVelocity = {random.next(), random.next(), random.next()};
    const BodyId body = world.createBody(def);
    ShapeDef shape;
    shape.friction = 0.5f;
    shape.restitution = 0.2f * (random.next() + 1.0f);
    switch (i % 4) {
    case 0:
      world.createShape(body, shape, Sphere{{}, 0.25f + 0.1f * random.next()});
      break;
    case 1:
      world.createShape(body, shape, Capsule{{-0.2f, 0.0f, 0.0f}, {0.2f, 0.0f, 0.0f}, 0.15f});
      break;
    case 2:
      world.createShape(body, shape, makeBoxHull({0.3f, 0.15f, 0.2f}));
      break;
    default: {
      std::vector<Vec3f> cloud;
      for (int k = 0; k < 12; ++k) {
        cloud.push_back(Vec3f{random.next(), random.next(), random.next()} * 0.3f);
      }
      world.createShape(body, shape, computeHull(cloud));
    }
    }
    bodies.push_back(body);
  }
  return bodies;
}

TEST(Rigid3dPile, every_kind_of_shape_poured_into_a_box_comes_to_rest_inside_it) {
  World world;
  const std::vector<BodyId> bodies = pourPile(world);
  double energyAtRest = 0.0;
  for (int i = 0; i < 600; ++i) {
    world.step(dt);
  }
  std::vector<ContactData> contacts;
  world.contacts(contacts);
  float deepest = 0.0f;
  for (const ContactData& c : contacts) {
    for (int k = 0; k < c.manifold.pointCount; ++k) {
      deepest = std::min(deepest, c.manifold.points[static_cast<std::size_t>(k)].separation);
    }
  }
  for (const BodyId b : bodies) {
    const Vec3f p = world.position(b);
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    // Inside the walls and on or above the floor.
    EXPECT_LT(std::abs(p.x), 2.0f);
    EXPECT_LT(std::abs(p.z), 2.0f);
    EXPECT_GT(p.y, 0.0f);
    energyAtRest += world.kineticEnergy(b);
  }
  // Ten seconds on, the pile is at rest: under 1 mJ of motion per kilogram (a pile whose
  // contacts kept pushing it apart or jittering would hold far more), and no overlap deeper
  // than a few slops (linearSlop, 5 mm: the soft contacts leave about one).
  double mass = 0.0;
  for (const BodyId b : bodies) {
    mass += world.massData(b).mass;
  }
  EXPECT_LT(energyAtRest / mass, 1e-3);
  EXPECT_GT(deepest, -0.02f);
}

TEST(Rigid3dPile, the_same_pile_poured_twice_lands_the_same_to_the_bit) {
  World first;
  World second;
  pourPile(first);
  pourPile(second);
  for (int i = 0; i < 120; ++i) {
    first.step(dt);
    second.step(dt);
  }
  EXPECT_EQ(first.stateHash(), second.stateHash());
}

} // namespace
} // namespace impetus::rigid3d
