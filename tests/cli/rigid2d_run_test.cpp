// Black-box tests of `impetus run` on 2D rigid-body scenes ("kind": "rigid2d",
// docs/scene-format-2d.md): every shipped scene runs 10 s with finite output, a falling body
// follows the closed form of the soft step's integrator, Newton's cradle passes momentum along,
// the bumper cars keep their momentum, floating boxes settle at Archimedes' depth, effector time
// windows and joint anchors do what the page says, the output files have the documented layouts,
// and every bad scene exits 2 with one line that starts with the JSON path.
#include "cli_process.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

using impetus::testing::CliRun;
using impetus::testing::expectUsageError;
using impetus::testing::impetus;

std::string tempPath(const std::string& name) {
  return ::testing::TempDir() + "impetus_rigid2d_" + ::testing::UnitTest::GetInstance()->current_test_info()->name() +
         "_" + name;
}

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = tempPath(name);
  std::ofstream(path) << text;
  return path;
}

const std::string csvHeader = "step,time,body,name,x,y,angle,vx,vy,w,kinetic,potential";

/// One CSV row: the numbers, and the body's name (column 3).
struct Row {
  std::vector<double> v;
  std::string name;
};
enum Column { step, time, body, name, x, y, angle, vx, vy, w, kinetic, potential };

std::vector<Row> readCsv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, csvHeader);
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    Row row;
    std::stringstream fields(line);
    std::string field;
    int column = 0;
    while (std::getline(fields, field, ',')) {
      if (column == name) {
        row.name = field;
        row.v.push_back(0.0);
      } else {
        std::size_t used = 0;
        row.v.push_back(std::stod(field, &used));
        EXPECT_EQ(used, field.size()) << line;
      }
      ++column;
    }
    EXPECT_EQ(row.v.size(), 12u) << line;
    rows.push_back(row);
  }
  return rows;
}

/// rows[step][body name]
std::map<int, std::map<std::string, std::vector<double>>> byStep(const std::vector<Row>& rows) {
  std::map<int, std::map<std::string, std::vector<double>>> out;
  for (const Row& r : rows) {
    out[static_cast<int>(r.v[step])][r.name] = r.v;
  }
  return out;
}

std::vector<std::filesystem::path> shippedScenes() {
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(IMPETUS_SOURCE_DIR "/scenes/rigid2d")) {
    if (entry.path().extension() == ".json") {
      scenes.push_back(entry.path());
    }
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

std::string scene(const std::string& file) { return std::string(IMPETUS_SOURCE_DIR "/scenes/rigid2d/") + file; }

TEST(Rigid2dRun, every_shipped_scene_runs_ten_seconds_with_finite_output) {
  const auto scenes = shippedScenes();
  ASSERT_GE(scenes.size(), 8u);
  for (const char* required :
       {"pyramid", "chain", "bridge", "newtons_cradle", "ragdoll", "car", "buoyancy", "ch10_bumper_cars"}) {
    EXPECT_TRUE(std::filesystem::exists(scene(std::string(required) + ".json"))) << required;
  }
  for (const auto& file : scenes) {
    SCOPED_TRACE(file.string());
    const std::string out = tempPath(file.stem().string() + ".csv");
    const CliRun run = impetus({"run", file.string(), "--steps", "600", "--every", "60", "--out", out});
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_TRUE(run.err.empty()) << run.err;
    EXPECT_NE(run.out.find("600 steps"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("(10 s simulated"), std::string::npos) << run.out;
    const auto rows = readCsv(out);
    ASSERT_FALSE(rows.empty());
    std::map<double, int> perStep;
    for (const Row& row : rows) {
      for (const double v : row.v) {
        ASSERT_TRUE(std::isfinite(v));
      }
      ++perStep[row.v[step]];
    }
    ASSERT_EQ(perStep.size(), 11u); // 0, 60, ..., 600
    for (const auto& [s, n] : perStep) {
      EXPECT_EQ(n, perStep.begin()->second) << "every recorded step has every body, step " << s;
    }
  }
}

/// One body, no ground: free fall with a horizontal velocity.
const char* fallingScene = R"({"kind": "rigid2d", "description": "a falling ball",
  "world": {"gravity": [0, -9.81], "substeps": 4},
  "bodies": [{"name": "ball", "position": [1, 100], "linear_velocity": [3, 4], "angular_velocity": 2,
              "shapes": [{"type": "circle", "radius": 0.5, "density": 2}]},
             {"name": "floating", "position": [-5, 10], "gravity_scale": 0,
              "shapes": [{"type": "box", "half_extents": [1, 0.5]}]}]})";

TEST(Rigid2dRun, free_fall_matches_the_closed_form_of_the_substepped_integrator) {
  // Semi-implicit Euler at the substep h = dt / 4: after n substeps y = y0 + v0 t - g t^2 / 2 -
  // g h t / 2 (the first-order lag), x and the spin exact.
  const std::string path = writeTemp("fall.json", fallingScene);
  const std::string out = tempPath("fall.csv");
  const CliRun run = impetus({"run", path, "--steps", "120", "--every", "10", "--out", out});
  ASSERT_EQ(run.status, 0) << run.err;
  const auto steps = byStep(readCsv(out));
  ASSERT_EQ(steps.size(), 13u);
  const double g = 9.81;
  const double h = 1.0 / 240.0;
  const double m = 2.0 * M_PI * 0.25;
  for (const auto& [s, bodies] : steps) {
    const auto& ball = bodies.at("ball");
    const double t = ball[time];
    EXPECT_NEAR(t, s / 60.0, 1e-6);
    EXPECT_EQ(ball[body], 0.0);
    EXPECT_NEAR(ball[x], 1.0 + 3.0 * t, 1e-4);
    EXPECT_NEAR(ball[y], 100.0 + 4.0 * t - 0.5 * g * t * t - 0.5 * g * h * t, 2e-4);
    EXPECT_NEAR(ball[vx], 3.0, 1e-5);
    EXPECT_NEAR(ball[vy], 4.0 - g * t, 1e-4);
    EXPECT_NEAR(ball[angle], std::remainder(2.0 * t, 2.0 * M_PI), 1e-4);
    EXPECT_NEAR(ball[kinetic], 0.5 * m * (9.0 + std::pow(4.0 - g * t, 2)) + 0.5 * (0.5 * m * 0.25) * 4.0,
                1e-3 * ball[kinetic]);
    EXPECT_NEAR(ball[potential], m * g * ball[y], 1e-4 * ball[potential]);
    // gravity_scale 0: it stays where it is.
    const auto& still = bodies.at("floating");
    EXPECT_EQ(still[body], 1.0);
    EXPECT_DOUBLE_EQ(still[x], -5.0);
    EXPECT_DOUBLE_EQ(still[y], 10.0);
  }
  EXPECT_GT(0.5 * g * h * 2.0, 0.02); // the lag at 2 s is far above the tolerance
}

TEST(Rigid2dRun, newtons_cradle_passes_the_momentum_to_the_last_ball) {
  const std::string out = tempPath("cradle.csv");
  const std::string events = tempPath("cradle_events.csv");
  const CliRun run = impetus({"run", scene("newtons_cradle.json"), "--steps", "150", "--out", out, "--events", events});
  ASSERT_EQ(run.status, 0) << run.err;
  const auto steps = byStep(readCsv(out));
  // The first impact: the step in which ball0 stops moving right.
  int impact = -1;
  double speed = 0.0;
  for (const auto& [s, bodies] : steps) {
    if (bodies.at("ball0")[vx] > speed) {
      speed = bodies.at("ball0")[vx];
    } else if (speed > 1.0 && bodies.at("ball0")[vx] < 0.5 * speed) {
      impact = s;
      break;
    }
  }
  ASSERT_GT(impact, 0);
  // Released from 40 degrees on 5 m: v = sqrt(2 g L (1 - cos 40)) = 4.79 m/s at the bottom.
  EXPECT_NEAR(speed, std::sqrt(2.0 * 9.81 * 5.0 * (1.0 - std::cos(40.0 * M_PI / 180.0))), 0.05);
  // A quarter of a second after the first impact (the four are over): only the last ball moves,
  // with all but what its swing up has cost it of the first ball's speed.
  const auto& after = steps.at(impact + 15);
  EXPECT_GT(after.at("ball4")[vx], 0.9 * speed);
  for (const char* still : {"ball0", "ball1", "ball2", "ball3"}) {
    EXPECT_LT(std::abs(after.at(still)[vx]), 0.05 * speed) << still;
  }
  // Each collision of the row is a hit in the events file.
  std::ifstream in(events);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "step,time,event,body_a,name_a,body_b,name_b,x,y,normal_x,normal_y,speed,joint,force,torque");
  std::set<std::string> hitPairs;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) {
      f.push_back(field);
    }
    if (f.size() > 11 && f[2] == "hit") {
      hitPairs.insert(f[4] + "-" + f[6]);
      EXPECT_GT(std::stod(f[11]), 4.0) << line;
    }
  }
  EXPECT_EQ(hitPairs, (std::set<std::string>{"ball0-ball1", "ball1-ball2", "ball2-ball3", "ball3-ball4"}));
}

TEST(Rigid2dRun, bumper_cars_keep_their_momentum_with_both_solvers) {
  // Craft 1 (100 kg, 8 m/s along x) hits the middle of craft 2's side (100 kg, 2 m/s down),
  // e = 0.5, no friction: along x, v1' = (1 - e) / 2 8 = 2 m/s and v2' = (1 + e) / 2 8 = 6 m/s.
  for (const char* file : {"ch10_bumper_cars.json", "ch10_bumper_cars_soft.json"}) {
    SCOPED_TRACE(file);
    const bool book = std::string(file) == "ch10_bumper_cars.json";
    const std::string out = tempPath("cars.csv");
    const CliRun run = impetus({"run", scene(file), "--steps", "600", "--every", "600", "--out", out});
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.out.find(book ? "book solver" : "soft-step solver"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("1 contact begin,"), std::string::npos) << run.out;
    const auto steps = byStep(readCsv(out));
    const auto& start = steps.at(0);
    const auto& end = steps.at(600);
    // Momentum: (800, -200) kg m/s before and after the crash.
    for (const Column c : {vx, vy}) {
      EXPECT_NEAR(100.0 * (end.at("craft1")[c] + end.at("craft2")[c]),
                  100.0 * (start.at("craft1")[c] + start.at("craft2")[c]), 0.1);
    }
    EXPECT_NEAR(start.at("craft1")[kinetic] + start.at("craft2")[kinetic], 3400.0, 1e-3);
    const double after = end.at("craft1")[kinetic] + end.at("craft2")[kinetic];
    // The closed form, 1200 J lost: the book's one impulse at one point of the face, and the soft
    // step's impact at both points of the face as a block (solved one after the other on craft
    // 1's light, 500 kg m^2 hull, they set it spinning).
    EXPECT_NEAR(end.at("craft1")[vx], 2.0, 0.01);
    EXPECT_NEAR(end.at("craft2")[vx], 6.0, 0.01);
    EXPECT_NEAR(end.at("craft2")[vy], -2.0, 1e-4);
    EXPECT_NEAR(after, 2200.0, 5.0);
    EXPECT_LT(std::abs(end.at("craft1")[w]), book ? 1e-6 : 0.02); // the soft contact's spring: 0.01 rad/s
  }
}

TEST(Rigid2dRun, floating_boxes_settle_at_the_depth_archimedes_predicts) {
  const std::string out = tempPath("buoyancy.csv");
  const CliRun run = impetus({"run", scene("buoyancy.json"), "--steps", "600", "--every", "600", "--out", out});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("1 effector"), std::string::npos) << run.out;
  const auto steps = byStep(readCsv(out));
  const auto& end = steps.at(600);
  // A 2 m x 1 m box of density rho in water of 1000 kg/m^2 floats level with rho / 1000 of its
  // height under: its centre at y = 0.5 - rho / 1000.
  for (const auto& [box, density] : std::map<std::string, double>{{"box250", 250}, {"box500", 500}, {"box750", 750}}) {
    EXPECT_NEAR(end.at(box)[y], 0.5 - density / 1000.0, 0.02) << box;
    EXPECT_NEAR(end.at(box)[vy], 0.0, 0.01) << box;
  }
  EXPECT_NEAR(end.at("box1500")[y], -5.5, 0.05); // sunk to the floor of the tank (y = -6)
}

TEST(Rigid2dRun, effectors_act_only_in_their_time_window) {
  // A 1 kg body pushed by 10 N from 0.5 s to 1 s: 5 m/s afterwards.
  const std::string path = writeTemp("thrust.json", R"({"kind": "rigid2d", "world": {"gravity": [0, 0]},
    "bodies": [{"name": "puck", "shapes": [{"type": "box", "half_extents": [0.5, 0.5], "density": 1}]}],
    "effectors": [{"type": "thruster", "body": "puck", "thrust": 10, "start": 0.5, "stop": 1}]})");
  const std::string out = tempPath("thrust.csv");
  const CliRun run = impetus({"run", path, "--steps", "120", "--every", "30", "--out", out});
  ASSERT_EQ(run.status, 0) << run.err;
  const auto steps = byStep(readCsv(out));
  EXPECT_DOUBLE_EQ(steps.at(30).at("puck")[vx], 0.0);
  EXPECT_NEAR(steps.at(60).at("puck")[vx], 5.0, 1e-4);
  EXPECT_NEAR(steps.at(120).at("puck")[vx], 5.0, 1e-4);
}

TEST(Rigid2dRun, a_conveyor_carries_its_crates_at_its_speed_and_filtered_boxes_pass_through) {
  const std::string out = tempPath("conveyor.csv");
  const CliRun run = impetus({"run", scene("conveyor.json"), "--steps", "180", "--every", "180", "--out", out});
  ASSERT_EQ(run.status, 0) << run.err;
  const auto steps = byStep(readCsv(out));
  const auto& end = steps.at(180);
  // After 3 s the crates ride at the belt's 2 m/s (friction 0.8 brings them there within 0.3 s).
  for (const char* crate : {"crate1", "crate2"}) {
    EXPECT_NEAR(end.at(crate)[vx], 2.0, 0.02) << crate;
    EXPECT_NEAR(end.at(crate)[vy], 0.0, 0.01) << crate;
  }
  // The filter joint's boxes ignore each other: both rest on the belt (centres 0.5 m up), riding.
  for (const char* ghost : {"ghost_low", "ghost_high"}) {
    EXPECT_NEAR(end.at(ghost)[y], 0.5, 0.02) << ghost;
    EXPECT_NEAR(end.at(ghost)[vx], 2.0, 0.02) << ghost;
  }
}

TEST(Rigid2dRun, the_chain_hangs_together_at_its_joints) {
  const std::string out = tempPath("chain.csv");
  const CliRun run = impetus({"run", scene("chain.json"), "--steps", "600", "--every", "100", "--out", out});
  ASSERT_EQ(run.status, 0) << run.err;
  for (const auto& [s, bodies] : byStep(readCsv(out))) {
    // Each link is 1 m along its x axis; its ends meet the neighbours' (and the first the pin).
    double px = 0.0;
    double py = 25.0;
    for (int i = 0; i < 20; ++i) {
      const auto& link = bodies.at("link" + std::to_string(i));
      const double cx = std::cos(link[angle]) * 0.5;
      const double cy = std::sin(link[angle]) * 0.5;
      EXPECT_LT(std::hypot(link[x] - cx - px, link[y] - cy - py), 0.02) << "step " << s << " link " << i;
      px = link[x] + cx;
      py = link[y] + cy;
    }
  }
}

TEST(Rigid2dRun, json_output_has_frames_with_energies_and_event_counts) {
  const std::string out = tempPath("cradle.json");
  const CliRun run = impetus({"run", scene("newtons_cradle.json"), "--steps", "100", "--every", "25", "--out", out});
  ASSERT_EQ(run.status, 0) << run.err;
  std::ifstream in(out);
  const json doc = json::parse(in);
  EXPECT_EQ(doc.at("kind"), "rigid2d");
  EXPECT_EQ(doc.at("solver"), "soft");
  EXPECT_EQ(doc.at("steps"), 100);
  EXPECT_EQ(doc.at("every"), 25);
  ASSERT_EQ(doc.at("bodies").size(), 7u);
  EXPECT_EQ(doc.at("bodies")[0].at("name"), "frame");
  EXPECT_EQ(doc.at("bodies")[0].at("type"), "static");
  EXPECT_EQ(doc.at("bodies")[2].at("type"), "dynamic");
  ASSERT_EQ(doc.at("joints").size(), 5u);
  EXPECT_EQ(doc.at("joints")[4].at("type"), "distance");
  EXPECT_EQ(doc.at("joints")[4].at("body_b"), 6);
  const json& frames = doc.at("frames");
  ASSERT_EQ(frames.size(), 5u);
  std::int64_t hits = 0;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const json& frame = frames[f];
    EXPECT_EQ(frame.at("step"), 25 * static_cast<int>(f));
    ASSERT_EQ(frame.at("positions").size(), 7u);
    ASSERT_EQ(frame.at("angles").size(), 7u);
    ASSERT_EQ(frame.at("velocities").size(), 7u);
    ASSERT_EQ(frame.at("angular_velocities").size(), 7u);
    EXPECT_NEAR(frame.at("total").get<double>(),
                frame.at("kinetic").get<double>() + frame.at("potential").get<double>(), 1e-6);
    // Gravity and frictionless joints: the energy stays within 1% until the impacts.
    EXPECT_NEAR(frame.at("total").get<double>(), frames[0].at("total").get<double>(),
                0.01 * frames[0].at("total").get<double>());
    hits += frame.at("hits").get<std::int64_t>();
  }
  EXPECT_EQ(hits, 4); // ball0-1, 1-2, 2-3, 3-4, about 1.2 s after the release
  EXPECT_EQ(frames[2].at("hits"), 0);
}

TEST(Rigid2dRun, summary_is_one_line_with_counts_events_and_energies) {
  const CliRun run = impetus({"run", scene("bridge.json"), "--steps", "60"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("27 bodies (24 dynamic)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("21 joints"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("60 steps"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("Energies at the end: kinetic"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("contact begins"), std::string::npos) << run.out;
  EXPECT_EQ(std::count(run.out.begin(), run.out.end(), '\n'), 1) << run.out;
}

TEST(Rigid2dRun, particle_scenes_still_run_with_or_without_their_kind) {
  const std::string plain = R"({"particles": [{"position": [0, 1, 0]}]})";
  const std::string kinded = R"({"kind": "particles", "particles": [{"position": [0, 1, 0]}]})";
  for (const std::string& text : {plain, kinded}) {
    const CliRun run = impetus({"run", writeTemp("p.json", text), "--steps", "10"});
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.out.find("1 particle"), std::string::npos) << run.out;
  }
}

TEST(Rigid2dRun, invalid_scenes_exit_two_naming_the_json_path) {
  struct Case {
    std::string scene;
    const char* needle;
  };
  const std::string ground =
      R"({"name": "ground", "type": "static", "shapes": [{"type": "box", "half_extents": [5, 1]}]})";
  const std::string ball = R"({"name": "ball", "position": [0, 3], "shapes": [{"type": "circle", "radius": 0.5}]})";
  const auto doc = [&](const std::string& rest) {
    return R"({"kind": "rigid2d", "bodies": [)" + ground + ", " + ball + "]" + rest + "}";
  };
  const Case cases[] = {
      {R"({"kind": "rigid2d", "bodies": [{"shapes": [], "colour": "red"}]})", "error: bodies[0].colour: unknown key"},
      {R"({"kind": "rigid2d", "world": {"gravity": [0, "down"]}})", "error: world.gravity[1]: expected a number"},
      {R"({"kind": "rigid2d", "world": {"solver": "magic"}})", "error: world.solver: unknown solver 'magic'"},
      {R"({"kind": "rigid2d", "world": {"substeps": 0}})", "error: world.substeps = 0"},
      {R"({"kind": "rigid2d", "bodies": [{"position": [0, 1, 2]}]})",
       "error: bodies[0].position: expected an array of 2 numbers"},
      {R"({"kind": "rigid2d", "bodies": [{"type": "wobbly"}]})", "error: bodies[0].type: unknown body type 'wobbly'"},
      {R"({"kind": "rigid2d", "bodies": [{"shapes": [{"type": "circle", "radius": 1, "density": -1}]}]})",
       "error: bodies[0].shapes[0].density = -1: must be finite and non-negative"},
      {R"({"kind": "rigid2d", "bodies": [{"shapes": [{"type": "circle", "radius": 1, "density": 0}]}]})",
       "error: bodies[0].shapes[0].density = 0: a shape on a dynamic body needs a positive density"},
      {R"({"kind": "rigid2d", "bodies": [{"shapes": [{"type": "polygon", "points": [[0, 0], [1, 1], [2, 2]]}]}]})",
       "error: bodies[0].shapes[0].points"},
      {R"({"kind": "rigid2d", "bodies": [{"shapes": [{"type": "polygon", "points": [[0, 0], [1, 1]]}]}]})",
       "error: bodies[0].shapes[0].points: expected 3 to 8 points"},
      {R"({"kind": "rigid2d", "bodies": [{"shapes": [{"type": "box", "half_extents": [1, 0]}]}]})",
       "error: bodies[0].shapes[0].half_extents[1] = 0"},
      {R"({"kind": "rigid2d", "bodies": [{"shapes": [{"type": "capsule", "center1": [0, 0], "center2": [0, 0], "radius": 1}]}]})",
       "error: bodies[0].shapes[0].center2: must differ from center1"},
      {R"({"kind": "rigid2d", "bodies": [{"type": "static", "shapes": [{"type": "chain", "points": [[0, 0], [0, 0], [1, 0]]}]}]})",
       "error: bodies[0].shapes[0].points[1]"},
      {R"({"kind": "rigid2d", "bodies": [{"shapes": [{"type": "blob"}]}]})",
       "error: bodies[0].shapes[0].type: unknown shape type 'blob'"},
      {R"({"kind": "rigid2d", "bodies": [{"shapes": [{"type": "circle", "radius": 1, "material": "steel"}]}]})",
       "error: bodies[0].shapes[0].material: no material named 'steel'"},
      {R"({"kind": "rigid2d", "materials": {"ice": {"friction": -0.1}}})",
       "error: materials.ice.friction = -0.1: must be finite and non-negative"},
      {R"({"kind": "rigid2d", "bodies": [{"shapes": [{"type": "circle", "radius": 1, "restitution": 2}]}]})",
       "error: bodies[0].shapes[0].restitution = 2: must be in [0, 1]"},
      {R"({"kind": "rigid2d", "bodies": [{"shapes": [{"type": "circle", "radius": 1, "filter": {"mask": -1}}]}]})",
       "error: bodies[0].shapes[0].filter.mask = -1"},
      {R"({"kind": "rigid2d", "bodies": [{"name": "a"}, {"name": "a"}]})",
       "error: bodies[1].name: duplicate body name 'a'"},
      {R"({"kind": "rigid2d", "bodies": [{"name": "a,b"}]})", "error: bodies[0].name: 'a,b' must not contain commas"},
      {R"({"kind": "rigid2d", "bodies": [{"type": "static", "mass_properties": {"mass": 1}}]})",
       "error: bodies[0].mass_properties: only a dynamic body"},
      {doc(R"(, "joints": [{"type": "revolute", "body_a": "ground", "body_b": "bal", "anchor": [0, 3]}])"),
       "error: joints[0].body_b: no body named 'bal'"},
      {doc(R"(, "joints": [{"type": "revolute", "body_a": "ground", "body_b": "ground"}])"),
       "error: joints[0].body_b: a joint needs two different bodies"},
      {doc(R"(, "joints": [{"type": "hinge", "body_a": "ground", "body_b": "ball"}])"),
       "error: joints[0].type: unknown joint type 'hinge'"},
      {doc(R"(, "joints": [{"type": "revolute", "body_a": "ground", "body_b": "ball", "anchor": [0, 3], "anchor_b": [0, 3]}])"),
       "error: joints[0].anchor_b: give at most one of"},
      {doc(R"(, "joints": [{"type": "revolute", "body_a": "ground", "body_b": "ball", "lower_angle_deg": 10, "upper_angle_deg": -10}])"),
       "error: joints[0].upper_angle_deg = -10: must be >= lower_angle_deg"},
      {doc(R"(, "joints": [{"type": "distance", "body_a": "ground", "body_b": "ball", "length": -2}])"),
       "error: joints[0].length = -2: must be finite and positive"},
      {doc(R"(, "joints": [{"type": "weld", "body_a": "ground", "body_b": "ball", "motor_speed": 2}])"),
       "error: joints[0].motor_speed: unknown key"},
      {doc(R"(, "joints": [{"type": "wheel", "body_a": "ground", "body_b": "ball", "axis": [0, 0]}])"),
       "error: joints[0].axis: must be non-zero"},
      {doc(R"(, "effectors": [{"type": "thruster", "body": "nobody", "thrust": 1}])"),
       "error: effectors[0].body: no body named 'nobody'"},
      {doc(R"(, "effectors": [{"type": "buoyancy", "surface_height": 0, "fluid_density": 0}])"),
       "error: effectors[0].fluid_density = 0: must be finite and positive"},
      {doc(R"(, "effectors": [{"type": "explosion", "center": [0, 0], "radius": 2, "start": 2, "stop": 1}])"),
       "error: effectors[0].stop = 1: must be >= start"},
      {doc(R"(, "effectors": [{"type": "tornado"}])"), "error: effectors[0].type: unknown effector type 'tornado'"},
      {R"({"kind": "rigid3d"})", "error: kind: unknown scene kind 'rigid3d'"},
      {R"({"kind": "rigid2d", "particles": []})", "error: particles: unknown key"},
      {R"({"kind": "rigid2d", "bodies": [{"position": [0, 1]})", "error: json: malformed JSON"},
  };
  int i = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.scene);
    const std::string path = writeTemp("bad" + std::to_string(i++) + ".json", c.scene);
    const CliRun run = impetus({"run", path, "--steps", "10"});
    expectUsageError(run, c.needle);
    EXPECT_EQ(run.err.rfind(c.needle, 0), 0u) << run.err; // the line starts with the path
    EXPECT_TRUE(run.out.empty()) << run.out;
  }
}

TEST(Rigid2dRun, bad_arguments_exit_two_and_write_nothing) {
  const std::string path = writeTemp("fall.json", fallingScene);
  expectUsageError(impetus({"run", path, "--steps", "10", "--events", tempPath("e.txt")}), "--events");
  const std::string particles = writeTemp("p.json", R"({"particles": [{"position": [0, 1, 0]}]})");
  expectUsageError(impetus({"run", particles, "--steps", "10", "--events", tempPath("e.csv")}),
                   "only rigid2d scenes have contact events");
  // A scene that fails to load writes no trajectory.
  const std::string bad = writeTemp("bad.json", R"({"kind": "rigid2d", "bodies": [{"colour": 1}]})");
  const std::string out = tempPath("never.csv");
  expectUsageError(impetus({"run", bad, "--steps", "10", "--out", out}), "bodies[0].colour");
  EXPECT_FALSE(std::filesystem::exists(out));
}

/// A scene big enough for the step's parallel loops to split over threads: 1,200 boxes and
/// circles dropped in a walled bin (no sleeping), with restitution and rolling resistance.
std::string binScene() {
  json bodies = json::array();
  bodies.push_back({{"name", "bin"},
                    {"type", "static"},
                    {"shapes",
                     {{{"type", "box"}, {"half_extents", {30, 0.5}}, {"center", {0, -0.5}}},
                      {{"type", "segment"}, {"point1", {-30, 0}}, {"point2", {-30, 60}}},
                      {{"type", "segment"}, {"point1", {30, 0}}, {"point2", {30, 60}}}}}});
  for (int i = 0; i < 1200; ++i) {
    const double x = -28.0 + 1.15 * (i % 48);
    const double y = 1.0 + 1.2 * (i / 48);
    json shape = i % 2 == 0
                     ? json{{"type", "box"}, {"half_extents", {0.45, 0.45}}}
                     : json{{"type", "circle"}, {"radius", 0.45}, {"restitution", 0.3}, {"rolling_resistance", 0.02}};
    std::string name = "b"; // (not "b" + std::to_string(i): GCC 12's false -Wrestrict)
    name += std::to_string(i);
    bodies.push_back({{"name", name}, {"position", {x, y}}, {"shapes", {shape}}});
  }
  return json{{"kind", "rigid2d"}, {"world", {{"enable_sleep", false}}}, {"bodies", bodies}}.dump();
}

std::string hashLine(const CliRun& run) {
  const std::size_t at = run.out.find("state hash: ");
  return at == std::string::npos ? std::string() : run.out.substr(at, 12 + 16);
}

TEST(Rigid2dRun, hash_is_the_same_run_after_run_and_at_any_thread_count) {
  const std::string path = writeTemp("bin.json", binScene());
  const CliRun first = impetus({"run", path, "--steps", "90", "--hash"});
  ASSERT_EQ(first.status, 0) << first.err;
  const std::string reference = hashLine(first);
  ASSERT_EQ(reference.size(), 28U) << first.out;
  for (const char* threads : {"1", "2", "4"}) {
    const CliRun run = impetus({"run", path, "--steps", "90", "--threads", threads, "--hash"});
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(hashLine(run), reference) << threads << " threads";
  }
  // One step more is another state.
  EXPECT_NE(hashLine(impetus({"run", path, "--steps", "91", "--hash"})), reference);
}

TEST(Rigid2dRun, threads_must_be_sensible) {
  expectUsageError(impetus({"run", scene("pyramid.json"), "--steps", "1", "--threads", "0"}), "--threads = 0");
  expectUsageError(impetus({"run", scene("pyramid.json"), "--steps", "1", "--threads", "65"}), "--threads = 65");
}

} // namespace
