// The input validation audit of the command-line tool (docs/reliability.md, "Input validation"):
// every key of the two scene formats (docs/scene-format.md, docs/scene-format-2d.md) refuses a
// value of the wrong type, out of range or degenerate with exit status 2 and one line naming the
// value's JSON path; every number parameter of every `impetus calc` model refuses NaN and
// infinities naming the parameter.
#include "cli_process.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

using nlohmann::json;

using impetus::testing::CliRun;
using impetus::testing::expectUsageError;
using impetus::testing::impetus;

/// A scene text and what its one-line error must contain ("error: <path>...").
struct SceneCase {
  std::string scene;
  std::string needle;
};

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

void expectSceneErrors(const std::vector<SceneCase>& cases, const std::string& prefix) {
  int i = 0;
  for (const SceneCase& c : cases) {
    SCOPED_TRACE(c.scene);
    const std::string path = writeTemp(prefix + std::to_string(i++) + ".json", c.scene);
    expectUsageError(impetus({"run", path, "--steps", "2"}), "error: " + c.needle);
  }
}

// Particle scenes (docs/scene-format.md) ------------------------------------------------------

std::string particles(const std::string& key, const std::string& element) {
  return R"({"particles": [{"name": "p", "position": [0, 1, 0]}, {"name": "q", "position": [1, 1, 0]}], ")" + key +
         R"(": [)" + element + "]}";
}

TEST(CliValidation, particle_scene_world_and_document) {
  const auto world = [](const std::string& body) { return R"({"world": {)" + body + "}}"; };
  expectSceneErrors(
      {
          {world(R"("gravity": [0, "down", 0])"), "world.gravity[1]: expected a number"},
          {world(R"("gravity": [0, 1e39, 0])"), "world.gravity[1] = 1e+39: is out of range (single precision)"},
          {world(R"("gravity": [0, -9.81])"), "world.gravity: expected an array of 3 numbers"},
          {world(R"("wind": [1e999, 0, 0])"), "json: number out of range"}, // beyond a double
          {world(R"("integrator": "leapfrog")"), "world.integrator: unknown integrator 'leapfrog'"},
          {world(R"("substeps": 0)"), "world.substeps = 0: must be between 1 and 1000"},
          {world(R"("substeps": 2.5)"), "world.substeps: expected a whole number"},
          {world(R"("linear_drag": -1)"), "world.linear_drag = -1: must be finite and non-negative"},
          {world(R"("drag_coefficient": -0.5)"), "world.drag_coefficient = -0.5"},
          {world(R"("air_density": -1)"), "world.air_density = -1"},
          {world(R"("rest_threshold": -1)"), "world.rest_threshold = -1"},
          {world(R"("particle_restitution": 1.5)"), "world.particle_restitution = 1.5: must be in [0, 1]"},
          {world(R"("particle_collisions": 1)"), "world.particle_collisions: expected true or false"},
          {world(R"("gust": {"amplitude": [1, 0, 0], "period": 0, "wavelength": 1})"), "world.gust.period = 0"},
          {world(R"("gust": {"amplitude": [1, 0, 0], "period": 1, "wavelength": -2})"), "world.gust.wavelength = -2"},
          {world(R"("gust": {"period": 1, "wavelength": 1})"), "world.gust.amplitude: missing"},
          {world(R"("gravty": [0, -1, 0])"), "world.gravty: unknown key"},
          {R"({"particles": {"position": [0, 0, 0]}})", "particles: expected an array"},
          {R"({"colour": "red"})", "colour: unknown key"},
          {R"([1, 2, 3])", "document: expected a JSON object"},
          {R"({"particles": [)", "json: malformed JSON"},
      },
      "pw");
}

TEST(CliValidation, particle_scene_obstacles_and_particles) {
  const auto obstacle = [](const std::string& body) { return R"({"obstacles": [{)" + body + "}]}"; };
  const auto particle = [](const std::string& body) { return R"({"particles": [{)" + body + "}]}"; };
  expectSceneErrors(
      {
          {obstacle(R"("type": "cone")"), "obstacles[0].type: unknown obstacle type 'cone'"},
          {obstacle(R"("type": "plane", "normal": [0, 0, 0])"), "obstacles[0].normal: must be non-zero"},
          {obstacle(R"("type": "plane", "offset": "low")"), "obstacles[0].offset: expected a number"},
          {obstacle(R"("type": "sphere", "center": [0, 0, 0], "radius": 0)"), "obstacles[0].radius = 0"},
          {obstacle(R"("type": "sphere", "radius": 1)"), "obstacles[0].center: missing"},
          {obstacle(R"("type": "box", "center": [0, 0, 0], "half_extents": [1, 0, 1])"),
           "obstacles[0].half_extents[1] = 0"},
          {obstacle(
               R"("type": "box", "center": [0, 0, 0], "half_extents": [1, 1, 1], "rotation": {"axis": [0, 0, 0], "angle_deg": 5})"),
           "obstacles[0].rotation.axis: rotation axis must be non-zero"},
          {obstacle(R"("type": "capsule", "a": [0, 0, 0], "b": [1, 0, 0], "radius": -1)"), "obstacles[0].radius = -1"},
          {obstacle(R"("type": "sphere", "center": [0, 0, 0], "radius": 1, "restitution": 2)"),
           "obstacles[0].restitution = 2: must be in [0, 1]"},
          {obstacle(R"("type": "sphere", "center": [0, 0, 0], "radius": 1, "friction": -1)"),
           "obstacles[0].friction = -1"},
          {particle(R"("position": [0, 0, 0], "mass": 0)"), "particles[0].mass = 0: must be finite and positive"},
          {particle(R"("position": [0, 0, 0], "mass": 1e-50)"), "particles[0].mass = 0: must be finite and positive"},
          {particle(R"("position": [0, 0, 0], "radius": -1)"), "particles[0].radius = -1"},
          {particle(R"("position": [0, 0, 0], "lifetime": 0)"), "particles[0].lifetime = 0"},
          {particle(R"("position": [0, 0, 0], "velocity": [1, 2])"), "particles[0].velocity: expected an array of 3"},
          {particle(R"("position": [1e39, 0, 0])"), "particles[0].position[0] = 1e+39"},
          {particle(R"("position": [0, 0, 0], "pinned": "yes")"), "particles[0].pinned: expected true or false"},
          {particle(R"("mass": 1)"), "particles[0]: give exactly one of position, grid, line or random_box"},
          {particle(R"("grid": {"origin": [0, 0, 0], "counts": [0, 1, 1], "spacing": [1, 1, 1]})"),
           "particles[0].grid.counts[0] = 0"},
          {particle(R"("grid": {"origin": [0, 0, 0], "counts": [1, 1, 1]})"), "particles[0].grid.spacing: missing"},
          {particle(R"("line": {"from": [0, 0, 0], "to": [1, 0, 0], "count": 0})"), "particles[0].line.count = 0"},
          {particle(R"("random_box": {"min": [0, 0, 0], "max": [1, -1, 1], "count": 3})"),
           "particles[0].random_box.max: must be >= min"},
          {particle(R"("random_box": {"min": [0, 0, 0], "max": [1, 1, 1], "count": 3, "seed": -1})"),
           "particles[0].random_box.seed = -1"},
          {R"({"particles": [{"name": "a", "position": [0, 0, 0]}, {"name": "a", "position": [1, 0, 0]}]})",
           "particles[1].name: duplicate particle name 'a'"},
      },
      "po");
}

TEST(CliValidation, particle_scene_connections) {
  expectSceneErrors(
      {
          {particles("springs", R"({"a": 5, "b": "q"})"), "springs[0].a = 5: no such particle"},
          {particles("springs", R"({"a": "nobody", "b": "q"})"), "springs[0].a: no particle named 'nobody'"},
          {particles("springs", R"({"a": "p", "b": "q", "anchor": [0, 0, 0]})"),
           "springs[0]: give exactly one of b (a particle) or anchor"},
          {particles("springs", R"({"a": "p", "b": "p"})"), "springs[0].b: a spring needs two different particles"},
          {particles("springs", R"({"a": "p", "b": "q", "stiffness": -1})"), "springs[0].stiffness = -1"},
          {particles("springs", R"({"a": "p", "b": "q", "damping": -1})"), "springs[0].damping = -1"},
          {particles("springs", R"({"a": "p", "b": "q", "rest_length": -1})"), "springs[0].rest_length = -1"},
          {particles("springs", R"({"a": "p", "anchor": [0, 1e39, 0]})"), "springs[0].anchor[1] = 1e+39"},
          {particles("constraints", R"({"a": "p", "b": "q", "length": -1})"), "constraints[0].length = -1"},
          {particles("constraints", R"({"a": "p", "b": "q", "compliance": -1})"), "constraints[0].compliance = -1"},
          {particles("constraints", R"({"a": "p", "b": "q", "max_only": 1})"),
           "constraints[0].max_only: expected true or false"},
          {particles("constraints", R"({"a": "p", "b": "p"})"), "constraints[0].b: a constraint needs two different"},
          {R"({"ropes": [{"start": [0, 0, 0], "end": [0, 0, 0]}]})", "ropes[0].end: must differ from start"},
          {R"({"ropes": [{"start": [-3e38, 0, 0], "end": [3e38, 0, 0]}]})",
           "ropes[0].end = inf: must differ from start by a finite distance"},
          {R"({"ropes": [{"start": [0, 0, 0], "end": [1, 0, 0], "segments": 0}]})", "ropes[0].segments = 0"},
          {R"({"ropes": [{"start": [0, 0, 0], "end": [1, 0, 0], "total_mass": 0}]})", "ropes[0].total_mass = 0"},
          {R"({"ropes": [{"start": [0, 0, 0], "end": [1, 0, 0], "particle_radius": -1}]})",
           "ropes[0].particle_radius = -1"},
          {R"({"ropes": [{"start": [0, 0, 0], "end": [1, 0, 0], "compliance": -1}]})", "ropes[0].compliance = -1"},
          {R"({"ropes": [{"start": [0, 0, 0], "end": [1, 0, 0], "stiffness": 0}]})", "ropes[0].stiffness = 0"},
          {R"({"ropes": [{"start": [0, 0, 0], "end": [1, 0, 0], "damping": -1}]})", "ropes[0].damping = -1"},
          {R"({"ropes": [{"start": [0, 0, 0], "end": [1, 0, 0], "model": "chain"}]})",
           "ropes[0].model: unknown rope model 'chain'"},
          {R"({"cloths": [{"origin": [0, 0, 0], "rows": 1}]})", "cloths[0].rows = 1: must be between 2 and 10000"},
          {R"({"cloths": [{"origin": [0, 0, 0], "columns": 10001}]})", "cloths[0].columns = 10001"},
          {R"({"cloths": [{"origin": [0, 0, 0], "across": [1, 0, 0], "down": [2, 0, 0]}]})",
           "cloths[0].down: must be non-zero and not parallel to across"},
          {R"({"cloths": [{"origin": [0, -3e38, 0], "down": [0, -3e38, 0]}]})",
           "cloths[0].down = inf: puts a corner beyond single precision"},
          {R"({"cloths": [{"origin": [0, 0, 0], "total_mass": 0}]})", "cloths[0].total_mass = 0"},
          {R"({"cloths": [{"origin": [0, 0, 0], "particle_radius": 0}]})", "cloths[0].particle_radius = 0"},
          {R"({"cloths": [{"origin": [0, 0, 0], "structural_compliance": -1}]})",
           "cloths[0].structural_compliance = -1"},
          {R"({"cloths": [{"origin": [0, 0, 0], "shear_compliance": -1}]})", "cloths[0].shear_compliance = -1"},
          {R"({"cloths": [{"origin": [0, 0, 0], "bend_compliance": -1}]})", "cloths[0].bend_compliance = -1"},
          {R"({"cloths": [{"origin": [0, 0, 0], "structural_stiffness": 0}]})", "cloths[0].structural_stiffness = 0"},
          {R"({"cloths": [{"origin": [0, 0, 0], "shear_stiffness": -1}]})", "cloths[0].shear_stiffness = -1"},
          {R"({"cloths": [{"origin": [0, 0, 0], "bend_stiffness": 0}]})", "cloths[0].bend_stiffness = 0"},
          {R"({"cloths": [{"origin": [0, 0, 0], "damping": -1}]})", "cloths[0].damping = -1"},
          {R"({"cloths": [{"origin": [0, 0, 0], "pinned": [[10, 0]]}]})", "cloths[0].pinned[0][0] = 10"},
          {R"({"cloths": [{"origin": [0, 0, 0], "pin_rows": [10]}]})", "cloths[0].pin_rows[0] = 10"},
          {R"({"cloths": [{"origin": [0, 0, 0], "pin_columns": [-1]}]})", "cloths[0].pin_columns[0] = -1"},
          {R"({"cloths": [{"origin": [0, 0, 0], "model": "silk"}]})", "cloths[0].model: unknown cloth model 'silk'"},
      },
      "pc");
}

TEST(CliValidation, particle_scene_attractors_and_emitters) {
  const auto emitter = [](const std::string& body) {
    return R"({"emitters": [{"position": [0, 0, 0], )" + body + "}]}";
  };
  expectSceneErrors(
      {
          {R"({"attractors": [{"position": [0, 0, 0], "softening": 0}]})", "attractors[0].softening = 0"},
          {R"({"attractors": [{"strength": 1}]})", "attractors[0].position: missing"},
          {R"({"attractors": [{"position": [0, 0, 0], "strength": "big"}]})",
           "attractors[0].strength: expected a number"},
          {emitter(R"("direction": [0, 0, 0])"), "emitters[0].direction: must be non-zero"},
          {emitter(R"("cone_angle_deg": 190)"), "emitters[0].cone_angle_deg = 190: must be in [0, 180] degrees"},
          {emitter(R"("min_speed": -1)"), "emitters[0].min_speed = -1"},
          {emitter(R"("max_speed": 0.5)"), "emitters[0].max_speed = 0.5: must be >= min_speed"},
          {emitter(R"("rate": -1)"), "emitters[0].rate = -1"},
          {emitter(R"("rate": 2e9)"), "emitters[0].rate = 2e+09: must be between 0 and 1e9 particles per second"},
          {emitter(R"("burst": 1000001)"), "emitters[0].burst = 1000001"},
          {emitter(R"("duration": -1)"), "emitters[0].duration = -1"},
          {emitter(R"("min_lifetime": 0)"), "emitters[0].min_lifetime = 0"},
          {emitter(R"("max_lifetime": 0.5)"), "emitters[0].max_lifetime = 0.5: must be >= min_lifetime"},
          {emitter(R"("mass": 0)"), "emitters[0].mass = 0"},
          {emitter(R"("radius": -1)"), "emitters[0].radius = -1"},
          {emitter(R"("seed": -1)"), "emitters[0].seed = -1"},
          {emitter(R"("planar": "no")"), "emitters[0].planar: expected true or false"},
      },
      "pe");
}

// 2D rigid-body scenes (docs/scene-format-2d.md) ----------------------------------------------

const std::string ground =
    R"({"name": "ground", "type": "static", "shapes": [{"type": "box", "half_extents": [5, 1]}]})";
const std::string ball = R"({"name": "ball", "position": [0, 3], "shapes": [{"type": "circle", "radius": 0.5}]})";
const std::string box =
    R"({"name": "box", "position": [2, 3], "shapes": [{"type": "box", "half_extents": [0.5, 0.5]}]})";

/// A rigid2d document with ground, ball and box, and `rest` after the bodies.
std::string rigid(const std::string& rest) {
  return R"({"kind": "rigid2d", "bodies": [)" + ground + ", " + ball + ", " + box + "]" + rest + "}";
}
std::string world2d(const std::string& body) { return R"({"kind": "rigid2d", "world": {)" + body + "}}"; }
std::string body2d(const std::string& body) { return R"({"kind": "rigid2d", "bodies": [{)" + body + "}]}"; }
std::string shape2d(const std::string& shape, const std::string& bodyType = "dynamic") {
  return R"({"kind": "rigid2d", "bodies": [{"type": ")" + bodyType + R"(", "shapes": [{)" + shape + "}]}]}";
}
std::string joint2d(const std::string& joint) { return rigid(R"(, "joints": [{)" + joint + "}]"); }
std::string effector2d(const std::string& effector) { return rigid(R"(, "effectors": [{)" + effector + "}]"); }

TEST(CliValidation, rigid2d_world_materials_and_bodies) {
  expectSceneErrors(
      {
          {world2d(R"("gravity": [0, 1e39])"), "world.gravity[1] = 1e+39: is out of range (single precision)"},
          {world2d(R"("gravity": [0, -1e999])"), "json: number out of range"},
          {world2d(R"("solver": "magic")"), "world.solver: unknown solver 'magic'"},
          {world2d(R"("substeps": 65)"), "world.substeps = 65: must be between 1 and 64"},
          {world2d(R"("contact_hertz": -1)"), "world.contact_hertz = -1"},
          {world2d(R"("contact_damping_ratio": -1)"), "world.contact_damping_ratio = -1"},
          {world2d(R"("max_contact_push_speed": 0)"), "world.max_contact_push_speed = 0"},
          {world2d(R"("joint_hertz": -1)"), "world.joint_hertz = -1"},
          {world2d(R"("joint_damping_ratio": -1)"), "world.joint_damping_ratio = -1"},
          {world2d(R"("restitution_threshold": -1)"), "world.restitution_threshold = -1"},
          {world2d(R"("max_linear_speed": 0)"), "world.max_linear_speed = 0"},
          {world2d(R"("hit_event_threshold": -1)"), "world.hit_event_threshold = -1"},
          {world2d(R"("time_to_sleep": -1)"), "world.time_to_sleep = -1"},
          {world2d(R"("sleep_linear_tolerance": -1)"), "world.sleep_linear_tolerance = -1"},
          {world2d(R"("sleep_angular_tolerance": -1)"), "world.sleep_angular_tolerance = -1"},
          {world2d(R"("enable_sleep": "no")"), "world.enable_sleep: expected true or false"},
          {R"({"kind": "rigid2d", "materials": [1]})", "materials: expected an object of named materials"},
          {R"({"kind": "rigid2d", "materials": {"ice": {"density": -1}}})", "materials.ice.density = -1"},
          {R"({"kind": "rigid2d", "materials": {"ice": {"friction": -1}}})", "materials.ice.friction = -1"},
          {R"({"kind": "rigid2d", "materials": {"ice": {"restitution": 2}}})", "materials.ice.restitution = 2"},
          {R"({"kind": "rigid2d", "materials": {"ice": {"rolling_resistance": -1}}})",
           "materials.ice.rolling_resistance = -1"},
          {R"({"kind": "rigid2d", "materials": {"ice": {"colour": 1}}})", "materials.ice.colour: unknown key"},
          {body2d(R"("type": "wobbly")"), "bodies[0].type: unknown body type 'wobbly'"},
          {body2d(R"("position": [0])"), "bodies[0].position: expected an array of 2 numbers"},
          {body2d(R"("angle_deg": "up")"), "bodies[0].angle_deg: expected a number"},
          {body2d(R"("linear_velocity": [1e39, 0])"), "bodies[0].linear_velocity[0] = 1e+39"},
          // Finite but beyond the envelope: refused, not clamped or frozen in silence.
          {body2d(R"("position": [1e30, 1e30])"),
           "bodies[0].position.x = 1e+30: must be within 1e6 m of the world origin"},
          {body2d(R"("linear_velocity": [1e30, 0])"),
           "bodies[0].linear_velocity = 1e+30 m/s: must be at most the world's maxLinearSpeed, 400 m/s"},
          {world2d(R"("gravity": [0, -1e38])"), "world.gravity = 1e+38 m/s^2: must be at most 1e4 m/s^2"},
          {body2d(R"("angular_velocity": -1e39)"), "bodies[0].angular_velocity = -1e+39"},
          {body2d(R"("linear_damping": -1)"), "bodies[0].linear_damping = -1"},
          {body2d(R"("angular_damping": -1)"), "bodies[0].angular_damping = -1"},
          {body2d(R"("gravity_scale": 1e39)"), "bodies[0].gravity_scale = 1e+39"},
          {body2d(R"("fixed_rotation": 1)"), "bodies[0].fixed_rotation: expected true or false"},
          {body2d(R"("bullet": "y")"), "bodies[0].bullet: expected true or false"},
          {body2d(R"("awake": 0)"), "bodies[0].awake: expected true or false"},
          {body2d(R"("shapes": {})"), "bodies[0].shapes: expected an array of shapes"},
          {body2d(R"("shapes": [{"type": "circle", "radius": 1}], "mass_properties": {"mass": 0})"),
           "bodies[0].mass_properties.mass = 0"},
          {body2d(R"("shapes": [{"type": "circle", "radius": 1}], "mass_properties": {"mass": 1, "inertia": 0})"),
           "bodies[0].mass_properties.inertia = 0"},
          {body2d(
               R"("shapes": [{"type": "circle", "radius": 1}], "mass_properties": {"mass": 1, "center": [1e39, 0]})"),
           "bodies[0].mass_properties.center[0] = 1e+39"},
          {body2d(R"("mass_properties": {"mass": 1})"), "bodies[0].mass_properties.inertia: missing"},
          {body2d(R"("type": "static", "mass_properties": {"mass": 1})"),
           "bodies[0].mass_properties: only a dynamic body has a mass to set"},
      },
      "rw");
}

TEST(CliValidation, rigid2d_shapes) {
  expectSceneErrors(
      {
          {shape2d(R"("type": "blob")"), "bodies[0].shapes[0].type: unknown shape type 'blob'"},
          {shape2d(R"("radius": 1)"), "bodies[0].shapes[0].type: missing"},
          {shape2d(R"("type": "circle", "radius": 0)"), "bodies[0].shapes[0].radius = 0"},
          {shape2d(R"("type": "circle", "radius": -1)"), "bodies[0].shapes[0].radius = -1"},
          {shape2d(R"("type": "circle", "radius": 1, "center": [1e39, 0])"), "bodies[0].shapes[0].center[0] = 1e+39"},
          {shape2d(R"("type": "box", "half_extents": [1, 0])"), "bodies[0].shapes[0].half_extents[1] = 0"},
          // The file's words, not the library's (half_width, maxPolygonCoordinate).
          {shape2d(R"("type": "box", "half_extents": [1e7, 1])"),
           "bodies[0].shapes[0].half_extents[0] = 1e+07: must be within 1e6 m of the body origin"},
          {shape2d(R"("type": "box", "half_extents": [1, 1e-50])"), "bodies[0].shapes[0].half_extents[1] = 0"},
          {shape2d(R"("type": "polygon", "points": [[0, 0], [1, 1], [2, 2]])"),
           "bodies[0].shapes[0].points = 0: the points are collinear or coincident"},
          {shape2d(R"("type": "polygon", "points": [[0, 0], [1, 1]])"), "bodies[0].shapes[0].points: expected 3 to 8"},
          {shape2d(R"("type": "polygon", "points": [[0, 0], [1, 0], [0, 1]], "radius": -1)"),
           "bodies[0].shapes[0].radius = -1"},
          {shape2d(R"("type": "polygon", "points": [[0, 0], [1, 0], [0, "x"]])"),
           "bodies[0].shapes[0].points[2][1]: expected a number"},
          {shape2d(R"("type": "capsule", "center1": [0, 0], "center2": [0, 0], "radius": 1)"),
           "bodies[0].shapes[0].center2: must differ from center1"},
          {shape2d(R"("type": "capsule", "center1": [0, 0], "center2": [1, 0], "radius": 0)"),
           "bodies[0].shapes[0].radius = 0"},
          {shape2d(R"("type": "segment", "point1": [0, 0], "point2": [0, 0.001])", "static"),
           "bodies[0].shapes[0].point2: must differ from point1"},
          {shape2d(R"("type": "chain", "points": [[0, 0], [0, 0], [1, 0]])", "static"),
           "bodies[0].shapes[0].points[1] = 0: distance to points[0]"},
          {shape2d(R"("type": "chain", "points": [[0, 0]])", "static"), "bodies[0].shapes[0].points: expected 2 to"},
          {shape2d(R"("type": "chain", "loop": true, "points": [[0, 0], [1, 0]])", "static"),
           "bodies[0].shapes[0].points: expected 3 to"},
          {shape2d(R"("type": "circle", "radius": 1, "density": -1)"), "bodies[0].shapes[0].density = -1"},
          {shape2d(R"("type": "circle", "radius": 1, "density": 0)"),
           "bodies[0].shapes[0].density = 0: a shape on a dynamic body needs a positive density"},
          {shape2d(R"("type": "circle", "radius": 1, "friction": -1)"), "bodies[0].shapes[0].friction = -1"},
          {shape2d(R"("type": "circle", "radius": 1, "restitution": 2)"), "bodies[0].shapes[0].restitution = 2"},
          {shape2d(R"("type": "circle", "radius": 1, "rolling_resistance": -1)"),
           "bodies[0].shapes[0].rolling_resistance = -1"},
          {shape2d(R"("type": "circle", "radius": 1, "sensor": 1)"),
           "bodies[0].shapes[0].sensor: expected true or false"},
          {shape2d(R"("type": "circle", "radius": 1, "filter": {"mask": -1})"), "bodies[0].shapes[0].filter.mask = -1"},
          {shape2d(R"("type": "circle", "radius": 1, "filter": {"category": 1.5})"),
           "bodies[0].shapes[0].filter.category: expected a whole number"},
          {shape2d(R"("type": "circle", "radius": 1, "filter": {"group": 2147483648})"),
           "bodies[0].shapes[0].filter.group = 2147483648"},
          {shape2d(R"("type": "circle", "radius": 1, "material": "steel")"),
           "bodies[0].shapes[0].material: no material named 'steel'"},
      },
      "rs");
}

TEST(CliValidation, rigid2d_joints) {
  const auto pair = [](const std::string& type, const std::string& rest) {
    return joint2d(R"("type": ")" + type + R"(", "body_a": "ball", "body_b": "box")" + rest);
  };
  expectSceneErrors(
      {
          {joint2d(R"("type": "hinge", "body_a": "ground", "body_b": "ball")"), "joints[0].type: unknown joint type"},
          {joint2d(R"("type": "weld", "body_a": "ground", "body_b": "bal")"), "joints[0].body_b: no body named 'bal'"},
          {joint2d(R"("type": "weld", "body_a": "ball", "body_b": "ball")"),
           "joints[0].body_b: a joint needs two different bodies"},
          {joint2d(R"("type": "weld", "body_b": "ball")"), "joints[0].body_a: missing"},
          {pair("revolute", R"(, "anchor": [0, 3], "local_anchor_a": [0, 0])"),
           "joints[0].local_anchor_a: give at most one"},
          {pair("revolute", R"(, "anchor": [1e39, 3])"), "joints[0].anchor[0] = 1e+39"},
          {pair("revolute", R"(, "break_force": -1)"), "joints[0].break_force = -1"},
          {pair("revolute", R"(, "break_torque": -1)"), "joints[0].break_torque = -1"},
          {pair("revolute", R"(, "reference_angle_deg": "x")"), "joints[0].reference_angle_deg: expected a number"},
          {pair("revolute", R"(, "lower_angle_deg": 10, "upper_angle_deg": -10)"),
           "joints[0].upper_angle_deg = -10: must be >= lower_angle_deg (10)"},
          {pair("revolute", R"(, "enable_limit": true, "lower_angle_deg": -200, "upper_angle_deg": 10)"),
           "joints[0].lower_angle_deg = -200: must be in [-180, 180] degrees"},
          {pair("revolute", R"(, "enable_limit": true, "lower_angle_deg": 0, "upper_angle_deg": 190)"),
           "joints[0].upper_angle_deg = 190: must be in [-180, 180] degrees"},
          {pair("revolute", R"(, "max_motor_torque": -1)"), "joints[0].max_motor_torque = -1"},
          {pair("revolute", R"(, "motor_speed": 1e39)"), "joints[0].motor_speed = 1e+39"},
          {pair("revolute", R"(, "hertz": -1)"), "joints[0].hertz = -1"},
          {pair("revolute", R"(, "damping_ratio": -1)"), "joints[0].damping_ratio = -1"},
          {pair("revolute", R"(, "friction_torque": -1)"), "joints[0].friction_torque = -1"},
          {pair("prismatic", R"(, "axis": [0, 0])"), "joints[0].axis: must be non-zero"},
          {pair("prismatic", R"(, "axis": [1, 0], "local_axis_a": [1, 0])"), "joints[0].axis: give at most one"},
          {pair("prismatic", R"(, "lower_translation": 2, "upper_translation": 1)"),
           "joints[0].upper_translation = 1: must be >= lower_translation (2)"},
          {pair("prismatic", R"(, "max_motor_force": -1)"), "joints[0].max_motor_force = -1"},
          {pair("prismatic", R"(, "hertz": -1)"), "joints[0].hertz = -1"},
          {pair("distance", R"(, "length": 0)"), "joints[0].length = 0"},
          {joint2d(R"("type": "distance", "body_a": "ball", "body_b": "box", "anchor_a": [1, 3], "anchor_b": [1, 3])"),
           "joints[0].length: missing (the anchors start together"},
          {pair("distance", R"(, "min_length": -1)"), "joints[0].min_length = -1"},
          {pair("distance", R"(, "min_length": 2, "max_length": 1)"),
           "joints[0].max_length = 1: must be >= min_length"},
          {pair("distance", R"(, "max_motor_force": -1)"), "joints[0].max_motor_force = -1"},
          {pair("distance", R"(, "damping_ratio": -1)"), "joints[0].damping_ratio = -1"},
          {pair("weld", R"(, "linear_hertz": -1)"), "joints[0].linear_hertz = -1"},
          {pair("weld", R"(, "linear_damping_ratio": -1)"), "joints[0].linear_damping_ratio = -1"},
          {pair("weld", R"(, "angular_hertz": -1)"), "joints[0].angular_hertz = -1"},
          {pair("weld", R"(, "angular_damping_ratio": -1)"), "joints[0].angular_damping_ratio = -1"},
          {pair("wheel", R"(, "local_axis_a": [0, 0])"), "joints[0].local_axis_a: must be non-zero"},
          {pair("wheel", R"(, "hertz": -1)"), "joints[0].hertz = -1"},
          {pair("wheel", R"(, "max_motor_torque": -1)"), "joints[0].max_motor_torque = -1"},
          {pair("wheel", R"(, "lower_translation": 1, "upper_translation": -1)"),
           "joints[0].upper_translation = -1: must be >= lower_translation (1)"},
          {pair("motor", R"(, "max_force": -1)"), "joints[0].max_force = -1"},
          {pair("motor", R"(, "max_torque": -1)"), "joints[0].max_torque = -1"},
          {pair("motor", R"(, "correction_factor": 2)"), "joints[0].correction_factor = 2: must be in [0, 1]"},
          {pair("motor", R"(, "linear_offset": [1e39, 0])"), "joints[0].linear_offset[0] = 1e+39"},
          {joint2d(R"("type": "mouse", "body_b": "ball", "hertz": -1)"), "joints[0].hertz = -1"},
          {joint2d(R"("type": "mouse", "body_b": "ball", "max_force": -1)"), "joints[0].max_force = -1"},
          {joint2d(R"("type": "mouse", "body_b": "ball", "target": [0, 1e39])"), "joints[0].target[1] = 1e+39"},
          {joint2d(R"("type": "mouse", "hertz": 1)"), "joints[0].body_b: missing"},
          {joint2d(R"("type": "weld", "body_a": "ball", "body_b": "box", "name": "a,b")"),
           "joints[0].name: 'a,b' must not contain commas"},
      },
      "rj");
}

TEST(CliValidation, rigid2d_effectors) {
  expectSceneErrors(
      {
          {effector2d(R"("type": "vortex")"), "effectors[0].type: unknown effector type 'vortex'"},
          {effector2d(R"("type": "gravity_field")"), "effectors[0].acceleration: missing"},
          {effector2d(R"("type": "gravity_field", "acceleration": [0, 1], "region": {"min": [0, 0], "max": [-1, 1]})"),
           "effectors[0].region.max: must be >= min in both components"},
          {effector2d(R"("type": "gravity_field", "acceleration": [0, 1], "start": -1)"), "effectors[0].start = -1"},
          {effector2d(R"("type": "gravity_field", "acceleration": [0, 1], "start": 2, "stop": 1)"),
           "effectors[0].stop = 1: must be >= start"},
          {effector2d(R"("type": "point_attractor", "center": [0, 0])"), "effectors[0].mu: missing"},
          {effector2d(R"("type": "point_attractor", "center": [0, 0], "mu": 1, "softening": -1)"),
           "effectors[0].softening = -1"},
          {effector2d(R"("type": "point_attractor", "center": [0, 0], "mu": 1, "max_radius": 0)"),
           "effectors[0].max_radius = 0"},
          {effector2d(R"("type": "wind_drag", "body": "ball", "air_density": -1)"), "effectors[0].air_density = -1"},
          {effector2d(R"("type": "wind_drag", "body": "ball", "drag_area": -1)"), "effectors[0].drag_area = -1"},
          {effector2d(R"("type": "wind_drag", "body": "ball", "linear_drag": -1)"), "effectors[0].linear_drag = -1"},
          {effector2d(R"("type": "wind_drag", "body": "nobody")"), "effectors[0].body: no body named 'nobody'"},
          {effector2d(R"("type": "thruster", "body": "ball", "thrust": 1, "local_direction": [0, 0])"),
           "effectors[0].local_direction: must be non-zero"},
          {effector2d(R"("type": "thruster", "body": "ball")"), "effectors[0].thrust: missing"},
          {effector2d(R"("type": "thruster", "body": "ball", "thrust": 1e39)"), "effectors[0].thrust = 1e+39"},
          {effector2d(R"("type": "spring_damper", "body_a": "ball", "body_b": "box", "stiffness": -1)"),
           "effectors[0].stiffness = -1"},
          {effector2d(R"("type": "spring_damper", "body_a": "ball", "body_b": "box", "damping": -1)"),
           "effectors[0].damping = -1"},
          {effector2d(R"("type": "spring_damper", "body_a": "ball", "body_b": "box", "rest_length": -1)"),
           "effectors[0].rest_length = -1"},
          {effector2d(R"("type": "spring_damper", "body_a": "ball", "body_b": "ball")"),
           "effectors[0].body_b: a spring needs two different bodies"},
          {effector2d(R"("type": "spring_damper", "body_a": "ball")"), "effectors[0].anchor_b: missing"},
          {effector2d(R"("type": "explosion", "center": [0, 0], "radius": 0)"), "effectors[0].radius = 0"},
          {effector2d(R"("type": "explosion", "center": [0, 0], "radius": 1, "impulse": -1)"),
           "effectors[0].impulse = -1"},
          {effector2d(R"("type": "buoyancy")"), "effectors[0].surface_height: missing"},
          {effector2d(R"("type": "buoyancy", "surface_height": 0, "x_min": 1, "x_max": 0)"),
           "effectors[0].x_max = 0: must be >= x_min"},
          {effector2d(R"("type": "buoyancy", "surface_height": 0, "fluid_density": 0)"),
           "effectors[0].fluid_density = 0"},
          {effector2d(R"("type": "buoyancy", "surface_height": 0, "linear_drag": -1)"),
           "effectors[0].linear_drag = -1"},
          {effector2d(R"("type": "buoyancy", "surface_height": 0, "angular_drag": -1)"),
           "effectors[0].angular_drag = -1"},
      },
      "re");
}

// The valid boundary values of both formats load and run.
TEST(CliValidation, boundary_values_are_accepted) {
  const std::vector<std::string> scenes = {
      R"({"world": {"linear_drag": 0, "air_density": 0, "rest_threshold": 0, "particle_restitution": 1, "substeps": 1},
          "particles": [{"position": [0, 0, 0], "velocity": [0, 0, 0], "pinned": true}],
          "emitters": [{"position": [0, 0, 0], "cone_angle_deg": 0, "min_speed": 0, "max_speed": 0, "burst": 0}]})",
      rigid(R"(, "world": {"contact_hertz": 0, "joint_hertz": 0, "restitution_threshold": 0, "time_to_sleep": 0},
          "joints": [{"type": "revolute", "body_a": "ball", "body_b": "box", "enable_limit": true,
                      "lower_angle_deg": -180, "upper_angle_deg": 180, "break_force": 0},
                     {"type": "distance", "body_a": "ground", "body_b": "ball", "min_length": 0},
                     {"type": "motor", "body_a": "ground", "body_b": "box", "correction_factor": 0, "max_force": 0}],
          "effectors": [{"type": "explosion", "center": [0, 0], "radius": 1, "impulse": 0, "start": 0, "stop": 0}])"),
      shape2d(R"("type": "circle", "radius": 1, "density": 0, "friction": 0, "restitution": 1)", "static"),
  };
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    SCOPED_TRACE(scenes[i]);
    const CliRun run = impetus({"run", writeTemp("ok" + std::to_string(i) + ".json", scenes[i]), "--steps", "2"});
    EXPECT_EQ(run.status, 0) << run.err;
  }
}

// impetus calc ----------------------------------------------------------------------------------

/// A valid invocation of every model with required parameters (the others run on defaults).
const std::map<std::string, std::vector<std::string>> baselines = {
    // GPS and geodesy, sound (docs/digital-physics.md's examples).
    {"great-circle", {"--from", "40.71,-74.01", "--to", "51.51,-0.13"}},
    {"destination", {"--from", "40.71,-74.01", "--bearing", "51", "--distance", "1000000"}},
    {"cross-track", {"--start", "0,0", "--end", "0,40", "--point", "1,10"}},
    {"rhumb-line", {"--from", "40.71,-74.01", "--to", "51.51,-0.13"}},
    {"vincenty", {"--from", "40.71,-74.01", "--to", "51.51,-0.13"}},
    {"geodesic", {"--from", "40.71,-74.01", "--to", "51.51,-0.13"}},
    {"ecef", {"--position", "48.8584,2.2945"}},
    {"geodetic", {"--ecef", "4200958.827,168324.024,4780239.4"}},
    {"trilaterate", {"--centres", "0,0,0 10,0,0 4,8,0", "--ranges", "7.0711 9.4868 6.4807"}},
    {"gps-fix",
     {"--dimensions", "2", "--satellites", "0,0 10,0 4,8", "--pseudoranges", "5.5 8.5622577483 4.6231056256",
      "--speed-of-light", "1"}},
    {"distance-gain", {"--distance", "20"}},
    {"echo", {"--distance", "171.65"}},
    {"reflection", {"--source", "0,2,0", "--listener", "4,2,0"}},
    {"inertia-solid-sphere", {"--mass", "2", "--radius", "0.5"}},
    {"inertia-spherical-shell", {"--mass", "2", "--radius", "0.5"}},
    {"inertia-hollow-sphere", {"--mass", "1", "--inner-radius", "1", "--outer-radius", "2"}},
    {"inertia-solid-cylinder", {"--mass", "1", "--radius", "1", "--length", "2"}},
    {"inertia-cylindrical-shell", {"--mass", "1", "--radius", "1", "--length", "2"}},
    {"inertia-hollow-cylinder", {"--mass", "1", "--inner-radius", "1", "--outer-radius", "2", "--length", "2"}},
    {"inertia-box", {"--mass", "1", "--size-x", "1", "--size-y", "2", "--size-z", "3"}},
    {"inertia-rod", {"--mass", "1", "--length", "2"}},
    {"inertia-solid-cone", {"--mass", "1", "--radius", "1", "--height", "2"}},
    {"parallel-axis", {"--inertia", "1", "--mass", "2", "--distance", "3"}},
    {"polygon", {"--vertices", "0,0 3,0 0,4"}},
    {"constant-acceleration", {"--initial-velocity", "1", "--acceleration", "2", "--time", "3"}},
    {"quadratic-drag-motion",
     {"--initial-velocity", "10", "--drag-per-unit-mass", "0.1", "--time", "2", "--position", "5"}},
    {"angular-motion", {"--angular-acceleration", "1", "--time", "2"}},
    {"circular-motion", {"--radius", "1", "--angular-velocity", "2"}},
    {"point-on-rotating-body", {"--angular-velocity", "0,0,1", "--offset", "1,0,0"}},
    {"gravitation", {"--mass1", "1", "--mass2", "2", "--distance", "3"}},
    {"weight", {"--mass", "1"}},
    {"drag-force", {"--velocity", "10,0,0", "--area", "0.5", "--drag-coefficient", "0.47"}},
    {"ideal-drag-force", {"--velocity", "10,0,0", "--drag-constant", "0.1"}},
    {"pressure-force", {"--pressure", "1e5", "--area", "2"}},
    {"hydrostatic-pressure", {"--depth", "2"}},
    {"buoyancy", {"--body-density", "500"}},
    {"spring-damper", {"--stiffness", "10", "--rest-length", "1", "--position1", "0,0,0", "--position2", "2,0,0"}},
    {"torque", {"--arm", "1,0,0", "--force", "0,1,0"}},
    {"friction", {"--mass", "10", "--push-force", "20", "--static-coefficient", "0.5", "--kinetic-coefficient", "0.4"}},
    {"incline", {"--incline-angle-deg", "20", "--static-coefficient", "0.5", "--kinetic-coefficient", "0.4"}},
    {"angle-of-repose", {"--static-coefficient", "0.5"}},
    {"ship", {"--thrust", "1000", "--mass", "500", "--resistance-coefficient", "10", "--time", "5"}},
    {"box-tipping",
     {"--mass", "10", "--width", "1", "--height", "2", "--push-height", "1", "--static-coefficient", "0.5",
      "--kinetic-coefficient", "0.4"}},
    {"impulse", {"--mass", "1", "--velocity-after", "2", "--duration", "0.1"}},
    {"restitution", {"--v1-before", "2", "--v2-before", "0", "--v1-after", "0", "--v2-after", "1"}},
    {"restitution-bounce", {"--drop-height", "2", "--bounce-height", "1"}},
    {"impact-1d", {"--mass1", "1", "--velocity1", "2", "--mass2", "3", "--velocity2", "-1", "--restitution", "0.5"}},
    {"impact-spheres-2d",
     {"--mass1", "1", "--velocity1-x", "2", "--velocity1-y", "0", "--mass2", "1", "--normal-angle-deg", "30",
      "--restitution", "0.9"}},
    {"rigid-impact-2d", {"--mass1",       "1",    "--inertia1",         "0.1", "--velocity1-x", "2",
                         "--velocity1-y", "0",    "--offset1-x",        "0.1", "--offset1-y",   "0.1",
                         "--mass2",       "1",    "--inertia2",         "0.1", "--offset2-x",   "-0.1",
                         "--offset2-y",   "-0.1", "--normal-angle-deg", "0",   "--restitution", "0.5"}},
    {"projectile", {"--speed", "20", "--angle-deg", "30"}},
    {"terminal-velocity", {"--weight", "700", "--area", "0.7"}},
    {"reynolds-number", {"--speed", "10", "--length", "0.1"}},
    {"sphere-drag-coefficient", {"--reynolds", "1e5"}},
    {"magnus-force", {"--speed", "40", "--spin-rpm", "2000"}},
    {"ball-flight", {"--speed", "40", "--angle-deg", "30"}},
    {"rocket",
     {"--initial-mass", "1000", "--propellant-mass", "800", "--burn-rate", "10", "--exhaust-velocity", "3000"}},
    {"rifle-shot", {"--distance", "100", "--muzzle-speed", "800"}},
    {"aim", {"--distance", "10", "--speed", "20"}},
    {"minimum-launch-speed", {"--distance", "10"}},
    {"lorentz-factor", {"--speed", "1e7"}},
};

/// Parameters that hold words, files or point lists rather than numbers.
bool nonNumeric(const std::string& name) {
  for (const char* word :
       {"vertices", "material", "method", "scheme", "law", "drag-model", "lift-model", "wind-model", "file"}) {
    if (name == word) {
      return true;
    }
  }
  return false;
}

/// The parameters where +infinity means something (an immovable body, no rotation).
bool infinityAllowed(const std::string& model, const std::string& param) {
  const std::set<std::pair<std::string, std::string>> allowed = {
      {"impact-1d", "mass1"},         {"impact-1d", "mass2"},          {"impact-spheres-2d", "mass1"},
      {"impact-spheres-2d", "mass2"}, {"rigid-impact-2d", "mass1"},    {"rigid-impact-2d", "inertia1"},
      {"rigid-impact-2d", "mass2"},   {"rigid-impact-2d", "inertia2"},
  };
  return allowed.contains({model, param});
}

// Every number a model reads (scalar or a vector's component) refuses NaN and both infinities
// with one line naming the parameter and the value; +infinity only where it means something.
TEST(CliValidation, every_calc_parameter_refuses_nan_and_infinity) {
  const json models = json::parse(impetus({"calc", "--list", "--json"}).out);
  int probed = 0;
  for (const json& m : models) {
    const std::string name = m.at("name").get<std::string>();
    const auto known = baselines.find(name);
    const bool needsInput = std::any_of(m.at("params").begin(), m.at("params").end(),
                                        [](const json& p) { return p.at("required").get<bool>(); });
    if (needsInput && known == baselines.end()) {
      EXPECT_EQ(name, "composite") << name << " has required parameters but no baseline here";
      continue;
    }
    const std::vector<std::string> base = known != baselines.end() ? known->second : std::vector<std::string>{};
    {
      std::vector<std::string> args{"calc", name};
      args.insert(args.end(), base.begin(), base.end());
      const CliRun ok = impetus(args);
      ASSERT_EQ(ok.status, 0) << name << ": " << ok.err;
    }
    for (const json& p : m.at("params")) {
      const std::string param = p.at("name").get<std::string>();
      const std::string fallback = p.at("default").is_string() ? p.at("default").get<std::string>() : "";
      const auto given = std::find(base.begin(), base.end(), "--" + param);
      // Words and files are not numbers; an optional number left out selects what the model
      // computes (constant-acceleration's three knowns), so only the given ones are probed.
      if (nonNumeric(param) || (given == base.end() && fallback.empty())) {
        continue;
      }
      const std::string valid = given != base.end() ? *(given + 1) : fallback;
      // A vector ("x,y,z") or a list ("a b c", "x,y x,y") gets the bad value in its first number.
      const std::size_t firstEnd = valid.find_first_of(", ");
      const bool vector = firstEnd != std::string::npos;
      for (const std::string bad : {"nan", "inf", "-inf"}) {
        std::vector<std::string> args{"calc", name};
        for (std::size_t i = 0; i < base.size(); i += 2) {
          if (base[i] != "--" + param) {
            args.push_back(base[i]);
            args.push_back(base[i + 1]);
          }
        }
        args.push_back("--" + param);
        args.push_back(vector ? bad + valid.substr(firstEnd) : bad);
        SCOPED_TRACE(name + " --" + param + " " + args.back());
        const CliRun run = impetus(args);
        ++probed;
        if (bad == "inf" && infinityAllowed(name, param)) {
          EXPECT_EQ(run.status, 0) << run.err;
          continue;
        }
        EXPECT_EQ(run.status, 2) << run.out;
        EXPECT_NE(run.err.find("--" + param), std::string::npos) << run.err;
        EXPECT_NE(run.err.find(bad), std::string::npos) << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
      }
    }
  }
  EXPECT_GE(probed, 600);
}

// Negative and degenerate values of the calc models that have them: one line naming the
// parameter (as the user typed it) and the value.
TEST(CliValidation, calc_parameters_refuse_values_without_physical_meaning) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"inertia-solid-sphere", "--mass", "-1", "--radius", "1"}, "--mass = -1"},
      {{"inertia-solid-sphere", "--mass", "1", "--radius", "-1"}, "--radius = -1"},
      {{"inertia-hollow-sphere", "--mass", "1", "--inner-radius", "3", "--outer-radius", "2"}, "--inner-radius = 3"},
      {{"inertia-box", "--mass", "1", "--size-x", "-1", "--size-y", "1", "--size-z", "1"}, "--size-x = -1"},
      {{"parallel-axis", "--inertia", "-1", "--mass", "1", "--distance", "1"}, "--inertia = -1"},
      {{"polygon", "--vertices", "0,0 1,1 2,2"}, "degenerate"},
      {{"polygon", "--vertices", "0,0 1,0 0,1", "--density", "0"}, "--density = 0"},
      {{"constant-acceleration", "--initial-velocity", "1", "--acceleration", "2", "--time", "-1"}, "--time = -1"},
      {{"constant-acceleration", "--initial-velocity", "1", "--acceleration", "2"}, "give exactly three of"},
      {{"quadratic-drag-motion", "--initial-velocity", "1", "--drag-per-unit-mass", "-1", "--time", "1"},
       "--drag-per-unit-mass = -1"},
      {{"circular-motion", "--radius", "-1", "--angular-velocity", "1"}, "--radius = -1"},
      {{"gravitation", "--mass1", "1", "--mass2", "1", "--distance", "0"}, "--distance = 0"},
      {{"weight", "--mass", "-2"}, "--mass = -2"},
      {{"drag-force", "--velocity", "1,0,0", "--area", "-1", "--drag-coefficient", "1"}, "--area = -1"},
      {{"buoyancy", "--body-density", "-1"}, "--body-density = -1"},
      {{"spring-damper", "--stiffness", "-1", "--rest-length", "1", "--position1", "0,0,0", "--position2", "1,0,0"},
       "--stiffness = -1"},
      {{"friction", "--mass", "0", "--push-force", "1", "--static-coefficient", "0.5", "--kinetic-coefficient", "0.4"},
       "--mass = 0"},
      {{"friction", "--mass", "1", "--push-force", "1", "--static-coefficient", "0.5", "--kinetic-coefficient", "0.6"},
       "--kinetic-coefficient = 0.6"},
      {{"ship", "--thrust", "1", "--mass", "0", "--resistance-coefficient", "1", "--time", "1"}, "--mass = 0"},
      {{"box-tipping", "--mass", "1", "--width", "1", "--height", "1", "--push-height", "2", "--static-coefficient",
        "0.5", "--kinetic-coefficient", "0.4"},
       "--push-height = 2"},
      {{"impulse", "--mass", "1", "--velocity-after", "1", "--duration", "0"}, "--duration = 0"},
      {{"restitution-bounce", "--drop-height", "1", "--bounce-height", "2"}, "--bounce-height = 2"},
      {{"impact-1d", "--mass1", "1", "--velocity1", "1", "--mass2", "1", "--velocity2", "0", "--restitution", "1.5"},
       "--restitution = 1.5"},
      {{"projectile", "--speed", "-1", "--angle-deg", "30"}, "--speed = -1"},
      {{"terminal-velocity", "--weight", "1", "--area", "0"}, "--area = 0"},
      {{"reynolds-number", "--speed", "1", "--length", "0"}, "--length = 0"},
      {{"rocket", "--initial-mass", "100", "--propellant-mass", "100", "--burn-rate", "1", "--exhaust-velocity", "1"},
       "--propellant-mass = 100"},
      {{"rifle-shot", "--distance", "-1", "--muzzle-speed", "800"}, "--distance = -1"},
      {{"lorentz-factor", "--speed", "3e8"}, "--speed = 3e+08"},
      {{"explosion", "--count", "-1"}, "--count = -1"},
      {{"gps-clock", "--ground-radius", "0"}, "--ground-radius = 0"},
      {{"integrate-ship", "--time-step", "0"}, "--time-step = 0"},
      {{"adaptive-step", "--tolerance", "-1"}, "--tolerance = -1"},
      {{"oscillator-stability", "--steps", "0"}, "--steps = 0"},
      {{"cannon", "--muzzle-speed", "-1"}, "--muzzle-speed = -1"},
      {{"cannon2", "--mass", "0"}, "--mass = 0"},
  };
  for (const auto& [args, needle] : cases) {
    std::vector<std::string> full{"calc"};
    full.insert(full.end(), args.begin(), args.end());
    SCOPED_TRACE(args[0] + " -> " + needle);
    expectUsageError(impetus(full), needle);
  }
}

// Inputs valid one by one whose result overflows double, or that take an explicit method far
// past its stability limit, are refused naming the output (the fuzzer's finding 8: they printed
// inf and nan); a shell without drag has no terminal velocity, so none is printed.
TEST(CliValidation, calc_refuses_results_that_are_not_finite) {
  expectUsageError(impetus({"calc", "weight", "--mass", "1e308"}), "weight = inf");
  expectUsageError(impetus({"calc", "inertia-solid-sphere", "--mass", "1e308", "--radius", "1e308"}), "= inf");
  const CliRun unstable = impetus({"calc", "integrate-ship", "--mass", "1e-6"});
  EXPECT_EQ(unstable.status, 2) << unstable.out;
  EXPECT_NE(unstable.err.find("not finite"), std::string::npos) << unstable.err;
  const CliRun noDrag = impetus({"calc", "cannon2", "--drag-coefficient", "0"});
  EXPECT_EQ(noDrag.status, 0) << noDrag.err;
  EXPECT_EQ(noDrag.out.find("terminal_velocity"), std::string::npos) << noDrag.out;
  EXPECT_NE(noDrag.out.find("no terminal velocity"), std::string::npos) << noDrag.out;
}

} // namespace
