// The benchmark scenes are built as bench/particle_scenes.hpp describes them (counts, settings,
// obstacles, no initial overlap) and behave: finite, on the right side of every plane, settling.
#include "particle_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace {

using impetus::ParticleWorld;
using impetus::Vec3f;
namespace bench = impetus::bench;

constexpr float frame = 1.0f / 60.0f;

bool allFinite(const ParticleWorld& world) {
  for (const Vec3f& x : world.positions()) {
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z)) {
      return false;
    }
  }
  for (const Vec3f& v : world.velocities()) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      return false;
    }
  }
  return true;
}

TEST(RainScene, has_the_requested_particles_above_one_ground_plane_with_drag_and_wind) {
  for (const std::size_t count : {1u, 10u, 1000u, 10000u}) {
    const ParticleWorld world = bench::makeRainScene(count);
    EXPECT_EQ(world.particleCount(), count);
    EXPECT_EQ(world.obstacleCount(), 1u);
    EXPECT_EQ(world.settings().substeps, 4);
    EXPECT_FALSE(world.settings().particleCollisions);
    EXPECT_GT(world.settings().dragCoefficient, 0.0f);
    EXPECT_EQ(world.settings().wind, bench::rainWind);
    EXPECT_FLOAT_EQ(world.settings().gravity.y, -9.81f);
    for (const impetus::ParticleId id : world.ids()) {
      EXPECT_FLOAT_EQ(world.mass(id), bench::sceneParticleMass);
      EXPECT_FLOAT_EQ(world.radius(id), bench::sceneParticleRadius);
      const Vec3f x = world.position(id);
      EXPECT_GE(x.y, bench::sceneParticleRadius);
      EXPECT_LE(x.y, bench::sceneParticleRadius + bench::rainDropHeight);
    }
  }
}

TEST(RainScene, heights_are_spread_over_the_drop_range) {
  const ParticleWorld world = bench::makeRainScene(1000);
  int low = 0;
  int high = 0;
  for (const Vec3f& x : world.positions()) {
    const float h = (x.y - bench::sceneParticleRadius) / bench::rainDropHeight;
    low += h < 0.5f ? 1 : 0;
    high += h >= 0.5f ? 1 : 0;
  }
  EXPECT_NEAR(low, 500, 10);
  EXPECT_NEAR(high, 500, 10);
}

TEST(RainScene, particles_drift_downwind_as_they_fall_then_rest_on_the_ground) {
  ParticleWorld world = bench::makeRainScene(1000);
  std::vector<float> startHeight;
  for (const Vec3f& x : world.positions()) {
    startHeight.push_back(x.y);
  }
  for (int i = 0; i < 15; ++i) { // 0.25 s: a particle falls 0.31 m
    world.step(frame);
  }
  int airborne = 0;
  for (std::size_t i = 0; i < startHeight.size(); ++i) {
    if (startHeight[i] > 0.5f) {
      ++airborne;
      // Drag relative to the wind pushes it downwind, never faster than the wind.
      const Vec3f v = world.velocities()[i];
      EXPECT_GT(v.x, 0.0f);
      EXPECT_LT(v.x, bench::rainWind.x);
      EXPECT_GT(v.z, 0.0f);
      EXPECT_LT(v.z, bench::rainWind.z);
    }
  }
  EXPECT_GT(airborne, 700);
  for (int i = 15; i < 180; ++i) { // to 3 s
    world.step(frame);
    ASSERT_TRUE(allFinite(world)) << "step " << i;
  }
  // All landed, bounced and came to rest; static friction (mu m g = 0.2 N) holds them against
  // the wind's drag (0.06 N), so each touches the ground in every substep from now on.
  for (std::size_t i = 0; i < world.particleCount(); ++i) {
    EXPECT_NEAR(world.positions()[i].y, bench::sceneParticleRadius, 1e-3f);
    EXPECT_LT(impetus::length(world.velocities()[i]), 1e-3f);
  }
}

TEST(BoxScene, particles_fill_ten_layers_inside_six_planes_without_touching) {
  for (const std::size_t count : {1u, 10u, 11u, 1000u, 1001u, 5000u}) {
    const ParticleWorld world = bench::makeBoxScene(count);
    EXPECT_EQ(world.particleCount(), count);
    EXPECT_EQ(world.obstacleCount(), 6u);
    EXPECT_TRUE(world.settings().particleCollisions);
    const float side = bench::boxSide(count);
    const float r = bench::sceneParticleRadius;
    for (const impetus::ParticleId id : world.ids()) {
      const Vec3f x = world.position(id);
      EXPECT_GE(x.x, r);
      EXPECT_LE(x.x, side - r);
      EXPECT_GE(x.z, r);
      EXPECT_LE(x.z, side - r);
      EXPECT_GE(x.y, r);
      EXPECT_LE(x.y, static_cast<float>(bench::boxLayers) * bench::boxSpacing);
      const Vec3f v = world.velocity(id);
      EXPECT_LE(std::abs(v.x), bench::boxMaxSpeed);
      EXPECT_LE(std::abs(v.y), bench::boxMaxSpeed);
      EXPECT_LE(std::abs(v.z), bench::boxMaxSpeed);
    }
  }
  EXPECT_EQ(bench::boxLatticeSide(1000), 10u); // 10 layers of 10 x 10
  EXPECT_EQ(bench::boxLatticeSide(1001), 11u);
  EXPECT_EQ(bench::boxLatticeSide(100000), 100u);
  EXPECT_FLOAT_EQ(bench::boxSide(1000), 11.0f * bench::boxSpacing);
}

TEST(BoxScene, no_two_particles_overlap_at_the_start) {
  const ParticleWorld world = bench::makeBoxScene(1000);
  const auto x = world.positions();
  float closest = 1e9f;
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (std::size_t j = i + 1; j < x.size(); ++j) {
      closest = std::fmin(closest, impetus::distance(x[i], x[j]));
    }
  }
  EXPECT_NEAR(closest, bench::boxSpacing, 1e-5f);
  EXPECT_GT(closest, 2.0f * bench::sceneParticleRadius);
}

TEST(BoxScene, particles_stay_finite_inside_the_box_and_settle_on_the_floor) {
  ParticleWorld world = bench::makeBoxScene(1000);
  const double height0 = world.potentialEnergy();
  for (int i = 0; i < 120; ++i) { // 2 s
    world.step(frame);
    ASSERT_TRUE(allFinite(world)) << "step " << i;
  }
  const float side = bench::boxSide(1000);
  const float r = bench::sceneParticleRadius;
  // Particle pairs are resolved after the walls in each substep, so the pile's pressure may leave
  // a particle partly in a wall until the next substep; its centre stays inside the box.
  const float slack = r;
  for (const Vec3f& x : world.positions()) {
    EXPECT_GE(x.x, r - slack);
    EXPECT_LE(x.x, side - r + slack);
    EXPECT_GE(x.z, r - slack);
    EXPECT_LE(x.z, side - r + slack);
    EXPECT_GE(x.y, r - slack);
    EXPECT_LE(x.y, bench::boxHeight - r + slack);
  }
  // The pile is lower than the lattice was (potential energy fell) and nearly still.
  EXPECT_LT(world.potentialEnergy(), height0);
  EXPECT_LT(world.kineticEnergy(), 0.1 * (height0 - world.potentialEnergy()));
}

} // namespace
