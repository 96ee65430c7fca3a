// Polygon narrowphase micro-benchmark (Google Benchmark): collidePolygons on the box pairs of
// the large_pyramid scene after one simulated second (the boxes settled into their resting
// contacts), against the general separating-axis path that it shortcuts for two plain boxes
// (src/rigid2d/manifold_internal.hpp). The pairs are those whose fat bounding boxes overlap,
// as the broadphase finds them: side by side, stacked and on the ground, shape A the lower
// shape index as in the world. Counter per_pair: the time of one call.
#include "rigid2d_scenes.hpp"

#include <impetus/rigid2d/constants.hpp>
#include <impetus/rigid2d/manifold.hpp>

#include "rigid2d/manifold_internal.hpp"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

namespace {

using namespace impetus;
using namespace impetus::rigid2d;

struct Pair {
  const Polygon* a;
  Transform2f xfA;
  const Polygon* b;
  Transform2f xfB;
};

struct PyramidPairs {
  std::vector<Polygon> polygons; // by shape
  std::vector<Pair> pairs;
};

/// The pyramid's pairs after 60 steps, built on first use (Google Benchmark reruns a benchmark
/// while it sizes the run).
const PyramidPairs& pyramidPairs() {
  static const PyramidPairs built = [] {
    const bench::Rigid2dScene scene = bench::largePyramidScene();
    bench::ImpetusScene world = bench::buildImpetusScene(scene);
    for (int i = 0; i < 60; ++i) {
      world.world.step(bench::sceneTimeStep);
    }
    const std::vector<Transform2f> transforms = bench::bodyTransforms(world);
    PyramidPairs out;
    std::vector<AABB> boxes;
    for (const bench::SceneShape& s : scene.shapes) {
      out.polygons.push_back(makeOffsetBox(s.halfWidth, s.halfHeight, s.center, s.angle));
      AABB box = computeAABB(out.polygons.back(), transforms[s.body]);
      box.lower -= Vec2f{aabbMargin, aabbMargin};
      box.upper += Vec2f{aabbMargin, aabbMargin};
      boxes.push_back(box);
    }
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      for (std::size_t j = i + 1; j < boxes.size(); ++j) {
        if (boxes[i].lower.x <= boxes[j].upper.x && boxes[j].lower.x <= boxes[i].upper.x &&
            boxes[i].lower.y <= boxes[j].upper.y && boxes[j].lower.y <= boxes[i].upper.y) {
          const std::uint32_t bodyA = scene.shapes[i].body;
          const std::uint32_t bodyB = scene.shapes[j].body;
          out.pairs.push_back({&out.polygons[i], transforms[bodyA], &out.polygons[j], transforms[bodyB]});
        }
      }
    }
    return out;
  }();
  return built;
}

template <Manifold (*Collide)(const Polygon&, const Transform2f&, const Polygon&, const Transform2f&)>
void run(benchmark::State& state) {
  const std::vector<Pair>& pairs = pyramidPairs().pairs;
  int touching = 0;
  for (auto _ : state) {
    touching = 0;
    for (const Pair& p : pairs) {
      const Manifold m = Collide(*p.a, p.xfA, *p.b, p.xfB);
      benchmark::DoNotOptimize(m);
      touching += m.pointCount > 0 ? 1 : 0;
    }
  }
  const auto count = static_cast<double>(pairs.size());
  state.counters["pairs"] = count;
  state.counters["touching"] = static_cast<double>(touching);
  state.counters["per_pair"] = benchmark::Counter(static_cast<double>(state.iterations()) * count,
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void pyramidBoxes(benchmark::State& state) { run<collidePolygons>(state); }
void pyramidBoxesGeneralPath(benchmark::State& state) { run<detail::collidePolygonsGeneral>(state); }

} // namespace

BENCHMARK(pyramidBoxes)->Unit(benchmark::kMicrosecond);
BENCHMARK(pyramidBoxesGeneralPath)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
