// Emitters: reproducible spawning (seeds), bursts, rates, lifetimes, and the book's ch. 2
// kinematic explosion run on the particle world.
#include <impetus/math/scalar.hpp>
#include <impetus/particles/particles.hpp>

#include "support/error_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <vector>

namespace impetus {
namespace {

constexpr float dt = 1.0f / 60.0f;

EmitterDef fountain(std::uint32_t seed) {
  EmitterDef e;
  e.position = {0.0f, 1.0f, 0.0f};
  e.direction = {0.0f, 1.0f, 0.0f};
  e.coneAngle = 0.4f;
  e.minSpeed = 2.0f;
  e.maxSpeed = 5.0f;
  e.burst = 20;
  e.rate = 120.0f;
  e.minLifetime = 0.5f;
  e.maxLifetime = 1.5f;
  e.seed = seed;
  return e;
}

std::vector<Vec3f> run(std::uint32_t seed, int steps) {
  ParticleWorld world;
  world.addObstacle(PlaneObstacle{});
  world.addEmitter(fountain(seed));
  for (int i = 0; i < steps; ++i) {
    world.step(dt);
  }
  return {world.positions().begin(), world.positions().end()};
}

TEST(Emitter, same_seed_gives_bit_identical_particles) {
  const std::vector<Vec3f> a = run(11, 100);
  const std::vector<Vec3f> b = run(11, 100);
  const std::vector<Vec3f> c = run(12, 100);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 100u);
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3f)), 0);
  // Another seed: other particles.
  EXPECT_TRUE(a.size() != c.size() || std::memcmp(a.data(), c.data(), a.size() * sizeof(Vec3f)) != 0);
}

TEST(Emitter, burst_spawns_once) {
  ParticleWorld world;
  EmitterDef e;
  e.burst = 25;
  e.minLifetime = 100.0f;
  e.maxLifetime = 100.0f;
  world.addEmitter(e);
  EXPECT_EQ(world.particleCount(), 0u); // spawning happens in the step
  world.step(dt);
  EXPECT_EQ(world.particleCount(), 25u);
  for (int i = 0; i < 30; ++i) {
    world.step(dt);
  }
  EXPECT_EQ(world.particleCount(), 25u);
}

// rate particles per second while the emitter runs (`duration`), with the fractional remainder
// carried from step to step: after t seconds, floor(rate t) of them (one more or less from float
// rounding of the running sum).
TEST(Emitter, rate_spawns_that_many_per_second_for_the_duration) {
  ParticleWorld world;
  world.setSettings([] {
    ParticleWorldSettings s;
    s.gravity = {};
    return s;
  }());
  EmitterDef e;
  e.burst = 3;
  e.rate = 45.0f; // not a multiple of 60: fractional particles per step
  e.duration = 2.0f;
  e.minLifetime = 100.0f;
  e.maxLifetime = 100.0f;
  const EmitterId id = world.addEmitter(e);
  for (int i = 0; i < 60; ++i) {
    world.step(dt);
  }
  EXPECT_NEAR(static_cast<double>(world.particleCount()), 3.0 + 45.0, 1.0);
  for (int i = 0; i < 120; ++i) { // to 3 s; emission stopped at 2 s
    world.step(dt);
  }
  EXPECT_NEAR(static_cast<double>(world.particleCount()), 3.0 + 90.0, 1.0);
  const std::size_t total = world.particleCount();
  world.removeEmitter(id);
  world.step(dt);
  EXPECT_EQ(world.particleCount(), total);
  expectErrorField([&] { world.removeEmitter(id); }, "emitter id");
}

// Every particle lives exactly its lifetime: it is destroyed in the step during which its age
// reaches it, it is never seen older, and its age is the time since it was created.
TEST(Emitter, lifetimes_are_respected) {
  ParticleWorld world;
  world.addEmitter(fountain(3));
  struct Seen {
    ParticleId id;
    float lifetime;
    float age;
    float born;
  };
  std::map<std::uint64_t, Seen> seen;
  const auto key = [](ParticleId id) { return (std::uint64_t{id.generation} << 32) | id.index; };
  for (int i = 0; i < 200; ++i) {
    world.step(dt);
    for (const ParticleId id : world.ids()) {
      const float age = world.age(id);
      const float lifetime = world.lifetime(id);
      ASSERT_LT(age, lifetime);
      ASSERT_GE(lifetime, 0.5f);
      ASSERT_LE(lifetime, 1.5f);
      auto [it, fresh] = seen.try_emplace(key(id), Seen{id, lifetime, age, world.time() - age});
      if (!fresh) {
        // Age advances with the world's clock (to float rounding of the two running sums).
        ASSERT_NEAR(world.time() - it->second.born, age, 1e-4f);
        it->second.age = age;
      }
    }
  }
  // Those that died were last seen less than one step before the end of their life.
  int died = 0;
  for (const auto& entry : seen) {
    const Seen& s = entry.second;
    if (!world.isValid(s.id)) {
      ++died;
      EXPECT_GE(s.age + dt, s.lifetime - 1e-4f);
    }
  }
  EXPECT_GT(died, 100);
}

// The book's ch. 2 kinematic explosion (spec ch. 1-6 section 4.2) as an emitter: a burst of 50
// particles in the plane, all around, speeds in [V/2, V], lives in [0.8 L, L], under gravity and
// nothing else. Each then follows x = v0 t + g t^2 / 2 (the book's closed form) with t its age:
// velocity Verlet is exact for a constant acceleration, so only float rounding remains (about
// 380 updates of positions up to 25 m, each rounded by at most 1e-6 m: 3e-4 m at worst). They
// all live until 0.8 L and are all gone after L.
TEST(Emitter, runs_the_books_kinematic_explosion) {
  const float V = 10.0f;
  const float L = 2.0f;
  ParticleWorldSettings s;
  s.integrator = ParticleIntegrator::velocityVerlet;
  ParticleWorld world(s);
  EmitterDef e;
  e.position = {5.0f, 20.0f, 0.0f};
  e.burst = 50;
  e.planar = true;
  e.coneAngle = pi<float>;
  e.minSpeed = 0.5f * V;
  e.maxSpeed = V;
  e.minLifetime = 0.8f * L;
  e.maxLifetime = L;
  world.addEmitter(e);
  world.step(dt);
  ASSERT_EQ(world.particleCount(), 50u);
  const Vec3f gravity = s.gravity;
  struct Launch {
    ParticleId id;
    Vec3f v0;
  };
  std::vector<Launch> launches;
  int left = 0;
  for (const ParticleId id : world.ids()) {
    const Vec3f v0 = world.velocity(id) - gravity * world.age(id);
    EXPECT_EQ(v0.z, 0.0f); // planar
    EXPECT_GE(length(v0), 0.5f * V * (1.0f - 1e-6f));
    EXPECT_LE(length(v0), V * (1.0f + 1e-6f));
    EXPECT_GE(world.lifetime(id), 0.8f * L);
    EXPECT_LE(world.lifetime(id), L);
    left += v0.x < 0.0f ? 1 : 0;
    launches.push_back({id, v0});
  }
  EXPECT_GT(left, 10); // all around, not one way
  EXPECT_LT(left, 40);
  while (world.time() < 0.8f * L - 2.0f * dt) {
    world.step(dt);
  }
  ASSERT_EQ(world.particleCount(), 50u);
  for (const Launch& l : launches) {
    const float t = world.age(l.id);
    EXPECT_NEAR(t, world.time(), 1e-5f);
    const Vec3f expected = e.position + l.v0 * t + gravity * (0.5f * t * t);
    const Vec3f x = world.position(l.id);
    EXPECT_NEAR(x.x, expected.x, 3e-4f);
    EXPECT_NEAR(x.y, expected.y, 3e-4f);
    EXPECT_EQ(x.z, 0.0f);
  }
  while (world.time() < L + 0.5f * dt) {
    world.step(dt);
  }
  EXPECT_EQ(world.particleCount(), 0u);
}

// Inside the cone: every launch direction is within coneAngle of the emitter's direction.
TEST(Emitter, directions_stay_in_the_cone) {
  ParticleWorldSettings s;
  s.gravity = {};
  ParticleWorld world(s);
  EmitterDef e;
  e.direction = {1.0f, 1.0f, 0.0f}; // normalized by the world
  e.coneAngle = 0.3f;
  e.burst = 500;
  e.minLifetime = 10.0f;
  e.maxLifetime = 10.0f;
  world.addEmitter(e);
  world.step(dt);
  const Vec3f axis = normalize(e.direction);
  float widest = 0.0f;
  for (const Vec3f& v : world.velocities()) {
    const float angle = std::acos(std::fmin(1.0f, dot(normalize(v), axis)));
    EXPECT_LE(angle, 0.3f + 1e-3f);
    widest = std::fmax(widest, angle);
  }
  EXPECT_GT(widest, 0.25f); // and it fills the cone
}

TEST(Emitter, bad_definitions_throw_naming_the_field) {
  ParticleWorld world;
  const auto bad = [&](auto change) {
    EmitterDef def;
    change(def);
    return [&world, def] { (void)world.addEmitter(def); };
  };
  expectErrorField(bad([](EmitterDef& d) { d.direction = {}; }), "direction");
  expectErrorField(bad([](EmitterDef& d) { d.maxSpeed = 0.5f; }), "maxSpeed");
  expectErrorField(bad([](EmitterDef& d) { d.minSpeed = -1.0f; }), "minSpeed");
  expectErrorField(bad([](EmitterDef& d) { d.burst = -1; }), "burst");
  expectErrorField(bad([](EmitterDef& d) { d.rate = -1.0f; }), "rate");
  expectErrorField(bad([](EmitterDef& d) { d.minLifetime = 0.0f; }), "minLifetime");
  expectErrorField(bad([](EmitterDef& d) { d.maxLifetime = 0.5f; }), "maxLifetime");
  expectErrorField(bad([](EmitterDef& d) { d.mass = 0.0f; }), "mass");
  expectErrorField(bad([](EmitterDef& d) { d.duration = -1.0f; }), "duration");
  world.step(dt);
  EXPECT_EQ(world.particleCount(), 0u);
}

} // namespace
} // namespace impetus
