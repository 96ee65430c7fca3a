// Particle-world benchmarks (Google Benchmark): one world.step(1/60 s) per iteration. Two scenes
// (bench/particle_scenes.hpp), each at 1k, 10k and 100k particles:
//   rain: gravity, quadratic drag relative to a wind, ground contact;
//   box:  particles colliding with each other in a box of planes.
// What is timed is the steady state: each scene is first run for a few simulated seconds (not
// timed) until its particles rest on the ground or have formed a pile, since falling particles
// touch nothing and cost less. Google Benchmark calls a benchmark several times while it sizes
// the run, so the settled worlds are built once per process and reused.
// Counters: items_per_second = particle-steps per second; steps/s = world steps per second
// (the figure to compare with the 60 Hz frame rate); per_particle_step = the time of one
// particle for one step, which stays flat when the cost grows linearly with the count.
// Figures and how to reproduce them: docs/performance.md.
#include "particle_scenes.hpp"

#include <benchmark/benchmark.h>

#include <cstddef>
#include <map>
#include <utility>

namespace {

constexpr float frame = 1.0f / 60.0f; // s, one game frame

enum class Scene { rain, box };

/// The scene with `count` particles after a few seconds of simulation, built on first use.
impetus::ParticleWorld& settledScene(Scene scene, std::size_t count) {
  static std::map<std::pair<Scene, std::size_t>, impetus::ParticleWorld> worlds;
  const auto key = std::make_pair(scene, count);
  auto it = worlds.find(key);
  if (it == worlds.end()) {
    // Rain: all at rest on the ground by 2.5 s. Box: the ten layers land by 0.55 s and the pile
    // has its steady number of contacts per particle by about 1.5 s.
    const int settleSteps = scene == Scene::rain ? 180 : 90;
    impetus::ParticleWorld world =
        scene == Scene::rain ? impetus::bench::makeRainScene(count) : impetus::bench::makeBoxScene(count);
    for (int i = 0; i < settleSteps; ++i) {
      world.step(frame);
    }
    it = worlds.emplace(key, std::move(world)).first;
  }
  return it->second;
}

void run(benchmark::State& state, Scene scene) {
  const auto count = static_cast<std::size_t>(state.range(0));
  impetus::ParticleWorld& world = settledScene(scene, count);
  for (auto _ : state) {
    world.step(frame);
    benchmark::DoNotOptimize(world.positions().data());
    benchmark::ClobberMemory();
  }
  const auto steps = static_cast<double>(state.iterations());
  state.SetItemsProcessed(state.iterations() * static_cast<benchmark::IterationCount>(count));
  state.counters["particles"] = static_cast<double>(count);
  state.counters["steps/s"] = benchmark::Counter(steps, benchmark::Counter::kIsRate);
  // Seconds per particle-step (kIsRate | kInvert): printed with an SI prefix, e.g. "31.2ns".
  state.counters["per_particle_step"] =
      benchmark::Counter(steps * static_cast<double>(count), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_RainGravityDragGround(benchmark::State& state) { run(state, Scene::rain); }
void BM_BoxParticleCollisions(benchmark::State& state) { run(state, Scene::box); }

} // namespace

BENCHMARK(BM_RainGravityDragGround)->Arg(1'000)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BoxParticleCollisions)->Arg(1'000)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
