// `impetus calc` on the sensors and display models, through the executable: the book's worked
// examples (the Mariana-trench ball, the balance board's 0.30/-0.10, find2dAngle's -10 degrees),
// the spec's frustum oracle, a recorded pinch, and bad input refused with one line naming the
// parameter.
#include "cli/cli_process.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using impetus::testing::CliRun;
using impetus::testing::expectUsageError;
using impetus::testing::impetus;
using nlohmann::json;

json run(const std::vector<std::string>& args) {
  std::vector<std::string> full{"calc"};
  full.insert(full.end(), args.begin(), args.end());
  full.emplace_back("--json");
  const CliRun r = impetus(full);
  EXPECT_EQ(r.status, 0) << r.err;
  return json::parse(r.out).at("outputs");
}

double value(const json& outputs, const std::string& name) { return outputs.at(name).at("value").get<double>(); }

TEST(SensorsCalc, the_books_worked_examples) {
  // Ch. 23: the sealed ball at 10,900 m: rho g h = 1025 x 9.81 x 10,900 Pa, all of it net.
  const json depth = run({"depth-pressure"});
  EXPECT_NEAR(value(depth, "differential"), 109'602'225.0, 1e-6);
  // Ch. 23: the balance board.
  const json board = run({"balance-board", "--loads", "30,15,20,35", "--body-weight", "102"});
  EXPECT_NEAR(value(board, "cog_x"), 0.30, 1e-15);
  EXPECT_NEAR(value(board, "cog_y"), -0.10, 1e-15);
  EXPECT_EQ(board.at("motion").at("value"), "both feet on");
  // Ch. 21: find2dAngle's -10 degrees (in its own argument order): 190 in the book, 350 right.
  const json tilt = run({"tilt-angle", "--ax", "0.984807753012208", "--ay", "-0.17364817766693"});
  EXPECT_NEAR(value(tilt, "angle_from_x"), 350.0, 1e-9);
  EXPECT_NEAR(value(tilt, "book_find2dAngle"), 190.0, 1e-4);
  // Ch. 25: x = 4.9 t^2 at 30 Hz: central 9.8 exactly; the book's acceleration 9.8 h.
  const json diff = run({"finite-difference"});
  EXPECT_NEAR(value(diff, "central"), 9.8, 1e-9);
  EXPECT_NEAR(value(diff, "book_findAcceleration"), 9.8 / 30.0, 1e-9);
  // Ch. 23: Android's getAltitude(1013.25, 1000).
  EXPECT_NEAR(value(run({"barometric-altitude", "--pressure", "100000"}), "android_altitude"), 110.90, 0.005);
}

TEST(SensorsCalc, recorded_pinch_and_touch_explosion) {
  const json g =
      run({"touch-gestures", "--recording", "0: 100,100 200,100; 0.1: 90,100 210,100; 0.2: 50,100 250,100; 0.3:"});
  EXPECT_EQ(value(g, "pinches"), 1.0);
  EXPECT_NEAR(value(g, "last_scale"), 2.0, 1e-12);
  EXPECT_EQ(value(g, "taps"), 0.0);
  const json e = run({"touch-explosion", "--recording", "0: 100,100; 0.2:; 0.3: 40,40 400,240; 0.4:"});
  EXPECT_EQ(value(e, "bursts"), 3.0);
  // (100, 100) px on a 480 px screen at 20 px/m: (5, 19) m.
  EXPECT_EQ(e.at("origins").at("value").at(0).at(1).get<double>(), 5.0);
  EXPECT_EQ(e.at("origins").at("value").at(0).at(2).get<double>(), 19.0);
}

TEST(DisplayCalc, spec_frustum_oracle_and_anaglyph) {
  const json f = run({"stereo-frustum"});
  const json left = f.at("left_frustum").at("value");
  EXPECT_NEAR(left.at(0).get<double>(), -0.102315, 5e-7);
  EXPECT_NEAR(left.at(1).get<double>(), 0.102965, 5e-7);
  // The projection's (0, 2) entry, (r + l)/(r - l), is the separation: 0.065 / W.
  EXPECT_NEAR(f.at("left_projection").at("value").at(0).at(2).get<double>(), value(f, "separation"), 1e-15);
  const json a = run({"anaglyph", "--left", "1,0,0", "--right", "0,0,1", "--mode", "gray"});
  EXPECT_NEAR(a.at("gray").at("value").at(0).get<double>(), 0.299, 1e-15);
  EXPECT_NEAR(a.at("gray").at("value").at(1).get<double>(), 0.114, 1e-15);
}

TEST(SensorsCalc, hourglass_drains_upright_and_stops_on_its_side) {
  // Upright every grain leaves the top bulb within the limit; on its side (90 degrees) the neck
  // lies level and most of the sand stays. Beverloo's 2D rate is the closed form for C = 1:
  // 0.82 / (pi (2 mm)^2 / 4) sqrt(9.80665) (8 - 3 mm)^1.5 = 289.0 grains/s.
  const json upright = run({"hourglass", "--grain-count", "150"});
  EXPECT_EQ(upright.at("drained").at("value"), true);
  EXPECT_EQ(value(upright, "grains_left"), 0.0);
  EXPECT_GT(value(upright, "drain_time"), 0.0);
  EXPECT_GT(value(upright, "flow_rate"), 0.0);
  EXPECT_NEAR(value(upright, "beverloo_rate"), 289.0, 0.1);
  const json side = run({"hourglass", "--grain-count", "150", "--tilt", "90", "--max-time", "2"});
  EXPECT_EQ(side.at("drained").at("value"), false);
  EXPECT_GT(value(side, "grains_left"), 75.0);
  expectUsageError(impetus({"calc", "hourglass", "--neck-width", "0.002"}), "--neck-width = 0.002");
  expectUsageError(impetus({"calc", "hourglass", "--grain-count", "5000"}), "--grain-count = 5000");
}

TEST(SensorsCalc, bad_input_is_refused_naming_the_parameter) {
  expectUsageError(impetus({"calc", "sensor-filter", "--cutoff-hz", "60"}), "--cutoff-hz = 60");
  expectUsageError(impetus({"calc", "accel-clip", "--range", "0"}), "--range = 0");
  expectUsageError(impetus({"calc", "tilt-angle", "--ax", "0", "--ay", "0"}), "--ay = 0");
  expectUsageError(impetus({"calc", "barometric-altitude", "--pressure", "-5"}), "--pressure = -5");
  expectUsageError(impetus({"calc", "touch-gestures", "--recording", "0: 1,2; x"}), "--recording");
  expectUsageError(impetus({"calc", "stereo-frustum", "--convergence", "0.01"}), "--convergence = 0.01");
  expectUsageError(impetus({"calc", "anaglyph", "--mode", "purple"}), "--mode");
  expectUsageError(impetus({"calc", "analog-button", "--raw", "300"}), "--raw = 300");
  expectUsageError(impetus({"calc", "savitzky-golay", "--order", "7"}), "--order = 7");
}

} // namespace
