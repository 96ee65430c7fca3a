// Builders of the benchmark scenes (see particle_scenes.hpp for what each one is).
#include "particle_scenes.hpp"

#include <cmath>
#include <random>

namespace impetus::bench {
namespace {

/// Fractional part of i times the golden ratio: an evenly spread sequence in [0, 1) (Weyl
/// sequence), so the drop heights cover the range without clumps and need no random generator.
float goldenFraction(std::size_t i) {
  const double x = static_cast<double>(i) * 0.6180339887498949;
  return static_cast<float>(x - std::floor(x));
}

/// Uniform in [lo, hi) from mt19937's raw output (bit-identical on every standard library,
/// unlike std::uniform_real_distribution).
float uniform(std::mt19937& rng, float lo, float hi) {
  return lo + (hi - lo) * static_cast<float>(static_cast<double>(rng()) / 4294967296.0);
}

} // namespace

ParticleWorld makeRainScene(std::size_t count) {
  ParticleWorldSettings settings;
  settings.wind = rainWind;
  settings.dragCoefficient = 0.47f; // a sphere at high Reynolds number
  settings.airDensity = 1.225f;     // sea-level air
  ParticleWorld world(settings);
  world.addObstacle(PlaneObstacle{{0.0f, 1.0f, 0.0f}, 0.0f}, SurfaceMaterial{0.6f, 0.4f});

  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(count))));
  for (std::size_t i = 0; i < count; ++i) {
    ParticleDef p;
    p.position = {static_cast<float>(i % side) * rainSpacing, sceneParticleRadius + rainDropHeight * goldenFraction(i),
                  static_cast<float>(i / side) * rainSpacing};
    p.mass = sceneParticleMass;
    p.radius = sceneParticleRadius;
    world.createParticle(p);
  }
  return world;
}

std::size_t boxLatticeSide(std::size_t count) {
  std::size_t k = 1;
  while (boxLayers * k * k < count) {
    ++k;
  }
  return k;
}

float boxSide(std::size_t count) { return static_cast<float>(boxLatticeSide(count) + 1) * boxSpacing; }

ParticleWorld makeBoxScene(std::size_t count) {
  ParticleWorldSettings settings;
  settings.particleCollisions = true;
  settings.particleRestitution = 0.5f;
  ParticleWorld world(settings);

  // Six planes, normals pointing into the box: floor y = 0, ceiling y = H, walls x, z = 0 and L.
  const float side = boxSide(count);
  const SurfaceMaterial wall{0.6f, 0.4f};
  world.addObstacle(PlaneObstacle{{0.0f, 1.0f, 0.0f}, 0.0f}, wall);
  world.addObstacle(PlaneObstacle{{0.0f, -1.0f, 0.0f}, -boxHeight}, wall);
  world.addObstacle(PlaneObstacle{{1.0f, 0.0f, 0.0f}, 0.0f}, wall);
  world.addObstacle(PlaneObstacle{{-1.0f, 0.0f, 0.0f}, -side}, wall);
  world.addObstacle(PlaneObstacle{{0.0f, 0.0f, 1.0f}, 0.0f}, wall);
  world.addObstacle(PlaneObstacle{{0.0f, 0.0f, -1.0f}, -side}, wall);

  // Lattice points at (i + 1) s: one spacing from each wall and from each other (gap s - 2r).
  const std::size_t k = boxLatticeSide(count);
  std::mt19937 rng(12345);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t ix = i % k;
    const std::size_t iz = (i / k) % k;
    const std::size_t iy = i / (k * k);
    ParticleDef p;
    p.position = {static_cast<float>(ix + 1) * boxSpacing, static_cast<float>(iy + 1) * boxSpacing,
                  static_cast<float>(iz + 1) * boxSpacing};
    p.velocity = {uniform(rng, -boxMaxSpeed, boxMaxSpeed), uniform(rng, -boxMaxSpeed, boxMaxSpeed),
                  uniform(rng, -boxMaxSpeed, boxMaxSpeed)};
    p.mass = sceneParticleMass;
    p.radius = sceneParticleRadius;
    world.createParticle(p);
  }
  return world;
}

} // namespace impetus::bench
