// `impetus run` on a rigid2d scene: steps the world and records, every K steps, each body's pose
// and velocity (CSV: one row per body per recorded step; JSON: one object per recorded step with
// the energies and the event counts), and every step's contact, sensor and joint-break events
// (--events, CSV). Formats: docs/scene-format-2d.md.
#include "rigid2d_run.hpp"

#include "rigid2d_scene.hpp"

#include <impetus/core/task_runner.hpp>
#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

namespace impetus::cli {
namespace {

using namespace rigid2d;

/// One body's state at an instant.
struct BodyState {
  Vec2f position; ///< body origin, m
  float angle = 0.0f;
  Vec2f velocity; ///< of the centre of mass, m/s
  float angularVelocity = 0.0f;
  double kinetic = 0.0;   ///< J
  double potential = 0.0; ///< J, -m g_body . c (zero at the origin)
};

/// The world's energies and the events since the previous recorded step.
struct Totals {
  double kinetic = 0.0;
  double potential = 0.0;
  [[nodiscard]] double total() const { return kinetic + potential; }
};

struct EventCounts {
  std::int64_t begins = 0;
  std::int64_t ends = 0;
  std::int64_t hits = 0;
  std::int64_t sensorBegins = 0;
  std::int64_t sensorEnds = 0;
  std::int64_t breaks = 0;
  double fastestHit = 0.0; ///< m/s
  void add(const EventCounts& o) {
    begins += o.begins;
    ends += o.ends;
    hits += o.hits;
    sensorBegins += o.sensorBegins;
    sensorEnds += o.sensorEnds;
    breaks += o.breaks;
    fastestHit = std::max(fastestHit, o.fastestHit);
  }
};

const char* typeName(BodyType t) {
  switch (t) {
  case BodyType::staticBody:
    return "static";
  case BodyType::kinematicBody:
    return "kinematic";
  case BodyType::dynamicBody:
    break;
  }
  return "dynamic";
}

const char* jointTypeName(JointType t) {
  switch (t) {
  case JointType::revolute:
    return "revolute";
  case JointType::prismatic:
    return "prismatic";
  case JointType::distance:
    return "distance";
  case JointType::weld:
    return "weld";
  case JointType::wheel:
    return "wheel";
  case JointType::motor:
    return "motor";
  case JointType::mouse:
    return "mouse";
  case JointType::filter:
    break;
  }
  return "filter";
}

/// Every body's state, the energies summed over the dynamic bodies; false if anything is not
/// finite.
bool sample(const Rigid2dScene& scene, std::vector<BodyState>& states, Totals& totals) {
  const World& world = scene.world;
  const Vec2f g = world.settings().gravity;
  states.resize(scene.bodies.size());
  totals = {};
  bool finite = true;
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    const BodyId id = scene.bodies[k];
    BodyState& s = states[k];
    s.position = world.position(id);
    s.angle = world.angle(id);
    s.velocity = world.linearVelocity(id);
    s.angularVelocity = world.angularVelocity(id);
    s.kinetic = 0.0;
    s.potential = 0.0;
    if (world.bodyType(id) == BodyType::dynamicBody) {
      const double m = world.mass(id);
      const double inertia = world.rotationalInertia(id);
      const Vec2f c = world.worldCenterOfMass(id);
      const double w = s.angularVelocity;
      s.kinetic =
          0.5 * m * (double{s.velocity.x} * s.velocity.x + double{s.velocity.y} * s.velocity.y) + 0.5 * inertia * w * w;
      s.potential = -m * scene.gravityScales[k] * (double{g.x} * c.x + double{g.y} * c.y) + 0.0; // no -0
    }
    totals.kinetic += s.kinetic;
    totals.potential += s.potential;
    finite = finite && isFinite(s.position) && std::isfinite(s.angle) && isFinite(s.velocity) &&
             std::isfinite(s.angularVelocity);
  }
  return finite && std::isfinite(totals.total());
}

std::ofstream openOut(const std::string& option, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) {
    throw Error(option, option + " = " + path + ": cannot be written");
  }
  return out;
}

void closeOut(std::ofstream& out, const std::string& option, const std::string& path) {
  out.close();
  if (!out) {
    throw Error(option, option + " = " + path + ": write failed");
  }
}

/// Where the recorded frames go.
class Recorder {
public:
  virtual ~Recorder() = default;
  virtual void frame(std::int64_t step, double time, const std::vector<BodyState>& states, const Totals& totals,
                     const EventCounts& events, std::size_t awake) = 0;
  virtual void finish() = 0;
  [[nodiscard]] std::int64_t frames() const { return frames_; }
  [[nodiscard]] std::int64_t rows() const { return rows_; }

protected:
  std::int64_t frames_ = 0;
  std::int64_t rows_ = 0;
};

/// One row per body per recorded step, with the body's own energies (a step's totals are the
/// sums over its rows). Numbers round-trip exactly.
class CsvRecorder final : public Recorder {
public:
  static constexpr const char* header = "step,time,body,name,x,y,angle,vx,vy,w,kinetic,potential";

  CsvRecorder(std::string path, const Rigid2dScene& scene)
      : path_(std::move(path)), out_(openOut("--out", path_)), names_(scene.bodyNames) {
    out_ << header << '\n';
  }

  void frame(std::int64_t step, double time, const std::vector<BodyState>& states, const Totals&, const EventCounts&,
             std::size_t) override {
    fmt::memory_buffer b;
    for (std::size_t k = 0; k < states.size(); ++k) {
      const BodyState& s = states[k];
      fmt::format_to(std::back_inserter(b), "{},{},{},{},{},{},{},{},{},{},{},{}\n", step, time, k, names_[k],
                     s.position.x, s.position.y, s.angle, s.velocity.x, s.velocity.y, s.angularVelocity, s.kinetic,
                     s.potential);
    }
    out_.write(b.data(), static_cast<std::streamsize>(b.size()));
    ++frames_;
    rows_ += static_cast<std::int64_t>(states.size());
  }

  void finish() override { closeOut(out_, "--out", path_); }

private:
  std::string path_;
  std::ofstream out_;
  std::vector<std::string> names_;
};

/// {"scene", "kind", "description", "dt", "substeps", "solver", "steps", "every", "bodies",
///  "joints", "frames": [{"step", "time", "kinetic", "potential", "total", "awake",
///  "contact_begins", "contact_ends", "hits", "fastest_hit", "sensor_begins", "sensor_ends",
///  "joint_breaks", "positions", "angles", "velocities", "angular_velocities"}]}, written as it
/// goes.
class JsonRecorder final : public Recorder {
public:
  JsonRecorder(std::string path, const RunOptions& o, const Rigid2dScene& scene, float dt)
      : path_(std::move(path)), out_(openOut("--out", path_)) {
    const World& world = scene.world;
    nlohmann::json bodies = nlohmann::json::array();
    for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
      bodies.push_back({{"name", scene.bodyNames[k]},
                        {"type", typeName(world.bodyType(scene.bodies[k]))},
                        {"mass", world.mass(scene.bodies[k])}});
    }
    nlohmann::json joints = nlohmann::json::array();
    for (std::size_t k = 0; k < scene.joints.size(); ++k) {
      const JointId id = scene.joints[k];
      joints.push_back({{"name", scene.jointNames[k]},
                        {"type", jointTypeName(world.jointType(id))},
                        {"body_a", scene.bodyNumber(world.jointBodyA(id))},
                        {"body_b", scene.bodyNumber(world.jointBodyB(id))}});
    }
    out_ << fmt::format("{{\n\"scene\": {},\n\"kind\": \"rigid2d\",\n\"description\": {},\n\"dt\": {},\n"
                        "\"substeps\": {},\n\"solver\": \"{}\",\n\"steps\": {},\n\"every\": {},\n\"bodies\": {},\n"
                        "\"joints\": {},\n\"frames\": [",
                        nlohmann::json(o.scene).dump(), nlohmann::json(scene.description).dump(), dt,
                        world.settings().substeps, world.settings().solver == SolverKind::bookImpulse ? "book" : "soft",
                        o.steps, o.every, bodies.dump(), joints.dump());
  }

  void frame(std::int64_t step, double time, const std::vector<BodyState>& states, const Totals& t,
             const EventCounts& e, std::size_t awake) override {
    fmt::memory_buffer b;
    const auto out = std::back_inserter(b);
    fmt::format_to(out,
                   "{}\n{{\"step\": {}, \"time\": {}, \"kinetic\": {}, \"potential\": {}, \"total\": {}, "
                   "\"awake\": {},\n \"contact_begins\": {}, \"contact_ends\": {}, \"hits\": {}, \"fastest_hit\": {}, "
                   "\"sensor_begins\": {}, \"sensor_ends\": {}, \"joint_breaks\": {},\n \"positions\": [",
                   frames_ == 0 ? "" : ",", step, time, t.kinetic, t.potential, t.total(), awake, e.begins, e.ends,
                   e.hits, e.fastestHit, e.sensorBegins, e.sensorEnds, e.breaks);
    for (std::size_t k = 0; k < states.size(); ++k) {
      fmt::format_to(out, "{}[{}, {}]", k == 0 ? "" : ", ", states[k].position.x, states[k].position.y);
    }
    fmt::format_to(out, "],\n \"angles\": [");
    for (std::size_t k = 0; k < states.size(); ++k) {
      fmt::format_to(out, "{}{}", k == 0 ? "" : ", ", states[k].angle);
    }
    fmt::format_to(out, "],\n \"velocities\": [");
    for (std::size_t k = 0; k < states.size(); ++k) {
      fmt::format_to(out, "{}[{}, {}]", k == 0 ? "" : ", ", states[k].velocity.x, states[k].velocity.y);
    }
    fmt::format_to(out, "],\n \"angular_velocities\": [");
    for (std::size_t k = 0; k < states.size(); ++k) {
      fmt::format_to(out, "{}{}", k == 0 ? "" : ", ", states[k].angularVelocity);
    }
    fmt::format_to(out, "]}}");
    out_.write(b.data(), static_cast<std::streamsize>(b.size()));
    ++frames_;
    rows_ += static_cast<std::int64_t>(states.size());
  }

  void finish() override {
    out_ << "\n]\n}\n";
    closeOut(out_, "--out", path_);
  }

private:
  std::string path_;
  std::ofstream out_;
};

/// Discards the frames (no --out).
class NoRecorder final : public Recorder {
public:
  void frame(std::int64_t, double, const std::vector<BodyState>&, const Totals&, const EventCounts&,
             std::size_t) override {
    ++frames_;
  }
  void finish() override {}
};

/// Reads a step's events off the world, counts them and (with --events) writes them: one row per
/// event, in the world's order: contact begins, ends, hits, sensor begins, ends, joint breaks.
class EventLog {
public:
  static constexpr const char* header =
      "step,time,event,body_a,name_a,body_b,name_b,x,y,normal_x,normal_y,speed,joint,force,torque";

  EventLog(const std::string& path, const Rigid2dScene& scene) : path_(path), scene_(scene) {
    if (!path_.empty()) {
      out_ = openOut("--events", path_);
      out_ << header << '\n';
    }
  }

  /// The events of the step just taken.
  EventCounts collect(std::int64_t step, double time) {
    const World& world = scene_.world;
    EventCounts c;
    const ContactEvents& contacts = world.contactEvents();
    const SensorEvents& sensors = world.sensorEvents();
    const JointEvents& joints = world.jointEvents();
    c.begins = static_cast<std::int64_t>(contacts.begins.size());
    c.ends = static_cast<std::int64_t>(contacts.ends.size());
    c.hits = static_cast<std::int64_t>(contacts.hits.size());
    c.sensorBegins = static_cast<std::int64_t>(sensors.begins.size());
    c.sensorEnds = static_cast<std::int64_t>(sensors.ends.size());
    c.breaks = static_cast<std::int64_t>(joints.breaks.size());
    for (const ContactHitEvent& h : contacts.hits) {
      c.fastestHit = std::max(c.fastestHit, double{h.approachSpeed});
    }
    if (path_.empty()) {
      return c;
    }
    b_.clear();
    for (const ContactBeginEvent& e : contacts.begins) {
      pair(step, time, "begin", e.shapeA, e.shapeB);
      line(",,,,,,,\n");
    }
    for (const ContactEndEvent& e : contacts.ends) {
      pair(step, time, "end", e.shapeA, e.shapeB);
      line(",,,,,,,\n");
    }
    for (const ContactHitEvent& e : contacts.hits) {
      pair(step, time, "hit", e.shapeA, e.shapeB);
      fmt::format_to(std::back_inserter(b_), ",{},{},{},{},{},,,\n", e.point.x, e.point.y, e.normal.x, e.normal.y,
                     e.approachSpeed);
    }
    for (const SensorEvent& e : sensors.begins) {
      pair(step, time, "sensor_begin", e.sensor, e.visitor);
      line(",,,,,,,\n");
    }
    for (const SensorEvent& e : sensors.ends) {
      pair(step, time, "sensor_end", e.sensor, e.visitor);
      line(",,,,,,,\n");
    }
    for (const JointBreakEvent& e : joints.breaks) {
      const std::size_t a = scene_.bodyNumber(world.jointBodyA(e.joint));
      const std::size_t b = scene_.bodyNumber(world.jointBodyB(e.joint));
      fmt::format_to(std::back_inserter(b_), "{},{},joint_break,{},{},{},{},,,,,,{},{},{}\n", step, time, a,
                     scene_.bodyNames[a], b, scene_.bodyNames[b], scene_.jointNumber(e.joint), e.force, e.torque);
    }
    out_.write(b_.data(), static_cast<std::streamsize>(b_.size()));
    return c;
  }

  void finish() {
    if (!path_.empty()) {
      closeOut(out_, "--events", path_);
    }
  }

private:
  void pair(std::int64_t step, double time, const char* event, ShapeId shapeA, ShapeId shapeB) {
    const World& world = scene_.world;
    const std::size_t a = scene_.bodyNumber(world.shapeBody(shapeA));
    const std::size_t b = scene_.bodyNumber(world.shapeBody(shapeB));
    fmt::format_to(std::back_inserter(b_), "{},{},{},{},{},{},{}", step, time, event, a, scene_.bodyNames[a], b,
                   scene_.bodyNames[b]);
  }
  void line(const char* rest) { b_.append(std::string_view(rest)); }

  std::string path_;
  const Rigid2dScene& scene_;
  std::ofstream out_;
  fmt::memory_buffer b_;
};

std::size_t awakeDynamic(const Rigid2dScene& scene) {
  std::size_t n = 0;
  for (const BodyId id : scene.bodies) {
    if (scene.world.bodyType(id) == BodyType::dynamicBody && scene.world.isAwake(id)) {
      ++n;
    }
  }
  return n;
}

} // namespace

int runRigid2dScene(const RunOptions& o, const nlohmann::json& doc) {
  if (!o.events.empty() && std::filesystem::path(o.events).extension() != ".csv") {
    throw Error("--events", "--events = " + o.events + ": the file name must end in .csv");
  }
  std::unique_ptr<ThreadPool> pool;
  if (o.threads > 1) {
    pool = std::make_unique<ThreadPool>(o.threads);
  }
  Rigid2dScene scene = parseRigid2dScene(doc, pool.get());
  World& world = scene.world;
  const auto dt = static_cast<float>(o.dt);
  std::unique_ptr<Recorder> recorder;
  if (o.out.empty()) {
    recorder = std::make_unique<NoRecorder>();
  } else if (std::filesystem::path(o.out).extension() == ".csv") {
    recorder = std::make_unique<CsvRecorder>(o.out, scene);
  } else {
    recorder = std::make_unique<JsonRecorder>(o.out, o, scene, dt);
  }
  EventLog events(o.events, scene);

  // The step turns a body at most a quarter turn a substep; a scene's faster spin is capped at
  // once, and the summary says so rather than leaving it to be discovered in the trajectory.
  const double spinCap = 0.25 * pi<double> * world.settings().substeps / static_cast<double>(dt);
  std::vector<std::string> capped;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const BodyId id = scene.bodies[i];
    const double spin = std::abs(static_cast<double>(world.angularVelocity(id)));
    if (world.bodyType(id) == BodyType::dynamicBody && spin > spinCap) {
      capped.push_back(fmt::format("bodies[{}] at {:.6g} rad/s", i, spin));
    }
  }

  std::vector<BodyState> states;
  Totals start;
  bool finite = sample(scene, states, start);
  recorder->frame(0, 0.0, states, start, {}, awakeDynamic(scene));
  Totals last = start;
  EventCounts sinceFrame;
  EventCounts all;
  std::int64_t failedAt = finite ? -1 : 0;
  for (std::int64_t step = 1; step <= o.steps && finite; ++step) {
    scene.effectors.apply(world, dt);
    world.step(dt);
    // The time the world has advanced: step whole steps of the float dt it was given.
    const double time = static_cast<double>(step) * static_cast<double>(dt);
    const EventCounts counts = events.collect(step, time);
    sinceFrame.add(counts);
    all.add(counts);
    Totals now;
    finite = sample(scene, states, now);
    if (step % o.every == 0 || step == o.steps || !finite) {
      last = now;
      recorder->frame(step, time, states, now, sinceFrame, awakeDynamic(scene));
      sinceFrame = {};
    }
    if (!finite) {
      failedAt = step;
    }
  }
  recorder->finish();
  events.finish();
  if (failedAt >= 0) {
    fmt::print(stderr, "error: the simulation produced a non-finite state by step {}\n", failedAt);
    return 1;
  }

  // One line: what the scene holds, how long it ran, what touched what, where the energy went.
  const auto count = [](std::size_t n, const char* one, const char* many) {
    return fmt::format("{} {}", n, n == 1 ? one : many);
  };
  std::size_t dynamic = 0;
  for (const BodyId id : scene.bodies) {
    dynamic += world.bodyType(id) == BodyType::dynamicBody ? 1 : 0;
  }
  const auto n = [](std::int64_t v) { return static_cast<std::size_t>(v); };
  fmt::print("{}: rigid2d, {} ({} dynamic), {}, {}, {}; {} of {} s ({:.6g} s simulated, {} each, {} solver). "
             "Events: {}, {}, {} (fastest {:.4g} m/s), {}; {} of {} dynamic awake at the end. Energies at the end: "
             "kinetic {:.6g} J, potential {:.6g} J, total {:.6g} J (at the start: kinetic {:.6g} J, potential "
             "{:.6g} J, total {:.6g} J).",
             o.scene, count(scene.bodies.size(), "body", "bodies"), dynamic, count(scene.shapeCount, "shape", "shapes"),
             count(scene.joints.size(), "joint", "joints"), count(scene.effectors.size(), "effector", "effectors"),
             count(n(o.steps), "step", "steps"), dt, static_cast<double>(o.steps) * static_cast<double>(dt),
             count(static_cast<std::size_t>(world.settings().substeps), "substep", "substeps"),
             world.settings().solver == SolverKind::bookImpulse ? "book" : "soft-step",
             count(n(all.begins), "contact begin", "contact begins"), count(n(all.ends), "end", "ends"),
             count(n(all.hits), "hit", "hits"), all.fastestHit, count(n(all.breaks), "joint break", "joint breaks"),
             awakeDynamic(scene), dynamic, last.kinetic, last.potential, last.total(), start.kinetic, start.potential,
             start.total());
  if (!capped.empty()) {
    fmt::print(" Capped: {} started spinning faster than the quarter turn a substep the step allows ({:.6g} rad/s "
               "at this dt) and turned at that rate.",
               fmt::join(capped, ", "), spinCap);
  }
  if (!o.out.empty()) {
    fmt::print(" Wrote {} ({} frames, {} body rows).", o.out, recorder->frames(), recorder->rows());
  }
  if (!o.events.empty()) {
    fmt::print(" Wrote {} ({} events).", o.events,
               all.begins + all.ends + all.hits + all.sensorBegins + all.sensorEnds + all.breaks);
  }
  fmt::print("\n");
  if (o.hash) {
    printStateHash(world.stateHash());
  }
  return 0;
}

} // namespace impetus::cli
