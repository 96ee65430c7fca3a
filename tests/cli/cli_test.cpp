// Black-box tests of the `impetus` executable: exit codes, one-line errors, JSON output, and
// the calc models' numbers against closed forms and the book's worked example.
#include "cli_process.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

using impetus::testing::CliRun;
using impetus::testing::expectUsageError;
using impetus::testing::impetus;

double output(const json& doc, const std::string& name) { return doc.at("outputs").at(name).at("value").get<double>(); }

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

TEST(Cli, version_and_help_exit_zero) {
  const CliRun version = impetus({"--version"});
  EXPECT_EQ(version.status, 0);
  EXPECT_NE(version.out.find("impetus 0."), std::string::npos);
  const CliRun help = impetus({"--help"});
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("calc"), std::string::npos);
  EXPECT_NE(help.out.find("demo"), std::string::npos);
}

TEST(Cli, an_unknown_command_is_named_with_the_real_ones) {
  const CliRun run = impetus({"frobnicate"});
  expectUsageError(run, "unknown command 'frobnicate'");
  for (const char* command : {"calc", "demo", "run"}) {
    EXPECT_NE(run.err.find(command), std::string::npos) << run.err;
  }
}

TEST(Cli, calc_list_json_describes_every_model_with_units) {
  const CliRun run = impetus({"calc", "--list", "--json"});
  ASSERT_EQ(run.status, 0) << run.err;
  const json models = json::parse(run.out);
  ASSERT_TRUE(models.is_array());
  EXPECT_GE(models.size(), 12U);
  for (const json& m : models) {
    EXPECT_FALSE(m.at("name").get<std::string>().empty());
    EXPECT_FALSE(m.at("summary").get<std::string>().empty());
    for (const json& p : m.at("params")) {
      EXPECT_TRUE(p.contains("unit"));
      EXPECT_TRUE(p.contains("default"));
    }
  }
  // The text listing names the same models.
  const CliRun text = impetus({"calc", "--list"});
  for (const json& m : models) {
    EXPECT_NE(text.out.find(m.at("name").get<std::string>()), std::string::npos);
  }
}

TEST(Cli, every_model_with_required_parameters_refuses_to_run_without_them) {
  const json models = json::parse(impetus({"calc", "--list", "--json"}).out);
  for (const json& m : models) {
    const bool needsInput = std::any_of(m.at("params").begin(), m.at("params").end(),
                                        [](const json& p) { return p.at("required").get<bool>(); });
    if (needsInput) {
      expectUsageError(impetus({"calc", m.at("name").get<std::string>()}), "missing parameter");
    }
  }
}

/// True when a JSON value holds a null anywhere (nlohmann writes NaN and infinity as null).
bool containsNull(const json& j) {
  if (j.is_null()) {
    return true;
  }
  if (j.is_structured()) {
    return std::any_of(j.begin(), j.end(), [](const json& e) { return containsNull(e); });
  }
  return false;
}

// Every model that needs no input must succeed and produce only finite numbers, or refuse with
// one usage line.
TEST(Cli, every_model_runs_on_its_defaults_without_nan) {
  const json models = json::parse(impetus({"calc", "--list", "--json"}).out);
  int ran = 0;
  for (const json& m : models) {
    const bool needsInput = std::any_of(m.at("params").begin(), m.at("params").end(),
                                        [](const json& p) { return p.at("required").get<bool>(); });
    if (needsInput) {
      continue;
    }
    const std::string name = m.at("name").get<std::string>();
    const CliRun run = impetus({"calc", name, "--json"});
    if (run.status == 2) { // optional inputs of which some must be given: a usage error, not a crash
      EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << name << ": " << run.err;
      continue;
    }
    ASSERT_EQ(run.status, 0) << name << ": " << run.err;
    const json doc = json::parse(run.out);
    EXPECT_FALSE(containsNull(doc.at("outputs"))) << name << " printed a non-finite value: " << run.out;
    ++ran;
  }
  EXPECT_GE(ran, 8); // cannon, cannon2, billiards, bat-ball, ... run on the book's own inputs
}

TEST(Cli, solid_sphere_matches_two_fifths_m_r_squared) {
  const CliRun run = impetus({"calc", "inertia-solid-sphere", "--mass", "2", "--radius", "0.5", "--json"});
  ASSERT_EQ(run.status, 0) << run.err;
  const json doc = json::parse(run.out);
  EXPECT_EQ(doc.at("model"), "inertia-solid-sphere");
  EXPECT_DOUBLE_EQ(doc.at("inputs").at("mass").at("value").get<double>(), 2.0);
  EXPECT_EQ(doc.at("inputs").at("radius").at("unit"), "m");
  EXPECT_NEAR(output(doc, "Ixx"), 0.4 * 2.0 * 0.25, 1e-15);
  EXPECT_EQ(doc.at("outputs").at("Ixx").at("unit"), "kg m^2");
  EXPECT_NEAR(output(doc, "volume"), 4.0 / 3.0 * M_PI * 0.125, 1e-15);
}

TEST(Cli, parameters_accept_equals_form_and_json_flag_anywhere) {
  const CliRun run = impetus({"calc", "--json", "inertia-rod", "--length=3", "--mass", "4"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NEAR(output(json::parse(run.out), "Ixx"), 4.0 * 9.0 / 12.0, 1e-15);
}

TEST(Cli, bad_input_exits_two_with_one_line_naming_it) {
  expectUsageError(impetus({"calc", "no-such-model"}), "no-such-model");
  expectUsageError(impetus({"calc", "inertia-rod", "--mass", "1", "--length", "2", "--colour", "red"}), "--colour");
  expectUsageError(impetus({"calc", "inertia-rod", "--mass", "1"}), "--length");
  expectUsageError(impetus({"calc", "inertia-rod", "--mass", "one", "--length", "2"}), "--mass");
  expectUsageError(impetus({"calc", "inertia-rod", "--mass", "nan", "--length", "2"}), "--mass = nan");
  expectUsageError(impetus({"calc", "inertia-rod", "--mass", "-1", "--length", "2"}), "--mass = -1");
  expectUsageError(impetus({"calc", "inertia-rod", "--mass", "1", "--length", "inf"}), "--length = inf");
  expectUsageError(
      impetus({"calc", "inertia-hollow-sphere", "--mass", "1", "--inner-radius", "2", "--outer-radius", "1"}),
      "--inner-radius = 2");
  expectUsageError(impetus({"calc", "inertia-rod", "--mass", "1", "--mass", "2", "--length", "1"}), "twice");
  expectUsageError(impetus({"calc"}), "missing model");
}

TEST(Cli, parallel_axis_adds_m_d_squared) {
  const CliRun run = impetus({"calc", "parallel-axis", "--inertia", "1.5", "--mass", "2", "--distance", "3", "--json"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_DOUBLE_EQ(output(json::parse(run.out), "inertia"), 1.5 + 2.0 * 9.0);
}

TEST(Cli, polygon_right_triangle_matches_closed_form) {
  // Legs a = 3 (x), b = 4 (y): area 6, centroid (1, 4/3), polar moment about the centroid
  // m (a^2 + b^2) / 18.
  const CliRun run = impetus({"calc", "polygon", "--vertices", "0,0 3,0 0,4", "--density", "2", "--json"});
  ASSERT_EQ(run.status, 0) << run.err;
  const json doc = json::parse(run.out);
  EXPECT_NEAR(output(doc, "area"), 6.0, 1e-12);
  EXPECT_NEAR(output(doc, "mass"), 12.0, 1e-12);
  EXPECT_NEAR(doc.at("outputs").at("centroid").at("value")[1].get<double>(), 4.0 / 3.0, 1e-12);
  EXPECT_NEAR(output(doc, "inertia"), 12.0 * 25.0 / 18.0, 1e-12);
  expectUsageError(impetus({"calc", "polygon", "--vertices", "0,0 1,1 2,2"}), "degenerate");
  expectUsageError(impetus({"calc", "polygon", "--vertices", "0,0 1,x 2,2"}), "--vertices");
}

// The book's example 1.1 with g = 9.8, against the spec's recomputed values (the book's own
// fuel weight, 920.6 N, does not follow from rho g V and is not used).
TEST(Cli, composite_reproduces_car_driver_fuel_example) {
  const CliRun run = impetus(
      {"calc", "composite", "--file", std::string(IMPETUS_SOURCE_DIR) + "/scenes/mass/car_driver_fuel.json", "--json"});
  ASSERT_EQ(run.status, 0) << run.err;
  const json doc = json::parse(run.out);
  EXPECT_NEAR(output(doc, "weight"), 19342.25, 1e-6);
  EXPECT_NEAR(output(doc, "mass"), 1973.699, 1e-3);
  const json cg = doc.at("outputs").at("center_of_mass").at("value");
  EXPECT_NEAR(cg[0].get<double>(), 30.4157, 5e-5);
  EXPECT_NEAR(cg[1].get<double>(), 30.5220, 5e-5);
  const json inertia = doc.at("outputs").at("inertia_tensor").at("value");
  EXPECT_NEAR(inertia[2][2].get<double>(), 4512.20, 5e-3);
  EXPECT_NEAR(output(doc, "part.fuel.mass"), 101.25, 1e-9);
}

TEST(Cli, composite_rotated_box_swaps_moments) {
  // A 1 x 2 x 3 m box turned 90 degrees about z: its x and y moments trade places, and the
  // principal moments stay the box's own.
  const std::string path = writeTemp("rotated_box.json", R"({"parts": [{"shape": "box", "size": [1, 2, 3],
      "mass": 12, "orientation": {"axis": [0, 0, 1], "angle_deg": 90}}]})");
  const CliRun run = impetus({"calc", "composite", "--file", path, "--json"});
  ASSERT_EQ(run.status, 0) << run.err;
  const json doc = json::parse(run.out);
  const json inertia = doc.at("outputs").at("inertia_tensor").at("value");
  EXPECT_NEAR(inertia[0][0].get<double>(), 12.0 * (1.0 + 9.0) / 12.0, 1e-12);
  EXPECT_NEAR(inertia[1][1].get<double>(), 12.0 * (4.0 + 9.0) / 12.0, 1e-12);
  const json moments = doc.at("outputs").at("principal_moments").at("value");
  EXPECT_NEAR(moments[0].get<double>(), 5.0, 1e-12);
  EXPECT_NEAR(moments[2].get<double>(), 13.0, 1e-12);
}

TEST(Cli, composite_rejects_malformed_files_naming_the_key) {
  expectUsageError(impetus({"calc", "composite", "--file", "/nonexistent/body.json"}), "/nonexistent/body.json");
  expectUsageError(impetus({"calc", "composite", "--file", writeTemp("bad1.json", "{ \"parts\": [ ")}),
                   "malformed JSON");
  expectUsageError(
      impetus({"calc", "composite", "--file",
               writeTemp("bad2.json", R"({"parts": [{"shape": "box", "size": [1, 2, 3], "mass": 1, "colour": 3}]})")}),
      "parts[0].colour");
  expectUsageError(
      impetus({"calc", "composite", "--file",
               writeTemp("bad3.json", R"({"parts": [{"shape": "solid-sphere", "radius": -1, "mass": 1}]})")}),
      "parts[0].radius = -1");
  expectUsageError(impetus({"calc", "composite", "--file",
                            writeTemp("bad4.json", R"({"parts": [{"shape": "box", "size": [1, 2], "mass": 1}]})")}),
                   "parts[0].size");
  expectUsageError(
      impetus({"calc", "composite", "--file",
               writeTemp("bad5.json", R"({"parts": [{"shape": "box", "size": [1, 2, 3], "mass": 1, "weight": 2}]})")}),
      "exactly one of");
  expectUsageError(
      impetus({"calc", "composite", "--file", writeTemp("bad6.json", R"({"parts": [{"shape": "custom", "mass": 1,
                              "inertia": [[1, 0, 0], [0, 1, 0], [0, 0, 3]]}]})")}),
      "triangle inequality");
  expectUsageError(impetus({"calc", "composite", "--file",
                            writeTemp("bad7.json", R"({"parts": [{"shape": "box", "size": [1, 1, 1], "mass": 1,
                              "orientation": {"axis": [0, 0, 0], "angle_deg": 5}}]})")}),
                   "parts[0].orientation.axis");
}

TEST(Cli, cannon_hits_the_default_target_and_aim_reports_unreachable_targets) {
  const CliRun shot = impetus({"calc", "cannon", "--json"});
  ASSERT_EQ(shot.status, 0) << shot.err;
  const json doc = json::parse(shot.out);
  EXPECT_EQ(doc.at("outputs").at("outcome").at("value"), "hit");
  // 45 degrees, 50 m/s, from a 2 m barrel: the shell reaches x = 250 (the target's near face)
  // when (250 - L sin a) / (v sin a) seconds have passed.
  const double t = (250.0 - 2.0 * std::sqrt(0.5)) / (50.0 * std::sqrt(0.5));
  EXPECT_NEAR(output(doc, "time"), t, 1e-6);
  expectUsageError(impetus({"calc", "aim", "--distance", "300", "--speed", "50"}), "--speed = 50");
  expectUsageError(impetus({"calc", "cannon", "--altitude-deg", "200"}), "--altitude-deg = 200");
  expectUsageError(impetus({"calc", "cannon2", "--wind-model", "breeze"}), "--wind-model = breeze");
}

TEST(Cli, demo_writes_trajectory_csv) {
  const std::string dir = ::testing::TempDir() + "impetus_demo_csv";
  const CliRun run = impetus({"demo", "cannon", "--out", dir});
  ASSERT_EQ(run.status, 0) << run.err;
  std::ifstream csv(dir + "/cannon.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "shot,t,x,y,z,vx,vy,vz");
  int rows = 0;
  for (std::string line; std::getline(csv, line);) {
    ++rows;
  }
  EXPECT_GT(rows, 100);
}

TEST(Cli, every_model_help_lists_its_parameters_with_units_defaults_and_formula) {
  // What docs/cli.md and the "unknown parameter" hint promise: the model's own parameters, not
  // the generic calc usage; --json gives the same description calc --list --json has.
  const CliRun listed = impetus({"calc", "--list", "--json"});
  ASSERT_EQ(listed.status, 0);
  for (const json& model : json::parse(listed.out)) {
    const std::string name = model.at("name").get<std::string>();
    const CliRun help = impetus({"calc", name, "--help"});
    ASSERT_EQ(help.status, 0) << name << ": " << help.err;
    EXPECT_NE(help.out.find(model.at("summary").get<std::string>()), std::string::npos) << name;
    for (const json& p : model.at("params")) {
      std::string line = "--" + p.at("name").get<std::string>();
      if (!p.at("unit").get<std::string>().empty()) {
        line += " [" + p.at("unit").get<std::string>() + "]";
      }
      EXPECT_NE(help.out.find(line), std::string::npos) << name << " lacks " << line << ":\n" << help.out;
      if (p.at("default").is_string() && !p.at("default").get<std::string>().empty()) {
        EXPECT_NE(help.out.find("(default " + p.at("default").get<std::string>() + ")"), std::string::npos) << name;
      }
    }
    const CliRun asJson = impetus({"calc", name, "--help", "--json"});
    ASSERT_EQ(asJson.status, 0) << name;
    EXPECT_EQ(json::parse(asJson.out), model) << name;
  }
  EXPECT_NE(impetus({"calc", "--help"}).out.find("MODEL --help"), std::string::npos);
}

TEST(Cli, a_file_given_as_the_demo_output_directory_is_refused_naming_it) {
  // Once an uncaught std::filesystem error: exit 134 (abort), a stack of text.
  const std::string file = writeTemp("impetus_demo_out_is_a_file", "not a directory\n");
  expectUsageError(impetus({"demo", "cannon", "--out", file}), "--out = " + file + ": is a file, not a directory");
  expectUsageError(impetus({"demo", "--out", file}), "--out = " + file + ": is a file, not a directory");
}

TEST(Cli, number_errors_have_one_form_naming_the_option_the_text_and_the_reason) {
  const std::string scene = writeTemp("impetus_numbers_scene.json", R"({"type": "particles", "particles": []})");
  // The same range whichever way the number is written.
  const char* steps = "must be a whole number from 1 to 100000000";
  expectUsageError(impetus({"run", scene, "--steps", "1e12"}), std::string("--steps = 1e12: ") + steps);
  expectUsageError(impetus({"run", scene, "--steps", "1000000000000"}),
                   std::string("--steps = 1000000000000: ") + steps);
  expectUsageError(impetus({"run", scene, "--steps", "many"}), std::string("--steps = many: ") + steps);
  expectUsageError(impetus({"run", scene, "--steps", "10", "--dt", "x"}), "--dt = x: not a number");
  expectUsageError(impetus({"run", scene, "--steps", "10", "--threads", "1e3"}),
                   "--threads = 1e3: must be a whole number from 1 to 64");
  expectUsageError(impetus({"calc", "inertia-rod", "--mass", "1e400", "--length", "1"}), "--mass = 1e400: overflows");
  expectUsageError(impetus({"calc", "inertia-rod", "--mass", "1e-400", "--length", "1"}),
                   "--mass = 1e-400: underflows");
  expectUsageError(impetus({"calc", "hourglass", "--grain-count", "1e8"}), "to 1000000");
  expectUsageError(impetus({"demo", "doppler", "--speed", "fast"}), "--speed = fast: not a number");
}

TEST(Cli, errors_name_the_users_words) {
  // Another parameter named in the reason is spelled as the user types it.
  expectUsageError(
      impetus({"calc", "inertia-hollow-sphere", "--mass", "1", "--inner-radius", "2", "--outer-radius", "1"}),
      "--inner-radius = 2: must not exceed --outer-radius");
  // A directory given as a file is said to be one (it read as empty JSON).
  const std::string dir = ::testing::TempDir();
  expectUsageError(impetus({"run", dir, "--steps", "1"}), "is a directory, not a file");
  expectUsageError(impetus({"calc", "composite", "--file", dir}), "is a directory, not a file");
  expectUsageError(impetus({"run", dir + "no_such_scene.json", "--steps", "1"}), "no such file");
}

TEST(Cli, a_spin_beyond_the_steps_cap_is_reported_in_the_run_summary) {
  // 1e38 rad/s is finite and the step turns the body at most a quarter turn a substep (188.5
  // rad/s at 60 Hz with 4 substeps): said, not done in silence.
  const std::string scene = writeTemp(
      "impetus_spin_cap.json",
      R"({"kind": "rigid2d", "bodies": [{"type": "dynamic", "angular_velocity": 1e38, "shapes": [{"type": "circle", "radius": 1}]},
                                         {"type": "dynamic", "position": [5, 0], "angular_velocity": 100, "shapes": [{"type": "circle", "radius": 1}]}]})");
  const CliRun run = impetus({"run", scene, "--steps", "2"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("Capped: bodies[0] at 1e+38 rad/s"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("(188.496 rad/s at this dt)"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("bodies[1]"), std::string::npos) << run.out; // under the cap
}

TEST(Cli, outputs_a_script_reads_are_always_there_and_typed) {
  // Nearly antipodal points: Vincenty does not converge, yet `distance` is there (the geodesic's),
  // or, in a build without GeographicLib, the pair is refused.
  const CliRun v = impetus({"calc", "vincenty", "--from", "0,0", "--to", "0.5,179.7", "--json"});
  if (v.status == 0) {
    const json doc = json::parse(v.out);
    EXPECT_FALSE(doc.at("outputs").at("converged").at("value").get<bool>());
    EXPECT_EQ(doc.at("outputs").at("method").at("value").get<std::string>(), "geodesic");
    EXPECT_DOUBLE_EQ(output(doc, "distance"), output(doc, "geodesic_distance"));
    EXPECT_NEAR(output(doc, "distance"), 19944127.42, 0.01); // GeographicLib's geodesic
  } else {
    expectUsageError(v, "nearly antipodal");
  }
  // A converging pair keeps Vincenty's answer.
  const CliRun near = impetus({"calc", "vincenty", "--from", "0,0", "--to", "1,1", "--json"});
  ASSERT_EQ(near.status, 0) << near.err;
  EXPECT_EQ(json::parse(near.out).at("outputs").at("method").at("value").get<std::string>(), "vincenty");
  // Every output of gps-clock is a number, the MHz one included.
  const CliRun clock = impetus({"calc", "gps-clock", "--json"});
  ASSERT_EQ(clock.status, 0) << clock.err;
  const json clockDoc = json::parse(clock.out); // kept: items() refers into it
  for (const auto& [name, value] : clockDoc.at("outputs").items()) {
    EXPECT_TRUE(value.at("value").is_number()) << name;
  }
  EXPECT_NEAR(output(clockDoc, "corrected_frequency_mhz"), 10.22999999543, 2e-11);
  // oscillator-stability's keys spell each method as --method does.
  const CliRun osc = impetus({"calc", "oscillator-stability", "--omega-dt", "2.5", "--json"});
  ASSERT_EQ(osc.status, 0) << osc.err;
  const json oscillator = json::parse(osc.out);
  EXPECT_NEAR(output(oscillator, "amplification.explicit-euler"), std::sqrt(1.0 + 2.5 * 2.5), 1e-12); // sqrt(1+z^2)
  EXPECT_TRUE(oscillator.at("outputs").contains("energy_log10.semi-implicit-euler"));
}

TEST(Cli, demos_run_and_unknown_demo_exits_two) {
  const CliRun car = impetus({"demo", "car-driver-fuel"});
  EXPECT_EQ(car.status, 0);
  EXPECT_NE(car.out.find("4512.20"), std::string::npos) << car.out;
  const CliRun box = impetus({"demo", "tumbling-box"});
  EXPECT_EQ(box.status, 0);
  EXPECT_NE(box.out.find("reversed"), std::string::npos);
  EXPECT_EQ(impetus({"demo", "nope"}).status, 2);
}

} // namespace
