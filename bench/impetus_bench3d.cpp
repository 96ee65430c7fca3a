// impetus-bench3d: the 3D benchmark scenes (rigid3d_scenes.hpp) in Impetus' rigid3d::World and
// in Bullet 3.24 (bullet_scenes.hpp), side by side: milliseconds per step (mean and median of
// the steps, each timed alone with std::chrono::steady_clock) and quality figures (how far each
// pyramid's top sank, the deepest overlap between two bodies at the end), each engine with the
// same bodies, boxes, densities and friction. Both single-threaded.
#include "bullet_scenes.hpp"
#include "rigid3d_impetus_scene.hpp"
#include "rigid3d_scenes.hpp"

#include <impetus/error.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

namespace {

namespace bench = impetus::bench;
using impetus::Transform3f;

struct EngineResult {
  double meanMs = 0.0;         ///< per step
  double medianMs = 0.0;       ///< per step
  float topSink = 0.0f;        ///< m below the rest height at the end (negative: above it)
  float topMaxSink = 0.0f;     ///< m, the most at the end of any step
  float largestOverlap = 0.0f; ///< m, at the end
  std::size_t touchingContacts = 0;
  bool finite = true;
};

/// The scene's pyramid tops: the most any sank below its rest height after any step.
struct TopWatch {
  const bench::Rigid3dScene& scene;
  float maxSink = -1.0e30f;

  void observe(std::size_t k, float height) { maxSink = std::max(maxSink, scene.topRestHeights[k] - height); }
};

/// Steps `steps` times, timing each step alone; after each (untimed) `observe()`.
template <typename Step, typename Observe> void timeSteps(int steps, Step&& step, Observe&& observe, EngineResult& r) {
  std::vector<double> ms;
  ms.reserve(static_cast<std::size_t>(steps));
  for (int i = 0; i < steps; ++i) {
    const auto start = std::chrono::steady_clock::now();
    step();
    const auto stop = std::chrono::steady_clock::now();
    ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
    observe();
  }
  r.meanMs = std::accumulate(ms.begin(), ms.end(), 0.0) / static_cast<double>(steps);
  const auto middle = ms.begin() + static_cast<std::ptrdiff_t>(ms.size() / 2);
  std::nth_element(ms.begin(), middle, ms.end());
  r.medianMs = *middle;
  if (ms.size() % 2 == 0) {
    r.medianMs = 0.5 * (r.medianMs + *std::max_element(ms.begin(), middle));
  }
}

void measureQuality(const bench::Rigid3dScene& scene, const std::vector<Transform3f>& poses, EngineResult& r) {
  r.finite = bench::allFinite(poses);
  r.topSink = bench::topSink(scene, poses);
  r.largestOverlap = r.finite ? bench::largestOverlap(scene, poses) : 0.0f;
}

EngineResult runImpetus(const bench::Rigid3dScene& scene, int steps, const bench::Impetus3dSettings& settings) {
  bench::Impetus3dScene built = bench::buildImpetus3dScene(scene, settings);
  EngineResult r;
  TopWatch watch{scene};
  timeSteps(
      steps, [&] { built.world.step(bench::scene3dTimeStep); },
      [&] {
        for (std::size_t k = 0; k < scene.tops.size(); ++k) {
          watch.observe(k, built.world.position(built.bodies[scene.tops[k]]).y);
        }
      },
      r);
  r.topMaxSink = watch.maxSink;
  r.touchingContacts = built.world.contactCount();
  measureQuality(scene, bench::bodyPoses(built), r);
  return r;
}

EngineResult runBullet(const bench::Rigid3dScene& scene, int steps) {
  bench::BulletScene built(scene);
  EngineResult r;
  TopWatch watch{scene};
  timeSteps(
      steps, [&] { built.step(); },
      [&] {
        for (std::size_t k = 0; k < scene.tops.size(); ++k) {
          watch.observe(k, built.height(scene.tops[k]));
        }
      },
      r);
  r.topMaxSink = watch.maxSink;
  r.touchingContacts = built.touchingContacts();
  measureQuality(scene, built.poses(), r);
  return r;
}

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

nlohmann::json toJson(const bench::Rigid3dScene& scene, const EngineResult& r) {
  nlohmann::json j;
  j["ms_per_step_mean"] = r.meanMs;
  j["ms_per_step_median"] = r.medianMs;
  if (!scene.tops.empty()) {
    j["top_sink_m"] = r.topSink;
    j["top_max_sink_m"] = r.topMaxSink;
  }
  j["largest_overlap_m"] = r.largestOverlap;
  j["touching_contacts"] = r.touchingContacts;
  j["finite"] = r.finite;
  return j;
}

/// One engine's table cells: mean, median, sink, max sink, overlap.
std::string cells(const bench::Rigid3dScene& scene, const std::optional<EngineResult>& r) {
  if (!r) {
    return std::string(45, ' '); // NOLINT(modernize-return-braced-init-list): braces would make two chars
  }
  const bool tops = !scene.tops.empty();
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "%8s %8s %8s %8s %8s%s", fixed(r->meanMs, 3).c_str(),
                fixed(r->medianMs, 3).c_str(), tops ? fixed(r->topSink, 4).c_str() : "-",
                tops ? fixed(r->topMaxSink, 4).c_str() : "-", fixed(r->largestOverlap, 4).c_str(),
                r->finite ? "" : " NaN!");
  return buffer;
}

} // namespace

int main(int argc, char** argv) {
  CLI::App app{"impetus-bench3d: 3D rigid-body scenes in Impetus and in Bullet 3.24, side by side (one thread each)"};
  std::vector<std::string> requested{"all"};
  std::optional<int> stepsOverride;
  std::string engine = "all";
  bench::Impetus3dSettings settings;
  bool json = false;
  app.add_option("--scene", requested,
                 "large_pyramid (Box3D's), jolt_pyramid (Jolt's PerformanceTest Pyramid), pyramid_20 or all")
      ->capture_default_str();
  app.add_option("--steps", stepsOverride,
                 "steps of 1/60 s (default: the scene's own: large_pyramid 200, the others 500)")
      ->check(CLI::PositiveNumber);
  app.add_option("--engine", engine, "which engines to run: all, impetus or bullet")
      ->check(CLI::IsMember({"all", "impetus", "bullet"}))
      ->capture_default_str();
  app.add_option("--substeps", settings.substeps, "Impetus solver substeps per step")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  app.add_option("--contact-hertz", settings.contactHertz,
                 "Impetus contact stiffness, Hz (capped at a quarter of the substep rate)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_flag("--json", json, "one JSON object per scene and line");
  CLI11_PARSE(app, argc, argv);

  std::vector<std::string> names;
  for (const std::string& r : requested) {
    if (r == "all") {
      for (const std::string& n : bench::rigid3dSceneNames()) {
        names.push_back(n);
      }
      continue;
    }
    try {
      (void)bench::makeRigid3dScene(r); // an unknown name fails before anything runs
    } catch (const impetus::Error& e) {
      std::cerr << "impetus-bench3d: " << e.what() << '\n';
      return 2;
    }
    names.push_back(r);
  }
  const bool runI = engine == "all" || engine == "impetus";
  const bool runB = engine == "all" || engine == "bullet";
  const std::string bulletName = bench::BulletScene::version();

  if (!json) {
    std::cout
        << "One thread each, steps of 1/60 s. Impetus: " << settings.substeps << " substeps, contacts at "
        << settings.contactHertz << " Hz, scalar solver. " << bulletName
        << ": btDiscreteDynamicsWorld, btDbvtBroadphase, btSequentialImpulseConstraintSolver with "
        << bench::bulletSolverIterations << " iterations, one fixed step of 1/60 s per step (no substeps).\n"
        << "ms = per step (mean, median); ratio = Bullet's mean / Impetus' mean; sink = how far the pyramid top\n"
        << "is below its rest height at the end (max: the most after any step); overlap = the deepest between two\n"
        << "bodies at the end; in m\n\n";
    std::printf("%-13s %6s %5s | %-44s | %-44s | %5s\n", "", "", "", "Impetus", bulletName.c_str(), "");
    std::printf("%-13s %6s %5s | %8s %8s %8s %8s %8s | %8s %8s %8s %8s %8s | %5s\n", "scene", "bodies", "steps", "mean",
                "median", "sink", "max sink", "overlap", "mean", "median", "sink", "max sink", "overlap", "ratio");
    std::fflush(stdout);
  }

  for (const std::string& name : names) {
    const bench::Rigid3dScene scene = bench::makeRigid3dScene(name);
    const int steps = stepsOverride.value_or(scene.defaultSteps);
    std::optional<EngineResult> ri;
    std::optional<EngineResult> rb;
    if (runI) {
      ri = runImpetus(scene, steps, settings);
    }
    if (runB) {
      rb = runBullet(scene, steps);
    }
    const bool both = ri.has_value() && rb.has_value();
    const double ratio = both ? rb->meanMs / ri->meanMs : 0.0;
    if (json) {
      nlohmann::json j;
      j["scene"] = scene.name;
      j["origin"] = scene.origin;
      j["bodies"] = scene.bodies.size();
      j["dynamic_bodies"] = bench::dynamicBodyCount(scene);
      j["steps"] = steps;
      j["time_step_s"] = bench::scene3dTimeStep;
      if (ri) {
        nlohmann::json i = toJson(scene, *ri);
        i["substeps"] = settings.substeps;
        i["contact_hertz"] = settings.contactHertz;
        j["impetus"] = std::move(i);
      }
      if (rb) {
        nlohmann::json b = toJson(scene, *rb);
        b["name"] = bulletName;
        b["solver_iterations"] = bench::bulletSolverIterations;
        b["substeps"] = 1;
        j["bullet"] = std::move(b);
      }
      if (both) {
        j["ratio"] = ratio;
        j["ratio_median"] = rb->medianMs / ri->medianMs;
      }
      std::cout << j.dump() << '\n' << std::flush;
    } else {
      std::printf("%-13s %6zu %5d | %s | %s | %5s\n", scene.name.c_str(), scene.bodies.size(), steps,
                  cells(scene, ri).c_str(), cells(scene, rb).c_str(), both ? fixed(ratio, 2).c_str() : "-");
      std::fflush(stdout);
    }
  }
  return 0;
}
