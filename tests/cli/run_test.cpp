// Black-box tests of `impetus run SCENE.json`: the shipped scenes run and give finite output in
// the documented CSV and JSON layouts, a falling particle follows the closed form, and every bad
// scene or argument exits 2 with one line that names the JSON path or the option.
#include "cli_process.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
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

/// A file in the test's temporary directory, named after the test (tests run in parallel).
std::string tempPath(const std::string& name) {
  return ::testing::TempDir() + "impetus_run_" + ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
         name;
}

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = tempPath(name);
  std::ofstream(path) << text;
  return path;
}

const std::string csvHeader = "step,time,particle,x,y,z,vx,vy,vz,kinetic,potential,spring,total";

/// The CSV as rows of numbers (after checking the header); every field must parse completely.
std::vector<std::vector<double>> readCsv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, csvHeader);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) {
      std::size_t used = 0;
      row.push_back(std::stod(field, &used));
      EXPECT_EQ(used, field.size()) << line;
    }
    EXPECT_EQ(row.size(), 13u) << line;
    rows.push_back(row);
  }
  return rows;
}

enum Column { step, time, particle, x, y, z, vx, vy, vz, kinetic, potential, spring, total };

std::vector<std::filesystem::path> shippedScenes() {
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(IMPETUS_SOURCE_DIR "/scenes/particles")) {
    if (entry.path().extension() == ".json") {
      scenes.push_back(entry.path());
    }
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

TEST(Run, every_shipped_particle_scene_runs_and_writes_finite_csv) {
  const auto scenes = shippedScenes();
  ASSERT_GE(scenes.size(), 4u); // ch. 2 explosion, ch. 8 simulator, ch. 13 ropes, cloth flag
  for (const auto& scene : scenes) {
    SCOPED_TRACE(scene.string());
    const std::string out = tempPath(scene.stem().string() + ".csv");
    // 1.5 s: long enough for every scene to get going, short enough that the sparks still live.
    const CliRun run = impetus({"run", scene.string(), "--steps", "90", "--every", "10", "--out", out});
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_TRUE(run.err.empty()) << run.err;
    EXPECT_NE(run.out.find("90 steps"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("energies kinetic"), std::string::npos) << run.out;
    const auto rows = readCsv(out);
    ASSERT_FALSE(rows.empty());
    std::set<double> steps;
    for (const auto& row : rows) {
      for (const double v : row) {
        ASSERT_TRUE(std::isfinite(v));
      }
      steps.insert(row[step]);
      EXPECT_NEAR(row[total], row[kinetic] + row[potential] + row[spring], 1e-9 * (1.0 + std::abs(row[total])));
    }
    // Recorded: the last step and every 10th (the explosion's sparks appear at step 1).
    EXPECT_TRUE(steps.contains(90.0));
    EXPECT_TRUE(steps.contains(10.0));
    EXPECT_FALSE(steps.contains(5.0));
  }
}

TEST(Run, json_output_has_one_frame_per_recorded_step) {
  const std::string out = tempPath("rope.json");
  const CliRun run = impetus(
      {"run", IMPETUS_SOURCE_DIR "/scenes/particles/ch13_rope.json", "--steps", "25", "--every", "10", "--out", out});
  ASSERT_EQ(run.status, 0) << run.err;
  std::ifstream in(out);
  const json doc = json::parse(in);
  EXPECT_EQ(doc.at("steps"), 25);
  EXPECT_EQ(doc.at("every"), 10);
  EXPECT_EQ(doc.at("substeps"), 4);
  EXPECT_NEAR(doc.at("dt").get<double>(), 1.0 / 60.0, 1e-8);
  ASSERT_EQ(doc.at("particle_names").size(), 20u);
  EXPECT_EQ(doc.at("particle_names")[0], "book[0]");
  EXPECT_EQ(doc.at("particle_names")[10], "xpbd[0]");
  const json& frames = doc.at("frames");
  ASSERT_EQ(frames.size(), 4u); // steps 0, 10, 20 and the last, 25
  const std::vector<int> expected{0, 10, 20, 25};
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const json& frame = frames[f];
    EXPECT_EQ(frame.at("step"), expected[f]);
    EXPECT_NEAR(frame.at("time").get<double>(), expected[f] / 60.0, 1e-6);
    ASSERT_EQ(frame.at("particles").size(), 20u);
    ASSERT_EQ(frame.at("positions").size(), 20u);
    ASSERT_EQ(frame.at("velocities").size(), 20u);
    for (const char* key : {"kinetic", "potential", "spring", "total"}) {
      EXPECT_TRUE(std::isfinite(frame.at(key).get<double>())) << key;
    }
    for (const json& p : frame.at("positions")) {
      ASSERT_EQ(p.size(), 3u);
      EXPECT_TRUE(std::isfinite(p[1].get<double>()));
    }
  }
  // The ropes start horizontal at y = 12 m with their first particles locked there.
  EXPECT_DOUBLE_EQ(frames[0].at("positions")[5][1].get<double>(), 12.0);
  EXPECT_DOUBLE_EQ(frames[3].at("positions")[0][1].get<double>(), 12.0);
  EXPECT_LT(frames[3].at("positions")[9][1].get<double>(), 12.0);
}

/// A thrown particle with no drag: x = x0 + u t, y = y0 + v t - g t^2 / 2.
std::string projectileScene(const std::string& integrator) {
  return R"({"description": "a thrown ball", "world": {"gravity": [0, -9.81, 0], "substeps": 4, "integrator": ")" +
         integrator + R"("},
             "particles": [{"name": "ball", "position": [1, 50, -2], "velocity": [3, 4, 0], "mass": 2}]})";
}

TEST(Run, projectile_trajectory_matches_the_closed_form_with_velocity_verlet) {
  const std::string scene = writeTemp("ball.json", projectileScene("velocity-verlet"));
  const std::string out = tempPath("ball.csv");
  const CliRun run = impetus({"run", scene, "--steps", "120", "--out", out});
  ASSERT_EQ(run.status, 0) << run.err;
  const auto rows = readCsv(out);
  ASSERT_EQ(rows.size(), 121u); // steps 0..120, one particle
  const double g = 9.81;
  const double energy0 = rows[0][total];
  EXPECT_NEAR(energy0, 0.5 * 2.0 * 25.0 + 2.0 * g * 50.0, 1e-3);
  for (const auto& row : rows) {
    const double t = row[time];
    EXPECT_NEAR(t, row[step] / 60.0, 1e-6);
    EXPECT_EQ(row[particle], 0.0);
    // Velocity Verlet is exact for a constant force: only float rounding remains.
    EXPECT_NEAR(row[x], 1.0 + 3.0 * t, 1e-4);
    EXPECT_NEAR(row[y], 50.0 + 4.0 * t - 0.5 * g * t * t, 2e-4);
    EXPECT_NEAR(row[z], -2.0, 1e-6);
    EXPECT_NEAR(row[vy], 4.0 - g * t, 1e-4);
    EXPECT_NEAR(row[total], energy0, 1e-5 * energy0);
  }
}

TEST(Run, semi_implicit_euler_trails_the_closed_form_by_g_h_t_over_2) {
  // n substeps of h: y_n = y0 + v t - g h^2 n (n + 1) / 2 = closed form - g h t / 2 (first order).
  const std::string scene = writeTemp("ball.json", projectileScene("semi-implicit-euler"));
  const std::string out = tempPath("ball.csv");
  const CliRun run = impetus({"run", scene, "--steps", "60", "--every", "6", "--out", out});
  ASSERT_EQ(run.status, 0) << run.err;
  const auto rows = readCsv(out);
  ASSERT_EQ(rows.size(), 11u);
  const double g = 9.81;
  const double h = 1.0 / 240.0;
  for (const auto& row : rows) {
    const double t = row[time];
    EXPECT_NEAR(row[y], 50.0 + 4.0 * t - 0.5 * g * t * t - 0.5 * g * h * t, 2e-4);
  }
  EXPECT_GT(0.5 * g * h * 1.0, 0.02); // the offset at 1 s is far above the tolerance
}

TEST(Run, emitted_particles_get_new_numbers_and_expire) {
  const std::string out = tempPath("explosion.csv");
  const CliRun run = impetus({"run", IMPETUS_SOURCE_DIR "/scenes/particles/ch02_explosion.json", "--steps", "150",
                              "--every", "30", "--out", out});
  ASSERT_EQ(run.status, 0) << run.err;
  std::map<double, std::set<double>> numbersByStep;
  for (const auto& row : readCsv(out)) {
    EXPECT_TRUE(numbersByStep[row[step]].insert(row[particle]).second) << "a number repeats within a step";
  }
  EXPECT_FALSE(numbersByStep.contains(0.0)); // the burst comes with the first step
  ASSERT_EQ(numbersByStep[30.0].size(), 50u);
  EXPECT_EQ(*numbersByStep[30.0].begin(), 0.0);
  EXPECT_EQ(*numbersByStep[30.0].rbegin(), 49.0);
  EXPECT_FALSE(numbersByStep.contains(150.0)); // 2.5 s: every spark (life <= 2 s) is gone
}

TEST(Run, summary_is_one_line_with_the_counts_steps_and_energies) {
  const std::string scene = writeTemp("ball.json", projectileScene("velocity-verlet"));
  const CliRun run = impetus({"run", scene, "--steps", "60"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("1 particle,"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("60 steps"), std::string::npos) << run.out;
  // Total energy m v0^2 / 2 + m g y0 = 25 + 981 J, kept by Verlet.
  EXPECT_NE(run.out.find("total 1006 J"), std::string::npos) << run.out;
  EXPECT_EQ(std::count(run.out.begin(), run.out.end(), '\n'), 1) << run.out;
}

TEST(Run, invalid_scenes_exit_two_naming_the_json_path) {
  struct Case {
    const char* scene;
    const char* needle;
  };
  const Case cases[] = {
      {R"({"particles": [{"position": [0, 1, 0]}, {"position": [0, 2, 0], "mass": -1}]})",
       "particles[1].mass = -1: must be finite and positive"},
      {R"({"particles": [{"position": [0, 1, 0], "colour": "red"}]})", "particles[0].colour: unknown key"},
      {R"({"world": {"gravity": [0, -9.81, 0], "wind": 3}})", "world.wind: expected an array of 3 numbers"},
      {R"({"particles": [{"position": [0, 1, 0]})", "malformed JSON"},
      {R"({"obstacles": [{"type": "plane"}, {"type": "sphere", "center": [0, 0, 0], "radius": -2}]})",
       "obstacles[1].radius = -2: must be finite and positive"},
      {R"({"obstacles": [{"type": "teapot"}]})", "obstacles[0].type: unknown obstacle type 'teapot'"},
      {R"({"obstacles": [{"type": "box", "center": [0, 0, 0], "half_extents": [1, 0, 1]}]})",
       "obstacles[0].half_extents[1] = 0"},
      {R"({"obstacles": [{"type": "plane", "restitution": 1.5}]})", "obstacles[0].restitution = 1.5"},
      {R"({"particles": [{"name": "a", "position": [0, 1, 0]}], "springs": [{"a": "a", "b": "z"}]})",
       "springs[0].b: no particle named 'z'"},
      {R"({"ropes": [{"start": [0, 0, 0], "end": [1, 0, 0], "segments": 0}]})", "ropes[0].segments = 0"},
      {R"({"cloths": [{"origin": [0, 0, 0], "rows": 4, "pin_rows": [4]}]})", "cloths[0].pin_rows[0] = 4"},
      {R"({"emitters": [{"position": [0, 0, 0], "cone_angle_deg": 270}]})", "emitters[0].cone_angle_deg = 270"},
      {R"({"world": {"integrator": "leapfrog"}})", "world.integrator: unknown integrator 'leapfrog'"},
      {R"([1, 2, 3])", "document: expected a JSON object"},
  };
  int i = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.scene);
    const std::string path = writeTemp("bad" + std::to_string(i++) + ".json", c.scene);
    expectUsageError(impetus({"run", path, "--steps", "10"}), c.needle);
  }
}

TEST(Run, bad_arguments_exit_two_with_one_line) {
  const std::string scene = writeTemp("ok.json", projectileScene("rk4"));
  expectUsageError(impetus({"run", scene, "--steps", "0"}), "--steps = 0");
  expectUsageError(impetus({"run", scene, "--steps", "-5"}), "--steps");
  expectUsageError(impetus({"run", scene, "--steps", "10", "--dt", "-1"}), "--dt = -1");
  expectUsageError(impetus({"run", scene, "--steps", "10", "--dt=0"}), "--dt = 0");
  expectUsageError(impetus({"run", scene, "--steps", "10", "--every", "0"}), "--every = 0");
  expectUsageError(impetus({"run", scene, "--steps", "10", "--out", tempPath("t.txt")}), ".csv or .json");
  expectUsageError(impetus({"run", scene}), "--steps");
  expectUsageError(impetus({"run", tempPath("missing.json"), "--steps", "10"}), "no such file");
}

TEST(Run, a_scene_over_its_body_count_is_refused_before_its_document_is_built) {
  // A million-body file once took 7 s and 1.4 GB to be refused; the counts are now read in one
  // pass over the text. What comes after the array (a world the loader would refuse first, even
  // malformed JSON) is never reached.
  std::string bodies = R"({"kind": "rigid2d", "bodies": [)";
  for (int i = 0; i <= 1'000'000; ++i) {
    bodies += i == 0 ? "{}" : ",{}";
  }
  bodies += R"(], "world": {"substeps": 0}, oops)";
  expectUsageError(impetus({"run", writeTemp("too_many_bodies.json", bodies), "--steps", "1"}),
                   "bodies[1000000]: more than 1000000 bodies in the scene");
  // At the limit the document is read as usual (here: its bad world is what is refused).
  std::string atLimit = R"({"kind": "rigid2d", "world": {"substeps": 0}, "bodies": [{}]})";
  expectUsageError(impetus({"run", writeTemp("bodies_at_limit.json", atLimit), "--steps", "1"}), "world.substeps = 0");
}

} // namespace
