// impetus-bench: the 2D rigid-body scenes of bench/rigid2d_scenes.hpp run side by side in Impetus
// and in its peers with identical geometry at 1/60 s per step: Box2D 2.4.1 (Debian's; single-
// threaded, 8 velocity and 3 position iterations, continuous collision off unless
// --box2d-continuous: see box2d_scenes.hpp) and, where CMake was pointed at a Box2D v3 build
// (IMPETUS_BOX2D3_DIR), Box2D v3 (4 substeps, continuous collision on, its defaults, on
// --threads workers: see box2d3_scenes.hpp). Impetus: 4 substeps, on --threads N threads
// (default 1). Nothing sleeps, in any engine, but in the scenes that say so (v3's smash, tumbler
// and rain, as v3's benchmark runs them). A scene with a script (the rain) spawns and destroys
// bodies between steps, inside the timed loop (as v3's benchmark).
//
//   impetus-bench [--scene NAME]... [--steps N] [--threads N] [--substeps N] [--contact-hertz H]
//                 [--engine all|impetus|box2d|box2d3] [--box2d-continuous] [--json]
//
// NAME is a scene (Box2D v3's large_pyramid, many_pyramids, tumbler, smash, joint_grid and rain
// (not in Box2D 2.4.1: it has no capsules); Impetus' ragdolls, pyramid_row, kinematic_tumbler, smash_awake,
// circle_rain_1k, circle_rain_10k, circle_rain_100k, or circle_rain_N / circle_rain_Nk for other counts), "circle_rain"
// (the three sizes) or "all" (the default). Each scene is built (not timed), then stepped N times (default: the scene's
// own count, 500 for the pyramids) with a steady clock around the whole step loop: no warm-up, the pyramid's first
// steps, when its contacts are created, are part of the benchmark. A ratio is the peer's time
// over Impetus' time (above 1: Impetus is faster). Quality figures, measured the same way in
// every engine: how far the pyramids' top boxes sank (at the end, and the most after any step),
// the deepest overlap of any two shapes at the end, and the widest joint gap. --json prints one
// JSON object per scene and line, the peers in "peers". Figures: docs/performance.md.
#include "box2d_scenes.hpp"
#if IMPETUS_HAVE_BOX2D3
#include "box2d3_scenes.hpp"
#endif
#include "rigid2d_scenes.hpp"

#include <impetus/core/task_runner.hpp>
#include <impetus/error.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <array>

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

using impetus::rigid2d::StepProfile;

/// What one engine did with one scene.
struct EngineResult {
  double msPerStep = 0.0;
  float topSink = 0.0f;         ///< m, at the end (negative: the tops rose)
  float topMaxSink = 0.0f;      ///< m, the most at the end of any step
  float largestOverlap = 0.0f;  ///< m
  float largestJointGap = 0.0f; ///< m, the widest gap between a joint's anchors (scenes with joints)
  std::size_t touchingContacts = 0;
  bool finite = true;
  /// Impetus and Box2D v3: the mean of the steps' profiles (World::profile(), b2World_GetProfile), ms.
  StepProfile profile;
};

/// The profile's parts by name, in step order (World::profile()).
std::vector<std::pair<const char*, float>> profileParts(const StepProfile& p) {
  return {{"pairs", p.pairs},
          {"collide", p.collide},
          {"prepare", p.prepare},
          {"integrate_velocities", p.integrateVelocities},
          {"warm_start", p.warmStart},
          {"solve", p.solveConstraints},
          {"integrate_positions", p.integratePositions},
          {"relax", p.relax},
          {"store_impulses", p.storeImpulses},
          {"finalize", p.finalize}};
}

/// Every part of a StepProfile, for sums and means.
constexpr std::array<float StepProfile::*, 12> profileMembers = {&StepProfile::step,
                                                                 &StepProfile::pairs,
                                                                 &StepProfile::collide,
                                                                 &StepProfile::solve,
                                                                 &StepProfile::prepare,
                                                                 &StepProfile::integrateVelocities,
                                                                 &StepProfile::warmStart,
                                                                 &StepProfile::solveConstraints,
                                                                 &StepProfile::integratePositions,
                                                                 &StepProfile::relax,
                                                                 &StepProfile::storeImpulses,
                                                                 &StepProfile::finalize};

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
  bench::ImpetusSpawner spawner(built.world);
  const bench::SceneScript script = scene.makeScript ? scene.makeScript() : bench::SceneScript{};
  EngineResult r;
  TopWatch watch(scene);
  std::vector<impetus::rigid2d::BodyId> tops;
  for (const std::uint32_t top : scene.tops) {
    tops.push_back(built.bodies[top]);
  }
  const double ms = timeMs([&] {
    for (int i = 0; i < steps; ++i) {
      if (script) {
        script(i, spawner);
      }
      built.world.step(bench::sceneTimeStep);
      for (float StepProfile::*part : profileMembers) {
        r.profile.*part += built.world.profile().*part;
      }
      for (std::size_t k = 0; k < tops.size(); ++k) {
        watch.observe(k, built.world.position(tops[k]).y);
      }
    }
  });
  for (float StepProfile::*part : profileMembers) {
    r.profile.*part /= static_cast<float>(steps);
  }
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

#if IMPETUS_HAVE_BOX2D3
EngineResult runBox2D3(const bench::Rigid2dScene& scene, int steps, int threads) {
  bench::Box2D3Scene built(scene, threads);
  const bench::SceneScript script = scene.makeScript ? scene.makeScript() : bench::SceneScript{};
  EngineResult r;
  TopWatch watch(scene);
  const double ms = timeMs([&] {
    for (int i = 0; i < steps; ++i) {
      if (script) {
        script(i, built);
      }
      built.step();
      const StepProfile stepProfile = built.profile();
      for (float StepProfile::*part : profileMembers) {
        r.profile.*part += stepProfile.*part;
      }
      for (std::size_t k = 0; k < scene.tops.size(); ++k) {
        watch.observe(k, built.height(scene.tops[k]));
      }
    }
  });
  for (float StepProfile::*part : profileMembers) {
    r.profile.*part /= static_cast<float>(steps);
  }
  r.topMaxSink = watch.maxSink;
  r.msPerStep = ms / steps;
  r.touchingContacts = built.touchingContacts();
  measureQuality(scene, built.transforms(), r);
  return r;
}
#endif

/// The scenes a --scene argument names.
std::vector<std::string> expand(const std::vector<std::string>& requested) {
  std::vector<std::string> names;
  for (const std::string& r : requested) {
    if (r == "all") {
      for (const std::string& n : bench::rigid2dSceneNames()) {
        names.push_back(n);
      }
    } else if (r == "circle_rain") {
      for (const char* n : {"circle_rain_1k", "circle_rain_10k", "circle_rain_100k"}) {
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

/// The quality figures of one engine's run, for the JSON, under `prefix` ("impetus_" or "").
void addQuality(nlohmann::json& j, const std::string& prefix, const bench::Rigid2dScene& scene, const EngineResult& r) {
  j[prefix + "ms_per_step"] = r.msPerStep;
  if (!scene.tops.empty()) {
    j[prefix + "top_sink_m"] = r.topSink;
    j[prefix + "top_max_sink_m"] = r.topMaxSink;
  }
  j[prefix + "largest_overlap_m"] = r.largestOverlap;
  if (!scene.joints.empty()) {
    j[prefix + "largest_joint_gap_m"] = r.largestJointGap;
  }
  j[prefix + "touching_contacts"] = r.touchingContacts;
  j[prefix + "finite"] = r.finite;
}

/// One table cell group: ms, sink, max sink, overlap.
std::string cells(const bench::Rigid2dScene& scene, const std::optional<EngineResult>& r) {
  if (!r) {
    return std::string(37, ' '); // NOLINT(modernize-return-braced-init-list): braces would make two chars
  }
  const bool tops = !scene.tops.empty();
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "%9s %9s %9s %7s%s", fixed(r->msPerStep, 3).c_str(),
                tops ? fixed(r->topSink, 4).c_str() : "-", tops ? fixed(r->topMaxSink, 4).c_str() : "-",
                fixed(r->largestOverlap, 4).c_str(), r->finite ? "" : " NaN!");
  return buffer;
}

} // namespace

int main(int argc, char** argv) {
  CLI::App app{"impetus-bench: 2D rigid-body scenes in Impetus and in its peers (Box2D 2.4.1; Box2D v3 where "
               "built with IMPETUS_BOX2D3_DIR), side by side"};
  std::vector<std::string> requested{"all"};
  std::optional<int> stepsOverride;
  std::string engine = "all";
  int threads = 1;
  bench::ImpetusSettings settings;
  bool json = false;
  bool peerContinuous = false;
#if IMPETUS_HAVE_BOX2D3
  const bool haveBox2D3 = true;
#else
  const bool haveBox2D3 = false;
#endif
  app.add_option("--scene", requested,
                 "large_pyramid, many_pyramids, tumbler, smash, joint_grid, rain (Box2D v3's scenes), ragdolls, "
                 "pyramid_row, "
                 "kinematic_tumbler, smash_awake, circle_rain_1k, circle_rain_10k, circle_rain_100k, circle_rain (all "
                 "three) or all")
      ->capture_default_str();
  app.add_option("--steps", stepsOverride, "steps of 1/60 s (default: the scene's own, 500 for the pyramids)")
      ->check(CLI::PositiveNumber);
  app.add_option("--engine", engine,
                 "which engines to run: all (Impetus and every peer built in), impetus, box2d (2.4.1) or box2d3 "
                 "(v3, where built)")
      ->check(CLI::IsMember({"all", "impetus", "box2d", "box2d3"}))
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
  app.add_option("--threads", threads,
                 "threads for Impetus (a ThreadPool) and Box2D v3 (its workers); Box2D 2.4.1 is single-threaded")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  app.add_flag("--box2d-continuous", peerContinuous,
               "switch Box2D 2.4.1's continuous collision on (its own default; off here: nothing in these scenes is "
               "fast enough to tunnel; Box2D v3 keeps its default, on)");
  app.add_flag("--json", json, "one JSON object per scene and line");
  CLI11_PARSE(app, argc, argv);
  if (engine == "box2d3" && !haveBox2D3) {
    std::cerr << "impetus-bench: --engine box2d3: this build has no Box2D v3 (configure with "
                 "-DIMPETUS_BOX2D3_DIR=<a Box2D v3 source tree built in its build/>)\n";
    return 2;
  }
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

  const bool runI = engine == "all" || engine == "impetus";
  const bool runB = engine == "all" || engine == "box2d";
  const bool runB3 = haveBox2D3 && (engine == "all" || engine == "box2d3");
  std::string box2d3Name = "box2d 3";
#if IMPETUS_HAVE_BOX2D3
  box2d3Name = bench::Box2D3Scene::version();
#endif
  if (!json) {
    std::cout << "Impetus on " << threads << (threads == 1 ? " thread" : " threads") << ", contacts solved with "
              << lanes << "; 1/60 s steps; Impetus " << settings.substeps << " substeps at " << settings.contactHertz
              << " Hz; Box2D 2.4.1 single-threaded, " << bench::box2dVelocityIterations << " velocity / "
              << bench::box2dPositionIterations << " position iterations, continuous collision "
              << (peerContinuous ? "on" : "off");
#if IMPETUS_HAVE_BOX2D3
    if (runB3) {
      std::cout << "; " << box2d3Name << " on " << threads << (threads == 1 ? " worker" : " workers") << ", "
                << bench::box2d3Substeps << " substeps, continuous collision on";
    }
#endif
    std::cout << "; sleeping only where the scene says (smash, tumbler, rain)\n"
              << "ms = per step; ratio = the peer's time / Impetus' time; sink = how far the pyramid top dropped by\n"
              << "the end (max: the most at any step); overlap = the deepest between two shapes at the end; in m\n\n";
    std::printf("%-14s %7s %5s | %-37s | %-37s | %6s", "", "", "", "Impetus", "Box2D 2.4.1", "");
    if (runB3) {
      std::printf(" | %-37s | %6s", "Box2D v3", "");
    }
    std::printf("\n%-14s %7s %5s | %9s %9s %9s %7s | %9s %9s %9s %7s | %6s", "scene", "bodies", "steps", "ms", "sink",
                "max sink", "overlap", "ms", "sink", "max sink", "overlap", "ratio");
    if (runB3) {
      std::printf(" | %9s %9s %9s %7s | %6s", "ms", "sink", "max sink", "overlap", "ratio");
    }
    std::printf("\n");
    std::fflush(stdout);
  }

  for (const std::string& name : names) {
    const bench::Rigid2dScene scene = bench::makeRigid2dScene(name);
    const int steps = stepsOverride.value_or(scene.defaultSteps);
    std::optional<EngineResult> ri;
    std::optional<EngineResult> rb;
    std::optional<EngineResult> rb3;
    if (runI) {
      ri = runImpetus(scene, steps, threads, settings);
    }
    if (runB && scene.box2d241) {
      rb = runBox2D(scene, steps, peerContinuous);
    }
#if IMPETUS_HAVE_BOX2D3
    if (runB3) {
      rb3 = runBox2D3(scene, steps, threads);
    }
#endif
    // A peer's time over Impetus' time; 0 unless both ran. (A plain double: GCC 12 misreads an
    // optional<double> here as maybe uninitialized.)
    const auto ratioOf = [&](const std::optional<EngineResult>& peer) {
      return ri.has_value() && peer.has_value() ? peer->msPerStep / ri->msPerStep : 0.0;
    };

    if (json) {
      nlohmann::json j;
      j["scene"] = scene.name;
      j["bodies"] = scene.bodies.size();
      j["dynamic_bodies"] = bench::dynamicBodyCount(scene);
      j["steps"] = steps;
      j["time_step_s"] = bench::sceneTimeStep;
      j["threads"] = threads;
      if (ri) {
        j["impetus_substeps"] = settings.substeps;
        j["impetus_contact_hertz"] = settings.contactHertz;
        j["impetus_contact_reuse_m"] = settings.contactReuseDistance;
        j["impetus_simd"] = probe.contactSimd();
        j["impetus_contact_lanes"] = probe.contactLanes();
        addQuality(j, "impetus_", scene, *ri);
        nlohmann::json profile;
        for (const auto& [part, ms] : profileParts(ri->profile)) {
          profile[part] = ms;
        }
        j["impetus_profile_ms"] = std::move(profile);
      }
      nlohmann::json peers = nlohmann::json::array();
      const auto addPeer = [&](const std::string& peerName, const std::optional<EngineResult>& r,
                               nlohmann::json peerSettings) {
        if (!r) {
          return;
        }
        nlohmann::json p;
        p["peer"] = peerName;
        p["settings"] = std::move(peerSettings);
        addQuality(p, "", scene, *r);
        if (ri) {
          p["ratio"] = ratioOf(r);
        }
        peers.push_back(std::move(p));
      };
      addPeer("box2d 2.4.1", rb,
              {{"threads", 1},
               {"velocity_iterations", bench::box2dVelocityIterations},
               {"position_iterations", bench::box2dPositionIterations},
               {"continuous", peerContinuous}});
#if IMPETUS_HAVE_BOX2D3
      addPeer(box2d3Name, rb3, {{"threads", threads}, {"substeps", bench::box2d3Substeps}, {"continuous", true}});
#endif
      j["peers"] = std::move(peers);
      std::cout << j.dump() << '\n' << std::flush;
    } else {
      const auto ratioCell = [&](const std::optional<EngineResult>& peer) {
        return ri.has_value() && peer.has_value() ? fixed(ratioOf(peer), 2) : std::string("-");
      };
      std::printf("%-14s %7zu %5d | %s | %s | %6s", scene.name.c_str(), scene.bodies.size(), steps,
                  cells(scene, ri).c_str(), cells(scene, rb).c_str(), ratioCell(rb).c_str());
      if (runB3) {
        std::printf(" | %s | %6s", cells(scene, rb3).c_str(), ratioCell(rb3).c_str());
      }
      std::printf("\n");
      if (ri) {
        std::printf("%-14s Impetus ms/step by stage:", "");
        for (const auto& [part, ms] : profileParts(ri->profile)) {
          std::printf(" %s %.3f", part, static_cast<double>(ms));
        }
        std::printf("\n");
      }
      if (rb3) {
        std::printf("%-14s Box2D v3 ms/step by stage:", "");
        for (const auto& [part, ms] : profileParts(rb3->profile)) {
          std::printf(" %s %.3f", part, static_cast<double>(ms));
        }
        std::printf("\n");
      }
      if (!scene.joints.empty()) {
        std::printf("%-14s %7zu joints; widest joint gap at the end: Impetus %s m, Box2D 2.4.1 %s m", "",
                    scene.joints.size(), ri ? fixed(ri->largestJointGap, 4).c_str() : "-",
                    rb ? fixed(rb->largestJointGap, 4).c_str() : "-");
        if (runB3) {
          std::printf(", Box2D v3 %s m", rb3 ? fixed(rb3->largestJointGap, 4).c_str() : "-");
        }
        std::printf("\n");
      }
      std::fflush(stdout);
    }
  }
  return 0;
}
