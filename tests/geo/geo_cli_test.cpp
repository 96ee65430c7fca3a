// `impetus calc` for GPS and geodesy, black-box: the spec's New York-London figures, Vincenty's
// non-convergence reported in the output, a 2D GPS fix, and an out-of-range latitude named.
#include "cli/cli_process.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <string>

namespace {

using impetus::testing::CliRun;
using impetus::testing::impetus;
using nlohmann::json;

json outputs(const CliRun& run) { return json::parse(run.out).at("outputs"); }

TEST(GeoCli, great_circle_and_rhumb_line_match_the_spec) {
  const CliRun gc = impetus({"calc", "great-circle", "--from", "40.7128,-74.0060", "--to", "51.5074,-0.1278",
                             "--radius", "6371000", "--json"});
  ASSERT_EQ(gc.status, 0) << gc.err;
  EXPECT_NEAR(outputs(gc).at("distance").at("value").get<double>(), 5570222.2, 0.1);
  EXPECT_NEAR(outputs(gc).at("initial_bearing").at("value").get<double>(), 51.2126, 1e-4);
  const CliRun rh = impetus(
      {"calc", "rhumb-line", "--from", "40.7128,-74.0060", "--to", "51.5074,-0.1278", "--radius", "6371000", "--json"});
  ASSERT_EQ(rh.status, 0) << rh.err;
  EXPECT_NEAR(outputs(rh).at("distance").at("value").get<double>(), 5794120.8, 0.1);
  EXPECT_NEAR(outputs(rh).at("bearing").at("value").get<double>(), 78.0441, 1e-4);
}

TEST(GeoCli, vincenty_reports_non_convergence_and_gps_fix_solves) {
  const CliRun v = impetus({"calc", "vincenty", "--from", "0,0", "--to", "0.5,179.7", "--json"});
  ASSERT_EQ(v.status, 0) << v.err;
  EXPECT_FALSE(outputs(v).at("converged").at("value").get<bool>());
  const CliRun fix = impetus({"calc", "gps-fix", "--dimensions", "2", "--satellites", "0,0 10,0 4,8", "--pseudoranges",
                              "5.5 8.5622577483 4.6231056256", "--speed-of-light", "1", "--json"});
  ASSERT_EQ(fix.status, 0) << fix.err;
  const json position = outputs(fix).at("position").at("value");
  EXPECT_NEAR(position[0].get<double>(), 3.0, 1e-6);
  EXPECT_NEAR(position[1].get<double>(), 4.0, 1e-6);
  EXPECT_NEAR(outputs(fix).at("range_bias").at("value").get<double>(), 0.5, 1e-6);
}

TEST(GeoCli, bad_latitude_and_unsolvable_geometry_exit_two_naming_the_field) {
  const CliRun bad = impetus({"calc", "great-circle", "--from", "91,0", "--to", "0,0"});
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--from.latitude = 91"), std::string::npos) << bad.err;
  const CliRun flat = impetus({"calc", "gps-fix", "--satellites", "0,0,0 10,0,0 4,8,0 -6,3,0", "--pseudoranges",
                               "5.5 8.5622577483 4.6231056256 9.5553851381"});
  EXPECT_EQ(flat.status, 2);
  EXPECT_NE(flat.err.find("--satellites"), std::string::npos) << flat.err;
}

} // namespace
