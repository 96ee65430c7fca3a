// Fuzzes the scene files of `impetus run`: arbitrary bytes go through the loaders exactly as the
// CLI reads a file (JSON object, its "kind", then the particle or the rigid2d loader), and
// straight into each loader too.
//
// Checked, for every input:
//  - loading gives a scene or an impetus::Error: no crash, no sanitizer report, no other exception
//    type (a json::type_error, std::out_of_range, ... escaping would kill the CLI);
//  - a scene that loads is stepped a few times (its effectors first, as `impetus run` does); a
//    step may throw impetus::Error, and nothing else;
//  - when every number of the document is of moderate size (0, or 1e-3 to 1e3 in magnitude), every
//    particle's and body's position and velocity (and angle) stays finite over those steps. Larger
//    values may overflow float physically (a 1e30 m/s body), so those scenes are only checked for
//    crashes and undefined behaviour.
//
// The work per input is bounded before anything is built: the particle generators (grid, line,
// random_box, ropes, cloths) may ask for up to 10^7 particles, which is a valid scene but minutes
// of fuzzing, so a document whose generators would create more than particleBudget particles is
// skipped; one whose emitters would emit too many is loaded but not stepped. Requests beyond the
// loader's own limits are kept: the loader must reject those itself.
#include "fuzz_support.hpp"

#include "json_fields.hpp"
#include "rigid2d_scene.hpp"
#include "scene_file.hpp"

#include <impetus/error.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <typeinfo>

namespace {

using impetus::fuzz::str;
using nlohmann::json;

/// Particles the generators of one document may create (before any step).
constexpr double particleBudget = 20'000.0;
/// Steps taken on a scene that loads, at the CLI's default time step.
constexpr int steps = 4;
constexpr float dt = 1.0f / 60.0f;
/// Particles (or bodies) times substeps times steps: beyond it a scene is loaded, not stepped.
constexpr double stepBudget = 400'000.0;

/// What a document asks for, read before the loaders see it.
struct Scan {
  double particles = 0.0; ///< particles the generators would create
  double emitted = 0.0;   ///< particles the emitters would create over `steps` steps
  bool moderate = true;   ///< every number is 0 or within [1e-3, 1e3] in magnitude
  bool springs = false;   ///< explicit spring-dampers: "springs", or a book-springs rope or cloth
};

/// A whole number in [lo, hi], or -1.
double wholeIn(const json& j, double lo, double hi) {
  if (!j.is_number_integer()) {
    return -1.0;
  }
  const double v = j.get<double>();
  return v >= lo && v <= hi ? v : -1.0;
}

/// Adds up the particles the generators ask for (within the loader's limits: beyond them the
/// loader throws before creating anything), the emitters' output, and whether the numbers are
/// moderate. Keys are matched wherever they appear: an over-estimate at worst.
void scan(const json& j, const std::string& key, Scan& s) {
  if (key == "springs" && j.is_array() && !j.empty()) {
    s.springs = true;
  }
  if (key == "model" && j.is_string() && j.get<std::string>() == "book-springs") {
    s.springs = true;
  }
  if (j.is_object()) {
    if (j.contains("rows") || j.contains("columns")) { // a cloth, 10 x 10 by default
      const double rows = j.contains("rows") ? wholeIn(j["rows"], 2, 1e4) : 10.0;
      const double columns = j.contains("columns") ? wholeIn(j["columns"], 2, 1e4) : 10.0;
      s.particles += rows > 0.0 && columns > 0.0 ? rows * columns : 0.0;
    }
    if (j.contains("rate") || j.contains("burst")) { // an emitter
      const double burst = j.contains("burst") ? std::max(0.0, wholeIn(j["burst"], 0, 1e6)) : 0.0;
      double rate = 0.0;
      if (j.contains("rate") && j["rate"].is_number()) {
        rate = j["rate"].get<double>();
      }
      // A rate whose particles per step do not fit an int is left in: the world must refuse it
      // up front, not overflow the count (so such a scene is stepped).
      const bool countOverflows = rate * static_cast<double>(dt) >= 2147483648.0;
      s.emitted += burst + (std::isfinite(rate) && rate > 0.0 && !countOverflows ? rate * dt * steps : 0.0);
    }
    for (const auto& item : j.items()) {
      scan(item.value(), item.key(), s);
    }
    return;
  }
  if (j.is_array()) {
    if (key == "counts" && j.size() == 3) { // a grid: the product, if the loader accepts it
      double product = 1.0;
      for (const json& c : j) {
        const double v = wholeIn(c, 1, 1e7);
        product = v > 0.0 ? product * v : 0.0;
      }
      s.particles += product <= 1e7 ? product : 0.0;
    }
    for (const json& element : j) {
      scan(element, key, s);
    }
    return;
  }
  if (!j.is_number()) {
    return;
  }
  if (key == "count") { // a line or a random box
    s.particles += std::max(0.0, wholeIn(j, 1, 1e7));
  } else if (key == "segments") { // a rope: segments + 1 particles
    const double v = wholeIn(j, 1, 1e6);
    s.particles += v > 0.0 ? v + 1.0 : 0.0;
  }
  // Bit fields and seeds are large by nature; they do not scale any physics.
  if (key == "seed" || key == "category" || key == "mask" || key == "group") {
    return;
  }
  const double v = std::abs(j.get<double>());
  if (!(v == 0.0 || (v >= 1e-3 && v <= 1e3))) {
    s.moderate = false;
  }
}

/// Runs `f`, which may throw impetus::Error and nothing else.
template <class F> void onlyImpetusErrors(const char* what, F&& f) {
  try {
    f();
  } catch (const impetus::Error&) {
    // The documented way to refuse a document or a step.
  } catch (const std::exception& e) {
    FUZZ_CHECK(false, std::string(what) + " threw " + typeid(e).name() + ": " + e.what());
  } catch (...) {
    FUZZ_CHECK(false, std::string(what) + " threw something that is not a std::exception");
  }
}

void stepParticles(impetus::cli::ParticleScene& scene, const Scan& s) {
  impetus::ParticleWorld& world = scene.world;
  const double work = (static_cast<double>(world.particleCount()) + s.emitted) * world.settings().substeps * steps;
  if (work > stepBudget) {
    return;
  }
  for (int k = 1; k <= steps; ++k) {
    world.step(dt); // an impetus::Error here is caught by the caller
    // Explicit spring-dampers are stable only for k h^2 / m below a bound (the book's rope needs
    // substeps under 5 ms: scenes/particles/ch13_rope.json), so a stiff one may blow up; those
    // scenes are checked for crashes only. (Drag used to blow up the same way: a light particle
    // in moderate drag gained energy every substep and reached NaN, regressions/scene_loader/
    // explicit-drag-nan.json; since cfb4d2c drag never reverses a particle's motion.)
    if (!s.moderate || s.springs) {
      continue;
    }
    const auto x = world.positions();
    const auto v = world.velocities();
    for (std::size_t i = 0; i < x.size(); ++i) {
      FUZZ_CHECK(isFinite(x[i]) && isFinite(v[i]), std::string("particle ") + std::to_string(i) + " after step " +
                                                       std::to_string(k) + ": position (" + str(x[i].x) + ", " +
                                                       str(x[i].y) + ", " + str(x[i].z) + "), velocity (" +
                                                       str(v[i].x) + ", " + str(v[i].y) + ", " + str(v[i].z) + ")");
    }
  }
}

void stepRigid2d(impetus::cli::Rigid2dScene& scene, const Scan& s) {
  impetus::rigid2d::World& world = scene.world;
  const double work = static_cast<double>(scene.bodies.size() + scene.shapeCount) * world.settings().substeps * steps;
  if (work > stepBudget) {
    return;
  }
  for (int k = 1; k <= steps; ++k) {
    scene.effectors.apply(world, dt);
    world.step(dt); // an impetus::Error here is caught by the caller
    if (!s.moderate) {
      continue;
    }
    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
      const impetus::rigid2d::BodyId id = scene.bodies[b];
      const impetus::Vec2f x = world.position(id);
      const impetus::Vec2f v = world.linearVelocity(id);
      const float angle = world.angle(id);
      const float w = world.angularVelocity(id);
      FUZZ_CHECK(isFinite(x) && isFinite(v) && std::isfinite(angle) && std::isfinite(w),
                 std::string("body ") + std::to_string(b) + " after step " + std::to_string(k) + ": position " +
                     str(x) + ", angle " + str(angle) + ", velocity " + str(v) + ", angular velocity " + str(w));
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Scene files are small; longer inputs only slow the search down.
  if (size > 16384) {
    return 0;
  }
  const std::string text(reinterpret_cast<const char*>(data), size);

  Scan s;
  try {
    scan(json::parse(text), "", s);
  } catch (const json::exception&) {
    // Not JSON: the loaders must say so (an impetus::Error), which costs nothing to find out.
  }
  if (s.particles > particleBudget) {
    return 0;
  }

  // As `impetus run` reads a file (apps/cli/run_command.cpp): a JSON object, its "kind", then the
  // loader for that kind; the particle loader gets the document without "kind".
  onlyImpetusErrors("loading and stepping like impetus run", [&] {
    nlohmann::json doc = impetus::cli::json_fields::parseObject(text, "a JSON object");
    if (impetus::cli::sceneKind(doc) == "rigid2d") {
      impetus::cli::Rigid2dScene scene = impetus::cli::parseRigid2dScene(doc);
      stepRigid2d(scene, s);
    } else {
      doc.erase("kind");
      impetus::cli::ParticleScene scene = impetus::cli::parseScene(doc.dump());
      stepParticles(scene, s);
    }
  });

  // The text straight into each loader: each must refuse the other's documents cleanly.
  onlyImpetusErrors("parseScene", [&] { (void)impetus::cli::parseScene(text); });
  onlyImpetusErrors("parseRigid2dScene", [&] { (void)impetus::cli::parseRigid2dScene(text); });
  return 0;
}
