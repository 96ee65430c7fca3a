// impetus-bench: the 2D rigid-body scenes of bench/rigid2d_scenes.hpp run side by side in Impetus
// and in Box2D 2.4.1 with identical geometry at 1/60 s per step (Impetus: 4 substeps, on
// --threads N threads, default 1; Box2D: single-threaded, 8 velocity and 3 position iterations;
// neither sleeps, and Box2D's continuous collision is off unless --box2d-continuous: see
// box2d_scenes.hpp).
//
//   impetus-bench [--scene NAME]... [--steps N] [--threads N] [--substeps N] [--contact-hertz H]
//                 [--engine both|impetus|box2d] [--box2d-continuous] [--json]
//
// NAME is a scene (large_pyramid, many_pyramids, tumbler, smash, joint_grid, ragdolls, rain_1k, rain_10k, rain_100k, or
// rain_N / rain_Nk for other counts), "rain" (the three rain sizes) or "all" (the default). Each
// scene is built (not timed), then stepped N times (default: the scene's own count, 500 for the
// pyramids) with a steady clock around the whole step loop: no warm-up, the pyramid's first
// steps, when its contacts are created, are part of the benchmark. The ratio is the peer's time
// over Impetus' time (above 1: Impetus is faster). Quality figures, measured the same way in
// both engines: how far the pyramids' top boxes sank (at the end, and the most after any step),
// and the deepest overlap of any two shapes at the end. --json prints one JSON object per scene
// and line. Figures: docs/performance.md.
#include "box2d_scenes.hpp"
#include "rigid2d_scenes.hpp"

#include <impetus/core/task_runner.hpp>
#include <impetus/error.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

using impetus::Transform2f;
namespace bench = impetus::bench;

/// What one engine did with one scene.
struct EngineResult {
  double msPerStep = 0.0;
  float topSink = 0.0f;         ///< m, at the end (negative: the tops rose)
  float topMaxSink = 0.0f;      ///< m, the most at the end of any step
  float largestOverlap = 0.0f;  ///< m
  float largestJointGap = 0.0f; ///< m, the widest gap between a joint's anchors (scenes with joints)
  std::size_t touchingContacts = 0;
  bool finite = true;
};

template <typename StepLoop> double timeMs(StepLoop&& loop) {
  const auto start = std::chrono::steady_clock::now();
  loop();
  const auto stop = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::milli>(stop - start).count();
}

void measureQuality(const bench::Rigid2dScene& scene, const std::vector<Transform2f>& transforms, EngineResult& r) {
  r.finite = bench::allFinite(transforms);
  r.topSink = bench::topSink(scene, transforms);
  r.largestOverlap = r.finite ? bench::largestOverlap(scene, transforms) : 0.0f;
  r.largestJointGap = r.finite ? bench::largestJointGap(scene, transforms) : 0.0f;
}

/// The scene's pyramid tops: their bodies' starting heights, to follow their sinking during the
/// run (reading a few bodies' positions per step costs nanoseconds against milliseconds).
struct TopWatch {
  std::vector<float> startHeights;
  float maxSink = 0.0f;

  explicit TopWatch(const bench::Rigid2dScene& scene) {
    for (const std::uint32_t top : scene.tops) {
      startHeights.push_back(scene.bodies[top].position.y);
    }
  }
  void observe(std::size_t i, float height) { maxSink = std::max(maxSink, startHeights[i] - height); }
};

EngineResult runImpetus(const bench::Rigid2dScene& scene, int steps, int threads, bench::ImpetusSettings settings) {
  // One thread: no task runner at all (the world runs its loops inline).
  std::unique_ptr<impetus::ThreadPool> pool;
  if (threads > 1) {
    pool = std::make_unique<impetus::ThreadPool>(threads);
  }
  settings.runner = pool.get();
  bench::ImpetusScene built = bench::buildImpetusScene(scene, settings);
  EngineResult r;
  TopWatch watch(scene);
  std::vector<impetus::rigid2d::BodyId> tops;
  for (const std::uint32_t top : scene.tops) {
    tops.push_back(built.bodies[top]);
  }
  const double ms = timeMs([&] {
    for (int i = 0; i < steps; ++i) {
      built.world.step(bench::sceneTimeStep);
      for (std::size_t k = 0; k < tops.size(); ++k) {
        watch.observe(k, built.world.position(tops[k]).y);
      }
    }
  });
  r.topMaxSink = watch.maxSink;
  r.msPerStep = ms / steps;
  r.touchingContacts = built.world.contactCount();
  measureQuality(scene, bench::bodyTransforms(built), r);
  return r;
}

EngineResult runBox2D(const bench::Rigid2dScene& scene, int steps, bool continuous) {
  bench::Box2DScene built = bench::buildBox2DScene(scene, continuous);
  EngineResult r;
  TopWatch watch(scene);
  std::vector<const b2Body*> tops;
  for (const std::uint32_t top : scene.tops) {
    tops.push_back(built.bodies[top]);
  }
  const double ms = timeMs([&] {
    for (int i = 0; i < steps; ++i) {
      built.world->Step(bench::sceneTimeStep, bench::box2dVelocityIterations, bench::box2dPositionIterations);
      for (std::size_t k = 0; k < tops.size(); ++k) {
        watch.observe(k, tops[k]->GetPosition().y);
      }
    }
  });
  r.topMaxSink = watch.maxSink;
  r.msPerStep = ms / steps;
  for (const b2Contact* c = built.world->GetContactList(); c != nullptr; c = c->GetNext()) {
    r.touchingContacts += c->IsTouching() ? 1 : 0;
  }
  measureQuality(scene, bench::bodyTransforms(built), r);
  return r;
}

/// The scenes a --scene argument names.
std::vector<std::string> expand(const std::vector<std::string>& requested) {
  std::vector<std::string> names;
  for (const std::string& r : requested) {
    if (r == "all") {
      for (const std::string& n : bench::rigid2dSceneNames()) {
        names.push_back(n);
      }
    } else if (r == "rain") {
      for (const char* n : {"rain_1k", "rain_10k", "rain_100k"}) {
        names.emplace_back(n);
      }
    } else {
      (void)bench::makeRigid2dScene(r); // throws for an unknown name before anything runs
      names.push_back(r);
    }
  }
  return names;
}

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

} // namespace

int main(int argc, char** argv) {
  CLI::App app{"impetus-bench: 2D rigid-body scenes in Impetus and in Box2D 2.4.1, side by side"};
  std::vector<std::string> requested{"all"};
  std::optional<int> stepsOverride;
  std::string engine = "both";
  int threads = 1;
  bench::ImpetusSettings settings;
  bool json = false;
  bool peerContinuous = false;
  app.add_option("--scene", requested,
                 "large_pyramid, many_pyramids, tumbler, smash, joint_grid, ragdolls, rain_1k, rain_10k, rain_100k, "
                 "rain (all three) or all")
      ->capture_default_str();
  app.add_option("--steps", stepsOverride, "steps of 1/60 s (default: the scene's own, 500 for the pyramids)")
      ->check(CLI::PositiveNumber);
  app.add_option("--engine", engine, "which engines to run")
      ->check(CLI::IsMember({"both", "impetus", "box2d"}))
      ->capture_default_str();
  app.add_option("--substeps", settings.substeps, "Impetus solver substeps per step")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  app.add_option("--contact-hertz", settings.contactHertz,
                 "Impetus contact stiffness, Hz (capped at a quarter of the substep rate)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--contact-reuse", settings.contactReuseDistance,
                 "Impetus manifold reuse: a touching pair that moved less than this relative to itself keeps its "
                 "manifold, carried with the bodies, m (0: collide every pair every step, as Box2D)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  std::string simd = "widest";
  app.add_option("--simd", simd,
                 "Impetus contact-solve lanes: the widest the CPU runs (AVX2: 8) or the baseline (SSE2: 4)")
      ->check(CLI::IsMember({"widest", "baseline"}));
  app.add_option("--threads", threads, "threads for Impetus (a ThreadPool; Box2D 2.4.1 is single-threaded)")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  app.add_flag("--box2d-continuous", peerContinuous,
               "switch Box2D's continuous collision on (its own default; off here: nothing in these scenes is fast "
               "enough to tunnel)");
  app.add_flag("--json", json, "one JSON object per scene and line");
  CLI11_PARSE(app, argc, argv);
  settings.simd = simd == "baseline" ? impetus::rigid2d::SimdLevel::baseline : impetus::rigid2d::SimdLevel::widest;
  impetus::rigid2d::WorldDef simdDef;
  simdDef.simd = settings.simd;
  const impetus::rigid2d::World probe(simdDef);
  const std::string lanes = std::string(probe.contactSimd()) + " (" + std::to_string(probe.contactLanes()) + " lanes)";

  std::vector<std::string> names;
  try {
    names = expand(requested);
  } catch (const impetus::Error& e) {
    std::cerr << "impetus-bench: " << e.what() << '\n';
    return 2;
  }

  const bool runI = engine != "box2d";
  const bool runB = engine != "impetus";
  if (!json) {
    std::cout << "Impetus on " << threads << (threads == 1 ? " thread" : " threads") << ", contacts solved with "
              << lanes << ", Box2D single-threaded; 1/60 s steps; Impetus " << settings.substeps << " substeps at "
              << settings.contactHertz << " Hz, Box2D 2.4.1 " << bench::box2dVelocityIterations << " velocity / "
              << bench::box2dPositionIterations << " position iterations, continuous collision "
              << (peerContinuous ? "on" : "off") << "; no sleeping\n"
              << "ms = per step; ratio = Box2D time / Impetus time; sink = how far the pyramid top dropped by the\n"
              << "end (max: the most at any step); overlap = the deepest between two shapes at the end; in m\n\n";
    std::printf("%-14s %7s %5s | %-37s | %-37s | %6s\n", "", "", "", "Impetus", "Box2D 2.4.1", "");
    std::printf("%-14s %7s %5s | %9s %9s %9s %7s | %9s %9s %9s %7s | %6s\n", "scene", "bodies", "steps", "ms", "sink",
                "max sink", "overlap", "ms", "sink", "max sink", "overlap", "ratio");
    std::fflush(stdout);
  }

  for (const std::string& name : names) {
    const bench::Rigid2dScene scene = bench::makeRigid2dScene(name);
    const int steps = stepsOverride.value_or(scene.defaultSteps);
    std::optional<EngineResult> ri;
    std::optional<EngineResult> rb;
    if (runI) {
      ri = runImpetus(scene, steps, threads, settings);
    }
    if (runB) {
      rb = runBox2D(scene, steps, peerContinuous);
    }
    // Peer time over Impetus time; only when both ran. (A plain double: GCC 12 misreads an
    // optional<double> here as maybe uninitialized.)
    const bool both = ri.has_value() && rb.has_value();
    const double ratio = both ? rb->msPerStep / ri->msPerStep : 0.0;

    if (json) {
      nlohmann::json j;
      j["scene"] = scene.name;
      j["bodies"] = scene.bodies.size();
      j["dynamic_bodies"] = bench::dynamicBodyCount(scene);
      j["steps"] = steps;
      j["time_step_s"] = bench::sceneTimeStep;
      j["threads"] = threads;
      if (ri) {
        j["impetus_ms_per_step"] = ri->msPerStep;
        j["impetus_substeps"] = settings.substeps;
        j["impetus_contact_hertz"] = settings.contactHertz;
        j["impetus_contact_reuse_m"] = settings.contactReuseDistance;
        j["impetus_simd"] = probe.contactSimd();
        j["impetus_contact_lanes"] = probe.contactLanes();
        if (!scene.tops.empty()) {
          j["impetus_top_sink_m"] = ri->topSink;
          j["impetus_top_max_sink_m"] = ri->topMaxSink;
        }
        j["impetus_largest_overlap_m"] = ri->largestOverlap;
        if (!scene.joints.empty()) {
          j["impetus_largest_joint_gap_m"] = ri->largestJointGap;
        }
        j["impetus_touching_contacts"] = ri->touchingContacts;
        j["impetus_finite"] = ri->finite;
      }
      if (rb) {
        j["peer"] = "box2d 2.4.1";
        j["peer_ms_per_step"] = rb->msPerStep;
        j["peer_velocity_iterations"] = bench::box2dVelocityIterations;
        j["peer_position_iterations"] = bench::box2dPositionIterations;
        j["peer_continuous"] = peerContinuous;
        if (!scene.tops.empty()) {
          j["peer_top_sink_m"] = rb->topSink;
          j["peer_top_max_sink_m"] = rb->topMaxSink;
        }
        j["peer_largest_overlap_m"] = rb->largestOverlap;
        if (!scene.joints.empty()) {
          j["peer_largest_joint_gap_m"] = rb->largestJointGap;
        }
        j["peer_touching_contacts"] = rb->touchingContacts;
        j["peer_finite"] = rb->finite;
      }
      if (both) {
        j["ratio"] = ratio;
      }
      std::cout << j.dump() << '\n' << std::flush;
    } else {
      const auto cells = [&](const std::optional<EngineResult>& r) {
        if (!r) {
          return std::string(37, ' ');
        }
        const bool tops = !scene.tops.empty();
        char buffer[128];
        std::snprintf(buffer, sizeof buffer, "%9s %9s %9s %7s%s", fixed(r->msPerStep, 3).c_str(),
                      tops ? fixed(r->topSink, 4).c_str() : "-", tops ? fixed(r->topMaxSink, 4).c_str() : "-",
                      fixed(r->largestOverlap, 4).c_str(), r->finite ? "" : " NaN!");
        return std::string(buffer);
      };
      std::printf("%-14s %7zu %5d | %s | %s | %6s\n", scene.name.c_str(), scene.bodies.size(), steps, cells(ri).c_str(),
                  cells(rb).c_str(), both ? fixed(ratio, 2).c_str() : "-");
      if (!scene.joints.empty()) {
        std::printf("%-14s %7zu joints; widest joint gap at the end: Impetus %s m, Box2D %s m\n", "",
                    scene.joints.size(), ri ? fixed(ri->largestJointGap, 4).c_str() : "-",
                    rb ? fixed(rb->largestJointGap, 4).c_str() : "-");
      }
      std::fflush(stdout);
    }
  }
  return 0;
}
