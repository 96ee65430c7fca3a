// What a sleeping world costs (Google Benchmark): one world.step(1/60 s) per iteration of a
// pile of boxes that has come to rest, with sleeping on (every island asleep) against the same
// pile with sleeping off (every body solved). The target (issue 19): asleep, under 2% of the
// awake step. The pile is the pyramid_row scene scaled to about 10,000 boxes (bench/rigid2d_scenes.hpp:
// pyramids of base 20, one box apart), settled once per process (not timed).
// Counters: bodies, awake bodies (0 when asleep), and the step time.
#include "rigid2d_scenes.hpp"

#include <benchmark/benchmark.h>

#include <memory>

namespace {

namespace bench = impetus::bench;

constexpr int pyramids = 48; // of base 20: 210 boxes each, 10,080 in all

/// The pile after it has come to rest (and, with sleeping on, fallen asleep), built once.
bench::ImpetusScene& settledPile(bool sleeping) {
  static std::unique_ptr<bench::ImpetusScene> worlds[2];
  std::unique_ptr<bench::ImpetusScene>& slot = worlds[sleeping ? 1 : 0];
  if (!slot) {
    bench::ImpetusSettings settings;
    settings.enableSleep = sleeping;
    slot = std::make_unique<bench::ImpetusScene>(
        bench::buildImpetusScene(bench::pyramidRowScene(pyramids, bench::pyramidRowBase), settings));
    for (int i = 0; i < 600 && (!sleeping || slot->world.awakeBodyCount() > 0); ++i) { // up to 10 s
      slot->world.step(bench::sceneTimeStep);
    }
  }
  return *slot;
}

void stepPile(benchmark::State& state, bool sleeping) {
  bench::ImpetusScene& scene = settledPile(sleeping);
  for (auto _ : state) {
    scene.world.step(bench::sceneTimeStep);
  }
  state.counters["bodies"] = static_cast<double>(scene.world.bodyCount());
  state.counters["awake"] = static_cast<double>(scene.world.awakeBodyCount());
}

void BM_RestingPileAwake(benchmark::State& state) { stepPile(state, false); }
void BM_RestingPileAsleep(benchmark::State& state) { stepPile(state, true); }

BENCHMARK(BM_RestingPileAwake)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RestingPileAsleep)->Unit(benchmark::kMicrosecond);

} // namespace

BENCHMARK_MAIN();
