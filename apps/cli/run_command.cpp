// `impetus run`: steps a scene file's particle world and records, every K steps, each particle's
// position and velocity and the world's energies, as CSV (one row per particle per recorded
// step) or JSON (one object per recorded step). Formats: docs/scene-format.md.
#include "run_command.hpp"

#include "json_fields.hpp"
#include "rigid2d_run.hpp"
#include "rigid2d_scene.hpp"
#include "scene_file.hpp"

#include <impetus/error.hpp>

#include <fmt/core.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <tuple>
#include <unordered_map>

namespace impetus::cli {
namespace {

/// The world's energies at one instant, J.
struct Energies {
  double kinetic = 0.0;
  double potential = 0.0; ///< gravitational, -m g . x (zero at the origin)
  double spring = 0.0;    ///< elastic, 1/2 k (|d| - r)^2 over the springs
  [[nodiscard]] double total() const { return kinetic + potential + spring; }
};

Energies energies(const ParticleWorld& world) {
  return {world.kineticEnergy(), world.potentialEnergy(), world.springEnergy()};
}

/// A stable number for each particle, in order of first appearance: the scene's particles are
/// 0..n-1 in the file's order (the world's order before the first step), emitted ones follow.
/// The world's ids reuse slots, and its dense order changes when particles expire.
class ParticleNumbers {
public:
  std::size_t operator()(ParticleId id) {
    const std::uint64_t key = (std::uint64_t{id.index} << 32) | id.generation;
    return numbers_.try_emplace(key, numbers_.size()).first->second;
  }

private:
  std::unordered_map<std::uint64_t, std::size_t> numbers_;
};

/// Where the recorded frames go.
class Recorder {
public:
  virtual ~Recorder() = default;
  virtual void frame(std::int64_t step, double time, const Energies& e, const ParticleWorld& world,
                     ParticleNumbers& numbers) = 0;
  virtual void finish() = 0;
  [[nodiscard]] std::int64_t frames() const { return frames_; }
  [[nodiscard]] std::int64_t rows() const { return rows_; }

protected:
  std::int64_t frames_ = 0;
  std::int64_t rows_ = 0;
};

/// Opens `path` for writing; a path that cannot be written is a bad argument.
std::ofstream openOut(const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) {
    throw Error("--out", "--out = " + path + ": cannot be written");
  }
  return out;
}

void closeOut(std::ofstream& out, const std::string& path) {
  out.close();
  if (!out) {
    throw Error("--out", "--out = " + path + ": write failed");
  }
}

/// One row per particle per recorded step; the energies repeat on each row of a step, so that
/// every row stands alone (a step without particles has no row). Numbers round-trip exactly.
class CsvRecorder final : public Recorder {
public:
  static constexpr const char* header = "step,time,particle,x,y,z,vx,vy,vz,kinetic,potential,spring,total";

  explicit CsvRecorder(std::string path) : path_(std::move(path)), out_(openOut(path_)) { out_ << header << '\n'; }

  void frame(std::int64_t step, double time, const Energies& e, const ParticleWorld& world,
             ParticleNumbers& numbers) override {
    const auto ids = world.ids();
    const auto x = world.positions();
    const auto v = world.velocities();
    fmt::memory_buffer buffer;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      fmt::format_to(std::back_inserter(buffer), "{},{},{},{},{},{},{},{},{},{},{},{},{}\n", step, time,
                     numbers(ids[i]), x[i].x, x[i].y, x[i].z, v[i].x, v[i].y, v[i].z, e.kinetic, e.potential, e.spring,
                     e.total());
    }
    out_.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    ++frames_;
    rows_ += static_cast<std::int64_t>(ids.size());
  }

  void finish() override { closeOut(out_, path_); }

private:
  std::string path_;
  std::ofstream out_;
};

/// {"scene", "description", "dt", "substeps", "steps", "every", "particle_names",
///  "frames": [{"step", "time", "kinetic", "potential", "spring", "total", "particles",
///              "positions", "velocities"}]}, written as it goes.
class JsonRecorder final : public Recorder {
public:
  JsonRecorder(std::string path, const RunOptions& o, const ParticleScene& scene, float dt)
      : path_(std::move(path)), out_(openOut(path_)) {
    out_ << fmt::format("{{\n\"scene\": {},\n\"description\": {},\n\"dt\": {},\n\"substeps\": {},\n\"steps\": {},\n"
                        "\"every\": {},\n\"particle_names\": {},\n\"frames\": [",
                        nlohmann::json(o.scene).dump(), nlohmann::json(scene.description).dump(), dt,
                        scene.world.settings().substeps, o.steps, o.every, nlohmann::json(scene.particleNames).dump());
  }

  void frame(std::int64_t step, double time, const Energies& e, const ParticleWorld& world,
             ParticleNumbers& numbers) override {
    const auto ids = world.ids();
    const auto x = world.positions();
    const auto v = world.velocities();
    fmt::memory_buffer b;
    const auto out = std::back_inserter(b);
    fmt::format_to(out,
                   "{}\n{{\"step\": {}, \"time\": {}, \"kinetic\": {}, \"potential\": {}, \"spring\": {}, "
                   "\"total\": {},\n \"particles\": [",
                   frames_ == 0 ? "" : ",", step, time, e.kinetic, e.potential, e.spring, e.total());
    for (std::size_t i = 0; i < ids.size(); ++i) {
      fmt::format_to(out, "{}{}", i == 0 ? "" : ", ", numbers(ids[i]));
    }
    fmt::format_to(out, "],\n \"positions\": [");
    for (std::size_t i = 0; i < ids.size(); ++i) {
      fmt::format_to(out, "{}[{}, {}, {}]", i == 0 ? "" : ", ", x[i].x, x[i].y, x[i].z);
    }
    fmt::format_to(out, "],\n \"velocities\": [");
    for (std::size_t i = 0; i < ids.size(); ++i) {
      fmt::format_to(out, "{}[{}, {}, {}]", i == 0 ? "" : ", ", v[i].x, v[i].y, v[i].z);
    }
    fmt::format_to(out, "]}}");
    out_.write(b.data(), static_cast<std::streamsize>(b.size()));
    ++frames_;
    rows_ += static_cast<std::int64_t>(ids.size());
  }

  void finish() override {
    out_ << "\n]\n}\n";
    closeOut(out_, path_);
  }

private:
  std::string path_;
  std::ofstream out_;
};

/// Discards the frames (no --out).
class NoRecorder final : public Recorder {
public:
  void frame(std::int64_t, double, const Energies&, const ParticleWorld&, ParticleNumbers&) override { ++frames_; }
  void finish() override {}
};

void validate(const RunOptions& o) {
  if (o.steps < 1 || o.steps > maxSteps) {
    throwInvalid("--steps", static_cast<double>(o.steps),
                 "must be a whole number from 1 to " + std::to_string(maxSteps));
  }
  if (!(std::isfinite(o.dt) && o.dt > 0.0 && o.dt <= 1.0)) {
    throwInvalid("--dt", o.dt, "must be in (0, 1] s");
  }
  if (o.every < 1 || o.every > maxSteps) {
    throwInvalid("--every", static_cast<double>(o.every),
                 "must be a whole number from 1 to " + std::to_string(maxSteps));
  }
  if (o.threads < 1 || o.threads > 64) {
    throwInvalid("--threads", static_cast<double>(o.threads), "must be a whole number from 1 to 64");
  }
  if (!o.out.empty()) {
    const std::string ext = std::filesystem::path(o.out).extension().string();
    if (ext != ".csv" && ext != ".json") {
      throw Error("--out", "--out = " + o.out + ": the file name must end in .csv or .json");
    }
  }
}

bool finite(const ParticleWorld& world, const Energies& e) {
  for (const Vec3f& x : world.positions()) {
    if (!isFinite(x)) {
      return false;
    }
  }
  return std::isfinite(e.total());
}

} // namespace

void printStateHash(std::uint64_t hash) { fmt::print("state hash: {:016x}\n", hash); }

int runScene(const RunOptions& o) {
  try {
    validate(o);
    // "kind" picks the loader: particles (the default) or rigid2d (docs/scene-format-2d.md).
    const std::string text = json_fields::readFile(o.scene);
    json_fields::requireArrayLimits(
        text, {{"bodies", maxSceneBodies}, {"particles", static_cast<std::size_t>(maxSceneParticles)}});
    nlohmann::json doc = json_fields::parseObject(text, "a JSON object (docs/scene-format.md)");
    if (sceneKind(doc) == "rigid2d") {
      return runRigid2dScene(o, doc);
    }
    if (!o.events.empty()) {
      throw Error("--events", "--events = " + o.events + ": only rigid2d scenes have contact events");
    }
    if (o.threads != 1) {
      throwInvalid("--threads", static_cast<double>(o.threads), "particle scenes run on one thread");
    }
    doc.erase("kind");
    ParticleScene scene = parseScene(doc.dump());
    ParticleWorld& world = scene.world;
    const auto dt = static_cast<float>(o.dt);
    std::unique_ptr<Recorder> recorder;
    if (o.out.empty()) {
      recorder = std::make_unique<NoRecorder>();
    } else if (std::filesystem::path(o.out).extension() == ".csv") {
      recorder = std::make_unique<CsvRecorder>(o.out);
    } else {
      recorder = std::make_unique<JsonRecorder>(o.out, o, scene, dt);
    }

    const std::size_t startParticles = world.particleCount();
    ParticleNumbers numbers;
    for (const ParticleId id : world.ids()) {
      (void)numbers(id);
    }
    const Energies start = energies(world);
    recorder->frame(0, 0.0, start, world, numbers);
    Energies last = start;
    for (std::int64_t step = 1; step <= o.steps; ++step) {
      world.step(dt);
      if (step % o.every == 0 || step == o.steps) {
        last = energies(world);
        // The time the world has advanced: step whole steps of the float dt it was given.
        recorder->frame(step, static_cast<double>(step) * static_cast<double>(dt), last, world, numbers);
        if (!finite(world, last)) {
          recorder->finish();
          fmt::print(stderr, "error: the simulation produced a non-finite state by step {}\n", step);
          return 1;
        }
      }
    }
    recorder->finish();

    // One paragraph: what the scene holds, how long it ran, and where its energy went.
    const auto count = [](std::size_t n, const char* one, const char* many) {
      return fmt::format("{} {}", n, n == 1 ? one : many);
    };
    std::string contents = fmt::format("{}, {}, {}, {}", count(startParticles, "particle", "particles"),
                                       count(world.obstacleCount(), "obstacle", "obstacles"),
                                       count(world.springCount(), "spring", "springs"),
                                       count(world.constraintCount(), "constraint", "constraints"));
    for (const auto& [n, one, many] :
         {std::tuple{scene.ropeCount, "rope", "ropes"}, std::tuple{scene.clothCount, "cloth", "cloths"},
          std::tuple{scene.attractorCount, "attractor", "attractors"},
          std::tuple{scene.emitterCount, "emitter", "emitters"}}) {
      if (n > 0) {
        contents += ", " + count(n, one, many);
      }
    }
    fmt::print("{}: {}; {} of {} s ({:.6g} s simulated, {} each). At the end: {}; energies kinetic {:.6g} J, "
               "potential {:.6g} J, spring {:.6g} J, total {:.6g} J (at the start {:.6g} J).",
               o.scene, contents, count(static_cast<std::size_t>(o.steps), "step", "steps"), dt,
               static_cast<double>(o.steps) * static_cast<double>(dt),
               count(static_cast<std::size_t>(world.settings().substeps), "substep", "substeps"),
               count(world.particleCount(), "particle", "particles"), last.kinetic, last.potential, last.spring,
               last.total(), start.total());
    if (!o.out.empty()) {
      fmt::print(" Wrote {} ({} frames, {} particle rows).", o.out, recorder->frames(), recorder->rows());
    }
    fmt::print("\n");
    if (o.hash) {
      printStateHash(world.stateHash());
    }
    return 0;
  } catch (const Error& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  }
}

} // namespace impetus::cli
